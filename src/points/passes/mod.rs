//! Point splatting with ε-z deferred compositing (paper §3.3.2, §3.5.2; Zhang & Pajarola 2006).
//!
//! Per frame and camera set: a compute pass makes every splat's covering rectangle
//! (`wgsl/points/cover.wgsl`); each group is drawn into its own image with a z-test
//! (`wgsl/points/pixel.wgsl`, or `wgsl/points/subpixel.wgsl` for exact depth); a compositing pass blends the
//! groups within ε of the nearest (`wgsl/points/composite.wgsl`). The single pass does this once with
//! the display mask choosing each subpixel's ray; the N-pass baseline does it per view with the
//! same kernel, ε and groups, then mask-composites; the single view once from the centre.

mod bind_groups;
mod chunks;
mod duplicate;
mod group_images;
mod pipelines;
mod prepared;
mod references;
mod views;

use crate::render::Method;

pub use pipelines::SplatParams;

use self::bind_groups::FrameGroups;
use self::pipelines::{Layouts, Pipelines, SplatPipelineKey};
use self::prepared::{Plan, PreparedSplats, SplatPath};
use self::views::SplatOutput;
use crate::error::{Error, Result};
use crate::frame::{Frame, FrameBinding};
use crate::gpu::pass_params::PassParams;
use crate::gpu::storage_fence::StorageFence;
use crate::param::Param;
use crate::points::options::SplatDepth;
use crate::points::{PointOptions, SplatScene};
use crate::render::atlas::{Atlas, AtlasCompositor};
use crate::render::npass::NPassHarness;
use crate::render::pipeline_cache::PipelineCache;
use crate::render::Renderer;
use crate::render::{begin_prepare, check_target, prepared_state};
use crate::target::SpatialTarget;

/// Splatting settings shared by every method (so the baselines splat exactly the same way).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SplatOptions {
    /// Single-pass depth mode (ignored on K = 1 displays, where both are exact).
    pub depth: SplatDepth,
    /// ε of the ε-z compositing in eye-depth (world) units: groups within ε of the nearest
    /// blend. See [`SplatOptions::epsilon_for`].
    pub epsilon: f32,
}

impl PointOptions {
    /// The splatter's options for `scene` (ε in its units).
    pub fn for_scene(&self, scene: &SplatScene) -> SplatOptions {
        SplatOptions {
            depth: self.depth,
            epsilon: SplatOptions::epsilon_for(scene, self.epsilon_fraction),
        }
    }
}

impl SplatOptions {
    /// Exact depth, ε = `fraction` × the diameter of `scene`'s bounding sphere.
    pub fn for_scene(scene: &SplatScene, fraction: f32) -> Self {
        Self {
            depth: SplatDepth::Exact,
            epsilon: Self::epsilon_for(scene, fraction),
        }
    }

    /// ε = `fraction` × the scene's depth extent (its bounding-sphere diameter).
    pub fn epsilon_for(scene: &SplatScene, fraction: f32) -> f32 {
        fraction * 2.0 * scene.bounds.radius()
    }

    fn validate(&self) -> Result<()> {
        if !(self.epsilon.is_finite() && self.epsilon >= 0.0) {
            return Err(Error::invalid(
                Param::Epsilon,
                format!("{}: must be finite and ≥ 0", self.epsilon),
            ));
        }
        Ok(())
    }
}

/// Point-splat renderer for one [`Method`].
pub struct PointSplatter {
    method: Method,
    /// How `method` renders on this adapter.
    path: SplatPath,
    /// Layered: layers per multiview pass.
    max_per_pass: u32,
    options: SplatOptions,
    layouts: Layouts,
    frame: FrameBinding,
    params: PassParams<SplatParams>,
    pipelines: PipelineCache<SplatPipelineKey, Pipelines>,
    /// The N-pass harness (view layers and their compositing): N-pass and layered only.
    npass: Option<NPassHarness>,
    /// Tiled only: composites the quilt atlas into the target.
    atlas_compositor: Option<AtlasCompositor>,
    /// Tiled and layered: the views go in chunks whose group images fit one texture of at most
    /// this many bytes.
    max_image_bytes: u64,
    prepared: Option<PreparedSplats>,
    /// The parallel camera model's crop, recorded last.
    crop: crate::render::camera_crop::CameraCrop,
    fence: StorageFence,
}

