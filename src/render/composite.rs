//! N-pass compositing: `I(x, y, c) = I_view(x,y,c)(x, y, c)` with the display mask.

use super::pipeline::{draw_fullscreen, fullscreen_pipeline};
use crate::error::Result;
use crate::frame::FrameBinding;
use crate::target::{SpatialTarget, SPATIAL_FORMAT};

/// The compositing pipeline (shared by every primitive's N-pass baseline).
pub struct Compositor {
    pipeline: wgpu::RenderPipeline,
    layers_layout: wgpu::BindGroupLayout,
}

impl Compositor {
    /// Build the pipeline; `frame_layout` is the shared group-0 layout.
    pub fn new(device: &wgpu::Device, frame_layout: &wgpu::BindGroupLayout) -> Result<Self> {
        let layers_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("composite layers"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::FRAGMENT,
                ty: wgpu::BindingType::Texture {
                    sample_type: wgpu::TextureSampleType::Float { filterable: false },
                    view_dimension: wgpu::TextureViewDimension::D2Array,
                    multisampled: false,
                },
                count: None,
            }],
        });
        let module = crate::shader::module(device, "render/composite.wgsl")?;
        let pipeline = fullscreen_pipeline(
            device,
            "composite",
            &module,
            &[Some(frame_layout), Some(&layers_layout)],
            SPATIAL_FORMAT,
        );
        Ok(Self {
            pipeline,
            layers_layout,
        })
    }

    /// Record the compositing pass from `layers` (a D2Array view) into `target`.
    pub fn encode(
        &self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        frame: &FrameBinding,
        layers: &wgpu::TextureView,
        target: &SpatialTarget,
    ) {
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("composite layers"),
            layout: &self.layers_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::TextureView(layers),
            }],
        });
        draw_fullscreen(
            encoder,
            "composite",
            &self.pipeline,
            &[&frame.bind_group, &group],
            &target.view,
        );
    }
}
