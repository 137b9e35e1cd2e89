// Mesh data pulled from storage (group 1), shared by the single-pass mesh stages.
// Keep in sync with `GpuVertex` in src/mesh/scene.rs.
#import shared/ray.wgsl

struct MeshVertex {
    position: vec4<f32>,
    normal: vec4<f32>,
    color: vec4<f32>,
}

fn triangle_vertex(tri: u32, corner: u32) -> MeshVertex {
    return mesh_vertices[mesh_indices[3u * tri + corner]];
}

fn eye_position(v: MeshVertex) -> vec3<f32> {
    return (frame.camera.eye_from_world * vec4<f32>(v.position.xyz, 1.0)).xyz;
}

// Shade the point of triangle `tri` hit by `ray` at (t, u, v): barycentric normal and colour,
// the Blinn-Phong of shared/shading.wgsl seen from the ray's origin.
fn shade_hit(tri: u32, ray: Ray, hit: vec3<f32>) -> vec3<f32> {
    let a = triangle_vertex(tri, 0u);
    let b = triangle_vertex(tri, 1u);
    let c = triangle_vertex(tri, 2u);
    let w = vec3<f32>(1.0 - hit.y - hit.z, hit.y, hit.z);
    let normal_world = w.x * a.normal.xyz + w.y * b.normal.xyz + w.z * c.normal.xyz;
    let normal = (frame.camera.normal_from_world * vec4<f32>(normal_world, 0.0)).xyz;
    let color = w.x * a.color.rgb + w.y * b.color.rgb + w.z * c.color.rgb;
    let position = ray.origin + hit.x * ray.direction;
    return shade_blinn_phong(frame.light, normal, position, ray.origin, color);
}
