//! Negative origins (a window left of or above the panel): the display formulas on both
//! sides of the panel edge, and the origin-0 mask moved.

use super::*;

/// The paper's Eq. 4–6 (docs/DESIGN.md §1) written out again for any integer panel column `x`
/// and row `y`: negative ones (left of / above the panel) by the equations' periodic extension.
fn paper_view_signed(x: i64, y: i64, c: i64) -> u32 {
    let x_offset = (3 * x).rem_euclid(8);
    let y_offset = (y + 1).rem_euclid(12);
    let v_r = ((1 + y_offset + y_offset / 3) / 2 + x_offset) % 8;
    ((v_r + c) % 8) as u32
}

/// The slanted model `⌊N·frac((k + s·l + φ)/P)⌋` in f64 on subpixel column `k = 3x + c` and
/// row `l = y` of the panel, any sign; and a view boundary closer than the mask's fixed point
/// resolves there (its phase is within (|k| + |l| + 1)·2⁻³² periods of the exact).
fn slanted_reference_view(
    [views, pitch, slant, phase]: [f64; 4],
    x: i64,
    y: i64,
    c: i64,
) -> (u32, bool) {
    let k = 3 * x + c;
    let t = (k as f64 + slant * y as f64 + phase) / pitch;
    let scaled = (t - t.floor()) * views;
    let tolerance = (k.abs() + y.abs() + 1) as f64 * views / 4_294_967_296.0 + 1e-9;
    let on_boundary = (scaled - scaled.round()).abs() <= tolerance;
    ((scaled.floor() as u32).min(views as u32 - 1), on_boundary)
}

/// A window left of or above the panel (negative origin, its two's complement in the mask's
/// wrap-around u32 arithmetic): on its every subpixel, off the panel and on it, the mask
/// equals the display's formula written out independently: the paper's equations (hubner8
/// and the slanted model that is it, exactly: their phases sit at least 1/6 view from a
/// boundary), the slanted model in f64 for a lens of no simple ratio, and the Looking Glass
/// shader with subpixel cells (every cell pattern: the cells' parities at negative columns and
/// rows).
#[test]
fn negative_origins_equal_the_display_formulas_on_both_sides_of_the_panel_edge() {
    // The signed paper equations are the library's on the panel.
    for (x, y) in [(0, 0), (5, 7), (1919, 1199), (123, 4567)] {
        for c in 0..3 {
            assert_eq!(
                paper_view_signed(x, y, c),
                hubner8_paper_view(x as u32, y as u32, c as u32)
            );
        }
    }
    let origins = [[-5, -3], [-1234, -567], [-7, 20], [33, -11]];
    let size = [1600u32, 900u32];
    let hubner8 = Display::new(DisplayKind::Hubner8).unwrap();
    let lens = [64.0, 12.37, -0.4142, 3.3];
    let odd = slanted(64, lens[1], lens[2], lens[3]);
    let (mut checked, mut boundary) = (0u64, 0u64);
    for origin in origins {
        let h = hubner8.clone().with_origin(origin).mask();
        let s = slanted_with_origin(origin);
        let o = odd.clone().with_origin(origin).mask();
        for y in 0..size[1] {
            for x in 0..size[0] {
                let (px, py) = (x as i64 + origin[0] as i64, y as i64 + origin[1] as i64);
                for c in 0..3 {
                    let paper = paper_view_signed(px, py, c as i64);
                    assert_eq!(h.view(x, y, c), paper, "hubner8 ({x},{y},{c}) {origin:?}");
                    assert_eq!(s.view(x, y, c), paper, "slanted ({x},{y},{c}) {origin:?}");
                    let (reference, on_boundary) = slanted_reference_view(lens, px, py, c as i64);
                    let ours = o.view(x, y, c);
                    assert!(
                        ours == reference || on_boundary,
                        "slanted {lens:?} ({x},{y},{c}) origin {origin:?}: {ours} vs {reference}"
                    );
                    boundary += u64::from(on_boundary);
                    checked += 1;
                }
            }
        }
    }
    assert!(
        boundary < checked / 1000,
        "{boundary} of {checked} near boundaries"
    );

    // Subpixel cells: a window over the panel's top-left corner, and one left of the panel
    // reaching past its bottom (rows counted from the bottom go negative there).
    let panel = [3840, 2160];
    let views = 49;
    let cases: [Gen3Case; 6] = [
        (0, &GEN3_CELLS[..1], false, None),
        (1, &GEN3_CELLS[..2], false, Some(false)),
        (2, &GEN3_CELLS[..2], true, Some(true)),
        (3, &GEN3_CELLS, false, None),
        (3, &GEN3_CELLS[..3], true, None),
        (4, &GEN3_CELLS[..2], false, None),
    ];
    for (pattern, cells, flip_x, inv) in cases {
        let json = gen3_json(pattern, cells, flip_x, inv, panel);
        let calibration = Calibration::from_json(&json, "gen3.json".as_ref()).unwrap();
        let display = Display::new(DisplayKind::LookingGlass { views, calibration }).unwrap();
        for (origin, size) in [([-501, -299], [1000, 600]), ([-7, 1903], [64, 300])] {
            let mask = display.clone().with_origin(origin).mask();
            let (mut checked, mut boundary) = (0u64, 0u64);
            for y in 0..size[1] {
                for x in 0..size[0] {
                    let (px, py) = (x as i64 + origin[0] as i64, y as i64 + origin[1] as i64);
                    for c in 0..3 {
                        let inv = inv.unwrap_or(false);
                        let (reference, scaled) = gen3_reference_view(
                            pattern, cells, flip_x, inv, panel, views, px, py, c,
                        );
                        let ours = mask.view(x, y, c as u32);
                        // As on the panel (the test above): 0.32 fixed point, within
                        // ~(|x| + |y|)·2⁻³² lens periods of a view boundary.
                        let on_boundary = (scaled - scaled.round()).abs() < 1e-4;
                        boundary += u64::from(on_boundary);
                        assert!(
                            ours == reference || on_boundary,
                            "pattern {pattern} ({} cells, flip {flip_x}, inv {inv}) at \
                             ({x},{y},{c}) origin {origin:?}: {ours} vs {reference}",
                            cells.len()
                        );
                        checked += 1;
                    }
                }
            }
            assert!(
                boundary < checked / 1000,
                "pattern {pattern} origin {origin:?}: {boundary} of {checked} near boundaries"
            );
        }
    }
}

