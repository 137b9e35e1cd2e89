//! Built-in data sets generated in code: a CT-like head phantom and the Marschner–Lobb signal.

use super::{check_dims, Volume};
use crate::error::Result;

/// A CT-like head: skin, skull, brain with ventricles, a few dense lesions, on a `n³` grid with
/// slightly anisotropic spacing (z 1.25× coarser, as CT slices often are).
pub fn ct_head(n: u32) -> Result<Volume> {
    let n = n.max(4);
    let nz = ((n as f32) / 1.25).round().max(4.0) as u32;
    let spacing = [1.0, 1.0, 1.25];
    let count = check_dims([n, n, nz].map(u64::from))?;
    let mut data = Vec::with_capacity(count as usize);
    // Coordinates in [-1, 1] over the physical extent.
    for z in 0..nz {
        for y in 0..n {
            for x in 0..n {
                let p = [
                    (x as f32 + 0.5) / n as f32 * 2.0 - 1.0,
                    (y as f32 + 0.5) / n as f32 * 2.0 - 1.0,
                    (z as f32 + 0.5) / nz as f32 * 2.0 - 1.0,
                ];
                data.push(head_density(p));
            }
        }
    }
    Volume::new([n, n, nz], spacing, data)
}

/// Ellipsoid "radius" of p for semi-axes r around centre c (1 on the surface).
fn ellipsoid(p: [f32; 3], c: [f32; 3], r: [f32; 3]) -> f32 {
    let q = [0, 1, 2].map(|i| (p[i] - c[i]) / r[i]);
    (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]).sqrt()
}

/// 1 inside an ellipsoid, 0 outside, with a smooth shell (no staircase contours when shaded).
fn inside(r: f32) -> f32 {
    const SOFT: f32 = 0.04;
    let t = ((r - (1.0 - SOFT)) / (2.0 * SOFT)).clamp(0.0, 1.0);
    1.0 - t * t * (3.0 - 2.0 * t)
}

fn mix(a: f32, b: f32, t: f32) -> f32 {
    a + (b - a) * t
}

fn head_density(p: [f32; 3]) -> f32 {
    let origin = [0.0; 3];
    let brain = 0.45 + 0.05 * (6.0 * p[0]).sin() * (5.0 * p[1]).cos();
    // Layers from the outside in: skin and soft tissue, bone, brain with a little texture.
    let mut d = 0.3 * inside(ellipsoid(p, origin, [0.72, 0.88, 0.8]));
    d = mix(d, 0.95, inside(ellipsoid(p, origin, [0.66, 0.82, 0.74])));
    d = mix(d, brain, inside(ellipsoid(p, origin, [0.6, 0.76, 0.68])));
    for side in [-0.12f32, 0.12] {
        d = mix(
            d,
            0.1,
            inside(ellipsoid(p, [side, 0.05, 0.0], [0.07, 0.3, 0.12])),
        ); // ventricles
    }
    for c in [[0.25, 0.3, 0.1], [-0.3, -0.2, -0.2], [0.1, -0.4, 0.35]] {
        d = mix(d, 0.75, inside(ellipsoid(p, c, [0.08, 0.08, 0.08]))); // dense lesions
    }
    d
}

/// The Marschner–Lobb test signal (f_M = 6, α = 0.25) on an `n³` grid over [−1, 1]³, the
/// standard stress test for reconstruction and sampling.
pub fn marschner_lobb(n: u32) -> Result<Volume> {
    let n = n.max(2);
    let (fm, alpha) = (6.0f32, 0.25f32);
    let pi = std::f32::consts::PI;
    let count = check_dims([n; 3].map(u64::from))?;
    let mut data = Vec::with_capacity(count as usize);
    for z in 0..n {
        for y in 0..n {
            for x in 0..n {
                let c = |i: u32| (i as f32 + 0.5) / n as f32 * 2.0 - 1.0;
                let (x, y, z) = (c(x), c(y), c(z));
                let r = (x * x + y * y).sqrt();
                let rho_r = (2.0 * pi * fm * (pi * r / 2.0).cos()).cos();
                data.push(
                    (1.0 - (pi * z / 2.0).sin() + alpha * (1.0 + rho_r)) / (2.0 * (1.0 + alpha)),
                );
            }
        }
    }
    Volume::new([n, n, n], [1.0; 3], data)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn built_in_data_is_in_range_and_not_constant() {
        for v in [ct_head(32).unwrap(), marschner_lobb(24).unwrap()] {
            let (lo, hi) = v
                .data
                .iter()
                .fold((1.0f32, 0.0f32), |(l, h), &x| (l.min(x), h.max(x)));
            assert!(lo >= 0.0 && hi <= 1.0 && hi - lo > 0.5, "{lo}..{hi}");
        }
        assert_eq!(ct_head(32).unwrap().spacing, [1.0, 1.0, 1.25]);
        // Too many voxels (or a u32 overflow of n³) is an error before anything is allocated.
        assert!(ct_head(2000).is_err());
        assert!(marschner_lobb(u32::MAX).is_err());
    }
}