impl PointSplatter {
    /// Prepare layouts; pipelines are built per display specialisation on first use.
    pub fn new(device: &wgpu::Device, method: Method, options: SplatOptions) -> Result<Self> {
        options.validate()?;
        let max_per_pass = device.limits().max_multiview_view_count;
        let multiview = device.features().contains(wgpu::Features::MULTIVIEW) && max_per_pass >= 2;
        let path = match method {
            Method::SinglePass => SplatPath::SinglePass,
            Method::SingleView => SplatPath::SingleView,
            Method::NPass => SplatPath::NPass,
            Method::Warp => SplatPath::References,
            Method::Tiled => SplatPath::Tiled,
            Method::Layered if multiview => SplatPath::Layered,
            Method::Layered => SplatPath::NPass,
            Method::Mrt => {
                return Err(Error::invalid(
                    Param::Method,
                    "mrt renders meshes only: splat group images are integer textures (packed \
                     colour, weight and depth), which cannot blend, so the paper's α = 0 writes \
                     to the other views' targets would overwrite them; tiled and layered \
                     duplicate splats",
                ))
            }
        };
        let layouts = Layouts::new(device);
        let npass = match path {
            SplatPath::NPass | SplatPath::Layered => {
                Some(NPassHarness::new(device, &layouts.frame)?)
            }
            _ => None,
        };
        let atlas_compositor = match path {
            SplatPath::Tiled => Some(AtlasCompositor::new(device, &layouts.frame)?),
            _ => None,
        };
        Ok(Self {
            method,
            path,
            max_per_pass,
            atlas_compositor,
            max_image_bytes: chunks::MAX_IMAGE_BYTES,
            options,
            frame: FrameBinding::new(device, &layouts.frame),
            params: PassParams::new(device, "splat pass constants"),
            layouts,
            pipelines: PipelineCache::new("splat"),
            npass,
            prepared: None,
            crop: crate::render::camera_crop::CameraCrop::new(device)?,
            fence: StorageFence::new(device)?,
        })
    }

    /// The settings.
    pub fn options(&self) -> SplatOptions {
        self.options
    }

    /// GPU bytes this renderer holds for its last frame (scratch buffers, group images, view
    /// layers), excluding the scene's splat buffer.
    pub fn allocated_bytes(&self) -> u64 {
        let prepared = self.prepared.as_ref().map_or(0, PreparedSplats::bytes);
        let layers = self
            .npass
            .as_ref()
            .and_then(|n| n.view_layers())
            .map_or(0, |l| l.bytes(4));
        prepared + layers
    }

    /// How this adapter renders the method, in words (the layered method without multiview
    /// is one pass per layer: the N-pass).
    pub fn describe(&self) -> String {
        let how = match (self.method, self.path) {
            (Method::Layered, SplatPath::Layered) => format!(
                "multiview, at most {} layers per pass (the adapter's limit)",
                self.max_per_pass
            ),
            (Method::Layered, _) => {
                "one pass per layer: the adapter has no multiview (MULTIVIEW)".to_string()
            }
            (m, _) => m.name().to_string(),
        };
        let chunked = |n: usize, what: &str| {
            format!(
                "{how}; views in {n} {what} (group images of at most {} bytes per texture)",
                self.max_image_bytes
            )
        };
        match self.prepared.as_ref().map(|p| &p.plan) {
            Some(Plan::Tiled { bands, .. }) if bands.len() > 1 => {
                chunked(bands.len(), "bands of tile rows")
            }
            Some(Plan::Layered { runs, .. }) if runs.len() > 1 => chunked(runs.len(), "runs"),
            _ => how,
        }
    }

    /// The largest group-image texture the tiled and layered methods allocate before they
    /// split the views into chunks that reuse one set of group images (default 1 GiB, what
    /// Vulkan guarantees one allocation may take; wgpu reports no such limit). Takes effect at
    /// the next `prepare`.
    pub fn set_max_image_bytes(&mut self, bytes: u64) {
        self.max_image_bytes = bytes;
        self.prepared = None;
    }

