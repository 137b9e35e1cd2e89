//! Single-pass triangle meshes (paper §3.2, §3.3.3, §3.5.3): one covering rectangle per
//! triangle, per-subpixel ray-triangle tests, the spatial image written directly.
//!
//! Every frame: a compute pass (`wgsl/mesh/single_pass_cover.wgsl`) transforms each triangle once and computes
//! its covering rectangle (docs/DESIGN.md §3, near-plane clipped); one geometry pass draws the
//! rectangles; the exact modes add a full-screen resolve that shades each subpixel once.
//!
//! Visibility ([`Visibility`]):
//! - `Exact`: rectangles rasterised at subpixel resolution (K·W × H); each fragment is one
//!   subpixel's ray; the hardware depth test keeps the nearest triangle id. Matches N-pass;
//!   needs no optional feature.
//! - `Atomic`: per-pixel fragments test the K rays and keep the nearest (depth, triangle)
//!   per subpixel with 64-bit atomics. Also matches N-pass; needs `SHADER_INT64_ATOMIC_MIN_MAX`.
//! - `Compute`: the rectangles rasterised in software by a compute pass, one invocation per
//!   triangle, same 64-bit atomics; no hardware rasteriser involved. Matches N-pass.
//! - `Fast`: the paper's — one depth per fragment (nearest hit subpixel) through the hardware
//!   depth test; dual-source blending keeps the subpixels a triangle misses. Approximate.

mod pipelines;
mod scratch;

#[cfg(test)]
pub(crate) use scratch::EYE_TRIANGLE_BYTES;

use crate::error::Result;
use crate::frame::{Frame, FrameBinding};
use crate::gpu::dispatch::dispatch_2d;
use crate::gpu::pipeline::{begin_pass, cleared, draw_fullscreen};
use crate::gpu::storage_fence::StorageFence;
use crate::mesh::options::{CoverBounds, ViewClusters, Visibility};
use crate::mesh::texture_buffers::TEXTURE_GROUP;
use crate::mesh::MeshBuffers;
use crate::render::pipeline_cache::PipelineCache;
use crate::render::specialize::Specialization;
use crate::render::{begin_prepare, check_prepared, check_target, Renderer};
use crate::target::SpatialTarget;
use pipelines::{Layouts, Pipelines};
use scratch::Scratch;

/// Creation-time options.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MeshSinglePassOptions {
    /// Visibility mode.
    pub visibility: Visibility,
    /// Covering-rectangle bounds.
    pub bounds: CoverBounds,
    /// Compute visibility: view clusters (the other modes take one, the covering quad).
    pub clusters: ViewClusters,
}

impl Default for MeshSinglePassOptions {
    fn default() -> Self {
        Self {
            visibility: Visibility::Exact,
            bounds: CoverBounds::Exact,
            clusters: ViewClusters::default(),
        }
    }
}

/// The single-pass mesh renderer. Pipelines are built per display specialisation (K, N) on
/// first use and cached; scratch buffers follow the frame size and triangle count.
pub struct MeshSinglePass {
    options: MeshSinglePassOptions,
    frame: FrameBinding,
    layouts: Layouts,
    /// Per display specialisation and whether the mesh is textured.
    pipelines: PipelineCache<(Specialization, bool), Pipelines>,
    scratch: Scratch,
    prepared: Option<PreparedFor>,
    /// The parallel camera model's crop, recorded last.
    crop: crate::render::camera_crop::CameraCrop,
    fence: StorageFence,
}

impl MeshSinglePass {
    /// Check that the device can run `options`; prepare the bind group layouts.
    pub fn new(device: &wgpu::Device, options: MeshSinglePassOptions) -> Result<Self> {
        // The parameters first: they are wrong on every adapter.
        if options.clusters == ViewClusters::Fixed(0) {
            return Err(crate::error::Error::invalid(
                crate::param::Param::ViewClusters,
                "0: the views need at least one cluster (1 = all views at once)",
            ));
        }
        if options.visibility != Visibility::Compute && options.clusters != ViewClusters::Fixed(1) {
            return Err(crate::error::Error::invalid(
                crate::param::Param::ViewClusters,
                format!(
                    "{}: only compute visibility groups views, and the visibility is {}",
                    options.clusters,
                    options.visibility.name()
                ),
            ));
        }
        crate::gpu::require_features(
            device,
            options.visibility.required_features(),
            &format!(
                "single-pass meshes with {} visibility",
                options.visibility.name()
            ),
            crate::advice::Advice::text("use ")
                .then(crate::advice::Setting::Visibility(Visibility::Exact))
                .then_text(", which every adapter runs, exact per subpixel"),
        )?;
        let layouts = Layouts::new(device);
        Ok(Self {
            options,
            frame: FrameBinding::new(device, &layouts.frame),
            layouts,
            pipelines: PipelineCache::new("single-pass mesh"),
            scratch: Scratch::new(device),
            prepared: None,
            crop: crate::render::camera_crop::CameraCrop::new(device)?,
            fence: StorageFence::new(device)?,
        })
    }

    /// The options this renderer was made with.
    pub fn options(&self) -> MeshSinglePassOptions {
        self.options
    }
}

/// What a [`MeshSinglePass`] was prepared for: display specialisation, size, triangle count.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct PreparedFor {
    spec: Specialization,
    size: [u32; 2],
    triangles: u32,
}

