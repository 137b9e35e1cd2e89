//! The volume on the GPU: its texture, the pre-integration table and empty-space distances,
//! and [`VolumeScene`], what every volume method renders.

use std::sync::atomic::{AtomicU64, Ordering};

use glam::{Mat4, Vec3};
use half::f16;
use wgpu::util::DeviceExt;

use super::preintegration::{PreintegrationTable, TABLE_SIZE};
use super::transfer::TransferFunction;
use super::{CellRanges, Volume, VolumeSettings};
use crate::advice::{Advice, Setting};
use crate::error::{Error, Result};
use crate::param::Param;

/// The volume as one RGBA16F 3D texture: Sobel gradient in RGB, scalar in A (paper §3.5.1).
pub struct VolumeTexture {
    /// The texture.
    pub texture: wgpu::Texture,
    /// Its 3D view.
    pub view: wgpu::TextureView,
    /// Its share of the memory budget.
    _charge: crate::budget::GpuCharge,
}

fn half4(v: [f32; 4]) -> [f16; 4] {
    v.map(f16::from_f32)
}

impl VolumeTexture {
    /// Compute gradients and upload; a dimension beyond `max_texture_dimension_3d` is an error
    /// that suggests downsampling.
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue, volume: &Volume) -> Result<Self> {
        volume.validate()?;
        Self::new_validated(device, queue, volume)
    }

    /// [`VolumeTexture::new`] for a volume its caller has just validated (one pass over the
    /// voxels less).
    pub(crate) fn new_validated(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        volume: &Volume,
    ) -> Result<Self> {
        let limit = device.limits().max_texture_dimension_3d;
        if let Some(&d) = volume.dims.iter().find(|&&d| d > limit) {
            return Err(Error::LimitExceeded {
                what: format!("volume dimension {d} of {:?}", volume.dims),
                value: d.into(),
                limit: limit.into(),
                param: None,
                advice: Some(
                    Advice::text(" (downsample it, e.g. ")
                        .then(Setting::Downsample(2))
                        .then_text(")"),
                ),
            });
        }
        let voxels: u64 = volume.dims.iter().map(|&d| u64::from(d)).product();
        let what = || format!("the {:?} volume texture (RGBA16F)", volume.dims);
        let charge = crate::budget::charge_gpu(what, voxels * 8)?;
        let texels: Vec<[f16; 4]> = volume.gradients().into_iter().map(half4).collect();
        let (texture, view) = crate::gpu::checked(device, "uploading the volume", || {
            upload(
                device,
                queue,
                "volume",
                (wgpu::TextureDimension::D3, volume.dims),
                wgpu::TextureFormat::Rgba16Float,
                bytemuck::cast_slice(&texels),
            )
        })?;
        Ok(Self {
            texture,
            view,
            _charge: charge,
        })
    }
}

/// The pre-integration table as an RGBA16F 2D texture (front scalar = row, back = column).
pub struct PreintegrationTexture {
    /// The texture.
    pub texture: wgpu::Texture,
    /// Its view.
    pub view: wgpu::TextureView,
}

impl PreintegrationTexture {
    /// Upload `table`.
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue, table: &PreintegrationTable) -> Self {
        let texels: Vec<[f16; 4]> = table.rgba.iter().copied().map(half4).collect();
        let n = TABLE_SIZE as u32;
        let (texture, view) = upload(
            device,
            queue,
            "pre-integration table",
            (wgpu::TextureDimension::D2, [n, n, 1]),
            wgpu::TextureFormat::Rgba16Float,
            bytemuck::cast_slice(&texels),
        );
        Self { texture, view }
    }
}

/// Empty-space distances ([`super::CellRanges::distances`]) as an R8Uint 3D texture, one texel
/// per voxel cell.
pub struct EmptyDistanceTexture {
    /// The texture.
    pub texture: wgpu::Texture,
    /// Its view.
    pub view: wgpu::TextureView,
    /// Its share of the memory budget (one byte per cell, about an eighth of the volume's).
    _charge: crate::budget::GpuCharge,
}

