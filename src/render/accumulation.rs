//! The copy of an RGBA16F accumulation target (already composited over the background) into
//! an RGBA8 image: the passes that blend hundreds of layers in float (the volume slices, the
//! Gaussians) end with it (`wgsl/render/accumulation_resolve.wgsl`).

use crate::error::Result;
use crate::frame::FrameBinding;
use crate::gpu::pipeline::{bind_group_layout, draw_fullscreen, fullscreen_pipeline};
use crate::gpu::texture::texture_2d_layout_entry;
use crate::target::SPATIAL_FORMAT;

/// The resolve pipeline and its layout.
pub(crate) struct AccumulationResolve {
    layout: wgpu::BindGroupLayout,
    pipeline: wgpu::RenderPipeline,
}

impl AccumulationResolve {
    /// `frame_layout` is the shared group-0 layout.
    pub fn new(device: &wgpu::Device, frame_layout: &wgpu::BindGroupLayout) -> Result<Self> {
        let layout = bind_group_layout(
            device,
            "accumulation",
            &[texture_2d_layout_entry(0, wgpu::ShaderStages::FRAGMENT)],
        );
        let module = crate::shader::module(device, "render/accumulation_resolve.wgsl")?;
        let pipeline = crate::gpu::checked(device, "building the accumulation resolve", || {
            fullscreen_pipeline(
                device,
                "accumulation resolve",
                &module,
                &[Some(frame_layout), Some(&layout)],
                SPATIAL_FORMAT,
            )
        })?;
        Ok(Self { layout, pipeline })
    }

    /// Record the copy of `accumulation` into `target` (an RGBA8 view of the same size).
    pub fn encode(
        &self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        frame: &FrameBinding,
        accumulation: &wgpu::TextureView,
        target: &wgpu::TextureView,
    ) {
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("accumulation"),
            layout: &self.layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::TextureView(accumulation),
            }],
        });
        draw_fullscreen(
            encoder,
            "accumulation resolve",
            &self.pipeline,
            &[&frame.bind_group, &group],
            target,
        );
    }
}
