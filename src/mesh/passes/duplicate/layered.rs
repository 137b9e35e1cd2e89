//! Layered duplication (Beck et al.): the mesh drawn once per pass into several layers of a
//! texture array at once (wgpu multiview: `@builtin(view_index)` picks the layer's camera),
//! each layer with its own depth, then the N-pass compositing. The adapter caps the layers per
//! pass (`max_multiview_view_count`, 6 on lavapipe): the views are split into as few passes as
//! that allows ([`MeshLayered::views_per_pass`]). Without multiview (GL) nothing can route one
//! draw to several layers, so the method is one pass per layer: the N-pass renderer itself.

use super::{batches, draw_mesh, mesh_pipeline, BatchedViews, BoundBatches, Shading};
use crate::error::Result;
use crate::frame::{frame_bind_group_layout, Frame, FrameBinding};
use crate::gpu::pipeline::{begin_pass_to, cleared, multiview_mask, PassTargets};
use crate::mesh::passes::npass::{MeshNPass, PreparedFor};
use crate::mesh::texture_buffers::{texture_bind_group_layout, TEXTURE_GROUP};
use crate::mesh::MeshBuffers;
use crate::render::npass::NPassHarness;
use crate::render::pipeline_cache::PipelineCache;
use crate::render::view_layers::{depth_array, layer_range};
use crate::render::{begin_prepare, check_target, prepared_state, Method, Prepared, Renderer};
use crate::target::{SpatialTarget, SPATIAL_FORMAT};

/// The layered mesh renderer: multiview where the adapter has it, else one pass per layer.
pub struct MeshLayered {
    path: Path,
}

#[allow(clippy::large_enum_variant)]
enum Path {
    Multiview(Multiview),
    PerLayer(MeshNPass),
}

impl MeshLayered {
    /// Multiview if `device` has it (and at least 2 views per pass), else one pass per layer.
    pub fn new(device: &wgpu::Device) -> Result<Self> {
        let path = match Self::views_per_pass_on(device) {
            1 => Path::PerLayer(MeshNPass::new(device, Method::NPass)?),
            max => Path::Multiview(Multiview::new(device, max)?),
        };
        Ok(Self { path })
    }

    /// Layers one pass renders on `device`: the adapter's multiview limit, or 1 without
    /// multiview (or with a limit below 2).
    pub fn views_per_pass_on(device: &wgpu::Device) -> u32 {
        let max = device.limits().max_multiview_view_count;
        match device.features().contains(wgpu::Features::MULTIVIEW) && max >= 2 {
            true => max,
            false => 1,
        }
    }

    /// How this adapter renders the layers, in words (reports, the CLI).
    pub fn describe(&self) -> String {
        match &self.path {
            Path::Multiview(m) => format!(
                "multiview, at most {} layers per pass (the adapter's limit)",
                m.views.max_per_pass
            ),
            Path::PerLayer(_) => {
                "one pass per layer: the adapter has no multiview (MULTIVIEW)".to_string()
            }
        }
    }
}

/// The multiview path's pipelines and scratch.
struct Multiview {
    views: BatchedViews,
    layout: wgpu::PipelineLayout,
    frame: FrameBinding,
    /// By layers per pass.
    pipelines: PipelineCache<(u32, Shading), wgpu::RenderPipeline>,
    npass: NPassHarness,
    /// The prepared frame's depth array: one depth layer per layer of a pass.
    prepared: Option<Prepared<PreparedFor, crate::render::view_layers::DepthArray>>,
    /// The parallel camera model's crop, recorded last.
    crop: crate::render::camera_crop::CameraCrop,
}

impl Multiview {
    fn new(device: &wgpu::Device, max_per_pass: u32) -> Result<Self> {
        let frame_layout = frame_bind_group_layout(device);
        let views = BatchedViews::new(device, "layered views", max_per_pass);
        let layout = crate::gpu::pipeline::pipeline_layout(
            device,
            "mesh layered",
            &[
                Some(&frame_layout),
                Some(&views.layout),
                None,
                Some(&texture_bind_group_layout(device)),
            ],
        );
        Ok(Self {
            views,
            layout,
            pipelines: PipelineCache::new("mesh layered"),
            npass: NPassHarness::new(device, &frame_layout)?,
            frame: FrameBinding::new(device, &frame_layout),
            prepared: None,
            crop: crate::render::camera_crop::CameraCrop::new(device)?,
        })
    }

    fn prepare(&mut self, device: &wgpu::Device, mesh: &MeshBuffers, frame: &Frame) -> Result<()> {
        let last = self.prepared.take().map(|p| p.made);
        begin_prepare(device, frame, &mut self.prepared)?;
        self.npass.prepare(device, frame)?;
        let passes = batches(frame.camera.views, self.views.max_per_pass);
        let deepest = passes.iter().map(|r| r.len() as u32).max().unwrap_or(1);
        let depth = depth_array(last, device, frame.view_size(), deepest)?;
        for layers in passes.iter().map(|r| r.len() as u32) {
            let layout = &self.layout;
            let shading = Shading::of(mesh);
            self.pipelines
                .prepare(device, (layers, shading), |modules| {
                    let module = modules.get(device, "mesh/layered.wgsl")?;
                    let targets = [Some(SPATIAL_FORMAT.into())];
                    let mask = multiview_mask(layers);
                    mesh_pipeline(
                        device,
                        "mesh layered",
                        &module,
                        layout,
                        &targets,
                        mask,
                        shading,
                    )
                })?;
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
        let depth = &prepared_state("MeshLayered", &self.prepared, &PreparedFor::of(frame))?
            .made
            .texture;
        self.frame.write(device, &frame.for_view_images());
        let BoundBatches { passes, group } = self.views.bind(device, &frame.camera);
        let layers = &self.npass.layers()?.texture;
        for (i, range) in passes.iter().enumerate() {
            let count = range.len() as u32;
            let color = layer_range(layers, range.start, count);
            let depth = layer_range(depth, 0, count);
            let mut pass = begin_pass_to(
                encoder,
                "mesh layered",
                PassTargets {
                    colors: &[Some(cleared(&color, frame.background))],
                    depth: Some(&depth),
                    keep_depth: false,
                    multiview_mask: multiview_mask(count),
                },
            );
            pass.set_pipeline(self.pipelines.get(&(count, Shading::of(mesh)))?);
            pass.set_bind_group(0, &self.frame.bind_group, &[]);
            pass.set_bind_group(1, &group, &[self.views.offset(i)]);
            pass.set_bind_group(TEXTURE_GROUP, &mesh.textures.bind_group, &[]);
            draw_mesh(&mut pass, mesh, 1);
        }
        self.npass.composite(device, encoder, &self.frame, target)?;
        self.crop.encode(device, encoder, frame, target);
        Ok(())
    }
}

impl Renderer<MeshBuffers> for MeshLayered {
    fn prepare(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        mesh: &MeshBuffers,
        frame: &Frame,
    ) -> Result<()> {
        match &mut self.path {
            Path::Multiview(m) => m.prepare(device, mesh, frame),
            Path::PerLayer(n) => n.prepare(device, queue, mesh, frame),
        }
    }

    fn encode(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        mesh: &MeshBuffers,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()> {
        match &mut self.path {
            Path::Multiview(m) => m.encode(device, encoder, mesh, frame, target),
            Path::PerLayer(n) => n.encode(device, encoder, mesh, frame, target),
        }
    }
}
