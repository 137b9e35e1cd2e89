//! Scalar volumes: loading (raw, NRRD, VolPack .den, NIfTI, MetaImage), where a volume is in
//! the world (its voxel axes: [`Volume::axes`], docs/VOLUMES.md), built-in data sets,
//! gradients, transfer functions with pre-integration, and their GPU textures.

pub mod clip;
pub(crate) mod empty_space;
pub mod generate;
mod gradient;
pub mod load;
pub(crate) mod options;
pub mod orientation;
pub(crate) mod passes;
mod preintegration;
mod scene;
pub(crate) mod transfer;
pub mod values;
mod visible;

pub use clip::{ClipPlane, MAX_CLIP_PLANES};
pub use empty_space::{CellRanges, MAX_DISTANCE};
pub use options::{AlphaMode, Projection, VolumeOptions, VolumePath, VolumeSettings};
pub use passes::{VolumeRaycaster, VolumeSlicer};
pub use preintegration::PreintegrationTable;
pub use scene::{
    EmptyDistanceTexture, PreintegrationTexture, VolumeScene, VolumeTexture, MAX_EMPTY_STRIDE,
    MAX_SAMPLES_PER_RAY, SUGGESTED_EMPTY_STRIDE, SUGGESTED_SHARE_SAMPLES,
};
pub use transfer::{Transfer, TransferFunction, PRESETS};
pub use values::{Modality, Units, Values};

use glam::{Mat3, Vec3};

use crate::camera::Bounds;
use crate::error::{Error, Result};
use crate::param::Param;
use crate::render::Method;

/// The methods that render volumes: all but [`Method::Mrt`], which [`VolumeRaycaster::new`]
/// refuses with the reason (a volume has no depth buffer to share).
pub const METHODS: [Method; 6] = [
    Method::SinglePass,
    Method::NPass,
    Method::SingleView,
    Method::Tiled,
    Method::Layered,
    Method::Warp,
];

/// Most voxels a volume may have (4 bytes each on the CPU, 8 on the GPU): 1 Gi.
pub const MAX_VOXELS: u64 = 1 << 30;

/// A scalar volume normalised to 0..1, x fastest, then y, then z.
#[derive(Clone, Debug, PartialEq)]
pub struct Volume {
    /// Voxels along x, y, z.
    pub dims: [u32; 3],
    /// Voxel spacing along x, y, z (world units).
    pub spacing: [f32; 3],
    /// `dims[0]·dims[1]·dims[2]` scalars in 0..1.
    pub data: Vec<f32>,
    /// Where the voxel axes point on screen: column a is the unit direction of voxel axis a
    /// (x, y, z fastest first) in the renderer's world (x right, y up, z toward the viewer).
    /// The identity for files without a patient geometry; from the file's geometry for the
    /// others ([`orientation`], docs/VOLUMES.md "Where a volume is"). Orthonormal.
    pub axes: Mat3,
    /// What the scalars stand for: the values at 0 and 1 in the scan's units, its modality and
    /// window ([`values`]); normalised for data given in 0..1.
    pub values: Values,
}

/// A box of a volume to keep ([`Volume::cropped`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Crop {
    /// Voxel indices, `min` to `max` inclusive along x, y, z.
    Voxels {
        /// The first voxel kept along each axis.
        min: [u32; 3],
        /// The last voxel kept along each axis.
        max: [u32; 3],
    },
    /// A box in the spacing's units (mm for a scan) measured from the volume's first voxel's
    /// corner along its voxel axes.
    World {
        /// The box's near corner.
        min: [f32; 3],
        /// The box's far corner.
        max: [f32; 3],
    },
}

/// Peak CPU bytes per voxel from file to GPU upload: the decoded samples (f32), their
/// Sobel gradients (4 × f32), the half-float texels (4 × f16) and up to 4 bytes of file data.
pub const PEAK_BYTES_PER_VOXEL: u64 = 4 + 16 + 8 + 4;

