// 3D Gaussian splats in one pass (docs/GAUSSIANS.md): each Gaussian, in back-to-front order of
// the shared eye depth, is drawn once as a rectangle covering its 3σ square in every view
// between the offsets params.offsets.xy; every subpixel evaluates it for its own view — 2D mean
// and covariance through that view's Jacobian, SH colour along that view's direction — and
// blends it "over" what lies behind with its own α (dual-source blending: one α per channel).
// With params.fixed_view every channel shows the view at params.offsets.z (N-pass, single view,
// and the tiles of a quilt, drawn with the tile as the viewport).
// Accumulates in an RGBA16F target cleared to the background (render/accumulation_resolve.wgsl copies it).
enable dual_source_blending;
#import shared/frame.wgsl
#import shared/multiview.wgsl
#import gaussians/shared/gaussian.wgsl

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;
// Bindings read by gaussians/shared/gaussian.wgsl.
@group(1) @binding(0) var<storage, read> geometry: array<Gaussian>;
@group(1) @binding(1) var<storage, read> sh: array<u32>;
@group(1) @binding(2) var<uniform> params: GaussianParams;
// The draw order: Gaussian indices, back to front (gaussians/sort_*.wgsl or the CPU).
@group(1) @binding(3) var<storage, read> order: array<u32>;
// Colours per Gaussian and view (gaussians/colors.wgsl), when params.color_table is 1.
@group(1) @binding(4) var<storage, read> colors: array<vec2<u32>>;

struct SplatOut {
    @builtin(position) position: vec4<f32>,
    @location(0) @interpolate(flat) index: u32,
    @location(1) @interpolate(flat) eye_mean: vec3<f32>,
    @location(2) @interpolate(flat) cov_a: vec3<f32>,
    @location(3) @interpolate(flat) cov_b: vec3<f32>,
    // With a fixed view: the Gaussian's colour in it (one per Gaussian and view, as graphdeco's
    // preprocessing computes it).
    @location(4) @interpolate(flat) color: vec3<f32>,
}

// A vertex outside clip space: the rectangle is culled.
fn culled() -> SplatOut {
    return SplatOut(vec4<f32>(2.0, 2.0, 2.0, 1.0), 0u, vec3<f32>(0.0), vec3<f32>(0.0),
        vec3<f32>(0.0), vec3<f32>(0.0));
}

// The Mahalanobis radius beyond which a Gaussian of `opacity` has α < 1/255 (never drawn):
// opacity·exp(−k²/2) = 1/255.
fn alpha_radius(opacity: f32) -> f32 {
    return sqrt(2.0 * log(255.0 * opacity));
}

// Extent of the ellipse dᵀΣ⁻¹d ≤ k² of 2D covariance `cov` (a, b, c) along unit `e`.
fn ellipse_extent(cov: vec3<f32>, e: vec2<f32>, k: f32) -> f32 {
    let s = e.x * e.x * cov.x + 2.0 * e.x * e.y * cov.y + e.y * e.y * cov.z;
    return k * sqrt(max(s, 0.0));
}