    /// Constants of each camera pass of a frame rendered as `plan` says.
    fn passes(&self, frame: &Frame, groups: u32, plan: &Plan) -> Vec<SplatParams> {
        let camera = &frame.camera;
        let fixed = |offset: f32| SplatParams {
            cover_lo: offset,
            cover_hi: offset,
            fixed_offset: offset,
            use_mask: 0,
            epsilon: self.options.epsilon,
            groups,
            group_stride: 1,
            group_base: 0,
            first_view: 0,
            image_row: 0,
            _pad: [0; 2],
        };
        match plan {
            Plan::SinglePass => vec![SplatParams {
                cover_lo: -camera.max_offset(),
                cover_hi: camera.max_offset(),
                use_mask: 1,
                ..fixed(0.0)
            }],
            Plan::SingleView => vec![fixed(0.0)],
            Plan::NPass | Plan::References => (0..camera.views)
                .map(|i| fixed(camera.view_offset(i)))
                .collect(),
            Plan::Tiled { bands, .. } => duplicate::tiled_passes(fixed(0.0), bands),
            Plan::Layered { runs, .. } => {
                duplicate::layered_passes(fixed(0.0), runs, self.max_per_pass)
            }
        }
    }

    /// Write the constants of `frame` as `state` renders it (frame uniform, per-pass
    /// constants): the start of every encode.
    fn write_constants(
        &mut self,
        device: &wgpu::Device,
        scene: &SplatScene,
        frame: &Frame,
    ) -> Result<()> {
        let state = prepared_state("PointSplatter", &self.prepared, &self.needs(scene, frame))?;
        let passes = self.passes(frame, scene.groups(), &state.plan);
        self.frame.write(device, frame);
        self.params.write(device, &passes);
        Ok(())
    }

    /// The frame this method renders with: the methods that render view images render them
    /// (everything but the final compositing) with [`Frame::for_view_images`]; the others have
    /// none to scale.
    fn own_frame(&self, frame: &Frame) -> Result<Frame> {
        match self.path {
            SplatPath::NPass | SplatPath::Tiled | SplatPath::Layered => Ok(frame.for_view_images()),
            SplatPath::SinglePass | SplatPath::SingleView | SplatPath::References => {
                frame.check_full_views(self.method.name())?;
                Ok(frame.clone())
            }
        }
    }
}

impl Renderer<SplatScene> for PointSplatter {
    fn prepare(
        &mut self,
        device: &wgpu::Device,
        _queue: &wgpu::Queue,
        scene: &SplatScene,
        frame: &Frame,
    ) -> Result<()> {
        let last = self.prepared.take();
        begin_prepare(device, frame, &mut self.prepared)?;
        if self.path == SplatPath::References {
            return Err(crate::warp::references::not_a_frame_renderer(
                "PointSplatter",
            ));
        }
        let frame = &self.own_frame(frame)?;
        self.prepared = Some(self.make_state(device, scene, frame, last)?);
        Ok(())
    }

    fn encode(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        scene: &SplatScene,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()> {
        check_target(frame, target)?;
        let own = self.own_frame(frame)?;
        self.write_constants(device, scene, &own)?;
        let state = prepared_state("PointSplatter", &self.prepared, &self.needs(scene, &own))?;
        match &state.plan {
            Plan::Tiled { bands, atlas } => {
                self.encode_tiled(device, encoder, scene, &own, state, bands, atlas, target)?
            }
            Plan::Layered { runs, depth } => {
                self.encode_layered(device, encoder, scene, &own, state, runs, depth, target)?
            }
            _ => self.encode_views(
                device,
                encoder,
                scene,
                &own,
                state,
                SplatOutput::Target(target),
            )?,
        }
        // The single view is the centre camera on every subpixel: nothing of it is cropped.
        if self.path != SplatPath::SingleView {
            self.crop.encode(device, encoder, frame, target);
        }
        Ok(())
    }

    fn atlas(&self) -> Option<&Atlas> {
        match self.prepared.as_ref().map(|p| &p.plan) {
            Some(Plan::Tiled { atlas, .. }) => Some(atlas.as_ref()),
            _ => None,
        }
    }
}
