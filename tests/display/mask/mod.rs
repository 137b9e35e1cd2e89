//! Display masks: the paper's 8×12 mask is the slanted model; WGSL equals Rust everywhere;
//! the Looking Glass mapping reproduces the holoplay formula.

use crate::common;

mod cells;
mod models;
mod origins;
mod wgsl;

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

fn slanted_with_origin(origin: [i32; 2]) -> Mask {
    slanted(8, 8.0, 2.0 / 3.0, 7.0 / 6.0)
        .with_origin(origin)
        .mask()
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
