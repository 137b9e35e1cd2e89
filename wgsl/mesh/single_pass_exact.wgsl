// Single-pass meshes, `exact` visibility, geometry pass: the covering rectangles are rasterised
// at subpixel resolution (K·W × H), so every fragment is one ray — subpixel c = x mod K of
// pixel x / K, seen from view mask(pixel, c) — and the hardware depth test keeps the nearest
// hit per subpixel. Writes the triangle id; mesh/single_pass_exact_resolve.wgsl shades.
// No atomics, so it runs on every adapter.
#import mesh/shared/cover.wgsl

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;
// Bindings read by mesh/shared/cover_data.wgsl.
@group(1) @binding(2) var<storage, read> eye_triangles: array<EyeTriangle>;
// NDC rectangle (lo.xy, hi.xy) covering the triangle in all views; lo > hi when invisible.
@group(1) @binding(3) var<storage, read> cover_rects: array<vec4<f32>>;
// Bindings read by mesh/shared/mesh_data.wgsl.
@group(1) @binding(0) var<storage, read> mesh_vertices: array<MeshVertex>;
@group(1) @binding(1) var<storage, read> mesh_indices: array<u32>;

struct SubpixelOut {
    @location(0) triangle: u32,
    @builtin(frag_depth) depth: f32,
}

@fragment
fn fs_main(in: CoverFlatOut) -> SubpixelOut {
    let column = u32(in.position.x);
    let px = vec2<u32>(column / VIEWS_PER_PIXEL, u32(in.position.y));
    let c = column % VIEWS_PER_PIXEL;
    let centre = vec2<f32>(f32(px.x) + 0.5, in.position.y);
    let ray = view_ray(centre, ray_view(px, c));
    let hit = ray_triangle(ray, in.p0, in.p1, in.p2);
    if (hit.x < 0.0) {
        discard;
    }
    return SubpixelOut(in.tri, window_depth(hit.x * frame.camera.focal_distance));
}
