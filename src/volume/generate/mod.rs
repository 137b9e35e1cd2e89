//! Built-in data sets generated in code: a CT-like head and the Marschner–Lobb signal.

mod head;

use super::{check_dims, Volume};
use crate::error::Result;

/// A contrast CT of a head and neck (face, skull, teeth, spine, arteries, folded brain; see
/// `head.rs`) on a `n³` grid with slightly anisotropic spacing (z 1.25× coarser, as CT slices
/// often are).
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
                data.push(head::density(p));
            }
        }
    }
    Volume::new([n, n, nz], spacing, data)
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
