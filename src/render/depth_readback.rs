//! Depth buffers to the CPU through a shader copy of their f32 bits into an R32Uint image
//! (`wgsl/render/depth_readback.wgsl`): GL has no depth-to-buffer copies, so every adapter
//! takes this one path.

use crate::error::Result;
use crate::gpu::pipeline::{bind_group_layout, draw_fullscreen, fullscreen_pipeline};
use crate::gpu::texture::texture_2d;

/// The `Depth32Float` `texture` (with `TEXTURE_BINDING` usage) as f32 texels, rows top-down.
pub fn read_depth(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    texture: &wgpu::Texture,
) -> Result<Vec<f32>> {
    let layout = bind_group_layout(
        device,
        "depth readback",
        &[wgpu::BindGroupLayoutEntry {
            binding: 0,
            visibility: wgpu::ShaderStages::FRAGMENT,
            ty: wgpu::BindingType::Texture {
                sample_type: wgpu::TextureSampleType::Float { filterable: false },
                view_dimension: wgpu::TextureViewDimension::D2,
                multisampled: false,
            },
            count: None,
        }],
    );
    let module = crate::shader::module(device, "render/depth_readback.wgsl")?;
    let format = wgpu::TextureFormat::R32Uint;
    let pipeline = fullscreen_pipeline(device, "depth readback", &module, &[Some(&layout)], format);
    let size = [texture.width(), texture.height()];
    let usage = wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC;
    let image = texture_2d(device, "depth readback", size, format, usage)?;
    let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("depth readback"),
        layout: &layout,
        entries: &[wgpu::BindGroupEntry {
            binding: 0,
            resource: wgpu::BindingResource::TextureView(&texture.create_view(&Default::default())),
        }],
    });
    let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
        label: Some("depth readback"),
    });
    draw_fullscreen(
        &mut encoder,
        "depth readback",
        &pipeline,
        &[&group],
        &image.view,
    );
    queue.submit([encoder.finish()]);
    let bytes = crate::readback::read_texture_rgba8(device, queue, &image.texture, 0)?;
    Ok(bytemuck::pod_collect_to_vec(&bytes))
}
