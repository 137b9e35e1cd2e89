// An ordinary per-camera mesh render's vertex and fragment work, shared by the N-pass / single
// view (mesh/npass.wgsl) and the duplication methods (mesh/tiled*.wgsl, mesh/layered.wgsl,
// mesh/mrt.wgsl), so every method transforms and shades the same way. Reads `frame` and the
// textures (mesh/shared/texture.wgsl, group 3).
#import mesh/shared/texture.wgsl

// Keep in sync with `GpuVertex` in src/mesh/scene.rs.
struct VertexIn {
    @location(0) position: vec4<f32>,
    @location(1) normal: vec4<f32>,
    @location(2) color: vec4<f32>,
    @location(3) tex_coord: vec2<f32>,
    @location(4) texture: u32,
}

// A vertex seen by one camera: its clip position and what shading interpolates.
struct ViewVertex {
    clip: vec4<f32>,
    eye_position: vec3<f32>,
    eye_normal: vec3<f32>,
    color: vec4<f32>,
    tex_coord: vec2<f32>,
    texture: u32,
}

fn view_vertex(v: VertexIn, view: View) -> ViewVertex {
    let eye = frame.camera.eye_from_world * vec4<f32>(v.position.xyz, 1.0);
    let normal = (frame.camera.normal_from_world * vec4<f32>(v.normal.xyz, 0.0)).xyz;
    return ViewVertex(view.clip_from_eye * eye, eye.xyz, normal, v.color, v.tex_coord, v.texture);
}

// Blinn-Phong (shared/shading.wgsl) of a fragment seen from camera `view`: its colour times
// its texture's at `tex_coord` (the provoking vertex's `texture`, flat).
fn view_shade(view: View, eye_normal: vec3<f32>, eye_position: vec3<f32>, color: vec4<f32>, tex_coord: vec2<f32>, texture: u32) -> vec4<f32> {
    let base = color.rgb * texture_color(texture, tex_coord);
    let rgb = shade_blinn_phong(frame.light, eye_normal, eye_position, view.origin.xyz, base);
    return vec4<f32>(rgb, 1.0);
}

// Most views the duplication methods draw in one frame; keep in sync with `MAX_VIEWS` in
// src/display/mod.rs (the per-view uniforms are one fixed-size array).
const MAX_VIEWS: u32 = 256u;

// The views one pass of the layered and MRT methods draws: `first` .. `first + count`.
// Keep in sync with `ViewBatch` in src/mesh/passes/duplicate/mod.rs.
struct ViewBatch {
    first: u32,
    count: u32,
    _pad0: u32,
    _pad1: u32,
}
