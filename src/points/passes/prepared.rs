//! What a [`PointSplatter`]'s `prepare` makes for one frame, as one struct: the scratch the
//! cover pass writes, the group images, and the method's plan of camera passes with what only
//! that plan needs (the tiled atlas and its bands, the layered depth and its runs of views).
//! `encode` reads it through [`prepared_state`](crate::render::prepared_state), so a frame it
//! was not made for is `Err(NotPrepared)`, and no method's state can be missing for another.

use std::ops::Range;

use super::chunks::{layered_chunks, tiled_bands, Band};
use super::group_images::{GroupImages, GroupImagesKey};
use super::pipelines::{Geometry, SplatPipelineKey};
use super::{PointSplatter, SplatDepth};
use crate::advice::Setting;
use crate::error::{Error, Result};
use crate::frame::Frame;
use crate::gpu::gpu_buffer::GpuBuffer;
use crate::points::SplatScene;
use crate::render::atlas::Atlas;
use crate::render::batches::batches;
use crate::render::quilt::QuiltLayout;
use crate::render::specialize::Specialization;
use crate::render::view_layers::{depth_array, DepthArray};
use crate::render::PreparedState;

/// How a splatter renders its method on this adapter, chosen once by `new` (the MRT method,
/// which splats cannot do, has none).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum SplatPath {
    SinglePass,
    SingleView,
    /// One camera pass per view, then the mask: the N-pass, and the layered method on an
    /// adapter without multiview.
    NPass,
    /// A warp's reference views (through `ReferenceRenderer` only).
    References,
    Tiled,
    /// Multiview: at most the adapter's layer limit of views per pass.
    Layered,
}

/// A prepared frame's camera passes, with what only that way of rendering needs.
pub(super) enum Plan {
    /// One pass over every subpixel with the mask choosing its view.
    SinglePass,
    /// One pass from the centre camera.
    SingleView,
    /// One pass per view into the N-pass harness's layers.
    NPass,
    /// One pass per reference view into the warp's images.
    References,
    /// Bands of tile rows drawn into the group images in turn, composited into `atlas`.
    Tiled { bands: Vec<Band>, atlas: Box<Atlas> },
    /// Runs of consecutive views, drawn a multiview batch at a time with `depth`.
    Layered {
        runs: Vec<Range<u32>>,
        depth: DepthArray,
    },
}

/// The cover pass's output: eye-space splats and their covering rectangles.
pub(super) struct Scratch {
    pub eye_splats: GpuBuffer,
    pub rects: GpuBuffer,
}

/// What a [`PointSplatter`] was prepared for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct PreparedFor {
    pub spec: Specialization,
    pub subpixel: bool,
    pub size: [u32; 2],
    pub views: u32,
    pub splats: u32,
    pub groups: u32,
}

/// Everything `prepare` made for frames of one [`PreparedFor`].
pub(super) struct PreparedSplats {
    pub key: PreparedFor,
    pub plan: Plan,
    pub scratch: Scratch,
    pub images: GroupImages,
}

impl PreparedState for PreparedSplats {
    type Key = PreparedFor;

    fn key(&self) -> &PreparedFor {
        &self.key
    }
}

impl PreparedSplats {
    /// GPU bytes held (scratch, group images, the tiled atlas).
    pub fn bytes(&self) -> u64 {
        let atlas = match &self.plan {
            Plan::Tiled { atlas, .. } => atlas.bytes(),
            _ => 0,
        };
        self.scratch.eye_splats.used()
            + self.scratch.rects.used()
            + GroupImages::bytes(self.images.key)
            + atlas
    }
}

/// The multiview batches of one run of views (the adapter's layer limit), as view ranges.
pub(super) fn run_batches(run: &Range<u32>, max_per_pass: u32) -> Vec<Range<u32>> {
    batches(run.len() as u32, max_per_pass)
        .into_iter()
        .map(|b| b.start + run.start..b.end + run.start)
        .collect()
}

impl PointSplatter {
    /// Whether `frame` renders with per-subpixel depth images.
    pub(super) fn subpixel(&self, frame: &Frame) -> bool {
        self.path == SplatPath::SinglePass
            && self.options.depth == SplatDepth::Exact
            && frame.display.views_per_pixel() > 1
    }

    /// What `frame` of `scene` needs prepared: pipelines (display, subpixel images), sizes.
    pub(super) fn needs(&self, scene: &SplatScene, frame: &Frame) -> PreparedFor {
        PreparedFor {
            spec: Specialization::of(frame),
            subpixel: self.subpixel(frame),
            size: frame.size,
            views: frame.camera.views,
            splats: scene.count,
            groups: scene.groups(),
        }
    }

    /// The tiled atlas layout of `frame`.
    pub(super) fn quilt_layout(&self, frame: &Frame) -> QuiltLayout {
        QuiltLayout::for_views(frame.camera.views, frame.size)
    }

