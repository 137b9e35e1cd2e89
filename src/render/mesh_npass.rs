//! The mesh baselines: N-pass (one ordinary render per view into its own layer, then mask
//! compositing) and single view (the centre camera straight into the target).
//! Shading is `wgsl/shared/shading.wgsl`, the same the single-pass path uses.

use super::pipeline::{begin_pass, cleared};
use super::renderer::{check_target, Renderer};
use super::texture::{cached_texture_2d, Texture2d};
use super::view_layers::{nearest_depth_test, DEPTH_FORMAT};
use super::{Compositor, ViewLayers};
use crate::camera::ViewUniform;
use crate::error::Result;
use crate::frame::{frame_bind_group_layout, Frame, FrameBinding};
use crate::mesh::MeshBuffers;
use crate::target::{SpatialTarget, SPATIAL_FORMAT};

/// Which baseline to render.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MeshBaselineMethod {
    /// N views into N layers + compositing: the accuracy oracle and the speed baseline.
    NPass,
    /// The centre camera only (what a 2D display would show).
    SingleView,
}

/// N-pass or single-view mesh renderer. Holds pipelines and lazily sized scratch resources.
pub struct MeshBaseline {
    method: MeshBaselineMethod,
    pipeline: wgpu::RenderPipeline,
    view_layout: wgpu::BindGroupLayout,
    frame: FrameBinding,
    compositor: Compositor,
    layers: Option<ViewLayers>,
    single_view_depth: Option<Texture2d>,
    view_uniforms: Option<(wgpu::Buffer, wgpu::BindGroup, u32)>,
    view_stride: u64,
}

