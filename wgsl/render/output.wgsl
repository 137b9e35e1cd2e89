// Spatial image → a caller's texture or surface (src/render/output.rs): each pixel copied as it
// is, no filtering. The attachment's format does the channel order (BGRA); for sRGB formats the
// value is decoded here so that the hardware's encode gives back the very same 8-bit value:
// subpixels must reach the panel unchanged.
#import shared/frame.wgsl

@group(0) @binding(0) var spatial: texture_2d<f32>;

// 1 when the target format is sRGB-encoded.
override SRGB_TARGET: u32 = 0u;

fn srgb_to_linear(c: vec3<f32>) -> vec3<f32> {
    let low = c / 12.92;
    let high = pow((c + 0.055) / 1.055, vec3<f32>(2.4));
    return select(high, low, c <= vec3<f32>(0.04045));
}

@fragment
fn fs_main(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let v = textureLoad(spatial, vec2<u32>(position.xy), 0);
    if (SRGB_TARGET == 1u) {
        return vec4<f32>(srgb_to_linear(v.rgb), v.a);
    }
    return v;
}
