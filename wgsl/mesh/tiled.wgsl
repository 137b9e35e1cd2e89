// Tiled duplication (de Sorbier et al.), clip-distance variant: instance i is view i's copy of
// the mesh, drawn into view i's tile of one atlas with one depth buffer and clipped to the
// tile by four clip distances. Adapters without clip distances use mesh/tiled_discard.wgsl.
enable clip_distances;
#import shared/frame.wgsl
#import shared/quilt.wgsl
#import mesh/shared/view_vertex.wgsl
#import mesh/shared/tiled_vertex.wgsl

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;
// Bindings read by mesh/shared/texture.wgsl.
@group(3) @binding(0) var<storage, read> mesh_texels: array<u32>;
@group(3) @binding(1) var<storage, read> mesh_textures: array<MeshTexture>;

// Bindings read by mesh/shared/tiled_vertex.wgsl.
@group(1) @binding(0) var<uniform> views: array<View, MAX_VIEWS>;
@group(1) @binding(1) var<uniform> quilt: Quilt;

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @builtin(clip_distances) edges: array<f32, 4>,
    @location(0) eye_position: vec3<f32>,
    @location(1) eye_normal: vec3<f32>,
    @location(2) color: vec4<f32>,
    @location(4) tex_coord: vec2<f32>,
    @location(5) @interpolate(flat) texture: u32,
    @location(3) @interpolate(flat) view: u32,
}

// What the fragment stage reads (clip distances are vertex outputs only).
struct FragmentIn {
    @builtin(position) position: vec4<f32>,
    @location(0) eye_position: vec3<f32>,
    @location(1) eye_normal: vec3<f32>,
    @location(2) color: vec4<f32>,
    @location(4) tex_coord: vec2<f32>,
    @location(5) @interpolate(flat) texture: u32,
    @location(3) @interpolate(flat) view: u32,
}

@vertex
fn vs_main(v: VertexIn, @builtin(instance_index) view: u32) -> VertexOut {
    let t = tiled_vertex(v, view);
    let o = t.view;
    return VertexOut(o.clip, t.edges, o.eye_position, o.eye_normal, o.color, o.tex_coord, o.texture, view);
}

@fragment
fn fs_main(in: FragmentIn) -> @location(0) vec4<f32> {
    return view_shade(views[in.view], in.eye_normal, in.eye_position, in.color, in.tex_coord, in.texture);
}
