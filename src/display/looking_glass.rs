//! Looking Glass calibration files (`visual.json`) and their mapping onto the slanted model.
//!
//! The Looking Glass lenticular shader (holoplay / WebXR polyfill) computes, per subpixel `i` of
//! the fragment at normalised coordinates `u = (x+½)/W`, `v = (y_gl+½)/H` (bottom-up):
//! `a = (u + i·subp + v·tilt)·pitch′ − center`, `subp = σ/(3W)`, `tilt = σ·H/(W·slope)`,
//! `pitch′ = pitch·W/DPI·cos(atan(1/slope))`, σ = −1 if `flipImageX` else +1;
//! the view is `⌊N·frac(a)⌋`, or `⌊N·(1 − frac(a))⌋` when `invView` is 1.
//! Multiplying out with `k = 3x + i` and `y_gl = H − 1 − l` gives the slanted model exactly:
//! `P = 3W/pitch′`, `s = −3σ/slope`, subpixel order reversed when σ = −1, and
//! `φ = 1.5 + 3(H − ½)/slope − center·P` (σ = +1) or `φ = −½ − 3(H − ½)/slope − center·P` (σ = −1).
//! `invView` becomes the view-order flip `N − 1 − v`, which differs from `⌊N(1 − f)⌋` only on
//! exact view boundaries (a set of measure zero; the holoplay shader clamps those anyway).
//!
//! Calibrations with subpixel cells (`configVersion` "3.0") place each channel by its cell
//! instead of the stripe (`subpixel_cells.rs`); the phase is then linear in the pixel column
//! and row with a constant per cell and channel, which the mask takes directly
//! ([`Calibration::cell_geometry`]).

use std::path::{Path, PathBuf};

use super::lkg_family::LookingGlassFamily;
use super::subpixel_cells::SubpixelCells;
use crate::error::{Error, Result};

/// The calibration values the interleaving uses. Field names follow `visual.json`.
#[derive(Clone, Debug, PartialEq)]
pub struct Calibration {
    /// Lens pitch in lenses per inch.
    pub pitch: f64,
    /// Lens slope (screen rows per lens column shift).
    pub slope: f64,
    /// Phase offset in lens periods.
    pub center: f64,
    /// Panel dots per inch.
    pub dpi: f64,
    /// Panel width in pixels.
    pub screen_w: f64,
    /// Panel height in pixels.
    pub screen_h: f64,
    /// Panel mirrored horizontally (reverses subpixel order and slant).
    pub flip_image_x: bool,
    /// Views run right to left. Calibrations with subpixel cells may leave `invView` out;
    /// it is then 0, as Looking Glass's own loaders read it.
    pub inv_view: bool,
    /// The subpixel cells of a `configVersion` "3.0" calibration; `None`: the RGB stripe.
    pub cells: Option<SubpixelCells>,
    /// The device's serial number (its prefix names the family: [`LookingGlassFamily`]).
    pub serial: Option<String>,
    /// The angle in degrees the views span (`viewCone`), where the file gives one.
    pub view_cone: Option<f64>,
}

/// The mask of a calibration with subpixel cells, in lens periods (before the fixed point):
/// the phase of channel c of panel pixel (x, y top-down) is
/// `x·step_x + y·step_y + phases[cell][c]`, the cell from `pattern` and `y_gl = panel_top − y`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct CellGeometry {
    pub pattern: super::CellPattern,
    pub panel_top: u32,
    pub step_x: f64,
    pub step_y: f64,
    /// Per cell index 0…3 (already taken modulo the number of cells), per channel R, G, B.
    pub phases: [[f64; 3]; 4],
}

/// The slanted-model parameters a calibration maps to.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct SlantedEquivalent {
    pub pitch: f64,
    pub slant: f64,
    pub phase: f64,
    pub bgr: bool,
    pub flip_views: bool,
}

impl Calibration {
    /// Read a `visual.json`. Each field may be `{"value": x}` (as Looking Glass writes them) or a
    /// plain number. Missing or non-numeric fields are errors naming the field.
    pub fn load(path: &Path) -> Result<Self> {
        // BOM, CRLF and non-UTF-8 bytes as every text input (`crate::file`).
        let text = crate::file::read_text(path)?;
        Self::from_json(&text, path)
    }

