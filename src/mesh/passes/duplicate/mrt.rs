//! MRT duplication (de Sorbier, Nozick & Biri): per pass, one instanced draw of up to 8 views'
//! copies of the mesh over the whole image, each copy's fragments written with α = 1 to its
//! own render target and α = 0 (blended away) to the others; the targets are layers of the
//! N-pass's array and share one depth buffer, as in the paper. That sharing is the method's
//! error: a nearer fragment of one view hides farther ones of the other views of its pass
//! (measured against the N-pass in tests/meshes/duplication.rs).

use super::{batches, draw_mesh, mesh_pipeline, BatchedViews, BoundBatches, Shading};
use crate::error::Result;
use crate::frame::{frame_bind_group_layout, Frame, FrameBinding};
use crate::gpu::pipeline::{begin_pass_to, cleared, pipeline_layout, PassTargets};
use crate::mesh::passes::npass::PreparedFor;
use crate::mesh::texture_buffers::{texture_bind_group_layout, TEXTURE_GROUP};
use crate::mesh::MeshBuffers;
use crate::render::npass::NPassHarness;
use crate::render::pipeline_cache::PipelineCache;
use crate::render::ViewLayers;
use crate::render::{begin_prepare, check_prepared, check_target, Renderer};
use crate::target::{SpatialTarget, SPATIAL_FORMAT};

/// Most render targets the paper (and `wgsl/mesh/mrt.wgsl`) writes per pass.
pub const MAX_TARGETS: u32 = 8;

/// The MRT mesh renderer.
pub struct MeshMrt {
    views: BatchedViews,
    layout: wgpu::PipelineLayout,
    frame: FrameBinding,
    /// By render targets per pass.
    pipelines: PipelineCache<(u32, Shading), wgpu::RenderPipeline>,
    npass: NPassHarness,
    prepared: Option<PreparedFor>,
    /// The parallel camera model's crop, recorded last.
    crop: crate::render::camera_crop::CameraCrop,
}

impl MeshMrt {
    /// Layouts; pipelines are built per target count by `prepare`.
    pub fn new(device: &wgpu::Device) -> Result<Self> {
        let limits = device.limits();
        let bytes_per_target = 4; // RGBA8
        let max_per_pass = MAX_TARGETS
            .min(limits.max_color_attachments)
            .min(limits.max_color_attachment_bytes_per_sample / bytes_per_target)
            .max(1);
        let frame_layout = frame_bind_group_layout(device);
        let views = BatchedViews::new(device, "mrt views", max_per_pass);
        let layout = pipeline_layout(
            device,
            "mesh mrt",
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
            pipelines: PipelineCache::new("mesh mrt"),
            npass: NPassHarness::new(device, &frame_layout)?,
            frame: FrameBinding::new(device, &frame_layout),
            prepared: None,
            crop: crate::render::camera_crop::CameraCrop::new(device)?,
        })
    }

    /// Views one pass renders (render targets): 8, or fewer where the adapter allows fewer.
    pub fn views_per_pass(&self) -> u32 {
        self.views.max_per_pass
    }

    /// Per-view images of the last frame (layer i = view i), if any.
    pub fn view_layers(&self) -> Option<&ViewLayers> {
        self.npass.view_layers()
    }
}

impl Renderer<MeshBuffers> for MeshMrt {
    fn prepare(
        &mut self,
        device: &wgpu::Device,
        _queue: &wgpu::Queue,
        mesh: &MeshBuffers,
        frame: &Frame,
    ) -> Result<()> {
        begin_prepare(device, frame, &mut self.prepared)?;
        self.npass.prepare(device, frame)?;
        for range in batches(frame.camera.views, self.views.max_per_pass) {
            let targets = range.len() as u32;
            let layout = &self.layout;
            let shading = Shading::of(mesh);
            self.pipelines
                .prepare(device, (targets, shading), |modules| {
                    let module = modules.get(device, "mesh/mrt.wgsl")?;
                    let blended = Some(wgpu::ColorTargetState {
                        format: SPATIAL_FORMAT,
                        blend: Some(wgpu::BlendState::ALPHA_BLENDING),
                        write_mask: wgpu::ColorWrites::ALL,
                    });
                    let states = vec![blended; targets as usize];
                    mesh_pipeline(device, "mesh mrt", &module, layout, &states, None, shading)
                })?;
        }
        self.prepared = Some(PreparedFor::of(frame));
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
        check_prepared("MeshMrt", &self.prepared, &PreparedFor::of(frame))?;
        self.frame.write(device, &frame.for_view_images());
        let BoundBatches { passes, group } = self.views.bind(device, &frame.camera);
        let layers = self.npass.layers()?;
        for (i, range) in passes.iter().enumerate() {
            let colors: Vec<_> = layers.layer_views[range.start as usize..range.end as usize]
                .iter()
                .map(|view| Some(cleared(view, frame.background)))
                .collect();
            let mut pass = begin_pass_to(
                encoder,
                "mesh mrt",
                PassTargets {
                    colors: &colors,
                    depth: Some(&layers.depth_view),
                    keep_depth: false,
                    multiview_mask: None,
                },
            );
            let targets = range.len() as u32;
            pass.set_pipeline(self.pipelines.get(&(targets, Shading::of(mesh)))?);
            pass.set_bind_group(0, &self.frame.bind_group, &[]);
            pass.set_bind_group(1, &group, &[self.views.offset(i)]);
            pass.set_bind_group(TEXTURE_GROUP, &mesh.textures.bind_group, &[]);
            draw_mesh(&mut pass, mesh, targets);
        }
        self.npass.composite(device, encoder, &self.frame, target)?;
        self.crop.encode(device, encoder, frame, target);
        Ok(())
    }
}
