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
        let [w, h, d] = volume.dims;
        let texture = crate::gpu::checked(device, "uploading the volume", || {
            device.create_texture_with_data(
                queue,
                &wgpu::TextureDescriptor {
                    label: Some("volume"),
                    size: wgpu::Extent3d {
                        width: w,
                        height: h,
                        depth_or_array_layers: d,
                    },
                    mip_level_count: 1,
                    sample_count: 1,
                    dimension: wgpu::TextureDimension::D3,
                    format: wgpu::TextureFormat::Rgba16Float,
                    usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
                    view_formats: &[],
                },
                wgpu::util::TextureDataOrder::LayerMajor,
                bytemuck::cast_slice(&texels),
            )
        })?;
        let view = texture.create_view(&Default::default());
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
        let texture = device.create_texture_with_data(
            queue,
            &wgpu::TextureDescriptor {
                label: Some("pre-integration table"),
                size: wgpu::Extent3d {
                    width: n,
                    height: n,
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: wgpu::TextureFormat::Rgba16Float,
                usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
                view_formats: &[],
            },
            wgpu::util::TextureDataOrder::LayerMajor,
            bytemuck::cast_slice(&texels),
        );
        let view = texture.create_view(&Default::default());
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
        let texture = device.create_texture_with_data(
            queue,
            &wgpu::TextureDescriptor {
                label: Some("transparent bricks"),
                size: wgpu::Extent3d {
                    width: grid[0],
                    height: grid[1],
                    depth_or_array_layers: grid[2],
                },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D3,
                format: wgpu::TextureFormat::R8Uint,
                usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
                view_formats: &[],
            },
            wgpu::util::TextureDataOrder::LayerMajor,
            flags,
        );
        let view = texture.create_view(&Default::default());
        Self { texture, view }
    }
}
