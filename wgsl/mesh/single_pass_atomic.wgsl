// Single-pass meshes, `atomic` visibility, geometry pass: every hit subpixel keeps the nearest
// (depth, triangle) pair with one 64-bit atomic. The key is depth bits (high word; positive
// floats order like their bits) and triangle id (low word), stored inverted so that the cleared
// buffer (0) means "empty" and atomicMax picks the nearest. Shading happens once per subpixel
// in mesh/single_pass_atomic_resolve.wgsl.
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

@group(2) @binding(0) var<storage, read_write> nearest_keys: array<atomic<u64>>;

@fragment
fn fs_main(in: CoverOut) -> @location(0) vec4<f32> {
    let px = vec2<u32>(in.position.xy);
    let base = (px.y * u32(frame.camera.viewport.x) + px.x) * VIEWS_PER_PIXEL;
    let t = eye_triangles[in.tri];
    for (var c = 0u; c < VIEWS_PER_PIXEL; c++) {
        let ray = view_ray(in.position.xy, ray_view(px, c));
        let hit = ray_triangle(ray, t.p0.xyz, t.p1.xyz, t.p2.xyz);
        if (hit.x >= 0.0) {
            let depth = hit.x * frame.camera.focal_distance;
            let key = (u64(bitcast<u32>(depth)) << 32u) | u64(in.tri);
            atomicMax(&nearest_keys[base + c], ~key);
        }
    }
    // No colour is written here (the target's write mask is empty).
    return vec4<f32>(0.0);
}
