//! antimatter15's `.splat` (the WebGL viewer's format, written by its `convert.py`): no header,
//! 32 bytes per splat — position 3×f32 LE, linear scale 3×f32, RGBA 4×u8 (RGB the colour
//! `0.5 + SH_C0·f_dc`, A the opacity after the sigmoid, both ×255) and the unit rotation 4×u8
//! as `(q + 1)·128` in the order w, x, y, z. SH degree 0.

use std::path::Path;

use glam::Vec3;

use super::{checked, error, rotation};
use crate::error::Result;
use crate::gaussians::sh::dc_from_color;
use crate::gaussians::{check_budget, Gaussians};

/// Bytes per splat.
pub const SPLAT_BYTES: usize = 32;

/// A `.splat` file's `bytes` (`path` names it in errors).
pub fn parse_splat(bytes: &[u8], path: &Path) -> Result<Gaussians> {
    let fail = |reason: String| error(path, reason);
    if !bytes.len().is_multiple_of(SPLAT_BYTES) {
        return Err(fail(format!(
            "{} bytes: not a whole number of {SPLAT_BYTES}-byte splats (a cut file?)",
            bytes.len()
        )));
    }
    let n = bytes.len() / SPLAT_BYTES;
    check_budget(n as u64, 0, 0).map_err(|e| fail(e.to_string()))?;
    let mut g = Gaussians {
        positions: Vec::with_capacity(n),
        scales: Vec::with_capacity(n),
        rotations: Vec::with_capacity(n),
        opacities: Vec::with_capacity(n),
        sh_degree: 0,
        sh: Vec::with_capacity(n),
    };
    for (i, s) in bytes.chunks_exact(SPLAT_BYTES).enumerate() {
        let f = |at: usize| f32::from_le_bytes(s[at..at + 4].try_into().expect("4 bytes"));
        g.positions.push(Vec3::new(f(0), f(4), f(8)));
        g.scales.push(Vec3::new(f(12), f(16), f(20)));
        g.sh.push([24, 25, 26].map(|at| dc_from_color(f32::from(s[at]) / 255.0)));
        g.opacities.push(f32::from(s[27]) / 255.0);
        let [w, x, y, z] = [28, 29, 30, 31].map(|at| (f32::from(s[at]) - 128.0) / 128.0);
        g.rotations.push(rotation(i, w, x, y, z).map_err(fail)?);
    }
    checked(g, path)
}
