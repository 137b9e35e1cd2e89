// RGB-D image → spatial image by backward warping straight into each subpixel's view: no
// per-view images (src/warp/rgbd.rs, docs/WARPING.md). The views differ by a horizontal
// shift only, so each subpixel searches its reference row for the pair of neighbouring samples
// whose warped positions straddle it; the nearest such pair wins (occlusion), and a pair warped
// further apart than `hole_gap` straddles a disocclusion, filled from its far (background)
// sample. Where no pair reaches (the image's edges), the sample landing nearest is used.
#import shared/frame.wgsl
#import warp/shared/warp.wgsl
#import warp/shared/row_warp.wgsl

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;

@group(1) @binding(0) var color: texture_2d<f32>;
@group(1) @binding(1) var nearness: texture_2d<f32>;
@group(1) @binding(2) var<uniform> warp: Warp;

// The reads warp/shared/row_warp.wgsl makes (one image: the layer is always 0).
fn near_at(layer: u32, x: i32, row: i32) -> f32 {
    return textureLoad(nearness, vec2<i32>(x, row), 0).r;
}

fn color_at(layer: u32, x: i32, row: i32) -> vec3<f32> {
    return textureLoad(color, vec2<i32>(x, row), 0).rgb;
}

// View v at column u of row `row`: the one image's row searched over every nearness.
fn view_value(v: u32, row: i32, u: f32) -> Warped {
    let k = warp.parallax * view_position(v);
    return warp_row(0u, row, u, k, warp.focus, 0.0, 1.0, warp.size.x, warp.hole_gap);
}

@fragment
fn fs_main(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let px = vec2<u32>(position.xy);
    let panel = frame.camera.viewport;
    let reference = vec2<f32>(warp.size);
    // The pixel centre in reference pixels (the reference may be of another size).
    let u = (f32(px.x) + 0.5) * reference.x / panel.x - 0.5;
    let row = min(i32((f32(px.y) + 0.5) * reference.y / panel.y), i32(warp.size.y) - 1);
    return warp_subpixels(px, row, u);
}
