// View-index image: each channel = the view of that subpixel (test oracle and `autostereo mask --gpu`).
#import shared/frame.wgsl

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;

@fragment
fn fs_main(@builtin(position) position: vec4<f32>) -> @location(0) vec4<u32> {
    let px = vec2<u32>(position.xy);
    return vec4<u32>(mask_views(frame.mask, px), 255u);
}
