// 3D Gaussian splats in one pass (docs/GAUSSIANS.md): each Gaussian, in back-to-front order of
// the shared eye depth, is drawn once as a rectangle covering its 3σ square in every view
// between the offsets params.offsets.xy; every subpixel evaluates it for its own view — 2D mean
// and covariance through that view's Jacobian, SH colour along that view's direction — and
// blends it "over" what lies behind with its own α (dual-source blending: one α per channel).
// With params.fixed_view every channel shows the view at params.offsets.z (N-pass, single view,
// and the tiles of a quilt, drawn with the tile as the viewport).
// Accumulates in an RGBA16F target cleared to the background (gaussians/resolve.wgsl copies it).
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

struct SplatOut {
    @builtin(position) position: vec4<f32>,
    @location(0) @interpolate(flat) index: u32,
    @location(1) @interpolate(flat) eye_mean: vec3<f32>,
    @location(2) @interpolate(flat) cov_a: vec3<f32>,
    @location(3) @interpolate(flat) cov_b: vec3<f32>,
}

// A vertex outside clip space: the rectangle is culled.
fn culled() -> SplatOut {
    return SplatOut(vec4<f32>(2.0, 2.0, 2.0, 1.0), 0u, vec3<f32>(0.0), vec3<f32>(0.0),
        vec3<f32>(0.0));
}

@vertex
fn vs_main(@builtin(vertex_index) vertex: u32, @builtin(instance_index) slot: u32) -> SplatOut {
    let index = order[slot];
    if (index >= params.count) {
        return culled(); // padding of the sort, or a Gaussian outside the near and far planes
    }
    let g = geometry[index];
    let q = (frame.camera.eye_from_world * vec4<f32>(g.mean_opacity.xyz, 1.0)).xyz;
    if (!(-q.z > frame.camera.near && -q.z < frame.camera.far)) {
        return culled();
    }
    let cov = eye_covariance(g);
    // The 3σ squares of the two extreme views: a square's centre moves linearly with the
    // offset and its radius is largest at an end of the range (docs/GAUSSIANS.md), so their
    // union covers every view between.
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
    let corner = array<u32, 6>(0u, 1u, 2u, 2u, 1u, 3u)[vertex];
    let px = vec2<f32>(select(px_lo.x, px_hi.x, (corner & 1u) != 0u),
        select(px_lo.y, px_hi.y, (corner & 2u) != 0u));
    let clamped = clamp(px, vec2<f32>(-1.0), size + 1.0);
    let ndc = vec2<f32>(clamped.x / size.x * 2.0 - 1.0, 1.0 - clamped.y / size.y * 2.0);
    return SplatOut(vec4<f32>(ndc, 0.5, 1.0), index, q, cov[0], cov[1]);
}

struct BlendOut {
    @location(0) @blend_src(0) color: vec4<f32>,
    @location(0) @blend_src(1) alpha: vec4<f32>,
}

// α and premultiplied colour of the Gaussian for the view at offset vd, at pixel position px.
fn view_splat(in: SplatOut, vd: f32, px: vec2<f32>) -> vec4<f32> {
    let g = geometry[in.index];
    let projected = project(in.eye_mean, array<vec3<f32>, 2>(in.cov_a, in.cov_b), vd);
    let alpha = splat_alpha(projected, g.mean_opacity.w, px);
    if (alpha <= 0.0) {
        return vec4<f32>(0.0);
    }
    let color = sh_color(in.index, view_direction(g.mean_opacity.xyz, vd));
    return vec4<f32>(alpha * color, alpha);
}

@fragment
fn fs_main(in: SplatOut) -> BlendOut {
    // The pixel in the view image (a quilt tile's pixels start at its origin).
    let at = in.position.xy - params.tile.xy;
    let px = vec2<u32>(at);
    var color = vec3<f32>(0.0);
    var alpha = vec3<f32>(0.0);
    if (params.fixed_view != 0u || VIEWS_PER_PIXEL == 1u) {
        var vd = params.offsets.z;
        if (params.fixed_view == 0u) {
            vd = view_offset(ray_view(px, 0u));
        }
        let s = view_splat(in, vd, at);
        color = s.rgb;
        alpha = vec3<f32>(s.a);
    } else {
        for (var k = 0u; k < 3u; k++) {
            let s = view_splat(in, view_offset(ray_view(px, k)), at);
            color[k] = s[k];
            alpha[k] = s.a;
        }
    }
    if (all(alpha <= vec3<f32>(0.0))) {
        discard;
    }
    // dst = color + (1 − α_c)·dst per channel (blend factors One, OneMinusSrc1).
    return BlendOut(vec4<f32>(color, 1.0), vec4<f32>(alpha, 1.0));
}
