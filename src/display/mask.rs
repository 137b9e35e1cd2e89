//! The one definition of the mask maths, shared by Rust and WGSL.
//!
//! `view = ⌊N · frac((k + s·l + φ)/P)⌋` is evaluated as `t = k·A + l·B + C (mod 2³²)` with
//! `A = frac(1/P)`, `B = frac(s/P)`, `C = frac(φ/P)` in 0.32 fixed point (u32 wrap-around is the
//! `frac`), then `view = (t·N) >> 32`. Integer-only, so any `k` keeps full precision and
//! `wgsl/shared/mask.wgsl` reproduces it bit for bit. A, B, C are rounded *up*: on the panel
//! (k, l ≥ 0) the fixed-point phase is never below the exact one, so a subpixel whose exact
//! phase sits on a view boundary (every lenticular pixel, for instance) gets the exact view.
//! A window origin left of or above the panel (negative) is its two's complement: see
//! [`Mask::new`].
//!
//! Subpixel cells (`subpixel_cells.rs`) replace the subpixel column by the pixel column and the
//! one phase C by one per cell and channel: `t = x·A + y·B + C[cell][c]`, the cell from the
//! pattern, the column and the row counted from the panel's bottom.

use bytemuck::{Pod, Zeroable};

/// The geometry a [`Mask`] is compiled from.
#[derive(Clone, Copy, Debug)]
pub(crate) struct MaskGeometry {
    pub views: u32,
    pub pitch: f64,
    pub slant: f64,
    pub phase: f64,
    pub subpixel: bool,
    /// The window's origin on the panel; negative where the window starts left of or above
    /// the panel (a monitor placed there on a virtual desktop).
    pub origin: [i32; 2],
    pub flip_views: bool,
    pub bgr: bool,
    /// Subpixel cells: the steps and phases in lens periods instead of pitch, slant and phase.
    pub cells: Option<super::looking_glass::CellGeometry>,
}

/// A compiled display mask: `view(x, y, c)` for window pixel (x, y), channel c (0 = R).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Mask {
    uniform: MaskUniform,
}

const FLAG_SUBPIXEL: u32 = 1;
const FLAG_FLIP: u32 = 2;
const FLAG_BGR: u32 = 4;
const FLAG_CELLS: u32 = 8;

/// GPU form of [`Mask`]. Keep in sync with `struct DisplayMask` in `wgsl/shared/mask.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Pod, Zeroable)]
pub struct MaskUniform {
    step_column: u32,
    step_row: u32,
    phase: u32,
    views: u32,
    origin_x: u32,
    origin_y: u32,
    flags: u32,
    /// Subpixel cells: the `CellPatternMode`.
    cell_pattern: u32,
    /// Subpixel cells: the panel's last row (H − 1), from which rows count upwards.
    panel_top: u32,
    _pad: [u32; 3],
    /// Subpixel cells: the phase of R, G, B for cell index 0…3.
    cell_r: [u32; 4],
    cell_g: [u32; 4],
    cell_b: [u32; 4],
}
const _: () = assert!(std::mem::size_of::<MaskUniform>() == 96);
crate::shader::gpu_layout!(
    MaskUniform,
    "DisplayMask",
    [
        step_column,
        step_row,
        phase,
        views,
        origin_x,
        origin_y,
        flags,
        cell_pattern,
        panel_top,
        cell_r,
        cell_g,
        cell_b
    ]
);

/// `frac(v)` in 0.32 fixed point, rounded up (see the module docs).
fn fixed_frac_ceil(v: f64) -> u32 {
    let f = v - v.floor();
    let scaled = (f * 4_294_967_296.0).ceil();
    if scaled >= 4_294_967_296.0 {
        0
    } else {
        scaled as u32
    }
}

impl Mask {
    pub(crate) fn new(g: MaskGeometry) -> Self {
        let flag = |on: bool, bit: u32| if on { bit } else { 0 };
        let flags = flag(g.subpixel, FLAG_SUBPIXEL)
            | flag(g.flip_views, FLAG_FLIP)
            | flag(g.bgr, FLAG_BGR)
            | flag(g.cells.is_some(), FLAG_CELLS);
        let mut uniform = MaskUniform {
            step_column: fixed_frac_ceil(1.0 / g.pitch),
            step_row: fixed_frac_ceil(g.slant / g.pitch),
            phase: fixed_frac_ceil(g.phase / g.pitch),
            views: g.views,
            // A negative origin as its two's complement, here and nowhere else: the origin
            // enters only through wrap-around sums and products (`view` below, `mask_view` in
            // WGSL), which are exact modulo 2³² whatever the sign. So `x + origin_x` is the
            // true panel column k modulo 2³², and so are `3·k + slot`, `k·A` and `l·B` (the
            // phase is only ever wanted modulo 2³², one lens period) and `panel_top − l`; the
            // cells' parities (`& 1`, `& 3`) agree because 2³² is a multiple of 4. The one
            // difference from k, l ≥ 0: A and B are rounded up, so a negative k or l moves
            // the phase *below* the exact one (by under (|column| + |l|)·2⁻³² periods): only a
            // subpixel that close to a view boundary can change view, and negative k or l are
            // off the panel.
            origin_x: g.origin[0] as u32,
            origin_y: g.origin[1] as u32,
            flags,
            ..Zeroable::zeroed()
        };
        if let Some(cells) = g.cells {
            uniform.step_column = fixed_frac_ceil(cells.step_x);
            uniform.step_row = fixed_frac_ceil(cells.step_y);
            uniform.phase = 0;
            uniform.cell_pattern = cells.pattern.mode();
            uniform.panel_top = cells.panel_top;
            for (i, phases) in cells.phases.iter().enumerate() {
                uniform.cell_r[i] = fixed_frac_ceil(phases[0]);
                uniform.cell_g[i] = fixed_frac_ceil(phases[1]);
                uniform.cell_b[i] = fixed_frac_ceil(phases[2]);
            }
        }
        Self { uniform }
    }

