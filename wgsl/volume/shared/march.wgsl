// Ray marching through the volume box (volume/raycast*.wgsl): front to back with early
// termination, classified by the pre-integration table (Engel et al. 2001) and Blinn-Phong
// shaded from the averaged Sobel gradients (paper §3.5.1).
//
// Samples sit on the eye-depth planes d = k·Δ shared by every view (the view-aligned slices of
// the paper), so a single-pass ray and the N-pass ray of the same view and pixel take the same
// samples: the methods differ only in which views they evaluate per pixel and where they
// write them.
//
// Empty-space skipping (exact): after a segment that added nothing, the ray looks up the
// distance D of its sample's voxel cell (src/volume/empty_space.rs): every cell within D − 1
// of it is transparent under the transfer function, so the ray jumps to its last sample plane
// within D − 1 voxels along every axis. The skipped segments would each have added exactly
// zero, so the image is unchanged bit for bit.
//
// Reads `frame`, `volume`, `linear_clamp`, `preintegration`, `params`, `empty_distance`.
// Empty-space skipping compiled in (src/volume/passes/raycast.rs sets it per scene): without
// it the march is the plain loop.
override SKIP_EMPTY: bool = true;
// Probing stride through transparent material (`--empty-stride P`, `VolumeSettings::empty_stride`;
// an approximation, needs SKIP_EMPTY): after a segment that added nothing, the ray's next
// sample is P planes on instead of one. Where the pre-integrated segment between the two is
// exactly zero (no extinction anywhere between their scalars), the P segments are taken as
// transparent; otherwise the ray goes back and marches those planes one by one. What it can
// miss: material whose scalars lie outside both ends' range within those P planes (a feature
// thinner than P·Δ). 1: compiled out, the exact march.
override EMPTY_STRIDE: u32 = 1u;
// Coarse steps through thin material too (`--thin-alpha A`, `VolumeSettings::thin_alpha`; with
// EMPTY_STRIDE > 1): a probe whose segment adds at most A opacity per sample step is taken as
// one segment P steps long (opacity 1 − (1 − α)^P, colour scaled alike: exact where the scalar
// changes linearly over the P steps and the colour is constant), and probing goes on after it. 0: only transparent material.
override THIN_ALPHA: f32 = 0.0;
// What a ray shows (`Projection::code`, src/volume/options.rs): 0 the composited
// classification; 1 the maximum, 2 the minimum, 3 the mean scalar over the ray's samples,
// through the transfer function's colour at that scalar, opaque within the box (a projection
// has no depth order, so nothing to skip or probe: SKIP_EMPTY and EMPTY_STRIDE are off then).
override PROJECTION: u32 = 0u;
// PROJECTION 4: the isosurface's normalised scalar.
override ISO_VALUE: f32 = 0.5;

// The isosurface (PROJECTION 4) on the ray o + u·d from sample plane k0 (texture space; the
// eye ray origin + t·dir for the light): the first pair of samples that crosses ISO_VALUE from
// below (or the first sample, where the ray enters inside), the hit interpolated between them,
// lit with the gradient there; transparent where the ray never reaches the value.
fn isosurface(o: vec3<f32>, d: vec3<f32>, k0: f32, count: u32, origin: vec3<f32>, dir: vec3<f32>) -> vec4<f32> {
    var front = sample_plane(o, d, k0);
    if (front.a >= ISO_VALUE) {
        return lit_hit(front, k0, origin, dir);
    }
    for (var i = 1u; i <= count; i++) {
        let back = sample_plane(o, d, k0 + f32(i));
        if (back.a >= ISO_VALUE) {
            let t = clamp((ISO_VALUE - front.a) / max(back.a - front.a, 1e-6), 0.0, 1.0);
            return lit_hit(mix(front, back, t), k0 + f32(i) - 1.0 + t, origin, dir);
        }
        front = back;
    }
    return vec4<f32>(0.0);
}

// The surface at plane k (fractional) of the eye ray origin + t·dir, gradient g.xyz: the
// transfer function's colour at ISO_VALUE (white where it is transparent), Blinn-Phong lit as
// `shaded_segment` lights a segment (`blinn_phong`, two-sided).
fn lit_hit(g: vec4<f32>, k: f32, origin: vec3<f32>, dir: vec3<f32>) -> vec4<f32> {
    let c = textureSampleLevel(preintegration, linear_clamp, vec2<f32>(table_coord(ISO_VALUE), table_coord(ISO_VALUE)), 0.0);
    let base = select(vec3<f32>(1.0), min(c.rgb / max(c.a, 1e-6), vec3<f32>(1.0)), c.a > 0.0);
    let normal = (params.normal_from_tex * vec4<f32>(g.xyz, 0.0)).xyz;
    if (params.shade == 0u || dot(normal, normal) <= 1e-12) {
        return vec4<f32>(base, 1.0);
    }
    let position = origin + (k * params.step / frame.camera.focal_distance) * dir;
    let rgb = base * blinn_phong(normal, position, origin);
    return vec4<f32>(min(rgb, vec3<f32>(1.0)), 1.0);
}

