// Deferred shading of the single-pass mesh resolves: subpixel c of pixel px, whose nearest
// triangle the geometry pass found, is intersected again with its own ray and shaded.
#import shared/frame.wgsl
#import shared/multiview.wgsl
#import shared/ray.wgsl
#import mesh/shared/cover_data.wgsl
#import mesh/shared/shade_hit.wgsl

// `color` with subpixel c of pixel px (at frame position `position`) shaded from triangle `tri`.
fn resolve_subpixel(color: vec3<f32>, position: vec2<f32>, px: vec2<u32>, c: u32, tri: u32) -> vec3<f32> {
    let ray = view_ray(position, ray_view(px, c));
    let t = eye_triangles[tri];
    let hit = ray_triangle(ray, t.p0.xyz, t.p1.xyz, t.p2.xyz);
    if (hit.x < 0.0) {
        return color; // cannot happen for the same ray; keeps the background rather than NaN
    }
    let shaded = shade_hit(tri, ray, hit);
    if (VIEWS_PER_PIXEL == 1u) {
        return shaded;
    }
    var out = color;
    out[c] = shaded[c];
    return out;
}
