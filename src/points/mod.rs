//! Point clouds for splatting: loading (PLY, OBJ vertices), generated test clouds, completion of
//! missing normals and radii ([`estimate`]), grouping ([`GroupCount`], [`Grouping`]) and GPU
//! upload ([`SplatScene`]).
//!
//! Data flows `PointCloud` (what the file has) → [`PointCloud::complete`] → [`Splats`] (every
//! attribute) → grouping (`groups.rs`) → [`SplatScene`] (on the GPU, sorted by group).

pub mod estimate;
mod generate;
mod grid;
pub(crate) mod groups;
mod load;
pub(crate) mod options;
pub(crate) mod passes;
mod scene;

use std::time::Instant;

use glam::Vec3;

pub use groups::{GroupCount, Grouping, MAX_AUTO_GROUPS, MAX_CANDIDATES};
#[cfg(feature = "las")]
pub use load::las;
pub use options::{PointOptions, SplatDepth, DEFAULT_EPSILON_FRACTION};
pub use passes::{PointSplatter, SplatOptions};
pub use scene::{GpuSplat, SplatScene};

use crate::camera::Bounds;
use crate::error::{Error, Result};
use crate::param::Param;
use crate::render::Method;

/// The methods that render point splats: all but [`Method::Mrt`], which [`PointSplatter::new`]
/// refuses with the reason (splat images cannot blend).
pub const METHODS: [Method; 6] = [
    Method::SinglePass,
    Method::NPass,
    Method::SingleView,
    Method::Tiled,
    Method::Layered,
    Method::Warp,
];

/// Colour of points whose file has none.
pub const DEFAULT_COLOR: [f32; 3] = [0.8, 0.8, 0.8];

/// Points as a file gives them: positions, and whichever attributes it has.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PointCloud {
    /// Positions.
    pub positions: Vec<Vec3>,
    /// Normals (any length; normalised on use), if given.
    pub normals: Option<Vec<Vec3>>,
    /// Linear RGB colours in [0, 1], if given.
    pub colors: Option<Vec<[f32; 3]>>,
    /// Splat radii, if given.
    pub radii: Option<Vec<f32>>,
}

/// Splats with every attribute present.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Splats {
    /// Centres.
    pub positions: Vec<Vec3>,
    /// Unit normals (orientation free: shading is two-sided).
    pub normals: Vec<Vec3>,
    /// Linear RGB.
    pub colors: Vec<[f32; 3]>,
    /// Disk radii (0 = invisible).
    pub radii: Vec<f32>,
}

/// What [`PointCloud::complete`] did, and how long it took.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Completion {
    /// Normals were estimated (k-NN PCA).
    pub normals_estimated: bool,
    /// Radii were estimated (local spacing).
    pub radii_estimated: bool,
    /// Time of the neighbour search and estimation, ms (0 when nothing was estimated).
    pub estimate_ms: f64,
}

impl PointCloud {
    /// Number of points.
    pub fn len(&self) -> usize {
        self.positions.len()
    }

    /// No points.
    pub fn is_empty(&self) -> bool {
        self.positions.is_empty()
    }

    /// Bounding box; `None` when empty.
    pub fn bounds(&self) -> Option<Bounds> {
        Bounds::of_points(self.positions.iter().copied())
    }

    /// The points inside `keep` (faces included) with their attributes; refused naming the
    /// crop box where it keeps none.
    pub fn cropped(&self, keep: Bounds) -> Result<Self> {
        use crate::camera::crop_box::pick;
        let kept = keep.kept(&self.positions, "points")?;
        Ok(Self {
            positions: pick(&self.positions, &kept),
            normals: self.normals.as_deref().map(|v| pick(v, &kept)),
            colors: self.colors.as_deref().map(|v| pick(v, &kept)),
            radii: self.radii.as_deref().map(|v| pick(v, &kept)),
        })
    }

    /// Check lengths and that everything is finite (radii also ≥ 0).
    pub fn validate(&self) -> Result<()> {
        let n = self.len();
        let fail = |reason: String| Error::invalid(Param::PointCloud, reason);
        if n == 0 {
            return Err(fail("no points".into()));
        }
        if n > MAX_POINTS {
            return Err(fail(format!(
                "{n} points: at most {MAX_POINTS} are supported"
            )));
        }
        if let Some(i) = self
            .colors
            .iter()
            .flatten()
            .position(|c| !c.iter().all(|v| v.is_finite()))
        {
            return Err(fail(format!("point {i} has a non-finite colour")));
        }
        let lengths = [
            self.normals.as_ref().map(Vec::len),
            self.colors.as_ref().map(Vec::len),
            self.radii.as_ref().map(Vec::len),
        ];
        if lengths.iter().flatten().any(|&l| l != n) {
            return Err(fail(format!(
                "{n} positions but attribute lengths {lengths:?}"
            )));
        }
        if let Some(i) = self.positions.iter().position(|p| !p.is_finite()) {
            return Err(fail(format!("point {i} has a non-finite position")));
        }
        if let Some(i) = self.normals.iter().flatten().position(|v| !v.is_finite()) {
            return Err(fail(format!("point {i} has a non-finite normal")));
        }
        if let Some(i) = self
            .radii
            .iter()
            .flatten()
            .position(|r| !(r.is_finite() && *r >= 0.0))
        {
            return Err(fail(format!(
                "point {i} has a negative or non-finite radius"
            )));
        }
        Ok(())
    }

