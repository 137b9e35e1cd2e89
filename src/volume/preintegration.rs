//! The pre-integration table of a transfer function (Engel, Kraus & Ertl 2001): each slab's
//! colour and opacity between a front and a back scalar, made once per transfer function and
//! step, looked up by the march instead of integrating per sample.

use super::transfer::TransferFunction;
use crate::error::{Error, Result};
use crate::param::Param;

/// Entries per axis of the pre-integration table.
pub const TABLE_SIZE: usize = 256;

/// Premultiplied RGBA of a slab between front scalar `sf` (row) and back scalar `sb` (column),
/// for a slab `step` voxels thick: `α = 1 − exp(−Δ·∫τ/(sb − sf))` with extinction
/// `τ = −ln(1 − a)` per voxel, colour = α × the τ-weighted mean colour over [sf, sb].
#[derive(Clone, Debug, PartialEq)]
pub struct PreintegrationTable {
    /// `TABLE_SIZE²` entries, index `front · TABLE_SIZE + back`.
    pub rgba: Vec<[f32; 4]>,
    /// Slab thickness in voxels the table was made for.
    pub step: f32,
}

impl PreintegrationTable {
    /// Build the table for `tf` at sampling distance `step` (voxels).
    pub fn new(tf: &TransferFunction, step: f32) -> Result<Self> {
        tf.validate()?;
        if !(step.is_finite() && step > 0.0) {
            return Err(Error::invalid(
                Param::SamplingStep,
                format!("{step}: must be positive"),
            ));
        }
        // Prefix integrals of τ and τ·c over the table's scalar grid (trapezoid rule on a grid
        // 4× finer than the table).
        const FINE: usize = 4 * (TABLE_SIZE - 1);
        let mut tau_int = vec![0.0f64; FINE + 1];
        let mut col_int = vec![[0.0f64; 3]; FINE + 1];
        let sample = |i: usize| {
            let c = tf.eval(i as f32 / FINE as f32);
            let tau = -(1.0 - c[3].min(0.9999) as f64).ln();
            (
                tau,
                [c[0] as f64 * tau, c[1] as f64 * tau, c[2] as f64 * tau],
            )
        };
        let mut prev = sample(0);
        for i in 1..=FINE {
            let cur = sample(i);
            let h = 1.0 / FINE as f64;
            tau_int[i] = tau_int[i - 1] + 0.5 * h * (prev.0 + cur.0);
            col_int[i] = [0, 1, 2].map(|k| col_int[i - 1][k] + 0.5 * h * (prev.1[k] + cur.1[k]));
            prev = cur;
        }
        let mut rgba = Vec::with_capacity(TABLE_SIZE * TABLE_SIZE);
        for f in 0..TABLE_SIZE {
            for b in 0..TABLE_SIZE {
                let (i, j) = (f * 4, b * 4);
                let ds = (j as f64 - i as f64) / FINE as f64;
                let (tau_mean, col_mean) = if ds.abs() < 1e-9 {
                    let (t, c) = sample(i);
                    (t, if t > 0.0 { c.map(|v| v / t) } else { [0.0; 3] })
                } else {
                    let dt = (tau_int[j] - tau_int[i]) / ds;
                    let dc = [0, 1, 2].map(|k| (col_int[j][k] - col_int[i][k]) / ds);
                    (
                        dt,
                        if dt.abs() > 1e-12 {
                            dc.map(|v| v / dt)
                        } else {
                            [0.0; 3]
                        },
                    )
                };
                let alpha = 1.0 - (-tau_mean.max(0.0) * step as f64).exp();
                rgba.push([
                    (col_mean[0] * alpha) as f32,
                    (col_mean[1] * alpha) as f32,
                    (col_mean[2] * alpha) as f32,
                    alpha as f32,
                ]);
            }
        }
        Ok(Self { rgba, step })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constant_segment_matches_the_closed_form() {
        let tf = TransferFunction::new(vec![(0.0, [1.0, 0.5, 0.25, 0.2])]).unwrap();
        let table = PreintegrationTable::new(&tf, 2.0).unwrap();
        let alpha = 1.0 - (1.0f32 - 0.2).powf(2.0);
        for e in [table.rgba[0], table.rgba[TABLE_SIZE * 37 + 200]] {
            assert!((e[3] - alpha).abs() < 1e-4, "{e:?}");
            assert!((e[0] - alpha).abs() < 1e-4 && (e[1] - 0.5 * alpha).abs() < 1e-4);
        }
    }

    #[test]
    fn premultiplied_colour_never_exceeds_alpha() {
        let tf = TransferFunction::preset("ct-skin").unwrap();
        let table = PreintegrationTable::new(&tf, 0.5).unwrap();
        assert!(table
            .rgba
            .iter()
            .all(|e| e.iter().all(|v| v.is_finite()) && e[0] <= e[3] + 1e-5));
    }
}
