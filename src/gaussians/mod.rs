//! 3D Gaussian splats (3DGS, Kerbl et al. 2023): the scenes graphdeco's trainer, Polycam, Luma,
//! Scaniverse and SuperSplat make. Data and loaders: [`Gaussians`] (what every file becomes),
//! [`load`] (graphdeco `.ply`, antimatter15 `.splat`, Niantic `.spz`) and [`sh`] (graphdeco's
//! real spherical harmonics, the colour rule the renderers share). docs/GAUSSIANS.md.
//!
//! The arrays are flat and `bytemuck::Pod` element by element (`Vec3`, `Quat`, `f32`,
//! `[f32; 3]`), so a GPU scene uploads each as it is.

mod generate;
pub mod load;
mod options;
pub(crate) mod passes;
pub mod scene;
pub mod sh;

pub use options::GaussianOptions;
pub use passes::{cpu_order, GaussianSplatter, SortOn};
pub use scene::GaussianScene;

use std::path::Path;

use glam::{Mat3, Quat, Vec3};

use crate::camera::Bounds;
use crate::error::{Error, Result};
use crate::param::Param;
use crate::render::Method;

/// The methods that render 3D Gaussian splats; [`GaussianSplatter::new`] refuses the others
/// with the reason.
pub const METHODS: [Method; 4] = [
    Method::SinglePass,
    Method::NPass,
    Method::SingleView,
    Method::Tiled,
];

/// Highest spherical-harmonics degree read (graphdeco's trainer stops at 3; `.spz` degree 4 is
/// refused by name).
pub const MAX_SH_DEGREE: u32 = 3;

/// Most Gaussians a scene may have (GPU indices are u32, six vertices per Gaussian's quad).
pub const MAX_GAUSSIANS: usize = (u32::MAX / 6) as usize;

/// 3D Gaussians as the renderers use them: activated values, not the trainer's raw parameters
/// (the loaders apply the sigmoid to opacities, `exp` to log scales and normalise rotations).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Gaussians {
    /// Means, world space.
    pub positions: Vec<Vec3>,
    /// Standard deviations along the Gaussian's own axes (linear, ≥ 0).
    pub scales: Vec<Vec3>,
    /// Unit rotations of the Gaussian's axes (a file's `(w, x, y, z)` as `Quat::from_xyzw(x,
    /// y, z, w)`).
    pub rotations: Vec<Quat>,
    /// Opacity after the sigmoid, in [0, 1].
    pub opacities: Vec<f32>,
    /// Spherical-harmonics degree, 0 to [`MAX_SH_DEGREE`].
    pub sh_degree: u32,
    /// SH coefficients as RGB triples, coefficient-major per Gaussian: Gaussian `i`'s are
    /// `sh[i·K .. (i+1)·K]` with `K = (sh_degree + 1)²`, DC first, then graphdeco's order
    /// (`sh::eval`).
    pub sh: Vec<[f32; 3]>,
}

impl Gaussians {
    /// Load a graphdeco `.ply`, antimatter15 `.splat` or Niantic `.spz` file, told by its first
    /// bytes, else its extension ([`crate::formats`]); a file of another kind (a point-cloud
    /// PLY, a mesh) is refused as what it is (`Error::WrongKind`).
    pub fn load(path: &Path) -> Result<Self> {
        load::load(path)
    }

    /// Number of Gaussians.
    pub fn len(&self) -> usize {
        self.positions.len()
    }

    /// No Gaussians.
    pub fn is_empty(&self) -> bool {
        self.positions.is_empty()
    }

    /// SH coefficients per Gaussian: `(sh_degree + 1)²`.
    pub fn coefficients(&self) -> usize {
        coefficients(self.sh_degree)
    }

    /// Gaussian `i`'s SH coefficients (DC first).
    pub fn sh_of(&self, i: usize) -> &[[f32; 3]] {
        let k = self.coefficients();
        &self.sh[i * k..(i + 1) * k]
    }

    /// The Gaussians whose means lie inside `keep` (faces included: floaters around a capture
    /// go); refused naming the crop box where it keeps none.
    pub fn cropped(&self, keep: Bounds) -> Result<Self> {
        use crate::camera::crop_box::pick;
        let kept = keep.kept(&self.positions, "Gaussians")?;
        let k = self.coefficients();
        Ok(Self {
            positions: pick(&self.positions, &kept),
            scales: pick(&self.scales, &kept),
            rotations: pick(&self.rotations, &kept),
            opacities: pick(&self.opacities, &kept),
            sh_degree: self.sh_degree,
            sh: kept
                .iter()
                .flat_map(|&i| self.sh[i * k..(i + 1) * k].iter().copied())
                .collect(),
        })
    }

