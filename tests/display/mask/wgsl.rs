//! The WGSL mask equals the Rust mask on every subpixel, for every display kind.

use super::*;

/// The WGSL mask (`MaskImageRenderer`) equals the Rust mask on every subpixel of a `size`
/// window at `origin`, for every display kind (flipped and BGR on some).
fn assert_wgsl_mask_equals_rust_mask(origin: [i32; 2], size: [u32; 2]) {
    let ctx = common::gpu();
    let mut renderer = MaskImageRenderer::new(&ctx.device).unwrap();
    for (i, kind) in all_kinds().into_iter().enumerate() {
        let mut display = Display::new(kind).unwrap().with_origin(origin);
        display.flip_views = i % 2 == 1;
        display.bgr = i == 3;
        let mask = display.mask();
        let image = renderer
            .render(&ctx.device, &ctx.queue, &display, size)
            .unwrap();
        let mut mismatches = 0u64;
        for y in 0..size[1] {
            for x in 0..size[0] {
                for c in 0..3 {
                    if image.get(x, y, c) as u32 != mask.view(x, y, c) {
                        mismatches += 1;
                        if mismatches <= 5 {
                            eprintln!(
                                "{:?} origin {origin:?} ({x},{y},{c}): GPU {} CPU {}",
                                display.kind,
                                image.get(x, y, c),
                                mask.view(x, y, c)
                            );
                        }
                    }
                }
            }
        }
        assert_eq!(mismatches, 0, "{:?} origin {origin:?}", display.kind);
    }
}

/// docs/DESIGN.md §1: the WGSL mask equals the Rust mask on every subpixel of a 7680×4320 panel with a
/// non-zero window origin, for every display kind (Looking Glass with and without subpixel
/// cells; the window reaches past the cells' panel, whose rows count from its bottom).
#[test]
fn wgsl_mask_equals_rust_mask_on_an_8k_panel() {
    assert_wgsl_mask_equals_rust_mask([1234, 567], [7680, 4320]);
}

/// A window starting left of and above the panel (a monitor there on a virtual desktop has
/// negative coordinates): the WGSL mask takes the origin's two's complement as the Rust one
/// does, on the window's part off the panel and on it; and one reaching past the cells'
/// panel's bottom from the left.
#[test]
fn wgsl_mask_equals_rust_mask_at_negative_origins() {
    assert_wgsl_mask_equals_rust_mask([-1234, -567], [2560, 1440]);
    assert_wgsl_mask_equals_rust_mask([-37, 1500], [640, 1000]);
}