    /// Make (reusing what `last` holds where it still fits) the state frames like `frame` of
    /// `scene` need, and the pipelines they draw with.
    pub(super) fn make_state(
        &mut self,
        device: &wgpu::Device,
        scene: &SplatScene,
        frame: &Frame,
        last: Option<PreparedSplats>,
    ) -> Result<PreparedSplats> {
        let (last_plan, scratch, last_images) = match last {
            Some(s) => (Some(s.plan), Some(s.scratch), Some(s.images)),
            None => (None, None, None),
        };
        let mut scratch = scratch.unwrap_or_else(|| Scratch {
            eye_splats: GpuBuffer::new(device, "eye splats", wgpu::BufferUsages::STORAGE),
            rects: GpuBuffer::new(device, "splat cover rects", wgpu::BufferUsages::STORAGE),
        });
        let n = scene.count as u64;
        let what = |buffer| move || format!("{buffer} bytes ({n} splats)");
        scratch
            .eye_splats
            .ensure(device, what("eye-space splat"), n * 32)?;
        scratch
            .rects
            .ensure(device, what("splat cover rectangle"), n * 16)?;
        let (plan, size, layers) = self.plan(device, scene, frame, last_plan)?;
        let k = if self.subpixel(frame) {
            frame.display.views_per_pixel()
        } else {
            1
        };
        if self.subpixel(frame) {
            // Said in the frame's pixels (the caller's), not in the group images' columns
            // (the single pass's images are the frame's size).
            Error::check_subpixel_width(
                device,
                frame.size,
                k,
                Setting::SplatDepth(SplatDepth::Exact),
                Setting::SplatDepth(SplatDepth::Paper).into(),
            )?;
        }
        let key = GroupImagesKey {
            size: [size[0].saturating_mul(k), size[1]],
            groups: layers,
            subpixel: self.subpixel(frame),
        };
        let images = match last_images {
            Some(images) if images.key == key => images,
            last => {
                drop(last); // free before allocating the replacement
                GroupImages::new(device, key)?
            }
        };
        if let Some(npass) = &mut self.npass {
            npass.prepare(device, frame)?;
        }
        for geometry in self.geometries(frame, &plan) {
            let key = SplatPipelineKey {
                spec: Specialization::of(frame),
                geometry,
            };
            let layouts = &self.layouts;
            self.pipelines.prepare(device, key, |modules| {
                super::pipelines::build(device, modules, layouts, key)
            })?;
        }
        Ok(PreparedSplats {
            key: self.needs(scene, frame),
            plan,
            scratch,
            images,
        })
    }

    /// `frame`'s plan of camera passes (the duplicating methods' views chunked as
    /// `chunks.rs` says), and the group images one chunk needs: (size, layers).
    fn plan(
        &self,
        device: &wgpu::Device,
        scene: &SplatScene,
        frame: &Frame,
        last: Option<Plan>,
    ) -> Result<(Plan, [u32; 2], u32)> {
        let groups = scene.groups();
        let plain = |plan| Ok((plan, frame.size, groups));
        match self.path {
            SplatPath::SinglePass => plain(Plan::SinglePass),
            SplatPath::SingleView => plain(Plan::SingleView),
            SplatPath::NPass => plain(Plan::NPass),
            SplatPath::References => plain(Plan::References),
            SplatPath::Tiled => {
                let layout = self.quilt_layout(frame);
                let bands = tiled_bands(&layout, groups, self.max_image_bytes)?;
                let size = bands[0].layout.size(); // the first bands are the tallest
                let atlas = match last {
                    Some(Plan::Tiled { atlas, .. }) if atlas.fits(&layout, false) => atlas,
                    last => {
                        drop(last); // free before allocating the replacement
                        Box::new(Atlas::new(device, layout, false)?)
                    }
                };
                Ok((Plan::Tiled { bands, atlas }, size, groups))
            }
            SplatPath::Layered => {
                let runs = layered_chunks(
                    frame.camera.views,
                    frame.size,
                    groups,
                    device.limits().max_texture_array_layers,
                    self.max_image_bytes,
                )?;
                let longest = runs[0].len() as u32;
                let deepest = self.layer_batches(&runs).iter().map(|r| r.len()).max();
                let layers = deepest.unwrap_or(1) as u32;
                let last = match last {
                    Some(Plan::Layered { depth, .. }) => Some(depth),
                    _ => None,
                };
                let depth = depth_array(last, device, frame.size, layers)?;
                let layers = groups.saturating_mul(longest);
                Ok((Plan::Layered { runs, depth }, frame.size, layers))
            }
        }
    }

    /// The layered method's multiview batches, over every run of views.
    pub(super) fn layer_batches(&self, runs: &[Range<u32>]) -> Vec<Range<u32>> {
        runs.iter()
            .flat_map(|run| run_batches(run, self.max_per_pass))
            .collect()
    }

    /// The geometry passes `plan` draws with (the layered method: one per batch size).
    pub(super) fn geometries(&self, frame: &Frame, plan: &Plan) -> Vec<Geometry> {
        match plan {
            Plan::Tiled { .. } => vec![Geometry::Tiled],
            Plan::Layered { runs, .. } => {
                let mut sizes: Vec<u32> = self
                    .layer_batches(runs)
                    .iter()
                    .map(|r| r.len() as u32)
                    .collect();
                sizes.dedup();
                sizes
                    .into_iter()
                    .map(|layers| Geometry::Layered { layers })
                    .collect()
            }
            Plan::References => vec![Geometry::Reference],
            Plan::SinglePass | Plan::SingleView | Plan::NPass if self.subpixel(frame) => {
                vec![Geometry::Subpixel]
            }
            Plan::SinglePass | Plan::SingleView | Plan::NPass => vec![Geometry::Pixel],
        }
    }
}
