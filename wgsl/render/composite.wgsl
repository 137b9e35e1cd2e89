// N-pass compositing: I(x, y, c) = I_view(x,y,c)(x, y, c) from the per-view layers.
#import shared/frame.wgsl

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;

@group(1) @binding(0) var views: texture_2d_array<f32>;

@fragment
fn fs_main(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let px = vec2<u32>(position.xy);
    let v = mask_views(frame.mask, px);
    return vec4<f32>(
        textureLoad(views, px, v.x, 0).r,
        textureLoad(views, px, v.y, 0).g,
        textureLoad(views, px, v.z, 0).b,
        1.0,
    );
}