    /// Parse calibration JSON; `path` only names the source in errors.
    pub fn from_json(text: &str, path: &Path) -> Result<Self> {
        let err = |reason: String| Error::Calibration {
            path: PathBuf::from(path),
            reason,
        };
        let json: serde_json::Value =
            serde_json::from_str(text).map_err(|e| err(format!("not valid JSON: {e}")))?;
        let field = |name: &str| -> Result<f64> {
            let v = json
                .get(name)
                .ok_or_else(|| err(format!("missing field '{name}'")))?;
            let v = v.get("value").unwrap_or(v);
            v.as_f64().filter(|x| x.is_finite()).ok_or_else(|| {
                err(format!(
                    "field '{name}' is not a finite number: {}",
                    crate::error::quote(v.to_string())
                ))
            })
        };
        // Orientation flags neither model covers: refused rather than ignored, so a panel
        // mounted upside down or with BGR subpixels never gets a wrong mask silently.
        for (name, meaning) in [
            ("flipImageY", "a vertically flipped panel"),
            ("flipSubp", "reversed subpixel order"),
        ] {
            if json.get(name).is_some() && field(name)? != 0.0 {
                return Err(err(format!(
                    "field '{name}' = 1 ({meaning}) is not supported; only 0"
                )));
            }
        }
        let cells = SubpixelCells::from_json(&json, &err)?;
        let inv_view = match json.get("invView") {
            None if cells.is_some() => false,
            _ => field("invView")? != 0.0,
        };
        let view_cone = match json.get("viewCone") {
            None => None,
            Some(_) => {
                let degrees = field("viewCone")?;
                if !(degrees > 0.0 && degrees < 180.0) {
                    return Err(err(format!(
                        "field 'viewCone' = {degrees}: must be an angle in degrees between 0 and 180"
                    )));
                }
                Some(degrees)
            }
        };
        let serial = json
            .get("serial")
            .and_then(|s| s.as_str())
            .map(String::from);
        let calibration = Self {
            serial,
            view_cone,
            pitch: field("pitch")?,
            slope: field("slope")?,
            center: field("center")?,
            dpi: field("DPI")?,
            screen_w: field("screenW")?,
            screen_h: field("screenH")?,
            flip_image_x: field("flipImageX")? != 0.0,
            inv_view,
            cells,
        };
        for (name, v) in [
            ("pitch", calibration.pitch),
            ("DPI", calibration.dpi),
            ("screenW", calibration.screen_w),
            ("screenH", calibration.screen_h),
        ] {
            if v <= 0.0 {
                return Err(err(format!("field '{name}' must be positive, got {v}")));
            }
        }
        if calibration.slope == 0.0 {
            return Err(err("field 'slope' must not be 0".into()));
        }
        // The cell of a pixel counts rows from the panel's bottom.
        let h = calibration.screen_h;
        if calibration.cells.is_some() && (h.fract() != 0.0 || h > u32::MAX as f64) {
            return Err(err(format!(
                "field 'screenH' = {h}: subpixel cells need a whole number of rows"
            )));
        }
        Ok(calibration)
    }

    /// The device family its serial names, with Looking Glass's default views and quilt.
    pub fn family(&self) -> Option<&'static LookingGlassFamily> {
        LookingGlassFamily::of_serial(self.serial.as_deref()?)
    }

    /// The panel's size in pixels (`screenW` × `screenH`, rounded).
    pub fn panel_size(&self) -> [u32; 2] {
        let round = |v: f64| v.round().clamp(1.0, u32::MAX as f64) as u32;
        [round(self.screen_w), round(self.screen_h)]
    }

    /// The lens pitch across the screen as the holoplay shader uses it (lenses per screen width).
    pub fn screen_pitch(&self) -> f64 {
        self.pitch * self.screen_w / self.dpi * (1.0 / self.slope).atan().cos()
    }

    /// The holoplay shader's lens phase `frac(a)` in f64 (before `invView`), for panel pixel
    /// (x, y top-down) and subpixel i (with cells: channel i at its cell's offset).
    pub fn holoplay_phase(&self, x: u32, y: u32, i: u32) -> f64 {
        let sigma = if self.flip_image_x { -1.0 } else { 1.0 };
        let (w, h) = (self.screen_w, self.screen_h);
        let u = (x as f64 + 0.5) / w;
        let y_gl = h - 1.0 - y as f64;
        let v = (y_gl + 0.5) / h;
        let tilt = sigma * h / (w * self.slope);
        let a = match &self.cells {
            Some(cells) => {
                let [dx, dy] = cells.cell(x, y_gl as i64 as u32).offsets[i as usize];
                (u + dx / w) + (v + dy / h) * tilt
            }
            None => u + i as f64 * sigma / (3.0 * w) + v * tilt,
        };
        let a = a * self.screen_pitch() - self.center;
        a - a.floor()
    }

    /// The view the holoplay shader picks: `⌊N·frac(a)⌋`, or `⌊N·(1 − frac(a))⌋` with `invView`.
    pub fn holoplay_view(&self, views: u32, x: u32, y: u32, i: u32) -> u32 {
        let mut f = self.holoplay_phase(x, y, i);
        if self.inv_view {
            f = 1.0 - f;
        }
        ((f * views as f64).floor() as u32).min(views.saturating_sub(1))
    }

    /// The mask of a calibration with cells (module docs): multiplying out
    /// `(u + dx/W)·pitch′ + (v + dy/H)·tilt·pitch′ − center` with `y_gl = H − 1 − y`.
    pub(crate) fn cell_geometry(&self) -> Option<CellGeometry> {
        let cells = self.cells.as_ref()?;
        let sigma = if self.flip_image_x { -1.0 } else { 1.0 };
        let (w, h) = (self.screen_w, self.screen_h);
        let per_x = self.screen_pitch() / w;
        let per_y = sigma * self.screen_pitch() / (w * self.slope);
        let mut phases = [[0.0; 3]; 4];
        for (index, phase) in phases.iter_mut().enumerate() {
            let cell = &cells.cells[index % cells.cells.len()];
            for (c, [dx, dy]) in cell.offsets.iter().enumerate() {
                phase[c] = per_x * (0.5 + dx) + per_y * (h - 0.5 + dy) - self.center;
            }
        }
        Some(CellGeometry {
            pattern: cells.pattern,
            panel_top: (h as u32).wrapping_sub(1),
            step_x: per_x,
            step_y: -per_y,
            phases,
        })
    }

    pub(crate) fn slanted(&self) -> SlantedEquivalent {
        let pitch = 3.0 * self.screen_w / self.screen_pitch();
        let rows = 3.0 * (self.screen_h - 0.5) / self.slope;
        let (slant, phase) = if self.flip_image_x {
            (3.0 / self.slope, -0.5 - rows - self.center * pitch)
        } else {
            (-3.0 / self.slope, 1.5 + rows - self.center * pitch)
        };
        SlantedEquivalent {
            pitch,
            slant,
            phase,
            bgr: self.flip_image_x,
            flip_views: self.inv_view,
        }
    }
}