/// Check dimensions before anything is allocated: each ≥ 1, product ≤ [`MAX_VOXELS`], and the
/// volume's peak memory ([`PEAK_BYTES_PER_VOXEL`] per voxel) within the budget
/// (`crate::budget`).
pub fn check_dims(dims: [u64; 3]) -> Result<u64> {
    if dims.contains(&0) {
        return Err(Error::invalid(
            Param::VolumeDimensions,
            format!("{dims:?}: every dimension must be at least 1"),
        ));
    }
    let count = dims
        .iter()
        .try_fold(1u64, |acc, &d| acc.checked_mul(d))
        .filter(|&n| n <= MAX_VOXELS)
        .ok_or_else(|| {
            Error::invalid(
                Param::VolumeDimensions,
                format!("{dims:?}: more than {MAX_VOXELS} voxels"),
            )
        })?;
    crate::budget::check(
        || {
            format!("a {dims:?} volume ({count} voxels × {PEAK_BYTES_PER_VOXEL} bytes from file to GPU)")
        },
        count * PEAK_BYTES_PER_VOXEL,
    )?;
    Ok(count)
}

fn check_spacing(spacing: [f32; 3]) -> Result<()> {
    if spacing.iter().all(|s| s.is_finite() && *s > 0.0) {
        Ok(())
    } else {
        Err(Error::invalid(
            Param::VoxelSpacing,
            format!("{spacing:?}: must be positive and finite"),
        ))
    }
}

impl Volume {
    /// A volume from scalars already in 0..1 (checked: sizes, values in 0..1, spacing).
    pub fn new(dims: [u32; 3], spacing: [f32; 3], data: Vec<f32>) -> Result<Self> {
        let volume = Self {
            dims,
            spacing,
            data,
            axes: Mat3::IDENTITY,
            values: Values::NORMALISED,
        };
        volume.validate()?;
        Ok(volume)
    }

    /// This volume with its voxel axes pointing along `axes` ([`Volume::axes`]; checked
    /// orthonormal).
    pub fn with_axes(mut self, axes: Mat3) -> Result<Self> {
        self.axes = axes;
        orientation::check_axes(axes)?;
        Ok(self)
    }

    /// Check what [`Volume::new`] checks, for a volume whose public fields were set or changed
    /// directly: `VolumeTexture::new` (so `VolumeScene::new`) calls it before using the data.
    pub fn validate(&self) -> Result<()> {
        let count = check_dims(self.dims.map(u64::from))?;
        check_spacing(self.spacing)?;
        orientation::check_axes(self.axes)?;
        if self.data.len() as u64 != count {
            return Err(Error::invalid(
                Param::VolumeData,
                format!("{} values for dimensions {:?}", self.data.len(), self.dims),
            ));
        }
        if let Some(i) = self.data.iter().position(|v| !(0.0..=1.0).contains(v)) {
            return Err(Error::invalid(
                Param::VolumeData,
                format!("voxel {i} is {}: scalars must be in 0..1", self.data[i]),
            ));
        }
        Ok(())
    }

    /// This volume's scalars standing for `values` ([`Volume::values`]).
    pub fn with_values(mut self, values: Values) -> Self {
        self.values = values;
        self
    }

    /// A volume from raw samples of any range, mapped linearly from [min, max] (or `range`)
    /// to [0, 1] (a constant volume maps to 0); its [`Volume::values`] say the range, in the
    /// file's units.
    pub fn from_samples(
        dims: [u32; 3],
        spacing: [f32; 3],
        samples: Vec<f32>,
        range: Option<[f32; 2]>,
    ) -> Result<Self> {
        let [lo, hi] = range.unwrap_or_else(|| {
            let finite = samples.iter().copied().filter(|v| v.is_finite());
            let lo = finite.clone().fold(f32::INFINITY, f32::min);
            let hi = finite.fold(f32::NEG_INFINITY, f32::max);
            [lo, hi]
        });
        // In f64: the span of samples near ±f32::MAX overflows f32 (and made every voxel NaN).
        let (lo, hi) = (f64::from(lo), f64::from(hi));
        let scale = if hi > lo { 1.0 / (hi - lo) } else { 0.0 };
        let data = samples
            .into_iter()
            .map(|v| {
                if v.is_finite() {
                    ((f64::from(v) - lo) * scale).clamp(0.0, 1.0) as f32
                } else {
                    0.0
                }
            })
            .collect();
        Ok(Self::new(dims, spacing, data)?.with_values(Values {
            range: [lo, hi],
            units: Units::File,
            ..Values::NORMALISED
        }))
    }

