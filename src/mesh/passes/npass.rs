//! The mesh baselines: N-pass (one ordinary render per view into its own layer, then mask
//! compositing) and single view (the centre camera straight into the target); and, with the
//! same passes, a warp's reference views with their nearness (src/warp).
//! Shading is `wgsl/shared/shading.wgsl`, the same the single-pass path uses.

use super::duplicate::{mesh_pipeline, Shading};
use crate::camera::ViewUniform;
use crate::error::Result;
use crate::frame::{frame_bind_group_layout, Frame, FrameBinding};
use crate::gpu::pass_params::PassParams;
use crate::gpu::pipeline::{begin_pass_to, cleared, PassTargets};
use crate::gpu::texture::{cached_texture_2d, Texture2d};
use crate::mesh::texture_buffers::TEXTURE_GROUP;
use crate::mesh::MeshBuffers;
use crate::param::Param;
use crate::render::npass::NPassHarness;
use crate::render::view_layers::DEPTH_FORMAT;
use crate::render::Method;
use crate::render::ViewLayers;
use crate::render::{begin_prepare, check_target, prepared_state, Made, Prepared, Renderer};
use crate::target::{SpatialTarget, SPATIAL_FORMAT};
use crate::warp::references::{ReferenceImages, ReferenceRenderer, REFERENCE_NEARNESS_FORMAT};

/// N-pass or single-view mesh renderer. Holds pipelines and lazily sized scratch resources.
pub struct MeshNPass {
    method: Method,
    /// Without textures and with (`MeshBuffers::textured`).
    pipelines: [wgpu::RenderPipeline; 2],
    view_layout: wgpu::BindGroupLayout,
    frame: FrameBinding,
    npass: NPassHarness,
    /// This frame's view uniforms (one per view, dynamic offsets).
    views: PassParams<ViewUniform>,
    /// What `prepare` made for its frame: the single view's depth (`None` for the others).
    prepared: Option<Prepared<PreparedFor, Option<Texture2d>>>,
    /// The parallel camera model's crop, recorded last.
    crop: crate::render::camera_crop::CameraCrop,
}

impl MeshNPass {
    /// Build the pipelines for `method`: [`Method::NPass`] or [`Method::SingleView`] (the mesh
    /// single pass is [`crate::mesh::MeshSinglePass`]).
    pub fn new(device: &wgpu::Device, method: Method) -> Result<Self> {
        if !matches!(method, Method::NPass | Method::SingleView | Method::Warp) {
            return Err(crate::Error::invalid(
                Param::Method,
                format!(
                    "{method}: MeshNPass renders n-pass, single-view and a warp's references; \
                     use MeshSinglePass"
                ),
            ));
        }
        let frame_layout = frame_bind_group_layout(device);
        let view_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("view"),
            entries: &[PassParams::<ViewUniform>::layout_entry(
                0,
                wgpu::ShaderStages::VERTEX_FRAGMENT,
            )],
        });
        let module = crate::shader::module(device, "mesh/npass.wgsl")?;
        let textures = crate::mesh::texture_buffers::texture_bind_group_layout(device);
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("mesh view"),
            bind_group_layouts: &[
                Some(&frame_layout),
                Some(&view_layout),
                None,
                Some(&textures),
            ],
            immediate_size: 0,
        });
        // A warp's references write their nearness too (fs_reference), else the colour only.
        let (entry, targets): (_, &[_]) = if method == Method::Warp {
            (
                "fs_reference",
                &[
                    Some(SPATIAL_FORMAT.into()),
                    Some(REFERENCE_NEARNESS_FORMAT.into()),
                ],
            )
        } else {
            ("fs_main", &[Some(SPATIAL_FORMAT.into())])
        };
        let pipeline = |textured: bool| {
            let shading = Shading {
                fragment: entry,
                textured,
            };
            mesh_pipeline(
                device,
                "mesh N-pass",
                &module,
                &layout,
                targets,
                None,
                shading,
            )
        };
        Ok(Self {
            method,
            pipelines: [pipeline(false)?, pipeline(true)?],
            npass: NPassHarness::new(device, &frame_layout)?,
            frame: FrameBinding::new(device, &frame_layout),
            view_layout,
            views: PassParams::new(device, "view uniforms"),
            prepared: None,
            crop: crate::render::camera_crop::CameraCrop::new(device)?,
        })
    }

    /// Per-view images of the last N-pass render (layer i = view i), if any.
    pub fn view_layers(&self) -> Option<&ViewLayers> {
        self.npass.view_layers()
    }

    /// N view passes into the layers, then compositing.
    fn encode_npass(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        mesh: &MeshBuffers,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()> {
        let views = self.write_frame_views(device, &frame.for_view_images());
        let layers = self.npass.layers()?;
        for (i, layer) in layers.layer_views.iter().enumerate() {
            let view = (&views, i as u32);
            self.draw(encoder, mesh, frame, view, layer, &layers.depth_view);
        }
        self.npass.composite(device, encoder, &self.frame, target)?;
        self.crop.encode(device, encoder, frame, target);
        Ok(())
    }

    /// The centre camera straight into `target`.
    fn encode_single_view(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        mesh: &MeshBuffers,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()> {
        self.frame.write(device, frame);
        let camera = &frame.camera;
        let views = self.write_views(device, &[0.0], |vd| camera.view_uniform(vd));
        let depth = self
            .prepared
            .as_ref()
            .and_then(|p| p.made.as_ref())
            .made("MeshNPass single-view depth")?
            .view
            .clone();
        self.draw(encoder, mesh, frame, (&views, 0), &target.view, &depth);
        Ok(())
    }

    /// This frame's constants and the uniforms of every view of its camera; returns the view
    /// uniforms' bind group.
    fn write_frame_views(&mut self, device: &wgpu::Device, frame: &Frame) -> wgpu::BindGroup {
        self.frame.write(device, frame);
        let camera = &frame.camera;
        let offsets: Vec<f32> = (0..camera.views).map(|i| camera.view_offset(i)).collect();
        self.write_views(device, &offsets, |vd| camera.view_uniform(vd))
    }

    /// This frame's view uniforms (`src/gpu/pass_params.rs`) and their bind group, which
    /// every draw of the frame takes.
    fn write_views(
        &mut self,
        device: &wgpu::Device,
        offsets: &[f32],
        uniform: impl Fn(f32) -> ViewUniform,
    ) -> wgpu::BindGroup {
        let views: Vec<ViewUniform> = offsets.iter().map(|&vd| uniform(vd)).collect();
        self.views.write(device, &views);
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("view"),
            layout: &self.view_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: self.views.binding(),
            }],
        })
    }

    fn draw(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        mesh: &MeshBuffers,
        frame: &Frame,
        view: (&wgpu::BindGroup, u32),
        color: &wgpu::TextureView,
        depth: &wgpu::TextureView,
    ) {
        self.draw_to(
            encoder,
            mesh,
            view,
            &[Some(cleared(color, frame.background))],
            depth,
        );
    }

    /// Draw view `view` (the frame's view uniforms' bind group, the view's index) into `colors`
    /// (the colour, and a reference's nearness) and `depth`.
    fn draw_to(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        mesh: &MeshBuffers,
        (view_group, view): (&wgpu::BindGroup, u32),
        colors: &[Option<wgpu::RenderPassColorAttachment<'_>>],
        depth: &wgpu::TextureView,
    ) {
        let mut pass = begin_pass_to(
            encoder,
            "mesh view",
            PassTargets {
                colors,
                depth: Some(depth),
                keep_depth: false,
                multiview_mask: None,
            },
        );
        pass.set_pipeline(&self.pipelines[mesh.textured as usize]);
        pass.set_bind_group(0, &self.frame.bind_group, &[]);
        pass.set_bind_group(1, view_group, &[self.views.offset(view as usize)]);
        pass.set_bind_group(TEXTURE_GROUP, &mesh.textures.bind_group, &[]);
        pass.set_vertex_buffer(0, mesh.vertices.slice(..));
        pass.set_index_buffer(mesh.indices.slice(..), wgpu::IndexFormat::Uint32);
        pass.draw_indexed(0..mesh.index_count, 0, 0..1);
    }
}

