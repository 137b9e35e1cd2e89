// One ordinary perspective render of a mesh for one camera: the N-pass baseline's per-view pass
// and the single-view (SV) render. Shading from shared/shading.wgsl.
#import shared/frame.wgsl

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;

@group(1) @binding(0) var<uniform> view: View;

struct VertexIn {
    @location(0) position: vec4<f32>,
    @location(1) normal: vec4<f32>,
    @location(2) color: vec4<f32>,
}

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) eye_position: vec3<f32>,
    @location(1) eye_normal: vec3<f32>,
    @location(2) color: vec4<f32>,
}

@vertex
fn vs_main(v: VertexIn) -> VertexOut {
    let eye = frame.camera.eye_from_world * vec4<f32>(v.position.xyz, 1.0);
    var out: VertexOut;
    out.clip = view.clip_from_eye * eye;
    out.eye_position = eye.xyz;
    out.eye_normal = (frame.camera.normal_from_world * vec4<f32>(v.normal.xyz, 0.0)).xyz;
    out.color = v.color;
    return out;
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    let rgb = shade_blinn_phong(frame.light, in.eye_normal, in.eye_position, view.origin.xyz, in.color.rgb);
    return vec4<f32>(rgb, 1.0);
}
