// What both warps share: their constants and where a view sits among the display's. The
// references are R rendered views (warp/references.wgsl) or one RGB-D image (warp/rgbd.wgsl);
// either way views differ from a reference by a horizontal shift of k · (nearness − focus)
// reference pixels, searched row by row (warp/shared/row_warp.wgsl).
//
// Reads `frame` (shared/frame.wgsl), which the stage binds.

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
