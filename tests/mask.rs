//! Display masks: the paper's 8×12 mask is the slanted model; WGSL equals Rust everywhere;
//! the Looking Glass mapping reproduces the holoplay formula.

mod common;

use autostereo::display::{hubner8_paper_view, Calibration, Display, DisplayKind, Mask};
use autostereo::render::MaskImageRenderer;

fn slanted(views: u32, pitch: f64, slant: f64, phase: f64) -> Display {
    Display::new(DisplayKind::Slanted {
        views,
        pitch,
        slant,
        phase,
    })
    .unwrap()
}

/// A sample calibration with subpixel cells (`data/`), 49 views.
fn gen3(name: &str) -> DisplayKind {
    let path = format!("{}/data/{name}", env!("CARGO_MANIFEST_DIR"));
    DisplayKind::LookingGlass {
        views: 49,
        calibration: Calibration::load(path.as_ref()).unwrap(),
    }
}

fn sample_calibration() -> Calibration {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/data/lkg_sample_visual.json");
    Calibration::load(path.as_ref()).unwrap()
}

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

fn slanted_with_origin(origin: [i32; 2]) -> Mask {
    slanted(8, 8.0, 2.0 / 3.0, 7.0 / 6.0)
        .with_origin(origin)
        .mask()
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

/// Every display kind the GPU tests compare: Looking Glass with and without subpixel cells.
fn all_kinds() -> [DisplayKind; 7] {
    [
        DisplayKind::Hubner8,
        DisplayKind::Lenticular { views: 7 },
        DisplayKind::Lenticular { views: 256 },
        DisplayKind::Slanted {
            views: 64,
            pitch: 12.37,
            slant: -0.4142,
            phase: 3.3,
        },
        DisplayKind::LookingGlass {
            views: 45,
            calibration: sample_calibration(),
        },
        gen3("lkg_sample_32in_landscape_gen3_visual.json"),
        gen3("lkg_sample_go_gen3_visual.json"),
    ]
}

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

/// A configVersion 3 calibration (subpixel cells) as Looking Glass writes it.
fn gen3_json(
    pattern: u32,
    cells: &[[f64; 6]],
    flip_x: bool,
    inv_view: Option<bool>,
    size: [u32; 2],
) -> String {
    let cells: Vec<serde_json::Value> = cells
        .iter()
        .map(|c| {
            serde_json::json!({
                "ROffsetX": c[0], "ROffsetY": c[1], "GOffsetX": c[2],
                "GOffsetY": c[3], "BOffsetX": c[4], "BOffsetY": c[5],
            })
        })
        .collect();
    let mut json = serde_json::json!({
        "configVersion": "3.0",
        "pitch": {"value": 44.75058319896644},
        "slope": {"value": -6.874565686767793},
        "center": {"value": 0.16935753461833172},
        "DPI": {"value": 283.0},
        "screenW": {"value": size[0] as f64},
        "screenH": {"value": size[1] as f64},
        "flipImageX": {"value": if flip_x { 1.0 } else { 0.0 }},
        "CellPatternMode": {"value": pattern as f64},
        "subpixelCells": cells,
    });
    if let Some(inv) = inv_view {
        json["invView"] = serde_json::json!({"value": if inv { 1.0 } else { 0.0 }});
    }
    json.to_string()
}

/// Cells as on the current panels: channels shifted by about a third of a pixel across and a
/// quarter up or down, alternating between cells (four distinct cells for pattern 3).
const GEN3_CELLS: [[f64; 6]; 4] = [
    [-0.31, 0.25, 0.28, 0.25, 0.0, -0.25],
    [-0.31, -0.25, 0.28, -0.25, 0.0, 0.25],
    [0.31, 0.25, -0.28, 0.25, 0.0, -0.25],
    [0.31, -0.25, -0.28, -0.25, 0.0, 0.25],
];

/// The Looking Glass lenticular shader with subpixel cells (WebXR library 0.6, Unity plugin),
/// written out here independently of the library: the view of channel `c` of panel pixel
/// (x, y top-down; negative left of / above the panel, where the shader's formula goes on
/// periodically) and `N·f`, to judge closeness to a view boundary.
#[allow(clippy::too_many_arguments)]
fn gen3_reference_view(
    pattern: u32,
    cells: &[[f64; 6]],
    flip_x: bool,
    inv_view: bool,
    size: [u32; 2],
    views: u32,
    x: i64,
    y: i64,
    c: usize,
) -> (u32, f64) {
    let (pitch, slope, center, dpi) = (
        44.75058319896644,
        -6.874565686767793,
        0.16935753461833172,
        283.0,
    );
    let (w, h) = (size[0] as f64, size[1] as f64);
    let y_gl = size[1] as i64 - 1 - y;
    let u = (x as f64 + 0.5) / w;
    let v = (y_gl as f64 + 0.5) / h;
    let pitch_adjusted = pitch * w / dpi * (1.0f64 / slope).atan().cos();
    let tilt = h / (w * slope) * if flip_x { -1.0 } else { 1.0 };
    let cell = match pattern {
        0 => 0,
        1 => i64::from(x.rem_euclid(2) != y_gl.rem_euclid(2)),
        2 => x.rem_euclid(2),
        3 => (y_gl + 2 * x.rem_euclid(2)).rem_euclid(4),
        4 => y_gl.rem_euclid(2),
        _ => unreachable!(),
    } as usize
        % cells.len();
    let (dx, dy) = (cells[cell][2 * c], cells[cell][2 * c + 1]);
    let a = (u + dx / w) + (v + dy / h) * tilt;
    let p = a * pitch_adjusted - center;
    let mut f = p - p.floor();
    if inv_view {
        f = 1.0 - f;
    }
    let scaled = f * views as f64;
    ((scaled.floor() as u32).min(views - 1), scaled)
}

/// A cell pattern, its cells, `flipImageX` and `invView` (absent: `None`).
type Gen3Case = (u32, &'static [[f64; 6]], bool, Option<bool>);

/// Every cell pattern (and more patterns than cells, flipped panels, `invView`) against the
/// formula on every subpixel of a full 3840×2160 panel.
#[test]
fn subpixel_cell_masks_equal_the_looking_glass_formula_on_a_full_panel() {
    let size = [3840, 2160];
    let views = 49;
    let cases: [Gen3Case; 7] = [
        (0, &GEN3_CELLS[..1], false, None),
        (1, &GEN3_CELLS[..2], false, Some(false)),
        (2, &GEN3_CELLS[..2], false, None),
        (3, &GEN3_CELLS, false, None),
        (4, &GEN3_CELLS[..2], false, None),
        // Three cells for pattern 3's four indices: index 3 is cell 0 again.
        (3, &GEN3_CELLS[..3], true, None),
        (2, &GEN3_CELLS[..2], true, Some(true)),
    ];
    for (pattern, cells, flip_x, inv) in cases {
        let json = gen3_json(pattern, cells, flip_x, inv, size);
        let calibration = Calibration::from_json(&json, "gen3.json".as_ref()).unwrap();
        let mask = Display::new(DisplayKind::LookingGlass { views, calibration })
            .unwrap()
            .mask();
        assert_eq!(mask.views_per_pixel(), 3);
        let (mut checked, mut boundary) = (0u64, 0u64);
        for y in 0..size[1] {
            for x in 0..size[0] {
                for c in 0..3 {
                    let inv = inv.unwrap_or(false);
                    let (reference, scaled) = gen3_reference_view(
                        pattern, cells, flip_x, inv, size, views, x as i64, y as i64, c,
                    );
                    let ours = mask.view(x, y, c as u32);
                    // 0.32 fixed point: only subpixels within ~(x + y)·2⁻³² lens periods of a
                    // view boundary may differ (there `⌊N(1 − f)⌋` and `N − 1 − ⌊Nf⌋` differ too).
                    let on_boundary = (scaled - scaled.round()).abs() < 1e-4;
                    boundary += u64::from(on_boundary);
                    assert!(
                        ours == reference || on_boundary,
                        "pattern {pattern} ({} cells, flip {flip_x}, inv {inv}) at ({x},{y},{c}): \
                         {ours} vs {reference}",
                        cells.len()
                    );
                    checked += 1;
                }
            }
        }
        assert_eq!(checked, 3840 * 2160 * 3);
        assert!(
            boundary < checked / 1000,
            "pattern {pattern}: {boundary} near boundaries"
        );
    }
}

/// The cells matter: the same lens with a stripe puts most subpixels in another view (what a
/// tool that ignores the cells shows on these panels).
#[test]
fn subpixel_cells_change_most_views_against_the_stripe() {
    let size = [3840, 2160];
    let json = gen3_json(3, &GEN3_CELLS, false, Some(false), size);
    let cells = Calibration::from_json(&json, "gen3.json".as_ref()).unwrap();
    let mut stripe = cells.clone();
    stripe.cells = None;
    let mask = |calibration| {
        Display::new(DisplayKind::LookingGlass {
            views: 49,
            calibration,
        })
        .unwrap()
        .mask()
    };
    let (cells, stripe) = (mask(cells), mask(stripe));
    let mut differ = 0;
    let mut total = 0;
    for y in (0..size[1]).step_by(5) {
        for x in (0..size[0]).step_by(3) {
            for c in 0..3 {
                differ += u32::from(cells.view(x, y, c) != stripe.view(x, y, c));
                total += 1;
            }
        }
    }
    assert!(differ * 2 > total, "{differ} of {total} differ");
}

/// Calibration files with cells: the sample set loads, and broken cell tables are refused by
/// name.
#[test]
fn gen3_calibrations_load_and_broken_cells_are_refused_by_name() {
    for name in [
        "lkg_sample_16in_landscape_gen3_visual.json",
        "lkg_sample_16in_portrait_gen3_visual.json",
        "lkg_sample_32in_landscape_gen3_visual.json",
        "lkg_sample_go_gen3_visual.json",
    ] {
        let path = format!("{}/data/{name}", env!("CARGO_MANIFEST_DIR"));
        let calibration = Calibration::load(path.as_ref()).unwrap();
        assert!(calibration.cells.is_some(), "{name}");
        assert!(!calibration.inv_view, "{name}: no invView reads as 0");
        Display::parse(&format!("lkg:{path}")).unwrap();
    }
    let good = gen3_json(2, &GEN3_CELLS[..2], false, None, [3840, 2160]);
    let refused = |edit: &dyn Fn(&mut serde_json::Value), wanted: &str| {
        let mut json: serde_json::Value = serde_json::from_str(&good).unwrap();
        edit(&mut json);
        let err = Calibration::from_json(&json.to_string(), "v.json".as_ref())
            .unwrap_err()
            .to_string();
        assert!(err.contains(wanted) && err.contains("v.json"), "{err}");
    };
    refused(
        &|j| j["CellPatternMode"]["value"] = 5.0.into(),
        "CellPatternMode",
    );
    refused(
        &|j| j["CellPatternMode"]["value"] = 1.5.into(),
        "CellPatternMode",
    );
    refused(
        &|j| drop(j.as_object_mut().unwrap().remove("CellPatternMode")),
        "CellPatternMode",
    );
    refused(
        &|j| j["subpixelCells"][1]["GOffsetY"] = "x".into(),
        "subpixelCells[1].GOffsetY",
    );
    refused(
        &|j| {
            drop(
                j["subpixelCells"][0]
                    .as_object_mut()
                    .unwrap()
                    .remove("BOffsetX"),
            )
        },
        "BOffsetX",
    );
    refused(&|j| j["subpixelCells"] = 3.into(), "subpixelCells");
    refused(&|j| j["screenH"]["value"] = 2160.5.into(), "screenH");
    refused(
        &|j| j["flipImageY"] = serde_json::json!({"value": 1.0}),
        "flipImageY",
    );
    // An empty cell list is the stripe model, as Looking Glass's loaders read it.
    let mut json: serde_json::Value = serde_json::from_str(&good).unwrap();
    json["subpixelCells"] = serde_json::json!([]);
    json["invView"] = serde_json::json!({"value": 1.0});
    let stripe = Calibration::from_json(&json.to_string(), "v.json".as_ref()).unwrap();
    assert!(stripe.cells.is_none());
}
