//! Splats by per-view duplication: the cover pass once (eye-space splats), then per group one
//! draw of every view's copy — instanced into the tiles of an atlas-sized group image with one
//! depth buffer (tiled, `wgsl/points/tiled.wgsl`), or multiview into N layers per group
//! (layered, `wgsl/points/layered.wgsl`, in as few passes as the adapter's layer limit allows)
//! — then the same ε-z compositing per view (`wgsl/points/composite.wgsl`) and the mask.
//! One ray per pixel, exactly as the N-pass; each copy's quad is projected in the vertex
//! stage, as duplicating engines do.

use std::ops::Range;

use super::bind_groups::FrameGroups;
use super::pipelines::{Geometry, SplatParams, SplatPipelineKey, COVER_WORKGROUP};
use super::PointSplatter;
use crate::error::Result;
use crate::frame::Frame;
use crate::points::SplatScene;
use crate::render::batches::batches;
use crate::render::dispatch::dispatch_2d;
use crate::render::pass_params::constants_buffer;
use crate::render::pipeline::{begin_pass, begin_pass_to, cleared, multiview_mask, PassTargets};
use crate::render::quilt::QuiltLayout;
use crate::render::specialize::Specialization;
use crate::render::view_layers::layer_range;
use crate::render::Method;
use crate::target::SpatialTarget;

/// The layered method's per-pass constants: `base` for the cover pass, one per multiview
/// batch (its first view), one per view's compositing (group layers `g · N + v`).
pub(super) fn layered_passes(base: SplatParams, views: u32, max_per_pass: u32) -> Vec<SplatParams> {
    let mut passes = vec![base];
    passes.extend(batches(views, max_per_pass).iter().map(|r| SplatParams {
        first_view: r.start,
        ..base
    }));
    passes.extend((0..views).map(|v| SplatParams {
        group_stride: views,
        group_base: v,
        ..base
    }));
    passes
}

impl PointSplatter {
    /// The tiled atlas layout of `frame`.
    pub(super) fn quilt_layout(&self, frame: &Frame) -> QuiltLayout {
        QuiltLayout::for_views(frame.camera.views, frame.size)
    }

    /// The layered method's multiview batches.
    pub(super) fn layer_batches(&self, frame: &Frame) -> Vec<Range<u32>> {
        batches(frame.camera.views, self.max_per_pass)
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
        let views = frame.camera.views;
        let passes = self.passes(frame, scene.groups());
        self.frame.write(device, frame);
        self.params.write(device, &passes);
        let spec = Specialization::of(frame);
        let pipeline = |geometry| SplatPipelineKey { spec, geometry };
        let scratch = self.scratch.as_ref().expect("ensured");
        let images = &self.images.as_ref().expect("ensured").layers;
        let FrameGroups {
            cover: cover_group,
            quad: quad_group,
            images: images_group,
            params: params_group,
        } = self.frame_groups(device, scene);
        let group = |label, layout, entries: &[wgpu::BindGroupEntry]| {
            device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some(label),
                layout,
                entries,
            })
        };
        let entry = |binding, resource| wgpu::BindGroupEntry { binding, resource };
        // The cover pass only transforms the splats here: each copy's quad is the vertex
        // stage's.
        let any = self.geometries(frame)[0];
        let cover = &self.pipelines.get(&pipeline(any)).expect("built").cover;
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
        let composite = &self.pipelines.get(&pipeline(any)).expect("built").composite;
        if self.path == Method::Tiled {
            let atlas = self.atlas.as_ref().expect("allocated by prepare");
            let quilt = constants_buffer(
                device,
                "quilt layout",
                wgpu::BufferUsages::UNIFORM,
                bytemuck::bytes_of(&atlas.layout.uniform()),
            );
            let quilt_group = group(
                "splat quilt layout",
                &self.layouts.quilt,
                &[entry(0, quilt.as_entire_binding())],
            );
            let geometry = &self
                .pipelines
                .get(&pipeline(Geometry::Tiled))
                .expect("built");
            let offset = [self.params.offset(0)];
            for (range, layer) in scene.group_ranges.iter().zip(&images.layer_views) {
                let mut pass = begin_pass(
                    encoder,
                    "splat group (tiled)",
                    cleared(layer, [0.0; 4]),
                    Some(&images.depth_view),
                );
                pass.set_pipeline(&geometry.geometry);
                pass.set_bind_group(0, &self.frame.bind_group, &[]);
                pass.set_bind_group(1, &quad_group, &[]);
                pass.set_bind_group(2, &params_group, &offset);
                pass.set_bind_group(3, &quilt_group, &[]);
                pass.draw(range.start * 6..range.end * 6, 0..views);
            }
            // ε-z compositing of every tile at once: it only looks at texels.
            let mut pass = begin_pass(
                encoder,
                "splat composite (tiled)",
                cleared(&atlas.color.view, [0.0; 4]),
                None,
            );
            pass.set_pipeline(composite);
            pass.set_bind_group(0, &self.frame.bind_group, &[]);
            pass.set_bind_group(1, &images_group, &[]);
            pass.set_bind_group(2, &params_group, &offset);
            pass.draw(0..3, 0..1);
            drop(pass);
            let compositor = self.atlas_compositor.as_ref().expect("tiled");
            compositor.encode(device, encoder, &self.frame, atlas, target);
            return Ok(());
        }
        let batches = self.layer_batches(frame);
        let depth = self.layer_depth.as_ref().expect("allocated by prepare");
        for (g, range) in scene.group_ranges.iter().enumerate() {
            for (b, batch) in batches.iter().enumerate() {
                let layers = batch.len() as u32;
                let first = g as u32 * views + batch.start;
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
                pass.set_pipeline(&self.pipelines.get(&key).expect("built").geometry);
                pass.set_bind_group(0, &self.frame.bind_group, &[]);
                pass.set_bind_group(1, &quad_group, &[]);
                pass.set_bind_group(2, &params_group, &[self.params.offset(1 + b)]);
                pass.draw(range.start * 6..range.end * 6, 0..1);
            }
        }
        let npass = self.npass.as_ref().expect("layered keeps view layers");
        for (v, layer) in npass.layers().layer_views.iter().enumerate() {
            let mut pass = begin_pass(encoder, "splat composite", cleared(layer, [0.0; 4]), None);
            pass.set_pipeline(composite);
            pass.set_bind_group(0, &self.frame.bind_group, &[]);
            pass.set_bind_group(1, &images_group, &[]);
            let offset = self.params.offset(1 + batches.len() + v);
            pass.set_bind_group(2, &params_group, &[offset]);
            pass.draw(0..3, 0..1);
        }
        npass.composite(device, encoder, &self.frame, target);
        Ok(())
    }
}
