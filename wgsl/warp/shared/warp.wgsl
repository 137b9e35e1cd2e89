// What both warps share: their constants and where a view sits among the display's. The
// references are R rendered views (warp/references.wgsl) or one RGB-D image (warp/rgbd.wgsl);
// either way views differ from a reference by a horizontal shift of k · (nearness − focus)
// reference pixels, searched row by row (warp/shared/row_warp.wgsl).
//
// Reads `frame` (shared/frame.wgsl) and `warp`, which the stage binds, and calls the stage's
// `view_value(v, row, u) -> Warped`: view v's value at column u of reference row `row`.

// Keep in sync with `WarpUniform` in src/warp/uniform.rs.
struct Warp {
    size: vec2<u32>,   // the reference images' size (rendered references: the frame's)
    references: u32,   // R, spread evenly over the views' span (an RGB-D image: 1, the centre)
    fixed_view: u32,   // NO_VIEW: each subpixel's view from the mask; else this view everywhere
    parallax: f32,     // shift (reference pixels) per unit of nearness − focus per unit of view position
    focus: f32,        // nearness with no shift (rendered references: 1, the focal plane)
    hole_gap: f32,     // neighbours warped further apart than this straddle a hole
    hole_mask: u32,    // 1: write 1 where a subpixel was filled, 0 where it was seen
    same_surface: f32, // relative nearness difference under which two references blend
    _pad0: u32,
    _pad1: vec2<u32>,
}

const NO_VIEW: u32 = 0xffffffffu;

// Position t ∈ [−1, 1] of view v among the display's N (0 for a single view).
fn view_position(v: u32) -> f32 {
    let n = frame.mask.views;
    if (n <= 1u) {
        return 0.0;
    }
    return 2.0 * f32(v) / f32(n - 1u) - 1.0;
}

// The pixel `px`'s subpixels, each its own view's value at (u, row) of the references (or the
// hole mask): one search per distinct view of the pixel (a per-pixel mask: one for all three).
fn warp_subpixels(px: vec2<u32>, row: i32, u: f32) -> vec4<f32> {
    var out = vec3<f32>(0.0);
    var searched = NO_VIEW;
    var w = vec4<f32>(0.0);
    for (var c = 0u; c < 3u; c++) {
        var v = warp.fixed_view;
        if (v == NO_VIEW) {
            v = mask_view(frame.mask, px, c);
        }
        if (v != searched) {
            let found = view_value(v, row, u);
            w = vec4<f32>(found.color, select(0.0, 1.0, found.filled));
            searched = v;
        }
        out[c] = select(w[c], w.w, warp.hole_mask == 1u);
    }
    return vec4<f32>(out, 1.0);
}
