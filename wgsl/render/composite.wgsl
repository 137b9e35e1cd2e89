// N-pass compositing: I(x, y, c) = I_view(x,y,c)(x, y, c) from the per-view layers; layers
// smaller than the panel (`--view-scale`) are up-sampled bilinearly (shared/upsample.wgsl).
#import shared/frame.wgsl
#import shared/upsample.wgsl

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;

@group(1) @binding(0) var views: texture_2d_array<f32>;
// Keep in sync with `CompositeUniform` in src/render/composite.rs.
struct Composite {
    panel: vec2<u32>, // the spatial image's size
    _pad: vec2<u32>,
}
@group(1) @binding(1) var<uniform> composite: Composite;

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

fn upsampled(b: Bilinear, layer: u32) -> vec4<f32> {
    return bilinear_mix(
        b,
        textureLoad(views, b.lo, layer, 0),
        textureLoad(views, vec2<u32>(b.hi.x, b.lo.y), layer, 0),
        textureLoad(views, vec2<u32>(b.lo.x, b.hi.y), layer, 0),
        textureLoad(views, b.hi, layer, 0),
    );
}

@fragment
fn fs_scaled(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let px = vec2<u32>(position.xy);
    let v = mask_views(frame.mask, px);
    let b = bilinear_at(px, composite.panel, textureDimensions(views));
    return vec4<f32>(upsampled(b, v.x).r, upsampled(b, v.y).g, upsampled(b, v.z).b, 1.0);
}
