// Single-pass meshes, `atomic` and `compute` visibility, resolve pass: per subpixel, the winning
// triangle of mesh_single_pass_atomic.wgsl / mesh_single_pass_compute.wgsl is shaded.
#import shared/resolve.wgsl

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