@vertex
fn vs_main(@builtin(vertex_index) vertex: u32, @builtin(instance_index) slot: u32) -> SplatOut {
    let index = order[slot];
    if (index >= params.count) {
        return culled(); // padding of the sort, or a Gaussian outside the near and far planes
    }
    let g = geometry[index];
    let opacity = g.mean_opacity.w;
    let q = (frame.camera.eye_from_world * vec4<f32>(g.mean_opacity.xyz, 1.0)).xyz;
    if (!(-q.z > frame.camera.near && -q.z < frame.camera.far) || !(opacity * 255.0 > 1.0)) {
        return culled();
    }
    let cov = eye_covariance(g);
    // Every view between the offsets: a view's mean moves linearly with its offset, and the
    // extent of its ellipse along a fixed direction (the norm of an affine function of the
    // offset) and its 3σ square are largest at an end of the range (docs/GAUSSIANS.md), so the
    // two extreme views bound every view between.
    let lo = project(q, cov, params.offsets.x);
    let hi = project(q, cov, params.offsets.y);
    let r = max(lo.radius, hi.radius) + 1.0;
    if (r <= 1.0) {
        return culled();
    }
    let px_lo = min(lo.mean, hi.mean) - vec2<f32>(r);
    let px_hi = max(lo.mean, hi.mean) + vec2<f32>(r);
    let size = frame.camera.viewport;
    if (any(px_hi < vec2<f32>(0.0)) || any(px_lo > size)) {
        return culled();
    }
    // Two covers hold every pixel that can get α ≥ 1/255: the 3σ squares' box, and the box, in
    // the frame of the ellipse's axes, of the ellipses at the α = 1/255 radius. The smaller is
    // drawn: the oriented one for flat Gaussians seen at an angle, the square for round ones.
    let k = alpha_radius(opacity);
    let mid = 0.5 * (lo.cov + hi.cov);
    let angle = 0.5 * atan2(2.0 * mid.y, mid.x - mid.z);
    let e1 = vec2<f32>(cos(angle), sin(angle));
    let e2 = vec2<f32>(-e1.y, e1.x);
    let a_lo = min(dot(lo.mean, e1) - ellipse_extent(lo.cov, e1, k),
        dot(hi.mean, e1) - ellipse_extent(hi.cov, e1, k)) - 1.0;
    let a_hi = max(dot(lo.mean, e1) + ellipse_extent(lo.cov, e1, k),
        dot(hi.mean, e1) + ellipse_extent(hi.cov, e1, k)) + 1.0;
    let b_lo = min(dot(lo.mean, e2) - ellipse_extent(lo.cov, e2, k),
        dot(hi.mean, e2) - ellipse_extent(hi.cov, e2, k)) - 1.0;
    let b_hi = max(dot(lo.mean, e2) + ellipse_extent(lo.cov, e2, k),
        dot(hi.mean, e2) + ellipse_extent(hi.cov, e2, k)) + 1.0;
    let corner = array<u32, 6>(0u, 1u, 2u, 2u, 1u, 3u)[vertex];
    var px: vec2<f32>;
    let square = (px_hi - px_lo).x * (px_hi - px_lo).y;
    if ((a_hi - a_lo) * (b_hi - b_lo) < square) {
        let a = select(a_lo, a_hi, (corner & 1u) != 0u);
        let b = select(b_lo, b_hi, (corner & 2u) != 0u);
        px = a * e1 + b * e2;
    } else {
        let corner_px = vec2<f32>(select(px_lo.x, px_hi.x, (corner & 1u) != 0u),
            select(px_lo.y, px_hi.y, (corner & 2u) != 0u));
        px = clamp(corner_px, vec2<f32>(-1.0), size + 1.0);
    }
    let ndc = vec2<f32>(px.x / size.x * 2.0 - 1.0, 1.0 - px.y / size.y * 2.0);
    var color = vec3<f32>(0.0);
    if (params.fixed_view != 0u) {
        let basis = sh_basis(view_direction(g.mean_opacity.xyz, params.offsets.z));
        color = half_rgb(vec3<f32>(sh_channel(index, basis, 0u), sh_channel(index, basis, 1u),
            sh_channel(index, basis, 2u)));
    }
    return SplatOut(vec4<f32>(ndc, 0.5, 1.0), index, q, cov[0], cov[1], color);
}

struct BlendOut {
    @location(0) @blend_src(0) color: vec4<f32>,
    @location(0) @blend_src(1) alpha: vec4<f32>,
}

// α of the Gaussian for the view at offset vd at pixel position px (0: not drawn there).
fn view_alpha(in: SplatOut, vd: f32, px: vec2<f32>) -> f32 {
    let projected = project(in.eye_mean, array<vec3<f32>, 2>(in.cov_a, in.cov_b), vd);
    return splat_alpha(projected, geometry[in.index].mean_opacity.w, px);
}

// Channel c of the Gaussian's colour in view `view`: from the colour table, else its SH
// along the direction from that view's camera centre (rounded as the table rounds).
fn view_channel(in: SplatOut, view: u32, c: u32) -> f32 {
    if (params.color_table != 0u) {
        let words = colors[in.index * VIEW_COUNT + view];
        let rg = unpack2x16float(words.x);
        return select(select(rg.x, rg.y, c == 1u), unpack2x16float(words.y).x, c == 2u);
    }
    let dir = view_direction(geometry[in.index].mean_opacity.xyz, view_offset(view));
    return half_rgb(vec3<f32>(sh_channel(in.index, sh_basis(dir), c)))[0];
}

@fragment
fn fs_main(in: SplatOut) -> BlendOut {
    // The pixel in the view image (a quilt tile's pixels start at its origin).
    let at = in.position.xy - params.tile.xy;
    let px = vec2<u32>(at);
    var color = vec3<f32>(0.0);
    var alpha = vec3<f32>(0.0);
    if (params.fixed_view != 0u) {
        let a = view_alpha(in, params.offsets.z, at);
        if (a <= 0.0) {
            discard;
        }
        color = a * in.color;
        alpha = vec3<f32>(a);
    } else if (VIEWS_PER_PIXEL == 1u) {
        let view = ray_view(px, 0u);
        let a = view_alpha(in, view_offset(view), at);
        if (a <= 0.0) {
            discard;
        }
        for (var c = 0u; c < 3u; c++) {
            color[c] = a * view_channel(in, view, c);
        }
        alpha = vec3<f32>(a);
    } else {
        // Each channel its own view: α, then only that channel's colour.
        for (var c = 0u; c < 3u; c++) {
            let view = ray_view(px, c);
            let a = view_alpha(in, view_offset(view), at);
            if (a > 0.0) {
                color[c] = a * view_channel(in, view, c);
                alpha[c] = a;
            }
        }
        if (all(alpha <= vec3<f32>(0.0))) {
            discard;
        }
    }
    // dst = color + (1 − α_c)·dst per channel (blend factors One, OneMinusSrc1).
    return BlendOut(vec4<f32>(color, 1.0), vec4<f32>(alpha, 1.0));
}
