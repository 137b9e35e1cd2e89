//! Built-in data sets generated in code: a CT-like head phantom and the Marschner–Lobb signal.

use super::Volume;
use crate::error::Result;

/// A CT-like head: skin, skull, brain with ventricles, a few dense lesions, on a `n³` grid with
/// slightly anisotropic spacing (z 1.25× coarser, as CT slices often are).
pub fn ct_head(n: u32) -> Result<Volume> {
    let n = n.max(4);
    let nz = ((n as f32) / 1.25).round().max(4.0) as u32;
    let spacing = [1.0, 1.0, 1.25];
    let mut data = Vec::with_capacity((n * n * nz) as usize);
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

fn head_density(p: [f32; 3]) -> f32 {
    let outer = ellipsoid(p, [0.0, 0.0, 0.0], [0.72, 0.88, 0.8]);
    if outer > 1.0 {
        return 0.0; // air
    }
    let skull_outer = ellipsoid(p, [0.0, 0.0, 0.0], [0.66, 0.82, 0.74]);
    let skull_inner = ellipsoid(p, [0.0, 0.0, 0.0], [0.6, 0.76, 0.68]);
    if skull_outer > 1.0 {
        return 0.3; // skin and soft tissue
    }
    if skull_inner > 1.0 {
        return 0.95; // bone
    }
    for c in [[0.25, 0.3, 0.1], [-0.3, -0.2, -0.2], [0.1, -0.4, 0.35]] {
        if ellipsoid(p, c, [0.08, 0.08, 0.08]) < 1.0 {
            return 0.75; // dense lesions
        }
    }
    for side in [-0.12f32, 0.12] {
        if ellipsoid(p, [side, 0.05, 0.0], [0.07, 0.3, 0.12]) < 1.0 {
            return 0.1; // ventricles (fluid)
        }
    }
    0.45 + 0.05 * (6.0 * p[0]).sin() * (5.0 * p[1]).cos() // brain with a little texture
}

/// The Marschner–Lobb test signal (f_M = 6, α = 0.25) on an `n³` grid over [−1, 1]³, the
/// standard stress test for reconstruction and sampling.
pub fn marschner_lobb(n: u32) -> Result<Volume> {
    let n = n.max(2);
    let (fm, alpha) = (6.0f32, 0.25f32);
    let pi = std::f32::consts::PI;
    let mut data = Vec::with_capacity((n * n * n) as usize);
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
    }
}
