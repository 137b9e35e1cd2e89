//! The volume on the GPU: its texture, the pre-integration table and empty-space distances,
//! and [`VolumeScene`], what every volume method renders.

use std::sync::atomic::{AtomicU64, Ordering};

use glam::{Mat4, Vec3};
use half::f16;
use wgpu::util::DeviceExt;

use super::transfer::{PreintegrationTable, TransferFunction, TABLE_SIZE};
use super::{CellRanges, Volume};
use crate::error::{Error, Result};

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
                what: format!(
                    "volume dimension {d} of {:?} (downsample it, e.g. --downsample 2)",
                    volume.dims
                ),
                value: d.into(),
                limit: limit.into(),
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

/// A volume ready to render: GPU texture, box size, classification and sampling.
pub struct VolumeScene {
    /// Gradients + scalar (private: the cell ranges and the id describe this data).
    texture: VolumeTexture,
    /// World-space size of the box (centred at the origin before `model`).
    pub extent: Vec3,
    /// Smallest voxel spacing (the unit of transfer-function opacity).
    pub voxel: f32,
    /// Transfer function.
    pub transfer: TransferFunction,
    /// Distance Δ between samples along the eye depth, world units (default half the smallest
    /// voxel spacing). Coarser is faster and an approximation: pre-integration keeps one voxel
    /// within ≈ 44–47 dB of the default on the head and brainsmall (docs/VOLUMES.md, `--step`).
    pub step: f32,
    /// Volume → world transform (rotation of the volume).
    pub model: Mat4,
    /// Blinn-Phong shading from the gradients (off: emission-absorption only).
    pub shade: bool,
    /// Jump over space the transfer function makes fully transparent (ray-marching path;
    /// exact: the image is the same bit for bit, see `volume::empty_space`).
    pub skip_empty: bool,
    /// Sample sharing among a pixel's K rays (single pass, ray marching): where every pair of
    /// the rays' samples on a plane lies within this many voxels, they take their mean ray's
    /// samples (`wgsl/volume/shared/share.wgsl`). 0 (the default): every ray exact.
    pub share_samples: f32,
    /// Probing stride through transparent material (ray marching, every method; needs
    /// `skip_empty`): after a segment that added nothing, a ray probes this many sample planes
    /// ahead and takes the planes between as transparent where the pre-integrated segment
    /// between the two samples is exactly zero; where it is not, it marches them one by one
    /// (`wgsl/volume/shared/march.wgsl`). An approximation: it misses material thinner than
    /// `empty_stride` samples whose scalars lie outside both ends'. 1 (the default): exact.
    pub empty_stride: u32,
    /// With `empty_stride` > 1, probes also go on through thin material: a probe whose
    /// pre-integrated segment adds at most this opacity per sample step becomes one segment
    /// `empty_stride` steps long (opacity `1 − (1 − α)^P`, colour alike). 0 (the default): only
    /// transparent material.
    pub thin_alpha: f32,
    /// Table entries per voxel cell of the uploaded volume (empty-space skipping).
    pub(crate) cells: CellRanges,
    /// Identifies the uploaded volume for caches of data derived from it.
    pub(crate) id: u64,
}

/// The sample-sharing tolerance tests/share_samples.rs holds to its measured error bound, in
/// voxels: the largest on the measured curve (docs/volumes/BENCHMARKS.md) that keeps ≥ 40 dB
/// against the exact single pass on the head and brainsmall. On lavapipe sharing is slower than
/// the exact path at this tolerance, so nothing turns it on by default.
pub const SUGGESTED_SHARE_SAMPLES: f32 = 0.5;

/// The probing stride through transparent material USAGE.md suggests: 2 voxels at the default
/// step, which keeps ≥ 45 dB against the exact image even on phantoms with shells one or two
/// voxels thin (tests/empty_stride.rs; 8 loses up to 16 dB there), and ≥ 55 dB on the head and
/// brainsmall at 512² (docs/volumes/BENCHMARKS.md).
pub const SUGGESTED_EMPTY_STRIDE: u32 = 4;

