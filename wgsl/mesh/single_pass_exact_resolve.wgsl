// Single-pass meshes, `exact` visibility, resolve pass: per subpixel, the nearest triangle found
// by mesh/single_pass_exact.wgsl is intersected again with that subpixel's ray and shaded.
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
