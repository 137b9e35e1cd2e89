//! The spatial image a renderer writes: one RGBA8 texture, the display's interleaved pixels.

use crate::error::Result;
use crate::gpu::check_size_2d;
use crate::gpu::texture::{texture_2d, Texture2d};
use crate::image_io::RgbImage;
use crate::param::Param;
use crate::readback::read_texture_rgba8;

/// Format of every spatial image and per-view layer: plain (linear) 8-bit RGBA.
pub const SPATIAL_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

/// An output image on the GPU.
pub struct SpatialTarget {
    /// The texture (render attachment, storage, copy source and destination, sampled).
    pub texture: wgpu::Texture,
    /// A view of it.
    pub view: wgpu::TextureView,
    /// Made by the library (true) or wrapped around a caller's texture.
    owned: bool,
    /// The library's own target's share of the memory budget (a caller's texture is theirs).
    _charge: Option<crate::budget::GpuCharge>,
}

impl SpatialTarget {
    /// Allocate a `size` target after checking the device limits.
    pub fn new(device: &wgpu::Device, size: [u32; 2]) -> Result<Self> {
        check_size_2d(device, size[0], size[1])?;
        let Texture2d {
            texture,
            view,
            charge,
        } = texture_2d(
            device,
            "spatial image",
            size,
            SPATIAL_FORMAT,
            wgpu::TextureUsages::RENDER_ATTACHMENT
                | wgpu::TextureUsages::STORAGE_BINDING
                | wgpu::TextureUsages::TEXTURE_BINDING
                | wgpu::TextureUsages::COPY_SRC
                | wgpu::TextureUsages::COPY_DST,
        )?;
        Ok(Self {
            texture,
            view,
            owned: true,
            _charge: Some(charge),
        })
    }

    /// Usages a caller-made texture needs to be a spatial target: render attachment (the
    /// raster passes) and storage (the compute passes).
    pub const REQUIRED_USAGES: wgpu::TextureUsages =
        wgpu::TextureUsages::RENDER_ATTACHMENT.union(wgpu::TextureUsages::STORAGE_BINDING);

    /// Render straight into a texture the caller made: 2D, one mip, one sample,
    /// [`SPATIAL_FORMAT`], with [`SpatialTarget::REQUIRED_USAGES`] (add `COPY_SRC` to
    /// [`SpatialTarget::read`] it, `TEXTURE_BINDING` to copy it into a surface with
    /// [`crate::render::OutputBlit`]). Anything else is a clear error; surfaces, which rarely
    /// allow storage, take the spatial image through `OutputBlit` instead.
    pub fn from_texture(texture: wgpu::Texture) -> Result<Self> {
        let problem = if texture.format() != SPATIAL_FORMAT {
            Some(format!(
                "format {:?}: renderers write {SPATIAL_FORMAT:?} (use OutputBlit for other formats)",
                texture.format()
            ))
        } else if !texture.usage().contains(Self::REQUIRED_USAGES) {
            Some(format!(
                "usage {:?} lacks {:?}",
                texture.usage(),
                Self::REQUIRED_USAGES - texture.usage()
            ))
        } else if texture.dimension() != wgpu::TextureDimension::D2
            || texture.depth_or_array_layers() != 1
            || texture.mip_level_count() != 1
            || texture.sample_count() != 1
        {
            Some("must be 2D with one layer, one mip level and one sample".to_string())
        } else {
            None
        };
        if let Some(problem) = problem {
            return Err(crate::Error::invalid(Param::TargetTexture, problem));
        }
        let view = texture.create_view(&Default::default());
        Ok(Self {
            texture,
            view,
            owned: false,
            _charge: None,
        })
    }

    /// Make this a `size` target (a window was resized): a new texture when the size changed.
    /// The renderers follow at their next `prepare` with a frame of that size. A target
    /// wrapped around a caller's texture is the caller's to resize (an error here: silently
    /// swapping in a texture of the library's would stop frames reaching theirs).
    pub fn resize(&mut self, device: &wgpu::Device, size: [u32; 2]) -> Result<()> {
        if self.size() == size {
            return Ok(());
        }
        if !self.owned {
            return Err(crate::Error::invalid(
                Param::TargetTexture,
                "a caller's texture: make one of the new size and wrap it with from_texture",
            ));
        }
        *self = Self::new(device, size)?;
        Ok(())
    }

    /// Size in pixels.
    pub fn size(&self) -> [u32; 2] {
        [self.texture.width(), self.texture.height()]
    }

    /// Copy to the CPU as RGB8.
    pub fn read(&self, device: &wgpu::Device, queue: &wgpu::Queue) -> Result<RgbImage> {
        if !self.texture.usage().contains(wgpu::TextureUsages::COPY_SRC) {
            return Err(crate::Error::invalid(
                Param::TargetTexture,
                "reading it back needs COPY_SRC usage",
            ));
        }
        let rgba = read_texture_rgba8(device, queue, &self.texture, 0)?;
        Ok(RgbImage::from_rgba(self.size(), &rgba))
    }
}
