//! How a volume renderer samples and shades a [`VolumeScene`], and which single-pass path it
//! takes: settings of the renderer (given to [`crate::RendererOptions`] or to the volume
//! renderers' constructors), never of the scene, so that one uploaded volume renders with
//! several settings side by side.

use super::scene::{check_step, MAX_EMPTY_STRIDE};
use super::{AlphaMode, VolumeScene};
use crate::error::{Error, Result};
use crate::param::Param;

/// Volume settings: the single pass's path and how every method samples.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct VolumeOptions {
    /// The single pass's path (the other methods always ray-march).
    pub path: VolumePath,
    /// Sampling, shading and the measured approximations.
    pub settings: VolumeSettings,
}

/// How the volume single pass runs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum VolumePath {
    /// Ray marching in a compute pass, exact per channel.
    #[default]
    RayMarch,
    /// The paper's proxy slices (needs dual-source blending).
    Slices(AlphaMode),
}

/// Sampling, shading and the measured approximations of volume rendering. The default is the
/// exact image: half-voxel steps, shading, exact empty-space skipping, no probes, no sharing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VolumeSettings {
    /// Distance between samples along the eye depth, in voxels of the smallest spacing. `None`
    /// (the default): half a voxel, or what keeps a ray within
    /// [`super::MAX_SAMPLES_PER_RAY`] samples ([`VolumeScene::default_step`]). Coarser is faster
    /// and an approximation: pre-integration keeps one voxel within ≈ 44–47 dB of the default
    /// on the head and brainsmall (docs/VOLUMES.md).
    pub step: Option<f32>,
    /// Blinn-Phong shading from the gradients (off: emission-absorption only).
    pub shade: bool,
    /// Jump over space the transfer function makes fully transparent (ray marching; exact: the
    /// image is the same bit for bit, see `src/volume/empty_space.rs`).
    pub skip_empty: bool,
    /// Sample sharing among a pixel's K rays (single pass, ray marching): where every pair of
    /// the rays' samples on a plane lies within this many voxels, they take their mean ray's
    /// samples (`wgsl/volume/shared/share.wgsl`). 0: every ray exact.
    pub share_samples: f32,
    /// Probing stride through transparent material (ray marching, every method; needs
    /// `skip_empty`): after a segment that added nothing, a ray probes this many sample planes
    /// ahead and takes the planes between as transparent where the pre-integrated segment
    /// between the two samples is exactly zero; where it is not, it marches them one by one
    /// (`wgsl/volume/shared/march.wgsl`). An approximation: it misses material thinner than
    /// `empty_stride` samples whose scalars lie outside both ends'. 1: exact.
    pub empty_stride: u32,
    /// With `empty_stride` > 1, probes also go on through thin material: a probe whose
    /// pre-integrated segment adds at most this opacity per sample step becomes one segment
    /// `empty_stride` steps long (opacity `1 − (1 − α)^P`, colour alike). 0: only transparent
    /// material.
    pub thin_alpha: f32,
}

impl Default for VolumeSettings {
    fn default() -> Self {
        Self {
            step: None,
            shade: true,
            skip_empty: true,
            share_samples: 0.0,
            empty_stride: 1,
            thin_alpha: 0.0,
        }
    }
}

impl VolumeSettings {
    /// The exact image of these settings' step: no probes, no sharing (what an approximation
    /// is measured against).
    pub fn exact(self) -> Self {
        Self {
            share_samples: 0.0,
            empty_stride: 1,
            thin_alpha: 0.0,
            ..self
        }
    }

    /// The sampling distance in world units for `scene`.
    pub fn step_length(&self, scene: &VolumeScene) -> f32 {
        self.step
            .map_or(scene.default_step_length(), |voxels| voxels * scene.voxel)
    }

    /// Check the values that need no scene (renderer construction).
    pub fn validate(&self) -> Result<()> {
        if let Some(step) = self.step {
            if !(step.is_finite() && step > 0.0) {
                return Err(Error::invalid(
                    Param::SamplingStep,
                    format!("{step} voxels: must be positive and finite"),
                ));
            }
        }
        if !(self.share_samples.is_finite() && self.share_samples >= 0.0) {
            return Err(Error::invalid(
                Param::SampleSharing,
                format!(
                    "{}: must be a finite number of voxels, 0 or more",
                    self.share_samples
                ),
            ));
        }
        if !(1..=MAX_EMPTY_STRIDE).contains(&self.empty_stride) {
            return Err(Error::invalid(
                Param::EmptyStride,
                format!(
                    "{}: must be 1 (exact) to {MAX_EMPTY_STRIDE} sample planes",
                    self.empty_stride
                ),
            ));
        }
        if !(0.0..1.0).contains(&self.thin_alpha) {
            return Err(Error::invalid(
                Param::ThinAlpha,
                format!("{}: must be at least 0 and below 1", self.thin_alpha),
            ));
        }
        if self.thin_alpha != 0.0 && self.empty_stride < 2 {
            return Err(Error::invalid(
                Param::ThinAlpha,
                format!(
                    "{}: thin material is stepped through by the probes of the probing \
                     stride, which is {} (give a stride of 2 or more)",
                    self.thin_alpha, self.empty_stride
                ),
            ));
        }
        if self.empty_stride > 1 && !self.skip_empty {
            return Err(Error::invalid(
                Param::EmptyStride,
                format!(
                    "{}: probing is part of empty-space skipping, which is off; use stride 1 \
                     or turn skipping on",
                    self.empty_stride
                ),
            ));
        }
        Ok(())
    }

    /// Check these settings against `scene` (every frame: the step must fit its box).
    pub fn validate_for(&self, scene: &VolumeScene) -> Result<()> {
        self.validate()?;
        check_step(scene.extent, scene.voxel, self.step_length(scene))
    }
}
