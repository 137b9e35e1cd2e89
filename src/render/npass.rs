//! The N-pass harness every primitive's N-pass method shares: one layer per view, then the
//! mask compositing (`composite.rs`) into the spatial image.

use super::composite::Compositor;
use super::view_layers::ViewLayers;
use crate::error::{Error, Result};
use crate::frame::{Frame, FrameBinding};
use crate::target::SpatialTarget;

/// Per-view layers sized for the prepared frame, and their compositor.
pub(crate) struct NPassHarness {
    compositor: Compositor,
    layers: Option<ViewLayers>,
}

impl NPassHarness {
    /// `frame_layout` is the shared group-0 layout.
    pub fn new(device: &wgpu::Device, frame_layout: &wgpu::BindGroupLayout) -> Result<Self> {
        Ok(Self {
            compositor: Compositor::new(device, frame_layout)?,
            layers: None,
        })
    }

    /// Layers for `frame`'s view images (its [`Frame::view_size`]) and views (reallocated
    /// only when those change). The views are drawn with [`Frame::for_view_images`].
    pub fn prepare(&mut self, device: &wgpu::Device, frame: &Frame) -> Result<()> {
        let size = frame.view_size();
        let fits = |l: &ViewLayers| l.size() == size && l.layers() == frame.camera.views;
        if !self.layers.as_ref().is_some_and(fits) {
            self.layers = None; // free before allocating the replacement
            self.layers = Some(ViewLayers::new(device, size, frame.camera.views)?);
        }
        Ok(())
    }

    /// The layers [`NPassHarness::prepare`] allocated; `Err(NotPrepared)` before it ran.
    pub fn layers(&self) -> Result<&ViewLayers> {
        self.layers.as_ref().ok_or_else(|| Error::NotPrepared {
            renderer: "the N-pass view layers",
            frame: "a frame's view layers".to_string(),
            prepared: "nothing".to_string(),
        })
    }

    /// The layers of the last prepared frame, if any.
    pub fn view_layers(&self) -> Option<&ViewLayers> {
        self.layers.as_ref()
    }

    /// Record the compositing of the layers into `target`.
    pub fn composite(
        &self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        frame: &FrameBinding,
        target: &SpatialTarget,
    ) -> Result<()> {
        let layers = self.layers()?;
        self.compositor.encode(
            device,
            encoder,
            frame,
            &layers.array_view,
            layers.size(),
            target,
        );
        Ok(())
    }
}