impl MeshBaseline {
    /// Build the pipelines for `method`.
    pub fn new(device: &wgpu::Device, method: MeshBaselineMethod) -> Result<Self> {
        let frame_layout = frame_bind_group_layout(device);
        let view_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("view"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: true,
                    min_binding_size: wgpu::BufferSize::new(
                        std::mem::size_of::<ViewUniform>() as u64
                    ),
                },
                count: None,
            }],
        });
        let module = crate::shader::module(device, "mesh_view.wgsl")?;
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("mesh view"),
            bind_group_layouts: &[Some(&frame_layout), Some(&view_layout)],
            immediate_size: 0,
        });
        let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("mesh view"),
            layout: Some(&layout),
            vertex: wgpu::VertexState {
                module: &module,
                entry_point: Some("vs_main"),
                compilation_options: Default::default(),
                buffers: &[Some(MeshBuffers::vertex_layout())],
            },
            // No culling: OBJ winding is not reliable; shading is two-sided.
            primitive: wgpu::PrimitiveState::default(),
            depth_stencil: Some(nearest_depth_test()),
            multisample: Default::default(),
            fragment: Some(wgpu::FragmentState {
                module: &module,
                entry_point: Some("fs_main"),
                compilation_options: Default::default(),
                targets: &[Some(SPATIAL_FORMAT.into())],
            }),
            multiview_mask: None,
            cache: None,
        });
        let align = device.limits().min_uniform_buffer_offset_alignment as u64;
        Ok(Self {
            method,
            pipeline,
            compositor: Compositor::new(device, &frame_layout)?,
            frame: FrameBinding::new(device, &frame_layout),
            view_layout,
            layers: None,
            single_view_depth: None,
            view_uniforms: None,
            view_stride: (std::mem::size_of::<ViewUniform>() as u64).div_ceil(align) * align,
        })
    }

    /// Per-view images of the last N-pass render (layer i = view i), if any.
    pub fn view_layers(&self) -> Option<&ViewLayers> {
        self.layers.as_ref()
    }

    /// N view passes into the layers, then compositing.
    fn encode_npass(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        mesh: &MeshBuffers,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()> {
        frame.validate()?;
        self.frame.write(queue, frame);
        let camera = &frame.camera;
        let offsets: Vec<f32> = (0..camera.views).map(|i| camera.view_offset(i)).collect();
        self.write_views(device, queue, &offsets, |vd| camera.view_uniform(vd));
        if self.layers.as_ref().map(|l| l.key()) != Some((frame.size, camera.views)) {
            self.layers = None; // free before allocating the replacement
            self.layers = Some(ViewLayers::new(device, frame.size, camera.views)?);
        }
        let layers = self.layers.as_ref().expect("allocated above");
        for (i, layer) in layers.layer_views.iter().enumerate() {
            self.draw(encoder, mesh, frame, i as u32, layer, &layers.depth_view);
        }
        self.compositor
            .encode(device, encoder, &self.frame, &layers.array_view, target);
        Ok(())
    }

    /// The centre camera straight into `target`.
    fn encode_single_view(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        mesh: &MeshBuffers,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()> {
        frame.validate()?;
        self.frame.write(queue, frame);
        let camera = &frame.camera;
        self.write_views(device, queue, &[0.0], |vd| camera.view_uniform(vd));
        let depth = self.single_view_depth(device, frame.size);
        self.draw(encoder, mesh, frame, 0, &target.view, &depth);
        Ok(())
    }

    fn single_view_depth(&mut self, device: &wgpu::Device, size: [u32; 2]) -> wgpu::TextureView {
        cached_texture_2d(
            &mut self.single_view_depth,
            device,
            "single-view depth",
            size,
            DEPTH_FORMAT,
            wgpu::TextureUsages::RENDER_ATTACHMENT,
        )
        .clone()
    }

    fn write_views(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        offsets: &[f32],
        uniform: impl Fn(f32) -> ViewUniform,
    ) {
        let count = offsets.len() as u32;
        if self
            .view_uniforms
            .as_ref()
            .is_none_or(|(_, _, c)| *c < count)
        {
            let buffer = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("view uniforms"),
                size: self.view_stride * count as u64,
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("view"),
                layout: &self.view_layout,
                entries: &[wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                        buffer: &buffer,
                        offset: 0,
                        size: wgpu::BufferSize::new(std::mem::size_of::<ViewUniform>() as u64),
                    }),
                }],
            });
            self.view_uniforms = Some((buffer, group, count));
        }
        let mut bytes = vec![0u8; (self.view_stride * count as u64) as usize];
        for (i, &vd) in offsets.iter().enumerate() {
            let at = i * self.view_stride as usize;
            let u = uniform(vd);
            let src = bytemuck::bytes_of(&u);
            bytes[at..at + src.len()].copy_from_slice(src);
        }
        let (buffer, _, _) = self.view_uniforms.as_ref().expect("allocated above");
        queue.write_buffer(buffer, 0, &bytes);
    }

    fn draw(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        mesh: &MeshBuffers,
        frame: &Frame,
        view: u32,
        color: &wgpu::TextureView,
        depth: &wgpu::TextureView,
    ) {
        let (_, view_group, _) = self.view_uniforms.as_ref().expect("written before drawing");
        let mut pass = begin_pass(
            encoder,
            "mesh view",
            cleared(color, frame.background),
            Some(depth),
        );
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(0, &self.frame.bind_group, &[]);
        pass.set_bind_group(1, view_group, &[(view as u64 * self.view_stride) as u32]);
        pass.set_vertex_buffer(0, mesh.vertices.slice(..));
        pass.set_index_buffer(mesh.indices.slice(..), wgpu::IndexFormat::Uint32);
        pass.draw_indexed(0..mesh.index_count, 0, 0..1);
    }
}

impl Renderer<MeshBuffers> for MeshBaseline {
    fn encode(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        mesh: &MeshBuffers,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()> {
        frame.validate()?;
        check_target(frame, target)?;
        match self.method {
            MeshBaselineMethod::NPass => {
                self.encode_npass(device, queue, encoder, mesh, frame, target)
            }
            MeshBaselineMethod::SingleView => {
                self.encode_single_view(device, queue, encoder, mesh, frame, target)
            }
        }
    }
}
