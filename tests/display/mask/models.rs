//! The paper's mask is the slanted model, lenticular is x mod N, flips and BGR permute, and
//! the Looking Glass mapping reproduces the holoplay formula.

use super::*;

#[test]
fn hubner8_equals_paper_equations_and_slanted_8_8_two_thirds_seven_sixths() {
    let hubner = Display::new(DisplayKind::Hubner8).unwrap().mask();
    let slanted = slanted(8, 8.0, 2.0 / 3.0, 7.0 / 6.0).mask();
    // A 1920×1200 panel covers the 8×12 period many times over; add a window origin too.
    for origin in [[0, 0], [5, 7]] {
        let h = Display::new(DisplayKind::Hubner8)
            .unwrap()
            .with_origin(origin)
            .mask();
        let s = slanted_with_origin(origin);
        for y in 0..1200 {
            for x in 0..1920 {
                for c in 0..3 {
                    let paper = hubner8_paper_view(x + origin[0] as u32, y + origin[1] as u32, c);
                    assert_eq!(
                        h.view(x, y, c),
                        paper,
                        "hubner8 ({x},{y},{c}) origin {origin:?}"
                    );
                    assert_eq!(
                        s.view(x, y, c),
                        paper,
                        "slanted ({x},{y},{c}) origin {origin:?}"
                    );
                }
            }
        }
    }
    assert_eq!(hubner, slanted);
}

#[test]
fn lenticular_is_x_mod_n_on_every_channel() {
    for n in [1, 2, 3, 5, 8, 45, 64, 256] {
        let mask = Display::new(DisplayKind::Lenticular { views: n })
            .unwrap()
            .with_origin([13, 2])
            .mask();
        assert_eq!(mask.views_per_pixel(), 1);
        for y in [0, 1, 99] {
            for x in 0..3000 {
                let v = (x + 13) % n;
                assert_eq!(mask.pixel_views(x, y), [v, v, v], "N={n} x={x}");
            }
        }
    }
}

#[test]
fn flip_and_bgr_permute_views_and_channels() {
    let base = Display::new(DisplayKind::Hubner8).unwrap();
    let mut flipped = base.clone();
    flipped.flip_views = true;
    let mut bgr = base.clone();
    bgr.bgr = true;
    let (m, f, b) = (base.mask(), flipped.mask(), bgr.mask());
    for y in 0..24 {
        for x in 0..16 {
            for c in 0..3 {
                assert_eq!(f.view(x, y, c), 7 - m.view(x, y, c));
                // BGR: channel c sits where channel 2 − c sits on an RGB panel.
                assert_eq!(b.view(x, y, c), m.view(x, y, 2 - c));
            }
        }
    }
}

#[test]
fn looking_glass_mapping_reproduces_the_holoplay_formula() {
    let mut calibration = sample_calibration();
    for flip_x in [false, true] {
        for inv in [false, true] {
            calibration.flip_image_x = flip_x;
            calibration.inv_view = inv;
            let views = 45;
            let mask = Display::new(DisplayKind::LookingGlass {
                views,
                calibration: calibration.clone(),
            })
            .unwrap()
            .mask();
            let mut checked = 0;
            for y in (0..1600).step_by(7) {
                for x in (0..2560).step_by(3) {
                    for c in 0..3 {
                        let reference = calibration.holoplay_view(views, x, y, c);
                        let ours = mask.view(x, y, c);
                        // 0.32 fixed point carries the phase to ~(x + y)·2⁻³² lens periods:
                        // only subpixels that close to a view boundary may differ.
                        let scaled = calibration.holoplay_phase(x, y, c) * views as f64;
                        let on_boundary = (scaled - scaled.round()).abs() < 1e-4;
                        assert!(
                            ours == reference || on_boundary,
                            "({x},{y},{c}) flip {flip_x} inv {inv}: {ours} vs {reference}"
                        );
                        checked += 1;
                    }
                }
            }
            assert!(checked > 500_000);
        }
    }
}
