// One ordinary perspective render of a mesh for one camera: the N-pass baseline's per-view pass
// and the single-view (SV) render. Vertex and shading from mesh/shared/view_vertex.wgsl.
#import shared/frame.wgsl
#import mesh/shared/view_vertex.wgsl

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;
// Bindings read by mesh/shared/texture.wgsl.
@group(3) @binding(0) var<storage, read> mesh_texels: array<u32>;
@group(3) @binding(1) var<storage, read> mesh_textures: array<MeshTexture>;

@group(1) @binding(0) var<uniform> view: View;

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) eye_position: vec3<f32>,
    @location(1) eye_normal: vec3<f32>,
    @location(2) color: vec4<f32>,
    @location(4) tex_coord: vec2<f32>,
    @location(5) @interpolate(flat) texture: u32,
}

@vertex
fn vs_main(v: VertexIn) -> VertexOut {
    let o = view_vertex(v, view);
    return VertexOut(o.clip, o.eye_position, o.eye_normal, o.color, o.tex_coord, o.texture);
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    return view_shade(view, in.eye_normal, in.eye_position, in.color, in.tex_coord, in.texture);
}

// A reference view of a warp (src/warp): the same colour, and the bits of the nearness fd / d.
struct ReferenceOut {
    @location(0) color: vec4<f32>,
    @location(1) nearness: u32,
}

@fragment
fn fs_reference(in: VertexOut) -> ReferenceOut {
    let color = view_shade(view, in.eye_normal, in.eye_position, in.color, in.tex_coord, in.texture);
    return ReferenceOut(color, bitcast<u32>(frame.camera.focal_distance / -in.eye_position.z));
}
