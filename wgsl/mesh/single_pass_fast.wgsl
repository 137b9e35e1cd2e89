// Single-pass meshes, `fast` visibility (the paper's): per fragment, the K views' rays are tested
// against the triangle and shaded; one depth per fragment (the minimum over the hit subpixels)
// goes through the hardware depth test; dual-source blending keeps the subpixels the triangle
// misses (blend factor 0 on those channels).
enable dual_source_blending;
#import mesh/shared/cover.wgsl
#import mesh/shared/shade_hit.wgsl

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

struct FastOut {
    @location(0) @blend_src(0) color: vec4<f32>,
    @location(0) @blend_src(1) coverage: vec4<f32>,
    @builtin(frag_depth) depth: f32,
}

@fragment
fn fs_main(in: CoverOut) -> FastOut {
    let px = vec2<u32>(in.position.xy);
    var color = vec3<f32>(0.0);
    var coverage = vec3<f32>(0.0);
    var nearest = 3.0e38;
    let t = eye_triangles[in.tri];
    for (var c = 0u; c < VIEWS_PER_PIXEL; c++) {
        let ray = view_ray(in.position.xy, ray_view(px, c));
        let hit = ray_triangle(ray, t.p0.xyz, t.p1.xyz, t.p2.xyz);
        if (hit.x >= 0.0) {
            let shaded = shade_hit(in.tri, ray, hit);
            if (VIEWS_PER_PIXEL == 1u) {
                color = shaded;
                coverage = vec3<f32>(1.0);
            } else {
                color[c] = shaded[c];
                coverage[c] = 1.0;
            }
            nearest = min(nearest, hit.x * frame.camera.focal_distance);
        }
    }
    if (all(coverage == vec3<f32>(0.0))) {
        discard;
    }
    return FastOut(vec4<f32>(color, 1.0), vec4<f32>(coverage, 1.0), window_depth(nearest));
}
