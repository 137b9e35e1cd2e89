//! Splats as a warp's reference views (src/warp): the N-pass camera passes of the reference
//! frame, composited with the nearness of each pixel's nearest splat.

use super::{PointSplatter, SplatOutput};
use crate::error::Result;
use crate::frame::Frame;
use crate::points::SplatScene;
use crate::render::{begin_prepare, prepared_state};
use crate::warp::references::{check_reference_method, ReferenceImages, ReferenceRenderer};

impl ReferenceRenderer<SplatScene> for PointSplatter {
    fn prepare_references(
        &mut self,
        device: &wgpu::Device,
        _queue: &wgpu::Queue,
        scene: &SplatScene,
        frame: &Frame,
    ) -> Result<()> {
        let last = self.prepared.take();
        begin_prepare(device, frame, &mut self.prepared)?;
        check_reference_method("PointSplatter", self.method)?;
        self.prepared = Some(self.make_state(device, scene, frame, last)?);
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
        self.write_constants(device, scene, frame)?;
        let state = prepared_state("PointSplatter", &self.prepared, &self.needs(scene, frame))?;
        self.encode_views(
            device,
            encoder,
            scene,
            frame,
            state,
            SplatOutput::References(images),
        )
    }

    fn depth_meaning(&self) -> &'static str {
        "the nearest splat's depth"
    }
}
