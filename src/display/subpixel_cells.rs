//! The subpixel cells of Looking Glass's current calibrations (`configVersion` "3.0": Looking
//! Glass Go, 16" and 32" Spatial Displays). Their subpixels are not a ⅓-pixel RGB stripe: each
//! pixel belongs to a cell (chosen by `CellPatternMode` from its column and row), and the cell
//! gives each channel's offset from the pixel centre, in pixels. Looking Glass's lenticular
//! shader (WebXR library 0.6, Unity plugin) then takes, per channel c of pixel (x, y_gl),
//! y_gl counted from the bottom row, with `u = (x + ½)/W`, `v = (y_gl + ½)/H`:
//! `a_c = (u + dx_c/W) + (v + dy_c/H)·tilt`, `tilt = H/(W·slope)` (negated with `flipImageX`),
//! `f = frac(a_c·pitch′ − center)`, view `⌊N·f⌋` (`⌊N·(1 − f)⌋` with `invView`).
//! [`crate::display::Mask`] evaluates this in the same 0.32 fixed point as the stripe model.

use crate::error::{Error, Result};

/// How a pixel's cell follows from its column x and its row y_gl counted from the bottom
/// (`CellPatternMode`); the index is then taken modulo the number of cells.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CellPattern {
    /// Mode 0: every pixel is cell 0.
    Single,
    /// Mode 1: a checkerboard, cell 0 where x and y_gl have the same parity, else 1.
    Checkerboard,
    /// Mode 2: alternating columns, x mod 2.
    Columns,
    /// Mode 3: `(y_gl + 2·(x mod 2)) mod 4`.
    ColumnsAndRows,
    /// Mode 4: alternating rows, y_gl mod 2.
    Rows,
}

impl CellPattern {
    /// The pattern of `CellPatternMode` `mode`.
    pub fn from_mode(mode: u32) -> Option<Self> {
        Some(match mode {
            0 => Self::Single,
            1 => Self::Checkerboard,
            2 => Self::Columns,
            3 => Self::ColumnsAndRows,
            4 => Self::Rows,
            _ => return None,
        })
    }

    /// Its `CellPatternMode` number (also the mask's encoding).
    pub fn mode(self) -> u32 {
        match self {
            Self::Single => 0,
            Self::Checkerboard => 1,
            Self::Columns => 2,
            Self::ColumnsAndRows => 3,
            Self::Rows => 4,
        }
    }

    /// The cell index (before the modulo) of the pixel in column `x`, row `y_gl` from the
    /// bottom; always below 4.
    pub fn index(self, x: u32, y_gl: u32) -> u32 {
        match self {
            Self::Single => 0,
            Self::Checkerboard => (x ^ y_gl) & 1,
            Self::Columns => x & 1,
            Self::ColumnsAndRows => (y_gl.wrapping_add(2 * (x & 1))) & 3,
            Self::Rows => y_gl & 1,
        }
    }
}

/// One cell: each channel's (x, y) offset from the pixel centre in pixels, y upwards (the
/// calibration's `ROffsetX`, `ROffsetY`, `GOffsetX`, …).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SubpixelCell {
    /// Offsets of R, G, B.
    pub offsets: [[f64; 2]; 3],
}

/// A calibration's cells and the pattern that assigns them to pixels.
#[derive(Clone, Debug, PartialEq)]
pub struct SubpixelCells {
    /// Which cell each pixel belongs to.
    pub pattern: CellPattern,
    /// At least one.
    pub cells: Vec<SubpixelCell>,
}

/// Offsets beyond this many pixels are not a subpixel layout: refused as a broken file.
const MAX_OFFSET: f64 = 16.0;

impl SubpixelCells {
    /// The cell of pixel (x, y_gl).
    pub fn cell(&self, x: u32, y_gl: u32) -> &SubpixelCell {
        &self.cells[self.pattern.index(x, y_gl) as usize % self.cells.len()]
    }

    /// Parse `subpixelCells` and `CellPatternMode` of a calibration's JSON; `None` when it has
    /// no cells (an empty list, as Looking Glass's loaders read it, is the stripe model too).
    /// `err` makes the error naming the calibration file.
    pub(crate) fn from_json(
        json: &serde_json::Value,
        err: &dyn Fn(String) -> Error,
    ) -> Result<Option<Self>> {
        let Some(list) = json.get("subpixelCells") else {
            if json.get("CellPatternMode").is_some() {
                // A pattern without cells assigns nothing: the stripe model, as Looking
                // Glass's shaders take it.
                log::info!("calibration has CellPatternMode but no subpixelCells: stripe model");
            }
            return Ok(None);
        };
        let list = list
            .as_array()
            .ok_or_else(|| err(format!("field 'subpixelCells' is not a list: {list}")))?;
        if list.is_empty() {
            return Ok(None);
        }
        let mode = json
            .get("CellPatternMode")
            .ok_or_else(|| err("field 'subpixelCells' needs 'CellPatternMode'".into()))?;
        let mode = mode.get("value").unwrap_or(mode);
        let pattern = mode
            .as_f64()
            .filter(|m| m.fract() == 0.0 && *m >= 0.0)
            .and_then(|m| CellPattern::from_mode(m as u32))
            .ok_or_else(|| {
                err(format!(
                    "field 'CellPatternMode' = {mode}: the cell patterns are 0 (one cell), 1 \
                     (checkerboard), 2 (columns), 3 (columns and rows), 4 (rows)"
                ))
            })?;
        let cells = list
            .iter()
            .enumerate()
            .map(|(i, cell)| {
                let offset = |name: &str| -> Result<f64> {
                    let v = cell.get(name).ok_or_else(|| {
                        err(format!("subpixelCells[{i}]: missing field '{name}'"))
                    })?;
                    let v = v.get("value").unwrap_or(v);
                    v.as_f64()
                        .filter(|x| x.is_finite() && x.abs() <= MAX_OFFSET)
                        .ok_or_else(|| {
                            err(format!(
                                "subpixelCells[{i}].{name} = {v}: must be a finite offset of at \
                                 most {MAX_OFFSET} pixels"
                            ))
                        })
                };
                let mut offsets = [[0.0; 2]; 3];
                for (c, channel) in ["R", "G", "B"].iter().enumerate() {
                    offsets[c] = [
                        offset(&format!("{channel}OffsetX"))?,
                        offset(&format!("{channel}OffsetY"))?,
                    ];
                }
                Ok(SubpixelCell { offsets })
            })
            .collect::<Result<Vec<_>>>()?;
        Ok(Some(Self { pattern, cells }))
    }
}
