// Single-pass meshes, `exact` visibility, resolve pass: per subpixel, the winning triangle of
// mesh_single_pass_atomic.wgsl is intersected again with that subpixel's ray and shaded.
#import shared/frame.wgsl
#import shared/multiview.wgsl
#import shared/ray.wgsl
#import shared/cover_data.wgsl

// The same buffer as `nearest_keys`, read as (low, high) words of the inverted u64 keys.
@group(2) @binding(0) var<storage, read> nearest_keys: array<vec2<u32>>;

@vertex
fn vs_main(@builtin(vertex_index) vertex: u32) -> @builtin(position) vec4<f32> {
    return fullscreen_position(vertex);
}

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
        let ray = view_ray(position.xy, ray_view(px, c));
        let t = eye_triangles[tri];
        let hit = ray_triangle(ray, t.p0.xyz, t.p1.xyz, t.p2.xyz);
        if (hit.x < 0.0) {
            continue; // cannot happen for the same ray; keeps the background rather than NaN
        }
        let shaded = shade_hit(tri, ray, hit);
        if (VIEWS_PER_PIXEL == 1u) {
            color = shaded;
        } else {
            color[c] = shaded[c];
        }
    }
    return vec4<f32>(color, 1.0);
}