    /// Number of views N.
    pub fn views(&self) -> u32 {
        self.uniform.views
    }

    /// Distinct views per pixel K (1 or 3).
    pub fn views_per_pixel(&self) -> u32 {
        if self.uniform.flags & FLAG_SUBPIXEL != 0 {
            3
        } else {
            1
        }
    }

    /// The GPU uniform.
    pub fn uniform(&self) -> MaskUniform {
        self.uniform
    }

    /// View of channel `c` (0 = R, 1 = G, 2 = B) of window pixel `(x, y)` (y top-down).
    /// Mirrors `mask_view` in `wgsl/shared/mask.wgsl` operation for operation.
    #[inline]
    pub fn view(&self, x: u32, y: u32, c: u32) -> u32 {
        let m = &self.uniform;
        let slot = if m.flags & FLAG_BGR != 0 { 2 - c } else { c };
        let px = x.wrapping_add(m.origin_x);
        let row = y.wrapping_add(m.origin_y);
        let (column, phase) = if m.flags & FLAG_CELLS != 0 {
            let up = m.panel_top.wrapping_sub(row);
            let cell = cell_index(m.cell_pattern, px, up) as usize;
            let phases = [m.cell_r, m.cell_g, m.cell_b];
            (px, phases[slot as usize][cell])
        } else if m.flags & FLAG_SUBPIXEL != 0 {
            (px.wrapping_mul(3).wrapping_add(slot), m.phase)
        } else {
            (px, m.phase)
        };
        let t = column
            .wrapping_mul(m.step_column)
            .wrapping_add(row.wrapping_mul(m.step_row))
            .wrapping_add(phase);
        let v = mul_high(t, m.views);
        if m.flags & FLAG_FLIP != 0 {
            m.views - 1 - v
        } else {
            v
        }
    }

    /// The three channel views of pixel (x, y).
    pub fn pixel_views(&self, x: u32, y: u32) -> [u32; 3] {
        [self.view(x, y, 0), self.view(x, y, 1), self.view(x, y, 2)]
    }
}

/// The cell index 0…3 of panel column `x`, row `up` from the bottom, for `CellPatternMode`
/// `pattern` (`subpixel_cells.rs`; `mask_cell` in `wgsl/shared/mask.wgsl`).
#[inline]
fn cell_index(pattern: u32, x: u32, up: u32) -> u32 {
    match pattern {
        1 => (x ^ up) & 1,
        2 => x & 1,
        3 => up.wrapping_add(2 * (x & 1)) & 3,
        4 => up & 1,
        _ => 0,
    }
}

/// `(t · n) >> 32` with 16-bit halves, as WGSL has no 64-bit integers in its base.
#[inline]
fn mul_high(t: u32, n: u32) -> u32 {
    let hi = (t >> 16) * n;
    let lo = ((t & 0xffff) * n) >> 16;
    (hi + lo) >> 16
}

/// The paper's Eq. 4–6 on integer indices (docs/DESIGN.md §1), `y` top-down on the panel
/// (origin already added). Used to prove that `hubner8` equals the slanted model.
pub fn hubner8_paper_view(x: u32, y: u32, c: u32) -> u32 {
    let x_offset = (3 * x) % 8;
    let y_offset = (y + 1) % 12;
    let v_r = ((1 + y_offset + y_offset / 3) / 2 + x_offset) % 8;
    (v_r + c) % 8
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mul_high_is_exact() {
        for &t in &[
            0u32,
            1,
            0xffff,
            0x1_0000,
            0x8000_0000,
            u32::MAX,
            123_456_789,
        ] {
            for &n in &[1u32, 2, 3, 8, 45, 64, 256, 65535] {
                assert_eq!(mul_high(t, n) as u64, (t as u64 * n as u64) >> 32);
            }
        }
    }

    #[test]
    fn fixed_frac_rounds_up() {
        assert_eq!(fixed_frac_ceil(0.5), 1 << 31);
        assert_eq!(fixed_frac_ceil(1.25), 1 << 30);
        assert_eq!(fixed_frac_ceil(-0.25), 3 << 30);
        assert!(fixed_frac_ceil(1.0 / 3.0) as f64 >= 4_294_967_296.0 / 3.0);
    }
}