/// Moving the window by (−dx, −dy) on the panel shows at window pixel (x, y) what the window
/// at origin 0 shows at (x − dx, y − dy), for every display kind; and a band of a frame at a
/// negative origin (`Frame::band`) is that frame's mask moved by the band's origin.
#[test]
fn a_negative_origin_is_the_origin_0_mask_moved() {
    let mut kinds = all_kinds().to_vec();
    kinds.push(DisplayKind::OneView { views: 8, view: 5 });
    for kind in kinds {
        let at_0 = Display::new(kind.clone()).unwrap().mask();
        for [dx, dy] in [[5u32, 3u32], [1234, 567], [0, 9], [8, 0], [1, 1]] {
            let origin = [-(dx as i32), -(dy as i32)];
            let moved = Display::new(kind.clone())
                .unwrap()
                .with_origin(origin)
                .mask();
            for y in dy..dy + 240 {
                for x in dx..dx + 320 {
                    for c in 0..3 {
                        assert_eq!(
                            moved.view(x, y, c),
                            at_0.view(x - dx, y - dy, c),
                            "{kind:?} origin {origin:?} at ({x},{y},{c})"
                        );
                    }
                }
            }
        }
    }

    let bounds = autostereo::camera::Bounds {
        min: glam::Vec3::splat(-1.0),
        max: glam::Vec3::splat(1.0),
    };
    let mut frame = common::frame(bounds, "hubner8", 0.1, 1.0, [256, 128]);
    frame.display = frame.display.clone().with_origin([-100, -50]);
    let band = frame.band([64, 32], [128, 64]);
    assert_eq!(band.display.origin, [-36, -18]);
    let (whole, part) = (frame.display.mask(), band.display.mask());
    for y in 0..64 {
        for x in 0..128 {
            for c in 0..3 {
                assert_eq!(part.view(x, y, c), whole.view(x + 64, y + 32, c));
            }
        }
    }
}
