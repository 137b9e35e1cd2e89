// RGB-D image → spatial image by backward warping straight into each subpixel's view: no
// per-view images (src/rgbd/passes.rs, docs/WARPING.md). The views differ by a horizontal
// shift only, so each subpixel searches its reference row for the pair of neighbouring samples
// whose warped positions straddle it; the nearest such pair wins (occlusion), and a pair warped
// further apart than `hole_gap` straddles a disocclusion, filled from its far (background)
// sample. Where no pair reaches (the image's edges), the sample landing nearest is used.
#import shared/frame.wgsl
#import shared/row_warp.wgsl

// Keep in sync with `WarpUniform` in src/rgbd/passes.rs.
struct Warp {
    reference: vec2<u32>, // reference image size
    parallax: f32,        // shift (reference pixels) per unit nearness − focus at t = +1
    focus: f32,           // nearness on the display plane (no shift)
    fixed_view: u32,      // NO_VIEW: each subpixel's view from the mask; else this view
    hole_gap: f32,        // neighbours warped further apart than this straddle a hole
    hole_mask: u32,       // 1: write 1 where a subpixel was filled (hole or edge), 0 elsewhere
    _pad1: u32,
}

// Bindings read by shared/frame.wgsl.
@group(0) @binding(0) var<uniform> frame: Frame;

@group(1) @binding(0) var color: texture_2d<f32>;
@group(1) @binding(1) var nearness: texture_2d<f32>;
@group(1) @binding(2) var<uniform> warp: Warp;

const NO_VIEW: u32 = 0xffffffffu;

// Position t ∈ [−1, 1] of view v among the display's N (0 for a single view).
fn view_position(v: u32) -> f32 {
    let n = frame.mask.views;
    if (n <= 1u) {
        return 0.0;
    }
    return 2.0 * f32(v) / f32(n - 1u) - 1.0;
}

// The reads shared/row_warp.wgsl makes (one image: the layer is always 0).
fn near_at(layer: u32, x: i32, row: i32) -> f32 {
    return textureLoad(nearness, vec2<i32>(x, row), 0).r;
}

fn color_at(layer: u32, x: i32, row: i32) -> vec3<f32> {
    return textureLoad(color, vec2<i32>(x, row), 0).rgb;
}

@fragment
fn fs_main(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let px = vec2<u32>(position.xy);
    let panel = frame.camera.viewport;
    let reference = vec2<f32>(warp.reference);
    // The pixel centre in reference pixels (the reference may be of another size).
    let u = (f32(px.x) + 0.5) * reference.x / panel.x - 0.5;
    let row = min(i32((f32(px.y) + 0.5) * reference.y / panel.y), i32(warp.reference.y) - 1);
    // One search per distinct view of the pixel (a per-pixel mask: one for all three).
    var out = vec3<f32>(0.0);
    var searched = NO_VIEW;
    var w = vec4<f32>(0.0);
    for (var c = 0u; c < 3u; c++) {
        var v = warp.fixed_view;
        if (v == NO_VIEW) {
            v = mask_view(frame.mask, px, c);
        }
        if (v != searched) {
            let k = warp.parallax * view_position(v);
            let found = warp_row(0u, row, u, k, warp.focus, 0.0, 1.0, warp.reference.x, warp.hole_gap);
            w = vec4<f32>(found.color, select(0.0, 1.0, found.filled));
            searched = v;
        }
        out[c] = select(w[c], w.w, warp.hole_mask == 1u);
    }
    return vec4<f32>(out, 1.0);
}
