// Splats (paper §3.3.2, §3.5.2): data, per-pass parameters and the ray-splat test shared by the
// cover, geometry and compositing stages. Keep in sync with src/points/scene.rs (Splat) and
// src/points/passes/ (SplatParams).
#import shared/frame.wgsl
#import shared/multiview.wgsl
#import shared/ray.wgsl

struct Splat {
    position: vec3<f32>,
    radius: f32,
    normal: vec3<f32>,
    color: u32, // pack4x8unorm
}

// Per pass (dynamic offset): which cameras the pass renders, and ε.
struct SplatParams {
    cover_lo: f32,     // smallest camera offset the covering quads must cover
    cover_hi: f32,     // largest
    fixed_offset: f32, // camera offset of every ray when use_mask == 0
    use_mask: u32,     // 1: per (sub)pixel views from the mask (single pass)
    epsilon: f32,      // ε of the ε-z compositing, eye-depth units
    groups: u32,       // group images to composite (the array may hold a spare layer)
    group_stride: u32, // layer of group g: g · group_stride + group_base (layered: N, view)
    group_base: u32,
    first_view: u32,   // duplication geometry passes: the view of the first layer / tile
    image_row: u32,    // compositing: atlas texel row of the group images' row 0 (tiled bands)
    _pad1: u32,
    _pad2: u32,
}

// Gaussian kernel w = exp(−KERNEL_SHARPNESS · (ω/r)²), cut off at ω = r (w ≥ e⁻²).
const KERNEL_SHARPNESS: f32 = 2.0;
// Rays closer than this (cosine) to the splat plane miss: at grazing incidence the disk is a
// line, and the division in Eq. 2 would amplify rounding into Inf/NaN.
const GRAZING_COSINE: f32 = 1e-6;

// Radii outside (0, MAX_RADIUS) never hit and get no covering quad: r² must stay finite.
const MAX_RADIUS: f32 = 1e18;

fn valid_radius(r: f32) -> bool {
    return r > 0.0 && r < MAX_RADIUS;
}

struct SplatHit {
    weight: f32, // 0: miss
    depth: f32,  // eye depth of the hit
    point: vec3<f32>,
}

// Eq. 2: the ray meets the splat plane n·(x − p) = 0 at x̂ = O + t·D with
// t = n·(p − O) / n·D; inside the disk when |x̂ − p| ≤ r. NaN-safe: every failed test misses.
fn splat_hit(ray: Ray, s: Splat) -> SplatHit {
    let miss = SplatHit(0.0, 0.0, vec3<f32>(0.0));
    let denom = dot(s.normal, ray.direction);
    if (!(abs(denom) > GRAZING_COSINE * length(ray.direction)) || !valid_radius(s.radius)) {
        return miss;
    }
    let t = dot(s.normal, s.position - ray.origin) / denom;
    let depth = t * frame.camera.focal_distance;
    if (!(depth >= frame.camera.near && depth <= frame.camera.far)) {
        return miss;
    }
    let x = ray.origin + t * ray.direction;
    let q = dot(x - s.position, x - s.position) / (s.radius * s.radius);
    if (!(q <= 1.0)) {
        return miss;
    }
    return SplatHit(exp(-KERNEL_SHARPNESS * q), depth, x);
}

// The ray of the camera at eye-space offset `offset` through pixel position `frag`.
fn offset_ray(frag: vec2<f32>, offset: f32) -> Ray {
    let o = vec3<f32>(offset, 0.0, 0.0);
    return Ray(o, camera_ray_direction(frame.camera, frag, offset));
}

// Camera offset of ray c of pixel px in this pass.
fn pass_offset(px: vec2<u32>, c: u32) -> f32 {
    if (params.use_mask == 0u) {
        return params.fixed_offset;
    }
    return view_offset(ray_view(px, c));
}

// Shaded colour of a hit seen from `ray` (two-sided Blinn-Phong, eye space).
fn splat_color(s: Splat, ray: Ray, hit: SplatHit) -> vec3<f32> {
    let base = unpack4x8unorm(s.color).rgb;
    return shade_blinn_phong(frame.light, s.normal, hit.point, ray.origin, base);
}