// The projection (PROJECTION ≠ 0) of the scalars on sample planes k0 … k0 + count of the ray
// o + u·d (texture space): the samples the compositing march takes.
fn project(o: vec3<f32>, d: vec3<f32>, k0: f32, count: u32) -> vec4<f32> {
    var m = sample_plane(o, d, k0).a;
    var sum = m;
    for (var i = 1u; i <= count; i++) {
        let s = sample_plane(o, d, k0 + f32(i)).a;
        if (PROJECTION == 1u) {
            m = max(m, s);
        } else if (PROJECTION == 2u) {
            m = min(m, s);
        }
        sum += s;
    }
    if (PROJECTION == 3u) {
        m = sum / f32(count + 1u);
    }
    // The pre-integrated segment of constant scalar m: premultiplied colour over its opacity
    // is the transfer function's colour at m (black where it is transparent).
    let c = textureSampleLevel(preintegration, linear_clamp, vec2<f32>(table_coord(m), table_coord(m)), 0.0);
    let rgb = select(vec3<f32>(0.0), c.rgb / max(c.a, 1e-6), c.a > 0.0);
    return vec4<f32>(min(rgb, vec3<f32>(1.0)), 1.0);
}

// A warp's reference views (volume/raycast_reference.wgsl, src/warp) need one representative
// depth per ray: the eye depth where the accumulated opacity crosses ½ (interpolated within
// the segment), and for rays that never reach ½, the opacity-weighted mean depth of what they
// crossed. Compiled in only for that pipeline: the other marches are unchanged.
override TRACK_DEPTH: bool = false;
// Per ray (reset by the caller): the depth where α crossed ½ (0: not yet), and the running
// Σ w·d, Σ w of the segments' contributions w.
var<private> half_depth: f32 = 0.0;
var<private> weighted_depth: vec2<f32> = vec2<f32>(0.0);

// Note segment `seg` ending on plane k, composited onto `before` (giving `after`).
fn track_depth(before: vec4<f32>, after: vec4<f32>, seg: vec4<f32>, k: f32) {
    let w = (1.0 - before.a) * seg.a;
    weighted_depth += vec2<f32>(w * (k - 0.5) * params.step, w);
    if (half_depth == 0.0 && after.a >= 0.5) {
        let f = (0.5 - before.a) / max(after.a - before.a, 1e-6);
        half_depth = (k - 1.0 + f) * params.step;
    }
}

// The representative depth of the last ray (see TRACK_DEPTH); 0 where it crossed nothing.
fn representative_depth() -> f32 {
    if (half_depth > 0.0) {
        return half_depth;
    }
    if (weighted_depth.y > 0.0) {
        return weighted_depth.x / weighted_depth.y;
    }
    return 0.0;
}

// Texture-space position of sample plane k (eye depth k·Δ) on the ray o + u·d.
fn plane_position(o: vec3<f32>, d: vec3<f32>, k: f32) -> vec3<f32> {
    let depth = k * params.step;
    return o + (depth / frame.camera.focal_distance) * d;
}

// The ray o + u·d against the voxel cells, set up once per ray: voxels per texture unit, the
// last cell, the most voxels the ray moves along any axis from one sample plane to the next,
// and the least distance D that allows a jump of one plane (`empty_planes`).
struct CellRay {
    voxels: vec3<f32>,
    last: vec3<f32>,
    voxels_per_plane: f32,
    need: f32,
}

// Slack, in voxels, between the voxel coordinates computed here and the sampler's own.
const CELL_SLACK: f32 = 0.01;

fn cell_ray(d: vec3<f32>) -> CellRay {
    let voxels = vec3<f32>(textureDimensions(volume));
    let per_plane = abs(d * voxels) * (params.step / frame.camera.focal_distance);
    let voxels_per_plane = max(max(max(per_plane.x, per_plane.y), per_plane.z), 1e-6);
    return CellRay(
        voxels,
        vec3<f32>(textureDimensions(empty_distance) - 1u),
        voxels_per_plane,
        ceil(1.0 + CELL_SLACK + voxels_per_plane),
    );
}

