//! One cover + group + composite sequence per camera pass: the splat frame of the single pass,
//! the N-pass, the single view and a warp's references.

use super::group_images::draw_groups;
use super::pipelines::{SplatPipelineKey, COVER_WORKGROUP};
use super::prepared::PreparedSplats;
use super::{FrameGroups, PointSplatter};
use crate::error::Result;
use crate::frame::Frame;
use crate::gpu::dispatch::dispatch_2d;
use crate::gpu::pipeline::{begin_pass_to, cleared, PassTargets};
use crate::points::SplatScene;
use crate::render::specialize::Specialization;
use crate::target::SpatialTarget;
use crate::warp::references::ReferenceImages;

/// Where [`PointSplatter::encode_views`] composites.
pub(super) enum SplatOutput<'a> {
    /// The spatial target (single pass, single view) or the N-pass layers, then the target.
    Target(&'a SpatialTarget),
    /// A warp's reference views, colour and nearness.
    References(&'a ReferenceImages),
}

impl PointSplatter {
    /// One cover + group + composite sequence per camera pass of `frame`.
    /// (After `encode`'s checks and constants.)
    pub(super) fn encode_views(
        &self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        scene: &SplatScene,
        frame: &Frame,
        state: &PreparedSplats,
        output: SplatOutput<'_>,
    ) -> Result<()> {
        let key = SplatPipelineKey {
            spec: Specialization::of(frame),
            geometry: self.geometries(frame, &state.plan)[0],
        };
        let pipelines = self.pipelines.get(&key)?;
        let scratch = &state.scratch;
        let images = &state.images.layers;
        let passes = self.passes(frame, scene.groups(), &state.plan).len();
        let FrameGroups {
            cover: cover_group,
            quad: quad_group,
            images: images_group,
            params: params_group,
        } = self.frame_groups(device, scene, state)?;
        let workgroups = scene.count.div_ceil(COVER_WORKGROUP);
        let dispatch = dispatch_2d(device, workgroups);
        for i in 0..passes {
            let offset = [self.params.offset(i)];
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
                pass.set_pipeline(&pipelines.cover);
                pass.set_bind_group(0, &self.frame.bind_group, &[]);
                pass.set_bind_group(1, &cover_group, &[]);
                pass.set_bind_group(2, &params_group, &offset);
                pass.dispatch_workgroups(dispatch[0], dispatch[1], 1);
            }
            draw_groups(
                encoder,
                "splat group",
                images,
                &scene.group_ranges,
                &pipelines.geometry,
                &[
                    (&self.frame.bind_group, &[]),
                    (&quad_group, &[]),
                    (&params_group, &offset),
                ],
                0..1,
                None,
            );
            let colors = match (&output, &self.npass) {
                (SplatOutput::References(images), _) => vec![
                    Some(cleared(&images.color.layer_views[i], [0.0; 4])),
                    Some(cleared(&images.nearness.layer_views[i], [0.0; 4])),
                ],
                (SplatOutput::Target(_), Some(npass)) => {
                    vec![Some(cleared(&npass.layers()?.layer_views[i], [0.0; 4]))]
                }
                (SplatOutput::Target(target), None) => vec![Some(cleared(&target.view, [0.0; 4]))],
            };
            let targets = PassTargets {
                colors: &colors,
                depth: None,
                keep_depth: false,
                multiview_mask: None,
            };
            let mut pass = begin_pass_to(encoder, "splat composite", targets);
            pass.set_pipeline(&pipelines.composite);
            pass.set_bind_group(0, &self.frame.bind_group, &[]);
            pass.set_bind_group(1, &images_group, &[]);
            pass.set_bind_group(2, &params_group, &offset);
            pass.draw(0..3, 0..1);
        }
        if let (Some(npass), SplatOutput::Target(target)) = (&self.npass, output) {
            npass.composite(device, encoder, &self.frame, target)?;
        }
        Ok(())
    }
}
