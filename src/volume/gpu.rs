//! Volume data and pre-integration table on the GPU.

use half::f16;
use wgpu::util::DeviceExt;

use super::transfer::{PreintegrationTable, TABLE_SIZE};
use super::Volume;
use crate::error::{Error, Result};

/// The volume as one RGBA16F 3D texture: Sobel gradient in RGB, scalar in A (paper §3.5.1).
pub struct VolumeTexture {
    /// The texture.
    pub texture: wgpu::Texture,
    /// Its 3D view.
    pub view: wgpu::TextureView,
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
        Ok(Self { texture, view })
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

/// Transparent-brick flags ([`super::BrickRanges::transparent`]) as an R8Uint 3D texture, one
/// texel per brick.
pub struct TransparentBrickTexture {
    /// The texture.
    pub texture: wgpu::Texture,
    /// Its view.
    pub view: wgpu::TextureView,
}

impl TransparentBrickTexture {
    /// Upload `flags` (x fastest) of a `grid` of bricks.
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue, grid: [u32; 3], flags: &[u8]) -> Self {
        let format = wgpu::TextureFormat::R8Uint;
        let size = (wgpu::TextureDimension::D3, grid);
        let (texture, view) = upload(device, queue, "transparent bricks", size, format, flags);
        Self { texture, view }
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
