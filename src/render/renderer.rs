//! The interface every renderer shares: one frame of a scene into a spatial target. A renderer
//! per primitive (meshes: `Renderer<MeshBuffers>`, volumes: `Renderer<VolumeScene>`) and per
//! method (single pass, N-pass, single view), all behind one camera + display + output.

use crate::error::{Error, Result};
use crate::frame::Frame;
use crate::target::SpatialTarget;

/// Renders scenes of type `S` (single pass, N-pass, single view…).
pub trait Renderer<S: ?Sized> {
    /// Record one frame into the caller's `encoder` (uniforms go through `queue`).
    fn encode(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        scene: &S,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()>;

    /// Encode one frame, submit it and wait for the GPU.
    fn render(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        scene: &S,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()> {
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("frame"),
        });
        self.encode(device, queue, &mut encoder, scene, frame, target)?;
        queue.submit([encoder.finish()]);
        crate::readback::wait_idle(device)
    }
}

/// The target must have the frame's size.
pub(crate) fn check_target(frame: &Frame, target: &SpatialTarget) -> Result<()> {
    if target.size() != frame.size {
        return Err(Error::invalid(
            "target",
            format!(
                "size {:?} differs from the frame's {:?}",
                target.size(),
                frame.size
            ),
        ));
    }
    Ok(())
}
