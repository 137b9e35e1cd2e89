// Copies an RGBA16F accumulation (already composited over the background: the volume slices',
// the Gaussians') into the spatial image, a view layer or a quilt atlas.
#import shared/frame.wgsl

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;

@group(1) @binding(0) var accumulated: texture_2d<f32>;

@fragment
fn fs_main(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    return vec4<f32>(textureLoad(accumulated, vec2<u32>(position.xy), 0).rgb, 1.0);
}
