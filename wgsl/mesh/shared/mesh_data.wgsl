// Mesh data pulled from storage (group 1), shared by the single-pass mesh stages.
// Keep in sync with `GpuVertex` in src/mesh/scene.rs.
#import shared/ray.wgsl

struct MeshVertex {
    position: vec4<f32>,
    normal: vec4<f32>,
    color: vec4<f32>,
    tex_coord: vec2<f32>,
    texture: u32,
    _pad: u32,
}

fn triangle_vertex(tri: u32, corner: u32) -> MeshVertex {
    return mesh_vertices[mesh_indices[3u * tri + corner]];
}

fn eye_position(v: MeshVertex) -> vec3<f32> {
    return (frame.camera.eye_from_world * vec4<f32>(v.position.xyz, 1.0)).xyz;
}
