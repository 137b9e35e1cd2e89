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
mod references;
mod views;

use crate::render::Method;

pub use pipelines::SplatParams;

use self::bind_groups::FrameGroups;
use self::group_images::{GroupImages, GroupImagesKey};
use self::pipelines::{Geometry, Layouts, Pipelines, SplatPipelineKey};
use self::views::SplatOutput;
use crate::error::{Error, Result};
use crate::frame::{Frame, FrameBinding};
use crate::points::SplatScene;
use crate::render::atlas::{Atlas, AtlasCompositor};
use crate::render::gpu_buffer::GpuBuffer;
use crate::render::npass::NPassHarness;
use crate::render::pass_params::PassParams;
use crate::render::pipeline_cache::PipelineCache;
use crate::render::specialize::Specialization;
use crate::render::storage_fence::StorageFence;
use crate::render::Renderer;
use crate::render::{begin_prepare, check_prepared, check_target};
use crate::target::SpatialTarget;

/// Depth kept per group image by the single pass on subpixel (K = 3) displays.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SplatDepth {
    /// The paper's: one depth per pixel, the mean of its subpixels' hit depths.
    Paper,
    /// One depth per subpixel (subpixel-resolution geometry pass).
    Exact,
}

impl SplatDepth {
    /// Lower-case name (CLI, reports).
    pub fn name(self) -> &'static str {
        match self {
            Self::Paper => "paper",
            Self::Exact => "exact",
        }
    }
}

/// Splatting settings shared by every method (so the baselines splat exactly the same way).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SplatOptions {
    /// Single-pass depth mode (ignored on K = 1 displays, where both are exact).
    pub depth: SplatDepth,
    /// ε of the ε-z compositing in eye-depth (world) units: groups within ε of the nearest
    /// blend. See [`SplatOptions::epsilon_for`].
    pub epsilon: f32,
}

/// Default ε as a fraction of the scene's depth extent (its bounding-sphere diameter).
pub const DEFAULT_EPSILON_FRACTION: f32 = 0.01;

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
                "epsilon",
                format!("{}: must be finite and ≥ 0", self.epsilon),
            ));
        }
        Ok(())
    }
}

/// The cover pass's output: eye-space splats and their covering rectangles.
struct Scratch {
    eye_splats: GpuBuffer,
    rects: GpuBuffer,
}

/// Point-splat renderer for one [`Method`].
pub struct PointSplatter {
    method: Method,
    /// How `method` renders on this adapter: itself, or the N-pass for layered without
    /// multiview.
    path: Method,
    /// Layered: layers per multiview pass.
    max_per_pass: u32,
    options: SplatOptions,
    layouts: Layouts,
    frame: FrameBinding,
    params: PassParams<SplatParams>,
    pipelines: PipelineCache<SplatPipelineKey, Pipelines>,
    scratch: Option<Scratch>,
    images: Option<GroupImages>,
    /// N-pass and layered only.
    npass: Option<NPassHarness>,
    /// Tiled only: the quilt atlas the views are composited into, and its compositor.
    atlas: Option<Atlas>,
    atlas_compositor: Option<AtlasCompositor>,
    /// Layered only: a depth layer per layer of a multiview pass.
    layer_depth: Option<crate::render::view_layers::DepthArray>,
    /// Tiled and layered: the views in chunks whose group images fit one texture of at most
    /// `max_image_bytes`.
    chunks: duplicate::Chunks,
    max_image_bytes: u64,
    prepared: Option<PreparedFor>,
    /// The parallel camera model's crop, recorded last.
    crop: crate::render::camera_crop::CameraCrop,
    fence: StorageFence,
}

