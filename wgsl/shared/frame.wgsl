// Per-frame constants every pipeline binds at group 0, binding 0.
// Keep in sync with `FrameUniform` in src/frame.rs.
#import shared/camera.wgsl
#import shared/mask.wgsl
#import shared/shading.wgsl

struct Frame {
    camera: Camera,
    mask: DisplayMask,
    light: Light,
    background: vec4<f32>,
}

// Full-screen triangle covering the viewport; no vertex buffer. The vertex stage of every
// full-screen pass (compositing, mask image, resolves).
@vertex
fn vs_fullscreen(@builtin(vertex_index) vertex: u32) -> @builtin(position) vec4<f32> {
    let uv = vec2<f32>(f32((vertex << 1u) & 2u), f32(vertex & 2u));
    return vec4<f32>(uv * 2.0 - 1.0, 0.0, 1.0);
}
