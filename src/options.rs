//! The one decision "method + options → renderer", for every primitive: [`RendererOptions`]
//! holds the method and each primitive's settings (each primitive's own `options.rs`); its
//! constructors build the renderer.
//! The command line, the viewer, the bench and the tests all build renderers here.

use crate::error::{Error, Result};
use crate::gaussians::{GaussianOptions, GaussianScene, GaussianSplatter};
use crate::mesh::{MeshBuffers, MeshOptions};
use crate::mesh::{
    MeshLayered, MeshMrt, MeshNPass, MeshSinglePass, MeshSinglePassOptions, MeshTiled, Visibility,
};
use crate::param::Param;
use crate::points::{PointOptions, PointSplatter, SplatScene};
use crate::render::{Banded, Method, Renderer};
use crate::rgbd::RgbdScene;
use crate::volume::{VolumeOptions, VolumePath, VolumeRaycaster, VolumeScene, VolumeSlicer};
use crate::warp::{ReferenceRenderer, RgbdWarp, SceneWarp, WarpOptions};

/// How frames are made: the method, and each primitive's settings (a primitive reads only its
/// own). `RendererOptions::default()` is the exact single pass.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RendererOptions {
    /// Which cameras are evaluated, and how.
    pub method: Method,
    /// Triangle meshes.
    pub mesh: MeshOptions,
    /// Point splats.
    pub points: PointOptions,
    /// Volumes.
    pub volume: VolumeOptions,
    /// 3D Gaussian splats.
    pub gaussians: GaussianOptions,
    /// [`Method::Warp`]: of rendered reference views (meshes, points, volumes) or of an RGB-D
    /// image (always warped: it holds one view).
    pub warp: WarpOptions,
    /// Render every frame in bands of at most this many pixels ([`crate::render::Banded`]);
    /// `None`: whole, falling back to bands only where a frame is too large for the adapter.
    pub max_band_pixels: Option<u64>,
}

impl RendererOptions {
    /// `method` with every primitive's default settings.
    pub fn new(method: Method) -> Self {
        Self {
            method,
            ..Self::default()
        }
    }

    /// The mesh renderer these options describe.
    pub fn mesh_renderer(&self, device: &wgpu::Device) -> Result<Box<dyn Renderer<MeshBuffers>>> {
        Ok(self.banded(match self.method {
            Method::SinglePass => {
                Box::new(MeshSinglePass::new(device, self.mesh_single_pass(device))?)
            }
            Method::NPass | Method::SingleView => Box::new(MeshNPass::new(device, self.method)?),
            Method::Tiled => Box::new(MeshTiled::new(device, self.mesh.tile_clip)?),
            Method::Layered => Box::new(MeshLayered::new(device)?),
            Method::Mrt => Box::new(MeshMrt::new(device)?),
            Method::Warp => self.warp_of(device, MeshNPass::new(device, Method::Warp)?)?,
        }))
    }

    /// `renderer` falling back to bands where a frame is too large for the adapter (every
    /// method but the warp, which shifts pixels across band edges).
    fn banded<S: ?Sized + 'static>(&self, renderer: Box<dyn Renderer<S>>) -> Box<dyn Renderer<S>> {
        match self.method {
            Method::Warp => renderer,
            method => Box::new(Banded::new(renderer, method, self.max_band_pixels)),
        }
    }

    /// The mesh single pass's options on `device` (visibility resolved).
    pub fn mesh_single_pass(&self, device: &wgpu::Device) -> MeshSinglePassOptions {
        MeshSinglePassOptions {
            visibility: self
                .mesh
                .visibility
                .unwrap_or_else(|| Visibility::best_exact(device)),
            bounds: self.mesh.bounds,
            clusters: self.mesh.clusters,
        }
    }

    /// The splat renderer these options describe, for `scene` (ε is a share of its size).
    pub fn points_renderer(
        &self,
        device: &wgpu::Device,
        scene: &SplatScene,
    ) -> Result<Box<dyn Renderer<SplatScene>>> {
        let splatter = PointSplatter::new(device, self.method, self.points.for_scene(scene))?;
        Ok(self.banded(match self.method {
            Method::Warp => self.warp_of(device, splatter)?,
            _ => Box::new(splatter),
        }))
    }

    /// The volume renderer these options describe.
    pub fn volume_renderer(&self, device: &wgpu::Device) -> Result<Box<dyn Renderer<VolumeScene>>> {
        let settings = self.volume.settings;
        if settings.projection != crate::volume::Projection::Composite {
            let refused = match (self.volume.path, self.method) {
                (VolumePath::Slices(_), _) => Some("the paper's proxy slices composite"),
                (_, Method::Warp) => Some("the warp's references need a depth to warp by"),
                _ => None,
            };
            if let Some(why) = refused {
                return Err(Error::invalid(
                    Param::Projection,
                    format!(
                        "{}: ray marching only ({why}); every other method projects",
                        settings.projection.name()
                    ),
                ));
            }
        }
        if let VolumePath::Slices(alpha) = self.volume.path {
            if self.method != Method::SinglePass {
                return Err(Error::invalid(
                    Param::VolumePath,
                    format!(
                        "proxy slices are a single-pass path; the {} method ray-marches",
                        self.method
                    ),
                ));
            }
            let slicer = VolumeSlicer::new(device, alpha, settings)?;
            return Ok(self.banded(Box::new(slicer)));
        }
        let raycaster = VolumeRaycaster::new(device, self.method, settings)?;
        Ok(self.banded(match self.method {
            Method::Warp => self.warp_of(device, raycaster)?,
            _ => Box::new(raycaster),
        }))
    }

    /// The 3D Gaussian splat renderer these options describe.
    pub fn gaussians_renderer(
        &self,
        device: &wgpu::Device,
    ) -> Result<Box<dyn Renderer<GaussianScene>>> {
        let splatter = GaussianSplatter::new(device, self.method, self.gaussians)?;
        Ok(self.banded(Box::new(splatter)))
    }

    /// The RGB-D renderer these options describe: an RGB-D image holds one view, so its one
    /// method is [`Method::Warp`].
    pub fn rgbd_renderer(&self, device: &wgpu::Device) -> Result<Box<dyn Renderer<RgbdScene>>> {
        if self.method != Method::Warp {
            return Err(Error::invalid(
                Param::Method,
                format!(
                    "an RGB-D image holds one view, so it is warped into the others (method \
                     warp), not rendered by the {} method",
                    self.method
                ),
            ));
        }
        Ok(Box::new(RgbdWarp::new(device, self.warp)?))
    }

    /// [`Method::Warp`] of the reference views `references` renders.
    fn warp_of<S: ?Sized + 'static>(
        &self,
        device: &wgpu::Device,
        references: impl ReferenceRenderer<S> + 'static,
    ) -> Result<Box<dyn Renderer<S>>> {
        Ok(Box::new(SceneWarp::new(
            device,
            Box::new(references),
            self.warp,
        )?))
    }
}