    /// Every attribute present: missing normals and radii estimated from the 8 nearest
    /// neighbours, zero-length normals replaced by estimates too, missing colours
    /// [`DEFAULT_COLOR`]; radii multiplied by `radius_scale`.
    pub fn complete(&self, radius_scale: f32) -> Result<(Splats, Completion)> {
        self.validate()?;
        if !(radius_scale.is_finite() && radius_scale >= 0.0) {
            return Err(Error::invalid(
                Param::RadiusScale,
                format!("{radius_scale}: must be finite and ≥ 0"),
            ));
        }
        // Zero, denormal-short or overflowing normals cannot be normalised: estimate those.
        let bad_normal =
            |n: &Vec3| !(n.length_squared() >= 1e-24 && n.length_squared().is_finite());
        let estimate_normals = self
            .normals
            .as_ref()
            .is_none_or(|v| v.iter().any(bad_normal));
        let estimate_radii = self.radii.is_none();
        let mut completion = Completion {
            normals_estimated: estimate_normals,
            radii_estimated: estimate_radii,
            estimate_ms: 0.0,
        };
        let (estimated_normals, estimated_radii) = if estimate_normals || estimate_radii {
            let start = Instant::now();
            let e = estimate::normals_and_radii(&self.positions);
            completion.estimate_ms = start.elapsed().as_secs_f64() * 1e3;
            e
        } else {
            (Vec::new(), Vec::new())
        };
        let normals = match &self.normals {
            Some(given) => given
                .iter()
                .enumerate()
                .map(|(i, n)| match bad_normal(n) {
                    true => estimated_normals[i],
                    false => n.normalize(),
                })
                .collect(),
            None => estimated_normals,
        };
        let radii = self.radii.clone().unwrap_or(estimated_radii);
        let splats = Splats {
            positions: self.positions.clone(),
            normals,
            colors: self
                .colors
                .clone()
                .unwrap_or_else(|| vec![DEFAULT_COLOR; self.len()]),
            radii: radii.iter().map(|r| r * radius_scale).collect(),
        };
        splats.validate()?;
        Ok((splats, completion))
    }
}

/// Most points a cloud may have (GPU indices are u32, six vertices per splat).
pub const MAX_POINTS: usize = (u32::MAX / 6) as usize;

pub use crate::budget::PEAK_BYTES_PER_POINT;

impl Splats {
    /// Check lengths, that everything is finite, radii ≥ 0 and the point count.
    pub fn validate(&self) -> Result<()> {
        let n = self.positions.len();
        let fail = |reason: String| Error::invalid(Param::Splats, reason);
        if n == 0 {
            return Err(fail("no splats".into()));
        }
        if n > MAX_POINTS {
            return Err(fail(format!(
                "{n} splats: at most {MAX_POINTS} are supported"
            )));
        }
        let lengths = [self.normals.len(), self.colors.len(), self.radii.len()];
        if lengths.iter().any(|&l| l != n) {
            return Err(fail(format!(
                "{n} positions but normals/colours/radii {lengths:?}"
            )));
        }
        let bad = (0..n).find(|&i| {
            !(self.positions[i].is_finite()
                && self.normals[i].is_finite()
                && self.colors[i].iter().all(|c| c.is_finite())
                && self.radii[i].is_finite()
                && self.radii[i] >= 0.0)
        });
        match bad {
            Some(i) => Err(fail(format!(
                "splat {i} has a non-finite value or a negative radius (radius {})",
                self.radii[i]
            ))),
            None => Ok(()),
        }
    }

    /// Number of splats.
    pub fn len(&self) -> usize {
        self.positions.len()
    }

    /// No splats.
    pub fn is_empty(&self) -> bool {
        self.positions.is_empty()
    }

    /// Bounding box of the centres; `None` when empty.
    pub fn bounds(&self) -> Option<Bounds> {
        Bounds::of_points(self.positions.iter().copied())
    }

    /// Median radius (0 when empty).
    pub fn median_radius(&self) -> f32 {
        let mut r = self.radii.clone();
        if r.is_empty() {
            return 0.0;
        }
        let mid = r.len() / 2;
        *r.select_nth_unstable_by(mid, f32::total_cmp).1
    }
}
