// The parallel camera model's empty strips (src/render/camera_crop.rs): a subpixel whose
// view's shifted image does not reach it (|x_f − vd| > W/2 on the focal plane) shows the
// background. Drawn over the finished spatial image with the blend
// out = crop · background + (1 − crop) · image, the blend constant being the background.
#import shared/frame.wgsl

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;

@fragment
fn fs_main(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let px = vec2<u32>(position.xy);
    let views = vec3<f32>(mask_views(frame.mask, px));
    let x = camera_focal_point(frame.camera, position.xy).x;
    let n = f32(frame.camera.views);
    let vd = (views - 0.5 * (n - 1.0)) * frame.camera.separation;
    let outside = abs(vec3<f32>(x) - vd) > vec3<f32>(0.5 * frame.camera.focal_window.x);
    return vec4<f32>(select(vec3<f32>(0.0), vec3<f32>(1.0), outside), 0.0);
}