impl PreparedFor {
    fn of(frame: &Frame, mesh: &MeshBuffers) -> Self {
        Self {
            spec: Specialization::of(frame),
            size: frame.size,
            triangles: mesh.index_count / 3,
        }
    }
}

impl Renderer<MeshBuffers> for MeshSinglePass {
    fn prepare(
        &mut self,
        device: &wgpu::Device,
        _queue: &wgpu::Queue,
        mesh: &MeshBuffers,
        frame: &Frame,
    ) -> Result<()> {
        begin_prepare(device, frame, &mut self.prepared)?;
        frame.check_full_views("single-pass")?;
        let key = PreparedFor::of(frame, mesh);
        let (layouts, options) = (&self.layouts, self.options);
        let textured = mesh.textured;
        self.pipelines
            .prepare(device, (key.spec, textured), |modules| {
                pipelines::build(device, modules, layouts, options, key.spec, textured)
            })?;
        self.scratch
            .prepare(device, self.options.visibility, frame, key.triangles)?;
        self.prepared = Some(key);
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
        frame.check_full_views("single-pass")?;
        let key = PreparedFor::of(frame, mesh);
        check_prepared("MeshSinglePass", &self.prepared, &key)?;
        let (spec, triangles) = (key.spec, key.triangles);
        self.frame.write(device, frame);
        let pipelines = self.pipelines.get(&(spec, mesh.textured))?;
        let groups =
            self.scratch
                .bind_groups(device, &self.layouts, self.options.visibility, mesh)?;

        let s = &self.scratch;
        if let Some(keys) = s.keys_buffer() {
            encoder.clear_buffer(keys.buffer(), 0, Some(keys.used()));
        }
        if let Some(dispatch) = s.large_dispatch_buffer() {
            // No large triangles yet: an empty list, a dispatch of no workgroups.
            encoder.clear_buffer(dispatch.buffer(), 0, Some(scratch::LARGE_DISPATCH_BYTES));
            encoder.clear_buffer(s.rects_buffer(), 0, Some(scratch::LARGE_HEADER_BYTES));
        }
        self.fence.encode(device, encoder, s.cover_buffers());
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some(pipelines.compute_label),
                timestamp_writes: None,
            });
            pass.set_pipeline(&pipelines.compute);
            pass.set_bind_group(0, &self.frame.bind_group, &[]);
            pass.set_bind_group(1, &groups.cover_compute, &[]);
            if let Some(keys) = &groups.keys_dispatch {
                pass.set_bind_group(2, keys, &[]);
            }
            let [x, y] = dispatch_2d(device, triangles.div_ceil(pipelines::COVER_WORKGROUP));
            pass.dispatch_workgroups(x, y, 1);
        }
        if let (Some(large), Some(list), Some(keys), Some(dispatch)) = (
            &pipelines.large,
            &groups.large,
            &groups.keys_write,
            s.large_dispatch_buffer(),
        ) {
            // What the per-triangle pass could not finish within its loop budget.
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("mesh/single_pass_compute_large.wgsl"),
                timestamp_writes: None,
            });
            pass.set_pipeline(large);
            pass.set_bind_group(0, &self.frame.bind_group, &[]);
            pass.set_bind_group(1, list, &[]);
            pass.set_bind_group(2, keys, &[]);
            pass.dispatch_workgroups_indirect(dispatch.buffer(), 0);
        }
        if let Some(geometry) = &pipelines.geometry {
            let (color, depth, label) = match self.options.visibility {
                Visibility::Exact => (
                    wgpu::RenderPassColorAttachment {
                        view: s.triangle_ids_view()?,
                        depth_slice: None,
                        resolve_target: None,
                        ops: wgpu::Operations {
                            // NO_TRIANGLE in mesh/single_pass_exact_resolve.wgsl.
                            load: wgpu::LoadOp::Clear(wgpu::Color {
                                r: u32::MAX as f64,
                                g: 0.0,
                                b: 0.0,
                                a: 0.0,
                            }),
                            store: wgpu::StoreOp::Store,
                        },
                    },
                    s.depth_view(),
                    "mesh single pass (subpixel visibility)",
                ),
                Visibility::Atomic => (
                    cleared(&target.view, frame.background),
                    None,
                    "mesh single pass (atomic visibility)",
                ),
                _ => (
                    cleared(&target.view, frame.background),
                    s.depth_view(),
                    "mesh single pass (fast)",
                ),
            };
            let mut pass = begin_pass(encoder, label, color, depth);
            pass.set_pipeline(geometry);
            pass.set_bind_group(0, &self.frame.bind_group, &[]);
            pass.set_bind_group(1, &groups.mesh, &[]);
            if let Some(keys) = &groups.keys_write {
                pass.set_bind_group(2, keys, &[]);
            }
            if self.options.visibility == Visibility::Fast {
                pass.set_bind_group(TEXTURE_GROUP, &mesh.textures.bind_group, &[]);
            }
            pass.draw(0..triangles * 6, 0..1);
        }
        if let (Some(resolve), Some(visible)) = (&pipelines.resolve, &groups.visible) {
            draw_fullscreen(
                encoder,
                "mesh single pass (resolve)",
                resolve,
                &[
                    &self.frame.bind_group,
                    &groups.mesh,
                    visible,
                    &mesh.textures.bind_group,
                ],
                &target.view,
            );
        }
        self.crop.encode(device, encoder, frame, target);
        Ok(())
    }
}
