//! N-pass compositing: `I(x, y, c) = I_view(x,y,c)(x, y, c)` with the display mask. Layers of
//! the target's size are read texel for texel; smaller ones (the view images of
//! `Frame::view_scale`) are up-sampled bilinearly (`wgsl/shared/upsample.wgsl`).

use bytemuck::{Pod, Zeroable};

use crate::error::Result;
use crate::frame::FrameBinding;
use crate::gpu::pipeline::{draw_fullscreen, fullscreen_pipeline, fullscreen_pipeline_to};
use crate::target::{SpatialTarget, SPATIAL_FORMAT};

/// Keep in sync with `struct Composite` in `wgsl/render/composite.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct CompositeUniform {
    /// The spatial image's size.
    pub panel: [u32; 2],
    /// Padding.
    pub _pad: [u32; 2],
}
crate::shader::gpu_layout!(CompositeUniform, "Composite", [panel]);

/// The compositing pipelines (shared by every primitive's N-pass baseline).
pub struct Compositor {
    /// Layers of the target's size.
    pipeline: wgpu::RenderPipeline,
    /// Smaller layers, up-sampled.
    scaled: wgpu::RenderPipeline,
    layers_layout: wgpu::BindGroupLayout,
}

impl Compositor {
    /// Build the pipelines; `frame_layout` is the shared group-0 layout.
    pub fn new(device: &wgpu::Device, frame_layout: &wgpu::BindGroupLayout) -> Result<Self> {
        let layers_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("composite layers"),
            entries: &[
                wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Texture {
                        sample_type: wgpu::TextureSampleType::Float { filterable: false },
                        view_dimension: wgpu::TextureViewDimension::D2Array,
                        multisampled: false,
                    },
                    count: None,
                },
                crate::gpu::pipeline::uniform_entry(1, wgpu::ShaderStages::FRAGMENT),
            ],
        });
        let module = crate::shader::module(device, "render/composite.wgsl")?;
        let layouts = [Some(frame_layout), Some(&layers_layout)];
        let pipeline = fullscreen_pipeline(device, "composite", &module, &layouts, SPATIAL_FORMAT);
        let scaled = fullscreen_pipeline_to(
            device,
            "composite up-sampled",
            &module,
            &layouts,
            ("fs_scaled", &[Some(SPATIAL_FORMAT.into())]),
            &[],
        );
        Ok(Self {
            pipeline,
            scaled,
            layers_layout,
        })
    }

    /// Record the compositing pass from `layers` (a D2Array view of `layers_size` texels per
    /// layer) into `target`.
    pub fn encode(
        &self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        frame: &FrameBinding,
        layers: &wgpu::TextureView,
        layers_size: [u32; 2],
        target: &SpatialTarget,
    ) {
        let uniform = CompositeUniform {
            panel: target.size(),
            _pad: [0; 2],
        };
        let constants = crate::gpu::pass_params::constants_buffer(
            device,
            "composite",
            wgpu::BufferUsages::UNIFORM,
            bytemuck::bytes_of(&uniform),
        );
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("composite layers"),
            layout: &self.layers_layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(layers),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: constants.as_entire_binding(),
                },
            ],
        });
        let pipeline = if layers_size == target.size() {
            &self.pipeline
        } else {
            &self.scaled
        };
        draw_fullscreen(
            encoder,
            "composite",
            pipeline,
            &[&frame.bind_group, &group],
            &target.view,
        );
    }
}
