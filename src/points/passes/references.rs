//! Splats as a warp's reference views (src/warp): the N-pass camera passes of the reference
//! frame, composited with the nearness of each pixel's nearest splat.

use super::{PointSplatter, SplatOutput};
use crate::error::Result;
use crate::frame::Frame;
use crate::points::SplatScene;
use crate::render::{begin_prepare, check_prepared};
use crate::warp::references::{check_reference_method, ReferenceImages, ReferenceRenderer};

impl ReferenceRenderer<SplatScene> for PointSplatter {
    fn prepare_references(
        &mut self,
        device: &wgpu::Device,
        _queue: &wgpu::Queue,
        scene: &SplatScene,
        frame: &Frame,
    ) -> Result<()> {
        begin_prepare(device, frame, &mut self.prepared)?;
        check_reference_method("PointSplatter", self.method)?;
        self.ensure_resources(device, scene, frame)?;
        self.prepared = Some(self.needs(scene, frame));
        Ok(())
    }

    fn encode_references(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        scene: &SplatScene,
        frame: &Frame,
        images: &ReferenceImages,
    ) -> Result<()> {
        check_prepared("PointSplatter", &self.prepared, &self.needs(scene, frame))?;
        self.encode_views(
            device,
            encoder,
            scene,
            frame,
            SplatOutput::References(images),
        )
    }

    fn depth_meaning(&self) -> &'static str {
        "the nearest splat's depth"
    }
}
