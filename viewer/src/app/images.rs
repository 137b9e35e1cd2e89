//! What the viewer reads back and renders into: the screenshot, and targets copies can write.

use crate::error::Result;
use autostereo::image_io::RgbImage;
use autostereo::target::SpatialTarget;

use super::State;

impl State {
    /// What was presented: the surface texture where it can be read, else the spatial target
    /// (the surface is its copy, value for value).
    pub(super) fn screenshot(
        &self,
        surface: &wgpu::Texture,
        target: &SpatialTarget,
    ) -> Result<RgbImage> {
        let (device, queue) = (&self.ctx.device, &self.ctx.queue);
        if !surface.usage().contains(wgpu::TextureUsages::COPY_SRC) {
            eprintln!("the surface cannot be read back: saving the spatial target it copies");
            return Ok(target.read(device, queue)?);
        }
        let mut rgba = autostereo::readback::read_texture_rgba8(device, queue, surface, 0)?;
        if matches!(
            surface.format(),
            wgpu::TextureFormat::Bgra8Unorm | wgpu::TextureFormat::Bgra8UnormSrgb
        ) {
            rgba.chunks_exact_mut(4).for_each(|p| p.swap(0, 2));
        }
        Ok(RgbImage::from_rgba(
            [surface.width(), surface.height()],
            &rgba,
        ))
    }
}

/// A spatial target that copies can also write (the quilt preview's tiles).
pub(super) fn copyable_target(device: &wgpu::Device, size: [u32; 2]) -> Result<SpatialTarget> {
    autostereo::gpu::check_size_2d(device, size[0], size[1])?;
    let texture = device.create_texture(&wgpu::TextureDescriptor {
        label: Some("viewer image"),
        size: wgpu::Extent3d {
            width: size[0],
            height: size[1],
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: autostereo::target::SPATIAL_FORMAT,
        usage: SpatialTarget::REQUIRED_USAGES
            | wgpu::TextureUsages::TEXTURE_BINDING
            | wgpu::TextureUsages::COPY_SRC
            | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    });
    Ok(SpatialTarget::from_texture(texture)?)
}