impl EmptyDistanceTexture {
    /// Upload `distances` (x fastest) of a `grid` of cells.
    pub fn new(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        grid: [u32; 3],
        distances: &[u8],
    ) -> Result<Self> {
        let what = || format!("the {grid:?} empty-space distances (R8)");
        let charge = crate::budget::charge_gpu(what, distances.len() as u64)?;
        let format = wgpu::TextureFormat::R8Uint;
        let size = (wgpu::TextureDimension::D3, grid);
        let (texture, view) = crate::gpu::checked(device, "uploading the distances", || {
            upload(
                device,
                queue,
                "empty-space distances",
                size,
                format,
                distances,
            )
        })?;
        Ok(Self {
            texture,
            view,
            _charge: charge,
        })
    }
}

/// A sampled texture of `dimension` and `size` holding `bytes` (layer-major).
fn upload(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    label: &str,
    (dimension, size): (wgpu::TextureDimension, [u32; 3]),
    format: wgpu::TextureFormat,
    bytes: &[u8],
) -> (wgpu::Texture, wgpu::TextureView) {
    let texture = device.create_texture_with_data(
        queue,
        &wgpu::TextureDescriptor {
            label: Some(label),
            size: wgpu::Extent3d {
                width: size[0],
                height: size[1],
                depth_or_array_layers: size[2],
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension,
            format,
            usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
            view_formats: &[],
        },
        wgpu::util::TextureDataOrder::LayerMajor,
        bytes,
    );
    let view = texture.create_view(&Default::default());
    (texture, view)
}

/// A volume ready to render: GPU texture, box size, classification and placement. How it is
/// sampled and shaded is the renderer's ([`super::VolumeSettings`]).
pub struct VolumeScene {
    /// Gradients + scalar (private: the cell ranges and the id describe this data).
    texture: VolumeTexture,
    /// World-space size of the box (centred at the origin before `model`).
    pub extent: Vec3,
    /// Smallest voxel spacing (the unit of transfer-function opacity and of sampling steps).
    pub voxel: f32,
    /// Transfer function.
    pub transfer: TransferFunction,
    /// Volume → world transform: the caller's rotation after the volume's own axes
    /// ([`super::Volume::axes`]).
    pub model: Mat4,
    /// Half-spaces every method keeps (at most [`super::MAX_CLIP_PLANES`]; none: the whole
    /// box), src/volume/clip.rs.
    pub clip: Vec<super::ClipPlane>,
    /// The exact image's sampling distance ([`VolumeScene::default_step`]), world units.
    default_step: f32,
    /// Table entries per voxel cell of the uploaded volume (empty-space skipping).
    pub(crate) cells: CellRanges,
    /// Identifies the uploaded volume for caches of data derived from it.
    pub(crate) id: u64,
}

/// The sample-sharing tolerance tests/volumes/share_samples.rs holds to its measured error bound, in
/// voxels: the largest on the measured curve (docs/volumes/BENCHMARKS.md) that keeps ≥ 40 dB
/// against the exact single pass on the head and brainsmall. On lavapipe sharing is slower than
/// the exact path at this tolerance, so nothing turns it on by default.
pub const SUGGESTED_SHARE_SAMPLES: f32 = 0.5;

/// The probing stride through transparent material USAGE.md suggests: 2 voxels at the default
/// step, which keeps ≥ 45 dB against the exact image even on phantoms with shells one or two
/// voxels thin (cli/tests/accuracy/empty_stride.rs; 8 loses up to 16 dB there), and ≥ 55 dB on the head and
/// brainsmall at 512² (docs/volumes/BENCHMARKS.md).
pub const SUGGESTED_EMPTY_STRIDE: u32 = 4;

/// Largest probing stride through transparent material (`VolumeSettings::empty_stride`): past a
/// few voxels a probe only misses more, as the distance map already skips what is surely empty.
pub const MAX_EMPTY_STRIDE: u32 = 64;

/// Most samples a ray may take (a guard, and the bound on `--step`).
pub const MAX_SAMPLES_PER_RAY: f32 = 16384.0;

impl VolumeScene {
    /// Upload `volume`, classified by `transfer`, its voxel axes placed by its own
    /// [`super::Volume::axes`], then by `model`.
    pub fn new(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        volume: &Volume,
        transfer: TransferFunction,
        model: Mat4,
    ) -> Result<Self> {
        // Everything is checked before the upload.
        volume.validate()?;
        let voxel = volume.min_spacing();
        let default_step = Self::default_step(volume);
        check_scene(&transfer, model)?;
        let texture = VolumeTexture::new_validated(device, queue, volume)?;
        static NEXT_ID: AtomicU64 = AtomicU64::new(0);
        Ok(Self {
            texture,
            extent: volume.extent(),
            voxel,
            transfer,
            model: model * Mat4::from_mat3(volume.axes),
            clip: Vec::new(),
            default_step,
            cells: CellRanges::new(volume),
            id: NEXT_ID.fetch_add(1, Ordering::Relaxed),
        })
    }

    /// Check the public fields a caller may have changed since [`VolumeScene::new`]: the
    /// renderers call this before every frame.
    pub fn validate(&self) -> Result<()> {
        check_scene(&self.transfer, self.model)?;
        super::clip::check_planes(&self.clip)
    }

    /// The exact image's sampling distance for this volume, world units.
    pub fn default_step_length(&self) -> f32 {
        self.default_step
    }

    /// The uploaded volume (gradients + scalar).
    pub fn texture(&self) -> &VolumeTexture {
        &self.texture
    }

    /// Table entries per voxel cell (empty-space skipping).
    pub fn cells(&self) -> &CellRanges {
        &self.cells
    }

    /// Identifies the uploaded volume: caches of data derived from it key on this.
    pub(crate) fn id(&self) -> u64 {
        self.id
    }

    /// The sampling distance of the exact image (world units): half the smallest voxel spacing,
    /// or what keeps a ray within [`MAX_SAMPLES_PER_RAY`] on a very long volume (a 16384×1×1
    /// volume must not fail on a step the user never set).
    pub fn default_step(volume: &Volume) -> f32 {
        (0.5 * volume.min_spacing()).max(volume.extent().length() / (MAX_SAMPLES_PER_RAY - 1.0))
    }

    /// The sampling distance of `slices` samples across the box diagonal, in voxels of the
    /// smallest spacing (a [`super::VolumeSettings::step`]).
    pub fn step_for_slices(volume: &Volume, slices: u32) -> f32 {
        volume.extent().length() / slices.max(1) as f32 / volume.min_spacing()
    }
}

/// Transfer function and volume rotation (finite).
fn check_scene(transfer: &TransferFunction, model: Mat4) -> Result<()> {
    transfer.validate()?;
    if !model.is_finite() {
        return Err(Error::invalid(Param::VolumeRotation, "not finite"));
    }
    Ok(())
}

/// A sampling distance `step` (world units) for a box of `extent`: positive, at most
/// [`MAX_SAMPLES_PER_RAY`] samples across the box diagonal. The error speaks in voxels of the
/// smallest spacing `voxel` (world units), the unit [`super::VolumeSettings::step`] is given in.
pub(super) fn check_step(extent: Vec3, voxel: f32, step: f32) -> Result<()> {
    let diagonal = extent.length();
    if !(step.is_finite() && step > 0.0 && diagonal / step <= MAX_SAMPLES_PER_RAY) {
        return Err(Error::invalid(
            Param::SamplingStep,
            format!(
                "{} voxels: must be at least {} voxels (of the smallest spacing, {voxel} world \
                 units) for this volume, at most {MAX_SAMPLES_PER_RAY} samples across its \
                 diagonal",
                step / voxel,
                diagonal / MAX_SAMPLES_PER_RAY / voxel
            ),
        ));
    }
    Ok(())
}

/// The renderer's settings checked, alone and against a scene (src/volume/options.rs holds
/// them as plain values).
impl VolumeSettings {
    /// The sampling distance in world units for `scene`.
    pub fn step_length(&self, scene: &VolumeScene) -> f32 {
        self.step
            .map_or(scene.default_step_length(), |voxels| voxels * scene.voxel)
    }

    /// Check the values that need no scene (renderer construction).
    pub fn validate(&self) -> Result<()> {
        if !(self.isovalue.is_finite() && (0.0..=1.0).contains(&self.isovalue)) {
            return Err(Error::invalid(
                Param::Projection,
                format!(
                    "isovalue {}: a normalised scalar in 0..1 (the scan's range maps to it)",
                    self.isovalue
                ),
            ));
        }
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