/// Largest probing stride through transparent material (`VolumeScene::empty_stride`): past a
/// few voxels a probe only misses more, as the distance map already skips what is surely empty.
pub const MAX_EMPTY_STRIDE: u32 = 64;

/// Most samples a ray may take (a guard, and the bound on `--step`).
pub const MAX_SAMPLES_PER_RAY: f32 = 16384.0;

impl VolumeScene {
    /// Upload `volume`; sampling distance `step` world units (default: half the smallest voxel
    /// spacing).
    pub fn new(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        volume: &Volume,
        transfer: TransferFunction,
        step: Option<f32>,
        model: Mat4,
    ) -> Result<Self> {
        // Everything is checked before the upload.
        volume.validate()?;
        let voxel = volume.min_spacing();
        let step = step.unwrap_or_else(|| Self::default_step(volume));
        check_scene(volume.extent(), &transfer, step, model)?;
        let texture = VolumeTexture::new_validated(device, queue, volume)?;
        static NEXT_ID: AtomicU64 = AtomicU64::new(0);
        Ok(Self {
            texture,
            extent: volume.extent(),
            voxel,
            transfer,
            step,
            model,
            shade: true,
            skip_empty: true,
            share_samples: 0.0,
            empty_stride: 1,
            thin_alpha: 0.0,
            cells: CellRanges::new(volume),
            id: NEXT_ID.fetch_add(1, Ordering::Relaxed),
        })
    }

    /// Check the public fields a caller may have changed since [`VolumeScene::new`]: the
    /// renderers call this before every frame.
    pub fn validate(&self) -> Result<()> {
        check_scene(self.extent, &self.transfer, self.step, self.model)?;
        if !(self.share_samples.is_finite() && self.share_samples >= 0.0) {
            return Err(Error::invalid(
                "sample sharing tolerance (--share-samples)",
                format!(
                    "{}: must be a finite number of voxels, 0 or more",
                    self.share_samples
                ),
            ));
        }
        if !(1..=MAX_EMPTY_STRIDE).contains(&self.empty_stride) {
            return Err(Error::invalid(
                "probing stride through transparent material (--empty-stride)",
                format!(
                    "{}: must be 1 (exact) to {MAX_EMPTY_STRIDE} sample planes",
                    self.empty_stride
                ),
            ));
        }
        if !(0.0..1.0).contains(&self.thin_alpha) {
            return Err(Error::invalid(
                "thin-material opacity (--thin-alpha)",
                format!("{}: must be at least 0 and below 1", self.thin_alpha),
            ));
        }
        if self.empty_stride > 1 && !self.skip_empty {
            return Err(Error::invalid(
                "probing stride through transparent material (--empty-stride)",
                format!(
                    "{}: probing is part of empty-space skipping, which is off \
                     (--no-skip-empty); use stride 1 or turn skipping on",
                    self.empty_stride
                ),
            ));
        }
        Ok(())
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

    /// Sampling distance for `slices` samples across the box diagonal.
    pub fn step_for_slices(volume: &Volume, slices: u32) -> f32 {
        volume.extent().length() / slices.max(1) as f32
    }
}

/// Transfer function, sampling step (positive, at most [`MAX_SAMPLES_PER_RAY`] samples across the
/// box diagonal) and volume rotation (finite) of a scene whose box is `extent`.
fn check_scene(extent: Vec3, transfer: &TransferFunction, step: f32, model: Mat4) -> Result<()> {
    transfer.validate()?;
    let diagonal = extent.length();
    if !(step.is_finite() && step > 0.0 && diagonal / step <= MAX_SAMPLES_PER_RAY) {
        return Err(Error::invalid(
            "sampling step (--step, --slices)",
            format!(
                "{step}: must be positive and at least {} (the box diagonal / {MAX_SAMPLES_PER_RAY})",
                diagonal / MAX_SAMPLES_PER_RAY
            ),
        ));
    }
    if !model.is_finite() {
        return Err(Error::invalid("volume rotation", "not finite"));
    }
    Ok(())
}
