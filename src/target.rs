//! The spatial image a renderer writes: one RGBA8 texture, the display's interleaved pixels.

use crate::error::Result;
use crate::gpu::check_size_2d;
use crate::image_io::RgbImage;
use crate::readback::read_texture_rgba8;
use crate::render::texture::texture_2d;

/// Format of every spatial image and per-view layer: plain (linear) 8-bit RGBA.
pub const SPATIAL_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

/// An output image on the GPU.
pub struct SpatialTarget {
    /// The texture (render attachment, storage, copy source, sampled).
    pub texture: wgpu::Texture,
    /// A view of it.
    pub view: wgpu::TextureView,
}

impl SpatialTarget {
    /// Allocate a `size` target after checking the device limits.
    pub fn new(device: &wgpu::Device, size: [u32; 2]) -> Result<Self> {
        check_size_2d(device, size[0], size[1])?;
        let (texture, view) = texture_2d(
            device,
            "spatial image",
            size,
            SPATIAL_FORMAT,
            wgpu::TextureUsages::RENDER_ATTACHMENT
                | wgpu::TextureUsages::STORAGE_BINDING
                | wgpu::TextureUsages::TEXTURE_BINDING
                | wgpu::TextureUsages::COPY_SRC,
        );
        Ok(Self { texture, view })
    }

    /// Size in pixels.
    pub fn size(&self) -> [u32; 2] {
        [self.texture.width(), self.texture.height()]
    }

    /// Copy to the CPU as RGB8.
    pub fn read(&self, device: &wgpu::Device, queue: &wgpu::Queue) -> Result<RgbImage> {
        let rgba = read_texture_rgba8(device, queue, &self.texture, 0)?;
        Ok(RgbImage::from_rgba(self.size(), &rgba))
    }
}