    /// Scalar at integer voxel (clamped to the volume).
    #[inline]
    pub fn at(&self, x: i64, y: i64, z: i64) -> f32 {
        let c = |v: i64, n: u32| v.clamp(0, n as i64 - 1) as usize;
        let [nx, ny, nz] = self.dims;
        self.data[(c(z, nz) * ny as usize + c(y, ny)) * nx as usize + c(x, nx)]
    }

    /// World-space size of the box (voxel centres at the faces' half-voxel insets).
    pub fn extent(&self) -> Vec3 {
        Vec3::from_array(self.spacing)
            * Vec3::new(
                self.dims[0] as f32,
                self.dims[1] as f32,
                self.dims[2] as f32,
            )
    }

    /// Bounds of the box as its axes place it, centred at the origin.
    pub fn bounds(&self) -> Bounds {
        let a = self.axes;
        let abs = Mat3::from_cols(a.x_axis.abs(), a.y_axis.abs(), a.z_axis.abs());
        let half = abs * (self.extent() * 0.5);
        Bounds {
            min: -half,
            max: half,
        }
    }

    /// This volume with [`Values::robust`] measured: the values below which 1 % and 99 % of
    /// its voxels lie (a histogram of 65,536 bins over the normalised scalar: to 1/65,536 of
    /// the range).
    pub fn with_robust_range(mut self) -> Self {
        const BINS: usize = 1 << 16;
        let mut histogram = vec![0u64; BINS];
        for &s in &self.data {
            histogram[((s.clamp(0.0, 1.0) * (BINS - 1) as f32).round()) as usize] += 1;
        }
        let n = self.data.len() as u64;
        let at = |share: f64| {
            let wanted = ((n as f64 * share).ceil() as u64).max(1);
            let mut seen = 0;
            let bin = histogram
                .iter()
                .position(|&c| {
                    seen += c;
                    seen >= wanted
                })
                .unwrap_or(BINS - 1);
            self.values.value(bin as f32 / (BINS - 1) as f32)
        };
        self.values.robust = Some([at(0.01), at(0.99)]);
        self
    }

    /// The voxels of the box `crop` — `Crop::Voxels` from `min` to `max` inclusive, or
    /// `Crop::World` in the spacing's units (mm for a scan) from the volume's first voxel — as
    /// a volume of their own (same spacing, axes and values), centred where the renderers
    /// centre every volume. A box outside the volume, or empty, is refused naming the sizes.
    pub fn cropped(&self, crop: Crop) -> Result<Self> {
        let (min, max) = match crop {
            Crop::Voxels { min, max } => (min, max),
            Crop::World { min, max } => {
                let to_voxel = |v: [f32; 3], round: fn(f32) -> f32| {
                    [0, 1, 2].map(|a| round(v[a] / self.spacing[a]).max(0.0) as u32)
                };
                let max = to_voxel(max, f32::ceil).map(|v| v.saturating_sub(1));
                (to_voxel(min, f32::floor), max)
            }
        };
        let fits = (0..3).all(|a| min[a] <= max[a] && max[a] < self.dims[a]);
        if !fits {
            return Err(Error::invalid(
                Param::Crop,
                format!(
                    "voxels {min:?} to {max:?}: not a box inside the volume's {:?} voxels (each \
                     from ≤ to, to < the size)",
                    self.dims
                ),
            ));
        }
        let dims = [0, 1, 2].map(|a| max[a] - min[a] + 1);
        let mut data = Vec::with_capacity(dims.iter().map(|&d| d as usize).product());
        for z in min[2]..=max[2] {
            for y in min[1]..=max[1] {
                let row = (z as usize * self.dims[1] as usize + y as usize) * self.dims[0] as usize;
                data.extend_from_slice(&self.data[row + min[0] as usize..=row + max[0] as usize]);
            }
        }
        Ok(Volume::new(dims, self.spacing, data)?
            .with_axes(self.axes)?
            .with_values(self.values.clone()))
    }

