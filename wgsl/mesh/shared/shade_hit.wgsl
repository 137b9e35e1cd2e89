// Shading of the single pass's ray hits (mesh/shared/resolve.wgsl, mesh/single_pass_fast.wgsl).
// Reads `frame`, the mesh (mesh/shared/mesh_data.wgsl) and its textures
// (mesh/shared/texture.wgsl, group 3).
#import shared/frame.wgsl
#import shared/ray.wgsl
#import mesh/shared/mesh_data.wgsl
#import mesh/shared/texture.wgsl

// Shade the point of triangle `tri` hit by `ray` at (t, u, v): barycentric normal, colour and
// texture coordinate (the texture is the first vertex's, as src/mesh/mod.rs says), the
// Blinn-Phong of shared/shading.wgsl seen from the ray's origin.
fn shade_hit(tri: u32, ray: Ray, hit: vec3<f32>) -> vec3<f32> {
    let a = triangle_vertex(tri, 0u);
    let b = triangle_vertex(tri, 1u);
    let c = triangle_vertex(tri, 2u);
    let w = vec3<f32>(1.0 - hit.y - hit.z, hit.y, hit.z);
    let normal_world = w.x * a.normal.xyz + w.y * b.normal.xyz + w.z * c.normal.xyz;
    let normal = (frame.camera.normal_from_world * vec4<f32>(normal_world, 0.0)).xyz;
    let uv = w.x * a.tex_coord + w.y * b.tex_coord + w.z * c.tex_coord;
    let color = (w.x * a.color.rgb + w.y * b.color.rgb + w.z * c.color.rgb) * texture_color(a.texture, uv);
    let position = ray.origin + hit.x * ray.direction;
    return shade_blinn_phong(frame.light, normal, position, ray.origin, color);
}
