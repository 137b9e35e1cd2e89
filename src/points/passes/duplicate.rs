//! Splats by per-view duplication: the cover pass once (eye-space splats), then per group one
//! draw of every view's copy — instanced into the tiles of an atlas-sized group image with one
//! depth buffer (tiled, `wgsl/points/tiled.wgsl`), or multiview into N layers per group
//! (layered, `wgsl/points/layered.wgsl`, in as few passes as the adapter's layer limit allows)
//! — then the same ε-z compositing per view (`wgsl/points/composite.wgsl`) and the mask.
//! One ray per pixel, exactly as the N-pass; each copy's quad is projected in the vertex
//! stage, as duplicating engines do. Where every view's group images would outgrow one
//! texture, the views go in chunks that reuse them (`chunks.rs`).

use std::ops::Range;

use super::bind_groups::FrameGroups;
use super::chunks::{layered_chunks, tiled_bands, Band};
use super::group_images::draw_groups;
use super::pipelines::{Geometry, SplatParams, SplatPipelineKey, COVER_WORKGROUP};
use super::PointSplatter;
use crate::error::Result;
use crate::frame::Frame;
use crate::points::SplatScene;
use crate::render::atlas::TileSampling;
use crate::render::batches::batches;
use crate::render::dispatch::dispatch_2d;
use crate::render::pipeline::{
    begin_pass, begin_pass_to, cleared, kept, multiview_mask, PassTargets,
};
use crate::render::quilt::QuiltLayout;
use crate::render::specialize::Specialization;
use crate::render::view_layers::layer_range;
use crate::render::Made;
use crate::render::Method;
use crate::target::SpatialTarget;

/// How a duplicated frame's views are split so that their group images fit one texture.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(super) enum Chunks {
    #[default]
    None,
    /// Tiled: bands of tile rows of the atlas.
    Bands(Vec<Band>),
    /// Layered: runs of consecutive views.
    Runs(Vec<Range<u32>>),
}

/// The multiview batches of one run of views (the adapter's layer limit), as view ranges.
fn run_batches(run: &Range<u32>, max_per_pass: u32) -> Vec<Range<u32>> {
    batches(run.len() as u32, max_per_pass)
        .into_iter()
        .map(|b| b.start + run.start..b.end + run.start)
        .collect()
}

/// The layered method's per-pass constants: `base` for the cover pass, then per run of views
/// one per multiview batch (its first view) and one per view's compositing (group layers
/// `g · run length + view − run start`).
pub(super) fn layered_passes(
    base: SplatParams,
    runs: &[Range<u32>],
    max_per_pass: u32,
) -> Vec<SplatParams> {
    let mut passes = vec![base];
    for run in runs {
        passes.extend(run_batches(run, max_per_pass).iter().map(|b| SplatParams {
            first_view: b.start,
            ..base
        }));
        passes.extend(run.clone().map(|v| SplatParams {
            group_stride: run.len() as u32,
            group_base: v - run.start,
            ..base
        }));
    }
    passes
}

/// The tiled method's per-band constants (geometry and compositing of band i: pass i).
pub(super) fn tiled_passes(base: SplatParams, bands: &[Band]) -> Vec<SplatParams> {
    bands
        .iter()
        .map(|b| SplatParams {
            first_view: b.first_view,
            image_row: b.row,
            ..base
        })
        .collect()
}

impl PointSplatter {
    /// The tiled atlas layout of `frame`.
    pub(super) fn quilt_layout(&self, frame: &Frame) -> QuiltLayout {
        QuiltLayout::for_views(frame.camera.views, frame.size)
    }

    /// How `frame`'s views are chunked (`chunks.rs`) for this method, and the group images
    /// that hold one chunk: (size, layers).
    pub(super) fn plan_chunks(
        &self,
        device: &wgpu::Device,
        scene: &SplatScene,
        frame: &Frame,
    ) -> Result<(Chunks, [u32; 2], u32)> {
        let groups = scene.groups();
        Ok(match self.path {
            Method::Tiled => {
                let bands = tiled_bands(&self.quilt_layout(frame), groups, self.max_image_bytes)?;
                let size = bands[0].layout.size(); // the first bands are the tallest
                (Chunks::Bands(bands), size, groups)
            }
            Method::Layered => {
                let max_layers = device.limits().max_texture_array_layers;
                let runs = layered_chunks(
                    frame.camera.views,
                    frame.size,
                    groups,
                    max_layers,
                    self.max_image_bytes,
                )?;
                let longest = runs[0].len() as u32;
                (
                    Chunks::Runs(runs),
                    frame.size,
                    groups.saturating_mul(longest),
                )
            }
            _ => (Chunks::None, frame.size, groups),
        })
    }

    /// The layered method's multiview batches, over every run of views.
    pub(super) fn layer_batches(&self) -> Vec<Range<u32>> {
        match &self.chunks {
            Chunks::Runs(runs) => runs
                .iter()
                .flat_map(|run| run_batches(run, self.max_per_pass))
                .collect(),
            _ => Vec::new(),
        }
    }

