//! The display mask evaluated by the GPU (WGSL) into a view-index image.

use crate::display::Display;
use crate::error::{Error, Result};
use crate::frame::{frame_bind_group_layout, FrameBinding, FrameUniform};
use crate::gpu::check_size_2d;
use crate::gpu::pipeline::{draw_fullscreen, fullscreen_pipeline};
use crate::gpu::texture::{texture_2d, Texture2d};
use crate::image_io::RgbImage;
use crate::param::Param;
use crate::readback::read_texture_rgba8;

/// Renders `mask_views` of `wgsl/shared/mask.wgsl` for every pixel.
pub struct MaskImageRenderer {
    pipeline: wgpu::RenderPipeline,
    frame: FrameBinding,
}

const FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Uint;

impl MaskImageRenderer {
    /// Build the pipeline.
    pub fn new(device: &wgpu::Device) -> Result<Self> {
        let layout = frame_bind_group_layout(device);
        let module = crate::shader::module(device, "render/mask_image.wgsl")?;
        let pipeline = fullscreen_pipeline(device, "mask image", &module, &[Some(&layout)], FORMAT);
        Ok(Self {
            pipeline,
            frame: FrameBinding::new(device, &layout),
        })
    }

    /// View-index image of `display` for a `size` window: channel c = view of subpixel c.
    pub fn render(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        display: &Display,
        size: [u32; 2],
    ) -> Result<RgbImage> {
        check_size_2d(device, size[0], size[1])?;
        if display.views() > 256 {
            return Err(Error::invalid(
                Param::Views,
                "view-index images hold at most 256 views",
            ));
        }
        let mut uniform: FrameUniform = bytemuck::Zeroable::zeroed();
        uniform.set_mask(display.mask().uniform());
        self.frame.write_uniform(device, &uniform);
        let Texture2d { texture, view, .. } = texture_2d(
            device,
            "mask image",
            size,
            FORMAT,
            wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        )?;
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("mask image"),
        });
        draw_fullscreen(
            &mut encoder,
            "mask image",
            &self.pipeline,
            &[&self.frame.bind_group],
            &view,
        );
        queue.submit([encoder.finish()]);
        let rgba = read_texture_rgba8(device, queue, &texture, 0)?;
        Ok(RgbImage::from_rgba(size, &rgba))
    }
}
