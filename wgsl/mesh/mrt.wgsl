// MRT duplication (de Sorbier, Nozick & Biri): instance i is view batch.first + i's copy of the
// mesh, rasterised over the whole target; its fragments write their colour with α = 1 to
// render target i and α = 0 to the others, which blending leaves unchanged (the paper's alpha
// test). All targets share one depth buffer, so a nearer fragment of one view hides the
// farther fragments of every other view of the batch: the method's occlusion error.
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
    @location(3) @interpolate(flat) slot: u32,
}

// One output per render target; a pipeline with fewer targets ignores the rest.
struct Targets {
    @location(0) t0: vec4<f32>,
    @location(1) t1: vec4<f32>,
    @location(2) t2: vec4<f32>,
    @location(3) t3: vec4<f32>,
    @location(4) t4: vec4<f32>,
    @location(5) t5: vec4<f32>,
    @location(6) t6: vec4<f32>,
    @location(7) t7: vec4<f32>,
}

@vertex
fn vs_main(v: VertexIn, @builtin(instance_index) slot: u32) -> VertexOut {
    let o = view_vertex(v, views[batch.first + slot]);
    return VertexOut(o.clip, o.eye_position, o.eye_normal, o.color, o.tex_coord, o.texture, slot);
}

@fragment
fn fs_main(in: VertexOut) -> Targets {
    let c = view_shade(views[batch.first + in.slot], in.eye_normal, in.eye_position, in.color, in.tex_coord, in.texture);
    let none = vec4<f32>(0.0);
    let s = in.slot;
    return Targets(
        select(none, c, s == 0u),
        select(none, c, s == 1u),
        select(none, c, s == 2u),
        select(none, c, s == 3u),
        select(none, c, s == 4u),
        select(none, c, s == 5u),
        select(none, c, s == 6u),
        select(none, c, s == 7u),
    );
}
