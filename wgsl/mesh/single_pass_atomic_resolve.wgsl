// Single-pass meshes, `atomic` and `compute` visibility, resolve pass: per subpixel, the winning
// triangle of mesh/single_pass_atomic.wgsl / mesh/single_pass_compute.wgsl is shaded.
#import mesh/shared/resolve.wgsl

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;
// Bindings read by mesh/shared/cover_data.wgsl.
@group(1) @binding(2) var<storage, read> eye_triangles: array<EyeTriangle>;
// NDC rectangle (lo.xy, hi.xy) covering the triangle in all views; lo > hi when invisible.
@group(1) @binding(3) var<storage, read> cover_rects: array<vec4<f32>>;
// Bindings read by mesh/shared/mesh_data.wgsl.
@group(1) @binding(0) var<storage, read> mesh_vertices: array<MeshVertex>;
@group(1) @binding(1) var<storage, read> mesh_indices: array<u32>;
// Bindings read by mesh/shared/texture.wgsl.
@group(3) @binding(0) var<storage, read> mesh_texels: array<u32>;
@group(3) @binding(1) var<storage, read> mesh_textures: array<MeshTexture>;

// The same buffer as `nearest_keys`, read as (low, high) words of the inverted u64 keys.
@group(2) @binding(0) var<storage, read> nearest_keys: array<vec2<u32>>;

@fragment
fn fs_main(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let px = vec2<u32>(position.xy);
    let base = (px.y * u32(frame.camera.viewport.x) + px.x) * VIEWS_PER_PIXEL;
    var color = frame.background.rgb;
    for (var c = 0u; c < VIEWS_PER_PIXEL; c++) {
        let key = nearest_keys[base + c];
        if (all(key == vec2<u32>(0u))) {
            continue;
        }
        let tri = ~key.x;
        color = resolve_subpixel(color, position.xy, px, c, tri);
    }
    return vec4<f32>(color, 1.0);
}