    /// Average blocks of `factor`³ voxels (edges: partial blocks); spacing grows by `factor`.
    pub fn downsample(&self, factor: u32) -> Result<Self> {
        if factor == 0 {
            return Err(Error::invalid(
                Param::DownsampleFactor,
                "must be at least 1",
            ));
        }
        let dims = self.dims.map(|d| d.div_ceil(factor));
        let mut data = Vec::with_capacity(dims.iter().map(|&d| d as usize).product());
        // The voxels of block b along an axis of n voxels: only those inside the volume, so the
        // work is one visit per voxel whatever the factor.
        let block = |b: u32, n: u32| {
            let start = u64::from(b) * u64::from(factor);
            start as i64..(start + u64::from(factor)).min(u64::from(n)) as i64
        };
        for z in 0..dims[2] {
            for y in 0..dims[1] {
                for x in 0..dims[0] {
                    let (mut sum, mut n) = (0.0, 0.0);
                    for pz in block(z, self.dims[2]) {
                        for py in block(y, self.dims[1]) {
                            for px in block(x, self.dims[0]) {
                                sum += self.at(px, py, pz);
                                n += 1.0;
                            }
                        }
                    }
                    data.push(sum / n);
                }
            }
        }
        Ok(
            Volume::new(dims, self.spacing.map(|s| s * factor as f32), data)?
                .with_axes(self.axes)?
                .with_values(self.values.clone()),
        )
    }

    /// Smallest voxel spacing: the natural sampling distance.
    pub fn min_spacing(&self) -> f32 {
        self.spacing.iter().copied().fold(f32::INFINITY, f32::min)
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_crop_keeps_its_voxels_and_what_they_stand_for() {
        let data: Vec<f32> = (0..4 * 3 * 2).map(|i| i as f32 / 23.0).collect();
        let v = Volume::new([4, 3, 2], [0.5, 1.0, 2.0], data)
            .unwrap()
            .with_values(Values {
                range: [-1024.0, 3071.0],
                units: Units::Hounsfield,
                ..Values::NORMALISED
            });
        let c = v
            .cropped(Crop::Voxels {
                min: [1, 1, 1],
                max: [2, 2, 1],
            })
            .unwrap();
        assert_eq!((c.dims, c.spacing), ([2, 2, 1], [0.5, 1.0, 2.0]));
        assert_eq!(c.at(0, 0, 0), v.at(1, 1, 1));
        assert_eq!(c.at(1, 1, 0), v.at(2, 2, 1));
        assert_eq!(c.values, v.values);
        // In the spacing's units: x 0.5–1.5 (voxels 1, 2), y 1–3 (1, 2), z 2–4 (1).
        let world = v
            .cropped(Crop::World {
                min: [0.5, 1.0, 2.0],
                max: [1.5, 3.0, 4.0],
            })
            .unwrap();
        assert_eq!(world.data, c.data);
        for bad in [([0, 0, 0], [4, 2, 1]), ([2, 0, 0], [1, 2, 1])] {
            let crop = Crop::Voxels {
                min: bad.0,
                max: bad.1,
            };
            assert!(v.cropped(crop).is_err(), "{bad:?}");
        }
    }

    use super::*;

    #[test]
    fn downsample_averages_blocks_and_any_factor_is_cheap() {
        let data: Vec<f32> = (0..30).map(|i| i as f32 / 29.0).collect();
        let v = Volume::new([5, 3, 2], [1.0, 1.0, 2.0], data).unwrap();
        let d = v.downsample(2).unwrap();
        assert_eq!(d.dims, [3, 2, 1]);
        assert_eq!(d.spacing, [2.0, 2.0, 4.0]);
        // Block (2, 1, 0) holds only voxel (4, 2, z) for z = 0, 1: indices 14 and 29.
        assert!((d.data[5] - (14.0 + 29.0) / 2.0 / 29.0).abs() < 1e-6);
        // A factor beyond every dimension (even u32::MAX) is one block: the mean of all.
        for factor in [5, u32::MAX] {
            let one = v.downsample(factor).unwrap();
            assert_eq!(one.dims, [1, 1, 1]);
            assert!((one.data[0] - 0.5).abs() < 1e-6);
        }
        assert!(v.downsample(0).is_err());
    }
}
