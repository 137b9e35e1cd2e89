// Single-pass meshes, `exact` visibility, resolve pass: per subpixel, the nearest triangle found
// by mesh_single_pass_subpixel.wgsl is intersected again with that subpixel's ray and shaded.
#import shared/resolve.wgsl

// Triangle id per subpixel (K·W × H); NO_TRIANGLE where nothing was hit.
@group(2) @binding(0) var subpixel_triangles: texture_2d<u32>;

const NO_TRIANGLE: u32 = 0xffffffffu;

@fragment
fn fs_main(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let px = vec2<u32>(position.xy);
    var color = frame.background.rgb;
    for (var c = 0u; c < VIEWS_PER_PIXEL; c++) {
        let tri = textureLoad(subpixel_triangles, vec2<u32>(px.x * VIEWS_PER_PIXEL + c, px.y), 0).x;
        if (tri == NO_TRIANGLE) {
            continue;
        }
        color = resolve_subpixel(color, position.xy, px, c, tri);
    }
    return vec4<f32>(color, 1.0);
}