/// What a [`MeshNPass`] was prepared for: the frame's size and views.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct PreparedFor {
    size: [u32; 2],
    views: u32,
    /// The view images' size ([`Frame::view_size`]).
    view_size: [u32; 2],
}

impl PreparedFor {
    pub(crate) fn of(frame: &Frame) -> Self {
        Self {
            size: frame.size,
            views: frame.camera.views,
            view_size: frame.view_size(),
        }
    }
}

impl Renderer<MeshBuffers> for MeshNPass {
    fn prepare(
        &mut self,
        device: &wgpu::Device,
        _queue: &wgpu::Queue,
        _mesh: &MeshBuffers,
        frame: &Frame,
    ) -> Result<()> {
        let mut depth = self.prepared.take().and_then(|p| p.made);
        begin_prepare(device, frame, &mut self.prepared)?;
        match self.method {
            Method::NPass => {
                depth = None;
                self.npass.prepare(device, frame)?
            }
            Method::Warp => return Err(crate::warp::references::not_a_frame_renderer("MeshNPass")),
            _ => {
                frame.check_full_views("single-view")?;
                // The last frame's depth where it fits, else a new one.
                cached_texture_2d(
                    &mut depth,
                    device,
                    "single-view depth",
                    frame.size,
                    DEPTH_FORMAT,
                    wgpu::TextureUsages::RENDER_ATTACHMENT,
                )?;
            }
        }
        self.prepared = Some(Prepared {
            key: PreparedFor::of(frame),
            made: depth,
        });
        Ok(())
    }

    fn encode(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        mesh: &MeshBuffers,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()> {
        check_target(frame, target)?;
        prepared_state("MeshNPass", &self.prepared, &PreparedFor::of(frame))?;
        match self.method {
            Method::NPass => self.encode_npass(device, encoder, mesh, frame, target),
            _ => self.encode_single_view(device, encoder, mesh, frame, target),
        }
    }
}

impl ReferenceRenderer<MeshBuffers> for MeshNPass {
    fn prepare_references(
        &mut self,
        device: &wgpu::Device,
        _queue: &wgpu::Queue,
        _mesh: &MeshBuffers,
        frame: &Frame,
    ) -> Result<()> {
        begin_prepare(device, frame, &mut self.prepared)?;
        crate::warp::references::check_reference_method("MeshNPass", self.method)?;
        self.prepared = Some(Prepared {
            key: PreparedFor::of(frame),
            made: None,
        });
        Ok(())
    }

    fn encode_references(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        mesh: &MeshBuffers,
        frame: &Frame,
        images: &ReferenceImages,
    ) -> Result<()> {
        prepared_state("MeshNPass", &self.prepared, &PreparedFor::of(frame))?;
        let views = self.write_frame_views(device, frame);
        let layers = images.color.layer_views.iter();
        for (j, (color, nearness)) in layers.zip(&images.nearness.layer_views).enumerate() {
            let colors = [
                Some(cleared(color, frame.background)),
                Some(cleared(nearness, [0.0; 4])),
            ];
            let view = (&views, j as u32);
            self.draw_to(encoder, mesh, view, &colors, &images.color.depth_view);
        }
        Ok(())
    }

    fn depth_meaning(&self) -> &'static str {
        "the nearest triangle's depth"
    }
}
