// Per-triangle data made by mesh_cover.wgsl for the single-pass mesh stages (group 1, bindings
// 2 and 3, read-only here). Keep in sync with src/render/mesh_single_pass/.
#import shared/eye_triangle.wgsl

@group(1) @binding(2) var<storage, read> eye_triangles: array<EyeTriangle>;
// NDC rectangle (lo.xy, hi.xy) covering the triangle in all views; lo > hi when invisible.
@group(1) @binding(3) var<storage, read> cover_rects: array<vec4<f32>>;
