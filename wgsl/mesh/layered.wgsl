// Layered duplication (Beck et al.): one multiview draw renders the mesh into `batch.count`
// layers of a texture array, each with its own depth layer; layer i is view batch.first + i.
#import shared/frame.wgsl
#import mesh/shared/view_vertex.wgsl

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;
// Bindings read by mesh/shared/texture.wgsl.
@group(3) @binding(0) var<storage, read> mesh_texels: array<u32>;
@group(3) @binding(1) var<storage, read> mesh_textures: array<MeshTexture>;

@group(1) @binding(0) var<uniform> views: array<View, MAX_VIEWS>;
@group(1) @binding(1) var<uniform> batch: ViewBatch;

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) eye_position: vec3<f32>,
    @location(1) eye_normal: vec3<f32>,
    @location(2) color: vec4<f32>,
    @location(4) tex_coord: vec2<f32>,
    @location(5) @interpolate(flat) texture: u32,
    @location(3) @interpolate(flat) view: u32,
}

@vertex
fn vs_main(v: VertexIn, @builtin(view_index) layer: u32) -> VertexOut {
    let view = batch.first + layer;
    let o = view_vertex(v, views[view]);
    return VertexOut(o.clip, o.eye_position, o.eye_normal, o.color, o.tex_coord, o.texture, view);
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    return view_shade(views[in.view], in.eye_normal, in.eye_position, in.color, in.tex_coord, in.texture);
}
