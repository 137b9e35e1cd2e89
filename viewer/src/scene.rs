//! The viewer's scene: loaded data (a mesh, a point cloud, a volume or Gaussian splats, from
//! `autostereo::load` or made by the caller), the renderer options it is drawn with, and its
//! name; uploaded once the window's device exists.

use autostereo::camera::Bounds;
use autostereo::render::Method;
use autostereo::{AnyData, AnyScene, RendererOptions};

use crate::error::{Error, Result};

/// Data to view, with its renderer options (the method is the viewer's: `Options::method`,
/// then key m) and what the title calls it.
pub struct Scene {
    data: AnyData,
    bounds: Bounds,
    options: RendererOptions,
    name: String,
}

impl Scene {
    /// Refuses data with nothing to frame (a mesh without vertices).
    pub fn new(data: AnyData, options: RendererOptions, name: impl Into<String>) -> Result<Self> {
        let name = name.into();
        let Some(bounds) = data.bounds() else {
            return Err(Error::EmptyScene { name });
        };
        Ok(Self {
            data,
            bounds,
            options,
            name,
        })
    }

    /// Frame `bounds` instead of the data's own (a volume's visible part, say).
    pub fn with_bounds(mut self, bounds: Bounds) -> Self {
        self.bounds = bounds;
        self
    }

    /// On the device: the uploaded scene; the data is dropped (the GPU holds it now).
    pub(crate) fn upload(self, ctx: &autostereo::gpu::GpuContext) -> Result<Uploaded> {
        let scene = AnyScene::upload(&ctx.device, &ctx.queue, &self.data)?;
        if let AnyScene::Volume(volume) = &scene {
            self.options.volume.settings.validate_for(volume)?;
        }
        Ok(Uploaded {
            scene,
            bounds: self.bounds,
            options: self.options,
            name: self.name,
        })
    }
}

/// A scene on the GPU and its bounds.
pub(crate) struct Uploaded {
    pub scene: AnyScene,
    pub bounds: Bounds,
    /// What the title says.
    pub name: String,
    options: RendererOptions,
}

impl Uploaded {
    /// The renderer options for `method`.
    pub fn options(&self, method: Method) -> RendererOptions {
        RendererOptions {
            method,
            ..self.options
        }
    }
}