    /// Record a tiled or layered frame (after `encode`'s checks).
    pub(super) fn encode_duplicated(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        scene: &SplatScene,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()> {
        let passes = self.passes(frame, scene.groups());
        self.frame.write(device, frame);
        self.params.write(device, &passes);
        let spec = Specialization::of(frame);
        let pipeline = |geometry| SplatPipelineKey { spec, geometry };
        let scratch = self.scratch.made("PointSplatter scratch")?;
        let images = &self.images.made("PointSplatter group images")?.layers;
        let FrameGroups {
            cover: cover_group,
            quad: quad_group,
            images: images_group,
            params: params_group,
        } = self.frame_groups(device, scene)?;
        // The cover pass only transforms the splats here: each copy's quad is the vertex
        // stage's.
        let any = self.geometries(frame)[0];
        let cover = &self.pipelines.get(&pipeline(any))?.cover;
        self.fence.encode(
            device,
            encoder,
            [scratch.eye_splats.buffer(), scratch.rects.buffer()],
        );
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("splat cover"),
                timestamp_writes: None,
            });
            pass.set_pipeline(cover);
            pass.set_bind_group(0, &self.frame.bind_group, &[]);
            pass.set_bind_group(1, &cover_group, &[]);
            pass.set_bind_group(2, &params_group, &[self.params.offset(0)]);
            let dispatch = dispatch_2d(device, scene.count.div_ceil(COVER_WORKGROUP));
            pass.dispatch_workgroups(dispatch[0], dispatch[1], 1);
        }
        let composite = &self.pipelines.get(&pipeline(any))?.composite;
        if let Chunks::Bands(bands) = &self.chunks {
            let atlas = self.atlas.made("PointSplatter atlas")?;
            let geometry = self.pipelines.get(&pipeline(Geometry::Tiled))?;
            for (i, band) in bands.iter().enumerate() {
                let quilt = band.layout.uniform_buffer(device, band.layout.uniform());
                let quilt_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some("splat quilt layout"),
                    layout: &self.layouts.quilt,
                    entries: &[wgpu::BindGroupEntry {
                        binding: 0,
                        resource: quilt.as_entire_binding(),
                    }],
                });
                let offset = [self.params.offset(i)];
                draw_groups(
                    encoder,
                    "splat group (tiled)",
                    images,
                    &scene.group_ranges,
                    &geometry.geometry,
                    &[
                        (&self.frame.bind_group, &[]),
                        (&quad_group, &[]),
                        (&params_group, &offset),
                        (&quilt_group, &[]),
                    ],
                    band.views(),
                );
                // ε-z compositing of every tile of the band at once: it only looks at texels.
                let color = if i == 0 {
                    cleared(&atlas.color.view, [0.0; 4])
                } else {
                    kept(&atlas.color.view)
                };
                let mut pass = begin_pass(encoder, "splat composite (tiled)", color, None);
                let [w, h] = band.layout.size();
                pass.set_viewport(0.0, band.row as f32, w as f32, h as f32, 0.0, 1.0);
                pass.set_pipeline(composite);
                pass.set_bind_group(0, &self.frame.bind_group, &[]);
                pass.set_bind_group(1, &images_group, &[]);
                pass.set_bind_group(2, &params_group, &offset);
                pass.draw(0..3, 0..1);
            }
            let compositor = self
                .atlas_compositor
                .made("PointSplatter atlas compositor")?;
            compositor.encode(
                device,
                encoder,
                &self.frame,
                atlas,
                target,
                TileSampling::Bilinear,
            );
            return Ok(());
        }
        let Chunks::Runs(runs) = &self.chunks else {
            unreachable!("tiled and layered plan their chunks in prepare")
        };
        let depth = &self.layer_depth.made("PointSplatter layer depth")?.texture;
        let npass = self.npass.made("PointSplatter view layers")?;
        let mut next_pass = 1; // pass 0: the cover pass
        for run in runs {
            let batches = run_batches(run, self.max_per_pass);
            let stride = run.len() as u32;
            for (g, range) in scene.group_ranges.iter().enumerate() {
                for (b, batch) in batches.iter().enumerate() {
                    let layers = batch.len() as u32;
                    let first = g as u32 * stride + batch.start - run.start;
                    let color = layer_range(&images.texture, first, layers);
                    let depth = layer_range(depth, 0, layers);
                    let mut pass = begin_pass_to(
                        encoder,
                        "splat group (layered)",
                        PassTargets {
                            colors: &[Some(cleared(&color, [0.0; 4]))],
                            depth: Some(&depth),
                            keep_depth: false,
                            multiview_mask: multiview_mask(layers),
                        },
                    );
                    let key = pipeline(Geometry::Layered { layers });
                    pass.set_pipeline(&self.pipelines.get(&key)?.geometry);
                    pass.set_bind_group(0, &self.frame.bind_group, &[]);
                    pass.set_bind_group(1, &quad_group, &[]);
                    let offset = self.params.offset(next_pass + b);
                    pass.set_bind_group(2, &params_group, &[offset]);
                    pass.draw(range.start * 6..range.end * 6, 0..1);
                }
            }
            next_pass += batches.len();
            for v in run.clone() {
                let layer = &npass.layers()?.layer_views[v as usize];
                let mut pass =
                    begin_pass(encoder, "splat composite", cleared(layer, [0.0; 4]), None);
                pass.set_pipeline(composite);
                pass.set_bind_group(0, &self.frame.bind_group, &[]);
                pass.set_bind_group(1, &images_group, &[]);
                pass.set_bind_group(2, &params_group, &[self.params.offset(next_pass)]);
                pass.draw(0..3, 0..1);
                next_pass += 1;
            }
        }
        npass.composite(device, encoder, &self.frame, target)?;
        Ok(())
    }
}
