//! Small helpers shared by the pipelines.

/// A render pipeline for a full-screen triangle (`vs_fullscreen` / `fs_main`, no vertex buffers).
pub(crate) fn fullscreen_pipeline(
    device: &wgpu::Device,
    label: &str,
    module: &wgpu::ShaderModule,
    layouts: &[Option<&wgpu::BindGroupLayout>],
    format: wgpu::TextureFormat,
) -> wgpu::RenderPipeline {
    fullscreen_pipeline_with(device, label, module, layouts, format, &[])
}

/// [`fullscreen_pipeline`] with override constants.
pub(crate) fn fullscreen_pipeline_with(
    device: &wgpu::Device,
    label: &str,
    module: &wgpu::ShaderModule,
    layouts: &[Option<&wgpu::BindGroupLayout>],
    format: wgpu::TextureFormat,
    constants: &[(&str, f64)],
) -> wgpu::RenderPipeline {
    fullscreen_pipeline_to(
        device,
        label,
        module,
        layouts,
        ("fs_main", &[Some(format.into())]),
        constants,
    )
}

/// [`fullscreen_pipeline_with`] of fragment entry point `fragment.0` writing the targets
/// `fragment.1` (several render targets).
pub(crate) fn fullscreen_pipeline_to(
    device: &wgpu::Device,
    label: &str,
    module: &wgpu::ShaderModule,
    layouts: &[Option<&wgpu::BindGroupLayout>],
    fragment: (&str, &[Option<wgpu::ColorTargetState>]),
    constants: &[(&str, f64)],
) -> wgpu::RenderPipeline {
    let options = compilation(constants);
    let layout = pipeline_layout(device, label, layouts);
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(label),
        layout: Some(&layout),
        vertex: wgpu::VertexState {
            module,
            entry_point: Some("vs_fullscreen"),
            compilation_options: options.clone(),
            buffers: &[],
        },
        primitive: wgpu::PrimitiveState::default(),
        depth_stencil: None,
        multisample: wgpu::MultisampleState::default(),
        fragment: Some(wgpu::FragmentState {
            module,
            entry_point: Some(fragment.0),
            compilation_options: options,
            targets: fragment.1,
        }),
        multiview_mask: None,
        cache: None,
    })
}

/// A pipeline of instanced quads (`vs_main`, six vertices each, no vertex buffers) whose
/// `fs_main` blends "over" what is in the `format` target with one α per channel (dual-source
/// blending: `dst = color + (1 − α_c)·dst`): the volume slices' and the Gaussians' passes.
pub(crate) fn over_per_channel_pipeline(
    device: &wgpu::Device,
    label: &str,
    layout: &wgpu::PipelineLayout,
    module: &wgpu::ShaderModule,
    constants: &[(&str, f64)],
    format: wgpu::TextureFormat,
) -> wgpu::RenderPipeline {
    let options = compilation(constants);
    let over = wgpu::BlendComponent {
        src_factor: wgpu::BlendFactor::One,
        dst_factor: wgpu::BlendFactor::OneMinusSrc1,
        operation: wgpu::BlendOperation::Add,
    };
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(label),
        layout: Some(layout),
        vertex: wgpu::VertexState {
            module,
            entry_point: Some("vs_main"),
            compilation_options: options.clone(),
            buffers: &[],
        },
        primitive: wgpu::PrimitiveState::default(),
        depth_stencil: None,
        multisample: Default::default(),
        fragment: Some(wgpu::FragmentState {
            module,
            entry_point: Some("fs_main"),
            compilation_options: options,
            targets: &[Some(wgpu::ColorTargetState {
                format,
                blend: Some(wgpu::BlendState {
                    color: over,
                    alpha: over,
                }),
                write_mask: wgpu::ColorWrites::ALL,
            })],
        }),
        multiview_mask: None,
        cache: None,
    })
}

/// Compilation options with `constants` (the overrides of `wgsl/shared/multiview.wgsl` and
/// the stage's own) and zeroed workgroup memory: every pipeline of the crate compiles so.
pub(crate) fn compilation<'a>(
    constants: &'a [(&'a str, f64)],
) -> wgpu::PipelineCompilationOptions<'a> {
    wgpu::PipelineCompilationOptions {
        constants,
        zero_initialize_workgroup_memory: true,
    }
}

/// A bind group layout of `entries`.
pub(crate) fn bind_group_layout(
    device: &wgpu::Device,
    label: &str,
    entries: &[wgpu::BindGroupLayoutEntry],
) -> wgpu::BindGroupLayout {
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some(label),
        entries,
    })
}

/// A pipeline layout of `groups` (no immediates).
pub(crate) fn pipeline_layout(
    device: &wgpu::Device,
    label: &str,
    groups: &[Option<&wgpu::BindGroupLayout>],
) -> wgpu::PipelineLayout {
    device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some(label),
        bind_group_layouts: groups,
        immediate_size: 0,
    })
}