    /// Bounding box of the means; `None` when empty or not finite.
    pub fn bounds(&self) -> Option<Bounds> {
        Bounds::of_points(self.positions.iter().copied())
    }

    /// Gaussian `i`'s 3D covariance `Σ = R S Sᵀ Rᵀ` (R its rotation, S = diag(scale)).
    pub fn covariance(&self, i: usize) -> Mat3 {
        let m = Mat3::from_quat(self.rotations[i]) * Mat3::from_diagonal(self.scales[i]);
        m * m.transpose()
    }

    /// Check lengths and values: at least one Gaussian, at most [`MAX_GAUSSIANS`], degree ≤ 3,
    /// every array as long as the positions (the SH `(degree + 1)²` times), finite values,
    /// scales ≥ 0, unit rotations, opacities in [0, 1].
    pub fn validate(&self) -> Result<()> {
        match self.problem() {
            Some(reason) => Err(Error::invalid(Param::Gaussians, reason)),
            None => Ok(()),
        }
    }

    /// What [`Gaussians::validate`] refuses, in words (the loaders add the file).
    pub(crate) fn problem(&self) -> Option<String> {
        let n = self.len();
        if n == 0 {
            return Some("no Gaussians".into());
        }
        if n > MAX_GAUSSIANS {
            return Some(format!(
                "{n} Gaussians: at most {MAX_GAUSSIANS} are supported"
            ));
        }
        if self.sh_degree > MAX_SH_DEGREE {
            return Some(format!(
                "SH degree {}: at most {MAX_SH_DEGREE} is supported",
                self.sh_degree
            ));
        }
        let lengths = [
            self.scales.len(),
            self.rotations.len(),
            self.opacities.len(),
        ];
        if lengths.iter().any(|&l| l != n) {
            return Some(format!(
                "{n} positions but {} scales, {} rotations, {} opacities",
                lengths[0], lengths[1], lengths[2]
            ));
        }
        let k = self.coefficients();
        if self.sh.len() != n.saturating_mul(k) {
            return Some(format!(
                "{} SH coefficients: degree {} needs {k} per Gaussian, {} in all",
                self.sh.len(),
                self.sh_degree,
                n.saturating_mul(k)
            ));
        }
        let bad = |what: &str, i: usize| Some(format!("Gaussian {i} has {what}"));
        if let Some(i) = self.positions.iter().position(|p| !p.is_finite()) {
            return bad("a non-finite position", i);
        }
        if let Some(i) = self
            .scales
            .iter()
            .position(|s| !(s.is_finite() && s.min_element() >= 0.0))
        {
            return bad("a negative or non-finite scale", i);
        }
        if let Some(i) = self
            .rotations
            .iter()
            .position(|q| !(q.is_finite() && (q.length_squared() - 1.0).abs() <= 1e-3))
        {
            return bad("a rotation that is not a unit quaternion", i);
        }
        if let Some(i) = self.opacities.iter().position(|o| !(0.0..=1.0).contains(o)) {
            return bad("an opacity outside [0, 1]", i);
        }
        if let Some(j) = self
            .sh
            .iter()
            .position(|c| !c.iter().all(|v| v.is_finite()))
        {
            return bad("a non-finite SH coefficient", j / k);
        }
        None
    }
}

/// SH coefficients per Gaussian at `degree`: `(degree + 1)²`.
pub fn coefficients(degree: u32) -> usize {
    let d = degree as usize + 1;
    d * d
}

/// CPU bytes of one Gaussian at SH `degree` in [`Gaussians`]: 44 + 12·(degree + 1)².
pub fn bytes_per_gaussian(degree: u32) -> u64 {
    (12 + 12 + 16 + 4 + 12 * coefficients(degree)) as u64
}

/// `Err(MemoryBudget)` when `count` Gaussians of SH `degree`, plus `extra` bytes a loader holds
/// at the same time (a decompressed stream), exceed the budget (`crate::budget`). The figure
/// is twice the CPU arrays — the data and its GPU copy, which a software adapter keeps in RAM
/// — until a renderer's peak is measured.
pub(crate) fn check_budget(count: u64, degree: u32, extra: u64) -> Result<()> {
    let bytes = count
        .saturating_mul(2 * bytes_per_gaussian(degree))
        .saturating_add(extra);
    crate::budget::check(
        || {
            format!(
                "{count} Gaussians of SH degree {degree} × {} bytes, data and GPU copy",
                bytes_per_gaussian(degree)
            )
        },
        bytes,
    )
}

