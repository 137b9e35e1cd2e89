// Tiled duplication (de Sorbier et al.) for adapters without clip distances: as mesh/tiled.wgsl,
// but a copy's fragments outside its tile are discarded (the paper's per-tile clipping done
// per fragment; it costs early depth testing, so clip distances are used where they exist).
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
    @location(0) eye_position: vec3<f32>,
    @location(1) eye_normal: vec3<f32>,
    @location(2) color: vec4<f32>,
    @location(4) tex_coord: vec2<f32>,
    @location(5) @interpolate(flat) texture: u32,
    @location(3) @interpolate(flat) view: u32,
}

@vertex
fn vs_main(v: VertexIn, @builtin(instance_index) view: u32) -> VertexOut {
    let o = tiled_vertex(v, view).view;
    return VertexOut(o.clip, o.eye_position, o.eye_normal, o.color, o.tex_coord, o.texture, view);
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    if (!quilt_in_tile(quilt, in.view, in.clip.xy)) {
        discard;
    }
    return view_shade(views[in.view], in.eye_normal, in.eye_position, in.color, in.tex_coord, in.texture);
}