/// A colour attachment cleared to `clear`.
pub(crate) fn cleared(
    view: &wgpu::TextureView,
    clear: [f32; 4],
) -> wgpu::RenderPassColorAttachment<'_> {
    wgpu::RenderPassColorAttachment {
        view,
        depth_slice: None,
        resolve_target: None,
        ops: wgpu::Operations {
            load: wgpu::LoadOp::Clear(wgpu::Color {
                r: clear[0] as f64,
                g: clear[1] as f64,
                b: clear[2] as f64,
                a: clear[3] as f64,
            }),
            store: wgpu::StoreOp::Store,
        },
    }
}

/// A colour attachment that keeps what the texture holds (a pass that writes part of it).
pub(crate) fn kept(view: &wgpu::TextureView) -> wgpu::RenderPassColorAttachment<'_> {
    wgpu::RenderPassColorAttachment {
        view,
        depth_slice: None,
        resolve_target: None,
        ops: wgpu::Operations {
            load: wgpu::LoadOp::Load,
            store: wgpu::StoreOp::Store,
        },
    }
}

/// Begin a render pass writing `color`, with `depth` (if any) cleared to the far plane and
/// discarded at the end: the one pass shape every render pass of the crate has.
pub(crate) fn begin_pass<'e>(
    encoder: &'e mut wgpu::CommandEncoder,
    label: &str,
    color: wgpu::RenderPassColorAttachment<'_>,
    depth: Option<&wgpu::TextureView>,
) -> wgpu::RenderPass<'e> {
    begin_pass_to(
        encoder,
        label,
        PassTargets {
            colors: &[Some(color)],
            depth,
            keep_depth: false,
            multiview_mask: None,
        },
    )
}

/// What a render pass writes: colour attachments, a depth buffer (cleared to the far plane;
/// kept after the pass if `keep_depth`) and the multiview layers, if any.
pub(crate) struct PassTargets<'a> {
    pub colors: &'a [Option<wgpu::RenderPassColorAttachment<'a>>],
    pub depth: Option<&'a wgpu::TextureView>,
    pub keep_depth: bool,
    pub multiview_mask: Option<std::num::NonZeroU32>,
}

/// Begin a render pass writing `targets` ([`begin_pass`] in general).
pub(crate) fn begin_pass_to<'e>(
    encoder: &'e mut wgpu::CommandEncoder,
    label: &str,
    targets: PassTargets<'_>,
) -> wgpu::RenderPass<'e> {
    let store = if targets.keep_depth {
        wgpu::StoreOp::Store
    } else {
        wgpu::StoreOp::Discard
    };
    encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some(label),
        color_attachments: targets.colors,
        depth_stencil_attachment: targets.depth.map(|view| {
            wgpu::RenderPassDepthStencilAttachment {
                view,
                depth_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Clear(1.0),
                    store,
                }),
                stencil_ops: None,
            }
        }),
        timestamp_writes: None,
        occlusion_query_set: None,
        multiview_mask: targets.multiview_mask,
    })
}

/// Draw a full-screen triangle into `target` with `pipeline` and the given bind groups.
pub(crate) fn draw_fullscreen(
    encoder: &mut wgpu::CommandEncoder,
    label: &str,
    pipeline: &wgpu::RenderPipeline,
    bind_groups: &[&wgpu::BindGroup],
    target: &wgpu::TextureView,
) {
    let mut pass = begin_pass(encoder, label, cleared(target, [0.0; 4]), None);
    pass.set_pipeline(pipeline);
    for (i, group) in bind_groups.iter().enumerate() {
        pass.set_bind_group(i as u32, *group, &[]);
    }
    pass.draw(0..3, 0..1);
}

/// A uniform-buffer entry (no dynamic offset) of a bind group layout.
pub(crate) fn uniform_entry(
    binding: u32,
    stages: wgpu::ShaderStages,
) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: stages,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Uniform,
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    }
}

/// A storage-buffer entry of a bind group layout.
pub(crate) fn storage_entry(
    binding: u32,
    read_only: bool,
    stages: wgpu::ShaderStages,
) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: stages,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Storage { read_only },
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    }
}

/// The multiview mask of `layers` layers: the lowest `layers` bits.
pub(crate) fn multiview_mask(layers: u32) -> Option<std::num::NonZeroU32> {
    std::num::NonZeroU32::new(u32::MAX >> (32 - layers.clamp(1, 32)))
}

#[cfg(test)]
mod tests {
    #[test]
    fn masks_have_the_lowest_bits() {
        assert_eq!(super::multiview_mask(1).unwrap().get(), 1);
        assert_eq!(super::multiview_mask(6).unwrap().get(), 0b11_1111);
        assert_eq!(super::multiview_mask(32).unwrap().get(), u32::MAX);
    }
}