// The voxel coordinate q = p·voxels − ½ of sample plane k of the ray o + u·d.
fn plane_voxel(ray: CellRay, o: vec3<f32>, d: vec3<f32>, k: f32) -> vec3<f32> {
    return plane_position(o, d, k) * ray.voxels - 0.5;
}

// From sample plane k of the ray o + u·d: how many planes on the ray may jump (x: every
// segment up to there adds zero; 0: none) and the distance D of the sample's cell (y). Cell c
// holds the samples whose q has floor c (clamped, as the sampler clamps); a sample whose q is
// within D − 1 of this one along every axis lies in a cell within D − 1 of c. The planes'
// computed positions are monotone in k, so checking the landing plane's own position bounds
// every sample between, whatever the rounding (a far camera's positions round coarsely).
fn empty_planes(ray: CellRay, o: vec3<f32>, d: vec3<f32>, k: f32) -> vec2<f32> {
    let q = plane_voxel(ray, o, d, k);
    let cell = clamp(floor(q), vec3<f32>(0.0), ray.last);
    let distance = f32(textureLoad(empty_distance, vec3<u32>(cell), 0).x);
    let reach = distance - 1.0 - CELL_SLACK;
    let planes = floor(reach / ray.voxels_per_plane);
    if (planes < 1.0) {
        return vec2<f32>(0.0, distance);
    }
    let moved = abs(plane_voxel(ray, o, d, k + planes) - q);
    let within = max(max(moved.x, moved.y), moved.z) <= reach;
    return vec2<f32>(select(0.0, planes, within), distance);
}

// The shaded segment between samples `front` and `back` (back on plane k) of the ray
// origin + t·dir.
fn segment(front: vec4<f32>, back: vec4<f32>, k: f32, origin: vec3<f32>, dir: vec3<f32>) -> vec4<f32> {
    let depth = k * params.step;
    return shaded_segment(front, back, origin + (depth / frame.camera.focal_distance) * dir, origin);
}

// `acc` with `seg` composited behind it (front to back, premultiplied).
fn over(acc: vec4<f32>, seg: vec4<f32>) -> vec4<f32> {
    return vec4<f32>(acc.rgb + (1.0 - acc.a) * seg.rgb, acc.a + (1.0 - acc.a) * seg.a);
}

// The volume sample on plane k of the ray o + u·d (texture space).
fn sample_plane(o: vec3<f32>, d: vec3<f32>, k: f32) -> vec4<f32> {
    return textureSampleLevel(volume, linear_clamp, plane_position(o, d, k), 0.0);
}

// Plane index bounds that leave a march's range open at that end.
const ALL_PLANES: f32 = 3.0e38;

// Premultiplied RGBA along the ray origin + t·dir (eye depth t·fd).
fn march(origin: vec3<f32>, dir: vec3<f32>) -> vec4<f32> {
    return march_planes(origin, dir, vec2<f32>(-ALL_PLANES, ALL_PLANES), OPAQUE);
}