impl PointSplatter {
    /// Prepare layouts; pipelines are built per display specialisation on first use.
    pub fn new(device: &wgpu::Device, method: Method, options: SplatOptions) -> Result<Self> {
        options.validate()?;
        if method == Method::Mrt {
            return Err(Error::invalid(
                "method",
                "mrt renders meshes only: splat group images are integer textures (packed \
                 colour, weight and depth), which cannot blend, so the paper's α = 0 writes to \
                 the other views' targets would overwrite them; tiled and layered duplicate \
                 splats",
            ));
        }
        let max_per_pass = device.limits().max_multiview_view_count;
        let multiview = device.features().contains(wgpu::Features::MULTIVIEW) && max_per_pass >= 2;
        let path = match method {
            Method::Layered if !multiview => Method::NPass,
            m => m,
        };
        let layouts = Layouts::new(device);
        let npass = match path {
            Method::NPass | Method::Layered => Some(NPassHarness::new(device, &layouts.frame)?),
            _ => None,
        };
        let atlas_compositor = match path {
            Method::Tiled => Some(AtlasCompositor::new(device, &layouts.frame)?),
            _ => None,
        };
        Ok(Self {
            method,
            path,
            max_per_pass,
            atlas: None,
            atlas_compositor,
            layer_depth: None,
            chunks: duplicate::Chunks::None,
            max_image_bytes: chunks::MAX_IMAGE_BYTES,
            options,
            frame: FrameBinding::new(device, &layouts.frame),
            params: PassParams::new(device, "splat pass constants"),
            layouts,
            pipelines: PipelineCache::new("splat"),
            scratch: None,
            images: None,
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
        let scratch = self
            .scratch
            .as_ref()
            .map_or(0, |s| s.eye_splats.used() + s.rects.used());
        let images = self
            .images
            .as_ref()
            .map_or(0, |i| GroupImages::bytes(i.key));
        let layers = self
            .npass
            .as_ref()
            .and_then(|n| n.view_layers())
            .map_or(0, |l| l.bytes(4));
        let atlas = self.atlas.as_ref().map_or(0, Atlas::bytes);
        scratch + images + layers + atlas
    }

    /// How this adapter renders the method, in words (the layered method without multiview
    /// is one pass per layer: the N-pass).
    pub fn describe(&self) -> String {
        let how = match (self.method, self.path) {
            (Method::Layered, Method::Layered) => format!(
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
        match &self.chunks {
            duplicate::Chunks::Bands(b) if b.len() > 1 => chunked(b.len(), "bands of tile rows"),
            duplicate::Chunks::Runs(r) if r.len() > 1 => chunked(r.len(), "runs"),
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

    /// Whether `frame` renders with per-subpixel depth images.
    fn subpixel(&self, frame: &Frame) -> bool {
        self.path == Method::SinglePass
            && self.options.depth == SplatDepth::Exact
            && frame.display.views_per_pixel() > 1
    }

    /// Constants of each camera pass of the frame.
    fn passes(&self, frame: &Frame, groups: u32) -> Vec<SplatParams> {
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
        match self.path {
            Method::SinglePass => vec![SplatParams {
                cover_lo: -camera.max_offset(),
                cover_hi: camera.max_offset(),
                use_mask: 1,
                ..fixed(0.0)
            }],
            Method::SingleView => vec![fixed(0.0)],
            Method::NPass | Method::Warp => (0..camera.views)
                .map(|i| fixed(camera.view_offset(i)))
                .collect(),
            Method::Tiled | Method::Layered => match &self.chunks {
                duplicate::Chunks::Bands(bands) => duplicate::tiled_passes(fixed(0.0), bands),
                duplicate::Chunks::Runs(runs) => {
                    duplicate::layered_passes(fixed(0.0), runs, self.max_per_pass)
                }
                duplicate::Chunks::None => unreachable!("planned by prepare"),
            },
            Method::Mrt => unreachable!("refused by new"),
        }
    }

    /// The frame this method renders with: the methods that render view images render them
    /// (everything but the final compositing) with [`Frame::for_view_images`]; the others have
    /// none to scale.
    fn own_frame(&self, frame: &Frame) -> Result<Frame> {
        match self.path {
            Method::NPass | Method::Tiled | Method::Layered => Ok(frame.for_view_images()),
            other => {
                frame.check_full_views(other.name())?;
                Ok(frame.clone())
            }
        }
    }

    /// What `frame` of `scene` needs prepared: pipelines (display, subpixel images), sizes.
    fn needs(&self, scene: &SplatScene, frame: &Frame) -> PreparedFor {
        PreparedFor {
            spec: Specialization::of(frame),
            subpixel: self.subpixel(frame),
            size: frame.size,
            views: frame.camera.views,
            splats: scene.count,
            groups: scene.groups(),
        }
    }

    fn ensure_resources(
        &mut self,
        device: &wgpu::Device,
        scene: &SplatScene,
        frame: &Frame,
    ) -> Result<()> {
        let scratch = self.scratch.get_or_insert_with(|| Scratch {
            eye_splats: GpuBuffer::new("eye splats", wgpu::BufferUsages::STORAGE),
            rects: GpuBuffer::new("splat cover rects", wgpu::BufferUsages::STORAGE),
        });
        let n = scene.count as u64;
        let what = |buffer| move || format!("{buffer} bytes ({n} splats)");
        scratch
            .eye_splats
            .ensure(device, what("eye-space splat"), n * 32)?;
        scratch
            .rects
            .ensure(device, what("splat cover rectangle"), n * 16)?;
        let subpixel = self.subpixel(frame);
        let k = if subpixel {
            frame.display.views_per_pixel()
        } else {
            1
        };
        let (chunks, size, groups) = self.plan_chunks(device, scene, frame)?;
        self.chunks = chunks;
        if self.path == Method::Tiled {
            let layout = self.quilt_layout(frame);
            if !self.atlas.as_ref().is_some_and(|a| a.fits(&layout, false)) {
                self.atlas = None; // free before allocating the replacement
                self.atlas = Some(Atlas::new(device, layout, false)?);
            }
        }
        let size = [size[0].saturating_mul(k), size[1]];
        let key = GroupImagesKey {
            size,
            groups,
            subpixel,
        };
        if self.images.as_ref().map(|i| i.key) != Some(key) {
            self.images = None;
            self.images = Some(GroupImages::new(device, key)?);
        }
        if let Some(npass) = &mut self.npass {
            npass.prepare(device, frame)?;
        }
        if self.path == Method::Layered {
            let deepest = self.layer_batches().iter().map(|r| r.len()).max();
            let layers = deepest.unwrap_or(1) as u32;
            let last = self.layer_depth.take();
            self.layer_depth = Some(crate::render::view_layers::depth_array(
                last, device, frame.size, layers,
            )?);
        }
        for geometry in self.geometries(frame) {
            let key = SplatPipelineKey {
                spec: Specialization::of(frame),
                geometry,
            };
            let layouts = &self.layouts;
            self.pipelines.prepare(device, key, |modules| {
                pipelines::build(device, modules, layouts, key)
            })?;
        }
        Ok(())
    }

    /// The geometry passes `frame` draws with (the layered method: one per batch size).
    fn geometries(&self, frame: &Frame) -> Vec<Geometry> {
        match self.path {
            Method::Tiled => vec![Geometry::Tiled],
            Method::Layered => {
                let mut sizes: Vec<u32> = self
                    .layer_batches()
                    .iter()
                    .map(|r| r.len() as u32)
                    .collect();
                sizes.dedup();
                sizes
                    .into_iter()
                    .map(|layers| Geometry::Layered { layers })
                    .collect()
            }
            Method::Warp => vec![Geometry::Reference],
            _ if self.subpixel(frame) => vec![Geometry::Subpixel],
            _ => vec![Geometry::Pixel],
        }
    }
}

/// What a [`PointSplatter`] was prepared for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct PreparedFor {
    spec: Specialization,
    subpixel: bool,
    size: [u32; 2],
    views: u32,
    splats: u32,
    groups: u32,
}

impl Renderer<SplatScene> for PointSplatter {
    fn prepare(
        &mut self,
        device: &wgpu::Device,
        _queue: &wgpu::Queue,
        scene: &SplatScene,
        frame: &Frame,
    ) -> Result<()> {
        begin_prepare(device, frame, &mut self.prepared)?;
        if self.path == Method::Warp {
            return Err(crate::warp::references::not_a_frame_renderer(
                "PointSplatter",
            ));
        }
        let frame = &self.own_frame(frame)?;
        self.ensure_resources(device, scene, frame)?;
        self.prepared = Some(self.needs(scene, frame));
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
        check_prepared("PointSplatter", &self.prepared, &self.needs(scene, &own))?;
        if matches!(self.path, Method::Tiled | Method::Layered) {
            self.encode_duplicated(device, encoder, scene, &own, target)?;
        } else {
            self.encode_views(device, encoder, scene, &own, SplatOutput::Target(target))?;
        }
        // The single view is the centre camera on every subpixel: nothing of it is cropped.
        if self.path != Method::SingleView {
            self.crop.encode(device, encoder, frame, target);
        }
        Ok(())
    }

    fn atlas(&self) -> Option<&Atlas> {
        self.atlas.as_ref()
    }
}
