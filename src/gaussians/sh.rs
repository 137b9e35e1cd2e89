//! Real spherical harmonics as graphdeco's 3DGS renderer evaluates them
//! (`computeColorFromSH` in diff-gaussian-rasterization's `forward.cu`): degree 0 to 3, 16
//! coefficients per channel, DC first. The GPU shader mirrors [`eval`]; the renderer adds 0.5
//! to the sum and clamps at 0.

use glam::Vec3;

/// Degree 0: `1 / (2√π)`.
pub const SH_C0: f32 = 0.282_094_8;
/// Degree 1: `√3 / (2√π)`.
pub const SH_C1: f32 = 0.488_602_52;
/// Degree 2, coefficients 4 to 8.
pub const SH_C2: [f32; 5] = [
    1.092_548_5,
    -1.092_548_5,
    0.315_391_57,
    -1.092_548_5,
    0.546_274_24,
];
/// Degree 3, coefficients 9 to 15.
pub const SH_C3: [f32; 7] = [
    -0.590_043_6,
    2.890_611_4,
    -0.457_045_8,
    0.373_176_34,
    -0.457_045_8,
    1.445_305_7,
    -0.590_043_6,
];

/// The SH sum `Σ_k c_k·Y_k(dir)` of the first `(degree + 1)²` of `coeffs` (RGB triples, DC
/// first) for the unit direction from the camera centre to the Gaussian's mean (`dir` is
/// normalised here; a zero `dir` leaves the DC term). The raw sum: the renderers' colour is
/// `max(eval + 0.5, 0)`.
///
/// Panics when `coeffs` has fewer than `(degree + 1)²` triples.
pub fn eval(degree: u32, coeffs: &[[f32; 3]], dir: Vec3) -> Vec3 {
    let c = |k: usize| Vec3::from_array(coeffs[k]);
    let mut sum = SH_C0 * c(0);
    if degree == 0 {
        return sum;
    }
    let Vec3 { x, y, z } = dir.normalize_or_zero();
    sum += SH_C1 * (-y * c(1) + z * c(2) - x * c(3));
    if degree == 1 {
        return sum;
    }
    let (xx, yy, zz) = (x * x, y * y, z * z);
    let (xy, yz, xz) = (x * y, y * z, x * z);
    sum += SH_C2[0] * xy * c(4)
        + SH_C2[1] * yz * c(5)
        + SH_C2[2] * (2.0 * zz - xx - yy) * c(6)
        + SH_C2[3] * xz * c(7)
        + SH_C2[4] * (xx - yy) * c(8);
    if degree == 2 {
        return sum;
    }
    sum + SH_C3[0] * y * (3.0 * xx - yy) * c(9)
        + SH_C3[1] * xy * z * c(10)
        + SH_C3[2] * y * (4.0 * zz - xx - yy) * c(11)
        + SH_C3[3] * z * (2.0 * zz - 3.0 * xx - 3.0 * yy) * c(12)
        + SH_C3[4] * x * (4.0 * zz - xx - yy) * c(13)
        + SH_C3[5] * z * (xx - yy) * c(14)
        + SH_C3[6] * x * (xx - 3.0 * yy) * c(15)
}

/// The DC coefficient whose colour (`SH_C0·dc + 0.5`) is `color`.
pub fn dc_from_color(color: f32) -> f32 {
    (color - 0.5) / SH_C0
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each basis function integrates to 0 against every other and to 1 against itself over the
    /// sphere (orthonormal): checked by quadrature, so a wrong constant or sign pattern shows.
    #[test]
    fn the_basis_is_orthonormal() {
        let basis = |k: usize, dir: Vec3| {
            let mut coeffs = [[0.0f32; 3]; 16];
            coeffs[k] = [1.0; 3];
            eval(3, &coeffs, dir).x as f64
        };
        let (n_theta, n_phi) = (96, 192);
        let mut gram = [[0.0f64; 16]; 16];
        for i in 0..n_theta {
            let theta = (i as f64 + 0.5) * std::f64::consts::PI / n_theta as f64;
            for j in 0..n_phi {
                let phi = (j as f64 + 0.5) * std::f64::consts::TAU / n_phi as f64;
                let dir = Vec3::new(
                    (theta.sin() * phi.cos()) as f32,
                    (theta.sin() * phi.sin()) as f32,
                    theta.cos() as f32,
                );
                let weight = theta.sin()
                    * (std::f64::consts::PI / n_theta as f64)
                    * (std::f64::consts::TAU / n_phi as f64);
                let values: Vec<f64> = (0..16).map(|k| basis(k, dir)).collect();
                for a in 0..16 {
                    for b in 0..16 {
                        gram[a][b] += values[a] * values[b] * weight;
                    }
                }
            }
        }
        for (a, row) in gram.iter().enumerate() {
            for (b, v) in row.iter().enumerate() {
                let want = if a == b { 1.0 } else { 0.0 };
                assert!((v - want).abs() < 2e-3, "<Y{a}, Y{b}> = {v}");
            }
        }
    }

    #[test]
    fn degrees_use_only_their_coefficients() {
        let coeffs: Vec<[f32; 3]> = (0..16).map(|k| [k as f32, 1.0, -1.0]).collect();
        let dir = Vec3::new(0.3, -0.5, 0.8);
        assert_eq!(eval(0, &coeffs, dir), SH_C0 * Vec3::new(0.0, 1.0, -1.0));
        // Degree 1 along +z: only Y2 = C1·z is non-zero.
        let e = eval(1, &coeffs, Vec3::Z) - eval(0, &coeffs, Vec3::Z);
        assert!((e - SH_C1 * Vec3::new(2.0, 1.0, -1.0)).length() < 1e-6);
        assert_eq!(eval(2, &coeffs[..9], dir), eval(2, &coeffs, dir));
        assert!((dc_from_color(0.5 + SH_C0 * 0.7) - 0.7).abs() < 1e-6);
    }
}
