// Single-pass meshes, `exact` visibility, resolve pass: per subpixel, the nearest triangle found
// by mesh_single_pass_subpixel.wgsl is intersected again with that subpixel's ray and shaded.
#import shared/frame.wgsl
#import shared/multiview.wgsl
#import shared/ray.wgsl
#import shared/cover_data.wgsl

// Triangle id per subpixel (K·W × H); NO_TRIANGLE where nothing was hit.
@group(2) @binding(0) var subpixel_triangles: texture_2d<u32>;

const NO_TRIANGLE: u32 = 0xffffffffu;

@vertex
fn vs_main(@builtin(vertex_index) vertex: u32) -> @builtin(position) vec4<f32> {
    return fullscreen_position(vertex);
}

@fragment
fn fs_main(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let px = vec2<u32>(position.xy);
    var color = frame.background.rgb;
    for (var c = 0u; c < VIEWS_PER_PIXEL; c++) {
        let tri = textureLoad(subpixel_triangles, vec2<u32>(px.x * VIEWS_PER_PIXEL + c, px.y), 0).x;
        if (tri == NO_TRIANGLE) {
            continue;
        }
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
