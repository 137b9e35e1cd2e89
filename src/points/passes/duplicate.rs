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
use super::chunks::Band;
use super::group_images::draw_groups;
use super::pipelines::{Geometry, SplatParams, SplatPipelineKey, COVER_WORKGROUP};
use super::prepared::{run_batches, PreparedSplats};
use super::PointSplatter;
use crate::error::Result;
use crate::frame::Frame;
use crate::gpu::dispatch::dispatch_2d;
use crate::gpu::pipeline::{begin_pass, begin_pass_to, cleared, kept, multiview_mask, PassTargets};
use crate::points::SplatScene;
use crate::render::atlas::{Atlas, TileSampling};
use crate::render::specialize::Specialization;
use crate::render::view_layers::{layer_range, DepthArray};
use crate::render::Made;
use crate::target::SpatialTarget;

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
    /// The duplicated methods' cover pass: it only transforms the splats here, each copy's
    /// quad is the vertex stage's.
    fn encode_duplicated_cover(
        &self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        scene: &SplatScene,
        state: &PreparedSplats,
        groups: &FrameGroups,
        pipeline: SplatPipelineKey,
    ) -> Result<()> {
        let scratch = &state.scratch;
        self.fence.encode(
            device,
            encoder,
            [scratch.eye_splats.buffer(), scratch.rects.buffer()],
        );
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("splat cover"),
            timestamp_writes: None,
        });
        pass.set_pipeline(&self.pipelines.get(&pipeline)?.cover);
        pass.set_bind_group(0, &self.frame.bind_group, &[]);
        pass.set_bind_group(1, &groups.cover, &[]);
        pass.set_bind_group(2, &groups.params, &[self.params.offset(0)]);
        let dispatch = dispatch_2d(device, scene.count.div_ceil(COVER_WORKGROUP));
        pass.dispatch_workgroups(dispatch[0], dispatch[1], 1);
        Ok(())
    }

    /// Record a tiled frame (after `encode`'s checks and constants): per band of tile rows,
    /// every view's copy of each group into the band's group images, then the ε-z
    /// compositing of the band's tiles into `atlas`; the atlas through the mask last.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn encode_tiled(
        &self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        scene: &SplatScene,
        frame: &Frame,
        state: &PreparedSplats,
        bands: &[Band],
        atlas: &Atlas,
        target: &SpatialTarget,
    ) -> Result<()> {
        let pipeline = |geometry| SplatPipelineKey {
            spec: Specialization::of(frame),
            geometry,
        };
        let images = &state.images.layers;
        let groups = self.frame_groups(device, scene, state)?;
        self.encode_duplicated_cover(
            device,
            encoder,
            scene,
            state,
            &groups,
            pipeline(Geometry::Tiled),
        )?;
        let pipelines = self.pipelines.get(&pipeline(Geometry::Tiled))?;
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
                &pipelines.geometry,
                &[
                    (&self.frame.bind_group, &[]),
                    (&groups.quad, &[]),
                    (&groups.params, &offset),
                    (&quilt_group, &[]),
                ],
                band.views(),
                Some(band.layout.size()),
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
            pass.set_pipeline(&pipelines.composite);
            pass.set_bind_group(0, &self.frame.bind_group, &[]);
            pass.set_bind_group(1, &groups.images, &[]);
            pass.set_bind_group(2, &groups.params, &offset);
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
        Ok(())
    }

    /// Record a layered frame (after `encode`'s checks and constants): per run of views, each
    /// group multiview into the run's group-image layers a batch at a time, then each view's
    /// ε-z compositing into its view layer; the layers through the mask last.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn encode_layered(
        &self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        scene: &SplatScene,
        frame: &Frame,
        state: &PreparedSplats,
        runs: &[Range<u32>],
        depth: &DepthArray,
        target: &SpatialTarget,
    ) -> Result<()> {
        let pipeline = |geometry| SplatPipelineKey {
            spec: Specialization::of(frame),
            geometry,
        };
        let images = &state.images.layers;
        let groups = self.frame_groups(device, scene, state)?;
        let any = self.geometries(frame, &state.plan)[0];
        self.encode_duplicated_cover(device, encoder, scene, state, &groups, pipeline(any))?;
        let composite = &self.pipelines.get(&pipeline(any))?.composite;
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
                    let depth = layer_range(&depth.texture, 0, layers);
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
                    pass.set_bind_group(1, &groups.quad, &[]);
                    let offset = self.params.offset(next_pass + b);
                    pass.set_bind_group(2, &groups.params, &[offset]);
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
                pass.set_bind_group(1, &groups.images, &[]);
                pass.set_bind_group(2, &groups.params, &[self.params.offset(next_pass)]);
                pass.draw(0..3, 0..1);
                next_pass += 1;
            }
        }
        npass.composite(device, encoder, &self.frame, target)?;
        Ok(())
    }
}
