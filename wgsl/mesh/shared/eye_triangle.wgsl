// Triangles in eye space, as the single-pass mesh stages pass them from the per-triangle compute
// pass to the geometry and resolve passes (group 1, binding 2). Keep in sync with the byte size
// in src/mesh/passes/single_pass/scratch.rs.
#import mesh/shared/mesh_data.wgsl

// Eye-space vertices of one triangle (w unused).
struct EyeTriangle {
    p0: vec4<f32>,
    p1: vec4<f32>,
    p2: vec4<f32>,
}

// Triangle `tri` of the mesh transformed to eye space (one matrix product per vertex).
fn transform_triangle(tri: u32) -> array<vec3<f32>, 3> {
    return array<vec3<f32>, 3>(
        eye_position(triangle_vertex(tri, 0u)),
        eye_position(triangle_vertex(tri, 1u)),
        eye_position(triangle_vertex(tri, 2u)),
    );
}

fn eye_triangle(p: array<vec3<f32>, 3>) -> EyeTriangle {
    return EyeTriangle(vec4<f32>(p[0], 1.0), vec4<f32>(p[1], 1.0), vec4<f32>(p[2], 1.0));
}
