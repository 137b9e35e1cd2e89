//! An RGB-D image on the GPU: the colour (RGBA8) and nearness (R32Float) textures the warp
//! reads, made from an [`RgbdImage`] or borrowed from the caller.

use super::RgbdImage;
use crate::error::{Error, Result};
use crate::gpu::texture::{texture_2d, Texture2d};
use crate::param::Param;
use crate::target::SPATIAL_FORMAT;

/// Format of the nearness texture (0 = far … 1 = near).
pub const NEARNESS_MAP_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R32Float;

/// The reference image of a warp.
pub struct RgbdScene {
    /// RGBA8 (`target::SPATIAL_FORMAT`), read with `textureLoad`.
    pub color: wgpu::TextureView,
    /// [`NEARNESS_MAP_FORMAT`], one value per colour pixel.
    pub nearness: wgpu::TextureView,
    /// Width and height of both.
    pub size: [u32; 2],
    // Textures this scene created (none when it borrows the caller's views).
    _owned: Vec<Texture2d>,
}

impl RgbdScene {
    /// Upload `image`.
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue, image: &RgbdImage) -> Result<Self> {
        let size = image.size();
        crate::gpu::check_size_2d(device, size[0], size[1])?;
        let usage = wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST;
        let color = texture_2d(device, "rgbd colour", size, SPATIAL_FORMAT, usage)?;
        let nearness = texture_2d(device, "rgbd nearness", size, NEARNESS_MAP_FORMAT, usage)?;
        let rgba: Vec<u8> = image
            .color
            .data
            .chunks_exact(3)
            .flat_map(|p| [p[0], p[1], p[2], 255])
            .collect();
        let write = |texture: &wgpu::Texture, bytes: &[u8], texel: u32| {
            queue.write_texture(
                texture.as_image_copy(),
                bytes,
                wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(size[0] * texel),
                    rows_per_image: None,
                },
                texture.size(),
            );
        };
        write(&color.texture, &rgba, 4);
        write(&nearness.texture, bytemuck::cast_slice(&image.nearness), 4);
        Ok(Self {
            color: color.view.clone(),
            nearness: nearness.view.clone(),
            size,
            _owned: vec![color, nearness],
        })
    }

    /// The caller's textures: `color` RGBA8 (unorm), `nearness` R32Float, both `size` and
    /// bindable (`TEXTURE_BINDING`); mismatches are refused by name.
    pub fn from_textures(color: &wgpu::Texture, nearness: &wgpu::Texture) -> Result<Self> {
        let size = [color.width(), color.height()];
        let check = |t: &wgpu::Texture, name: Param, format: wgpu::TextureFormat| {
            let problem = if t.format() != format {
                Some(format!("is {:?}, needs {format:?}", t.format()))
            } else if [t.width(), t.height()] != size {
                Some(format!(
                    "is {}x{}, the colour texture {}x{}",
                    t.width(),
                    t.height(),
                    size[0],
                    size[1]
                ))
            } else if !t.usage().contains(wgpu::TextureUsages::TEXTURE_BINDING) {
                Some("lacks TEXTURE_BINDING usage".to_string())
            } else {
                None
            };
            match problem {
                Some(reason) => Err(Error::invalid(name, reason)),
                None => Ok(()),
            }
        };
        check(color, Param::RgbdColorTexture, SPATIAL_FORMAT)?;
        check(nearness, Param::RgbdNearnessTexture, NEARNESS_MAP_FORMAT)?;
        Ok(Self {
            color: color.create_view(&Default::default()),
            nearness: nearness.create_view(&Default::default()),
            size,
            _owned: Vec::new(),
        })
    }
}