/// The unit rotation of a file's (or an array's) `(w, x, y, z)` for Gaussian `i`; `Err` for a zero or non-finite quaternion.
pub fn unit_rotation(
    i: usize,
    w: f32,
    x: f32,
    y: f32,
    z: f32,
) -> std::result::Result<glam::Quat, String> {
    let q = glam::Quat::from_xyzw(x, y, z, w);
    let length = q.length();
    if !(length.is_finite() && length > 1e-12) {
        return Err(format!(
            "Gaussian {i} has a zero or non-finite rotation quaternion (w, x, y, z) = ({w}, {x}, {y}, {z})"
        ));
    }
    Ok(q / length)
}

/// The logistic sigmoid `1 / (1 + e^−x)`: a trainer's opacity logit → opacity.
pub fn sigmoid(x: f32) -> f32 {
    1.0 / (1.0 + (-x).exp())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn one(scale: Vec3, rotation: Quat) -> Gaussians {
        Gaussians {
            positions: vec![Vec3::ZERO],
            scales: vec![scale],
            rotations: vec![rotation],
            opacities: vec![0.5],
            sh_degree: 0,
            sh: vec![[0.0; 3]],
        }
    }

    #[test]
    fn covariance_is_r_s_st_rt() {
        let g = one(Vec3::new(2.0, 1.0, 0.5), Quat::IDENTITY);
        assert_eq!(
            g.covariance(0),
            Mat3::from_diagonal(Vec3::new(4.0, 1.0, 0.25))
        );
        // A quarter turn about z swaps the x and y variances.
        let turned = one(
            Vec3::new(2.0, 1.0, 0.5),
            Quat::from_rotation_z(std::f32::consts::FRAC_PI_2),
        );
        let c = turned.covariance(0);
        assert!((c.x_axis.x - 1.0).abs() < 1e-6 && (c.y_axis.y - 4.0).abs() < 1e-6);
        assert!(c.x_axis.y.abs() < 1e-6 && (c.z_axis.z - 0.25).abs() < 1e-6);
        // Symmetric for any rotation.
        let any = one(
            Vec3::new(0.3, 0.1, 0.05),
            Quat::from_xyzw(0.3, -0.2, 0.7, 0.5).normalize(),
        );
        let c = any.covariance(0);
        assert!(c.abs_diff_eq(c.transpose(), 1e-7));
    }

    #[test]
    fn validate_names_the_problem() {
        assert!(one(Vec3::ONE, Quat::IDENTITY).validate().is_ok());
        let mut g = one(Vec3::ONE, Quat::IDENTITY);
        g.sh_degree = 1;
        let e = g.validate().unwrap_err().to_string();
        assert!(e.contains("degree 1 needs 4 per Gaussian"), "{e}");
        g.sh_degree = 4;
        assert!(g.validate().unwrap_err().to_string().contains("at most 3"));
        let e = one(Vec3::new(1.0, -1.0, 1.0), Quat::IDENTITY)
            .validate()
            .unwrap_err()
            .to_string();
        assert!(e.contains("Gaussian 0 has a negative"), "{e}");
        let e = one(Vec3::ONE, Quat::from_xyzw(0.0, 0.0, 0.0, 2.0))
            .validate()
            .unwrap_err()
            .to_string();
        assert!(e.contains("unit quaternion"), "{e}");
        let mut g = one(Vec3::ONE, Quat::IDENTITY);
        g.opacities[0] = f32::NAN;
        assert!(g.validate().unwrap_err().to_string().contains("opacity"));
        g.opacities.clear();
        assert!(g
            .validate()
            .unwrap_err()
            .to_string()
            .contains("0 opacities"));
        assert!(Gaussians::default()
            .validate()
            .unwrap_err()
            .to_string()
            .contains("no Gaussians"));
    }

    #[test]
    fn bounds_are_the_means() {
        let mut g = one(Vec3::splat(10.0), Quat::IDENTITY);
        g.positions.push(Vec3::new(1.0, 2.0, -3.0));
        let b = g.bounds().unwrap();
        assert_eq!(b.min, Vec3::new(0.0, 0.0, -3.0));
        assert_eq!(b.max, Vec3::new(1.0, 2.0, 0.0));
    }
}