// Premultiplied RGBA of the segments between sample planes planes.x … planes.y of the ray
// origin + t·dir (clipped to the box, near and far; the first plane is the front sample),
// stopping once the accumulated opacity reaches `opaque`. `march` is the whole ray; the
// sample-sharing march (volume/shared/share.wgsl) splits one ray into ranges.
fn march_planes(origin: vec3<f32>, dir: vec3<f32>, planes: vec2<f32>, opaque: f32) -> vec4<f32> {
    let fd = frame.camera.focal_distance;
    let o = (params.tex_from_eye * vec4<f32>(origin, 1.0)).xyz;
    let d = (params.tex_from_eye * vec4<f32>(dir, 0.0)).xyz;
    // Slab test against [0, 1]³ (IEEE division: axis-parallel rays give ±inf, handled by min/max).
    let inv = 1.0 / d;
    let a = (vec3<f32>(0.0) - o) * inv;
    let b = (vec3<f32>(1.0) - o) * inv;
    let span = clip_span(o, d, vec2<f32>(
        max(max(min(a.x, b.x), min(a.y, b.y)), min(a.z, b.z)),
        min(min(max(a.x, b.x), max(a.y, b.y)), max(a.z, b.z)),
    ));
    let t_in = span.x;
    let t_out = span.y;
    let d_in = max(t_in * fd, frame.camera.near);
    let d_out = min(t_out * fd, frame.camera.far);
    if (!(d_out > d_in)) {
        return vec4<f32>(0.0);
    }
    let k0 = max(ceil(d_in / params.step), planes.x);
    let k1 = min(floor(d_out / params.step), planes.y);
    let count = min(u32(max(k1 - k0, 0.0)), params.max_samples);
    if (PROJECTION == 4u) {
        return isosurface(o, d, k0, count, origin, dir);
    }
    if (PROJECTION != 0u) {
        return project(o, d, k0, count);
    }
    var front = sample_plane(o, d, k0);
    var acc = vec4<f32>(0.0);
    if (!SKIP_EMPTY) {
        // The plain loop: measured ≈ 25 % faster on llvmpipe than the skipping loop with its
        // look-ups disabled, so it is a separate specialisation.
        for (var i = 1u; i <= count; i++) {
            let back = sample_plane(o, d, k0 + f32(i));
            let seg = segment(front, back, k0 + f32(i), origin, dir);
            let before = acc;
            acc = over(acc, seg);
            if (TRACK_DEPTH) {
                track_depth(before, acc, seg, k0 + f32(i));
            }
            if (acc.a >= opaque) {
                break;
            }
            front = back;
        }
        return acc;
    }
    // Sample i sits on plane k0 + i; the front sample is i − 1. Distances are looked up only
    // after a transparent segment, and not again before one could allow a jump. A jump lands
    // on the last plane j within reach and only re-samples there (`resume`): the one texture
    // fetch per iteration stays on one code path for all lanes.
    let cells = cell_ray(d);
    var look_up = true;
    var resume = false;
    var next_look_up = 0u;
    // EMPTY_STRIDE: the last segment added nothing, and the first sample a probe may start at
    // (past a probe that crossed material).
    var clear = true;
    var probe_from = 1u;
    var i = 1u;
    loop {
        if (i > count) {
            break;
        }
        if (look_up && i - 1u >= next_look_up) {
            look_up = false;
            let empty = empty_planes(cells, o, d, k0 + f32(i - 1u));
            if (empty.x >= 1.0) {
                i = u32(min(f32(i - 1u) + empty.x, f32(count)));
                resume = true;
            } else {
                // A jump needs D ≥ `need`. D changes by at most one per cell boundary crossed,
                // and a move of δ voxels crosses at most ⌈δ⌉ along an axis: no jump before
                // the ray has moved more than need − D − 1 voxels.
                let wait = floor((cells.need - empty.y - 1.0) / cells.voxels_per_plane) + 1.0;
                next_look_up = i - 1u + u32(max(wait, 1.0));
            }
        }
        // Segments this iteration spans: one, or a probe of EMPTY_STRIDE through clear space.
        var n = 1u;
        if (EMPTY_STRIDE > 1u && clear && !resume && i >= probe_from) {
            n = min(EMPTY_STRIDE, count + 1u - i);
        }
        let back = sample_plane(o, d, k0 + f32(i + n - 1u));
        if (!resume) {
            var seg = segment(front, back, k0 + f32(i + n - 1u), origin, dir);
            let step_alpha = seg.a;
            if (n > 1u && step_alpha > THIN_ALPHA) {
                // The probe crossed material: march its planes one by one from `front`.
                probe_from = i + n;
                continue;
            }
            if (n > 1u && step_alpha > 0.0) {
                // Thin material: the probe is one segment n steps long.
                let a = 1.0 - pow(1.0 - step_alpha, f32(n));
                seg = vec4<f32>(seg.rgb * (a / step_alpha), a);
            }
            if (n == 1u || seg.a > 0.0) {
                let before = acc;
                acc = over(acc, seg);
                if (TRACK_DEPTH) {
                    track_depth(before, acc, seg, k0 + f32(i + n - 1u));
                }
                if (acc.a >= opaque) {
                    break;
                }
            }
            look_up = step_alpha <= 0.0;
            clear = step_alpha <= THIN_ALPHA;
        }
        resume = false;
        front = back;
        i += n;
    }
    return acc;
}

// Premultiplied RGBA of the ray through pixel centre `frag` from the camera at offset `offset`.
fn ray_color(frag: vec2<f32>, offset: f32) -> vec4<f32> {
    let o = vec3<f32>(offset, 0.0, 0.0);
    return march(o, camera_ray_direction(frame.camera, frag, offset));
}

// `color` of per-channel coverage `alpha` over the background: exact per channel, each
// subpixel composited with its own α.
fn over_background(color: vec3<f32>, alpha: vec3<f32>) -> vec4<f32> {
    return vec4<f32>(color + (vec3<f32>(1.0) - alpha) * frame.background.rgb, 1.0);
}
