//! The interface every mesh renderer shares: one frame of a mesh into a spatial target.

use crate::error::Result;
use crate::frame::Frame;
use crate::mesh::MeshBuffers;
use crate::target::SpatialTarget;

/// A renderer of triangle meshes (single pass, N-pass, single view…).
pub trait MeshRenderer {
    /// Record one frame into the caller's `encoder` (uniforms go through `queue`).
    fn encode(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        mesh: &MeshBuffers,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()>;

    /// Encode one frame, submit it and wait for the GPU.
    fn render(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        mesh: &MeshBuffers,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()> {
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("mesh frame"),
        });
        self.encode(device, queue, &mut encoder, mesh, frame, target)?;
        queue.submit([encoder.finish()]);
        crate::readback::wait_idle(device)
    }
}
