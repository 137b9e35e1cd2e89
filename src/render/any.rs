//! One type that hides the primitive: a scene of any kind and a renderer of any primitive and
//! method, for viewers and tools that take whatever file they are given.

use crate::error::{Error, Result};
use crate::frame::Frame;
use crate::mesh::passes::{
    MeshLayered, MeshMrt, MeshNPass, MeshSinglePass, MeshSinglePassOptions, MeshTiled, TileClip,
    Visibility,
};
use crate::mesh::MeshBuffers;
use crate::points::passes::{PointSplatter, SplatOptions, DEFAULT_EPSILON_FRACTION};
use crate::points::SplatScene;
use crate::render::{Method, Renderer};
use crate::target::SpatialTarget;
use crate::volume::passes::VolumeRaycaster;
use crate::volume::VolumeScene;
use crate::warp::{ReferenceRenderer, SceneWarp, SceneWarpOptions};

/// A scene of any primitive, on the GPU.
pub enum AnyScene {
    /// Triangles.
    Mesh(MeshBuffers),
    /// Splats.
    Points(SplatScene),
    /// A volume with its classification.
    Volume(Box<VolumeScene>),
}

impl AnyScene {
    /// `mesh`, `points` or `volume`.
    pub fn primitive(&self) -> &'static str {
        match self {
            AnyScene::Mesh(_) => "mesh",
            AnyScene::Points(_) => "points",
            AnyScene::Volume(_) => "volume",
        }
    }
}

/// [`Method::Warp`] with the default options, from `references`.
fn warp<S: ?Sized + 'static>(
    device: &wgpu::Device,
    references: impl ReferenceRenderer<S> + 'static,
) -> Result<Box<dyn Renderer<S>>> {
    let options = SceneWarpOptions::default();
    Ok(Box::new(SceneWarp::new(
        device,
        Box::new(references),
        options,
    )?))
}

/// A renderer of one primitive, behind one type. Renders only scenes of its primitive.
pub enum AnyRenderer {
    /// Any mesh renderer.
    Mesh(Box<dyn Renderer<MeshBuffers>>),
    /// Any splat renderer.
    Points(Box<dyn Renderer<SplatScene>>),
    /// Any volume renderer.
    Volume(Box<dyn Renderer<VolumeScene>>),
}

impl AnyRenderer {
    /// The renderer of `method` for `scene`'s primitive with its default options: the fastest
    /// exact mesh visibility the adapter has, splat options for the scene, volume ray marching.
    pub fn new(device: &wgpu::Device, scene: &AnyScene, method: Method) -> Result<Self> {
        Ok(match scene {
            AnyScene::Mesh(_) => AnyRenderer::Mesh(match method {
                Method::SinglePass => Box::new(MeshSinglePass::new(
                    device,
                    MeshSinglePassOptions {
                        visibility: Visibility::best_exact(device),
                        ..Default::default()
                    },
                )?),
                Method::Tiled => Box::new(MeshTiled::new(device, TileClip::Auto)?),
                Method::Layered => Box::new(MeshLayered::new(device)?),
                Method::Mrt => Box::new(MeshMrt::new(device)?),
                Method::NPass | Method::SingleView => Box::new(MeshNPass::new(device, method)?),
                Method::Warp => warp(device, MeshNPass::new(device, method)?)?,
            }),
            AnyScene::Points(splats) => {
                let options = SplatOptions::for_scene(splats, DEFAULT_EPSILON_FRACTION);
                let splatter = PointSplatter::new(device, method, options)?;
                AnyRenderer::Points(match method {
                    Method::Warp => warp(device, splatter)?,
                    _ => Box::new(splatter),
                })
            }
            AnyScene::Volume(_) => {
                let raycaster = VolumeRaycaster::new(device, method)?;
                AnyRenderer::Volume(match method {
                    Method::Warp => warp(device, raycaster)?,
                    _ => Box::new(raycaster),
                })
            }
        })
    }

    /// `mesh`, `points` or `volume`.
    pub fn primitive(&self) -> &'static str {
        match self {
            AnyRenderer::Mesh(_) => "mesh",
            AnyRenderer::Points(_) => "points",
            AnyRenderer::Volume(_) => "volume",
        }
    }

    fn mismatch(&self, scene: &AnyScene) -> Error {
        Error::invalid(
            "scene",
            format!(
                "a {} scene for a {} renderer",
                scene.primitive(),
                self.primitive()
            ),
        )
    }
}

impl Renderer<AnyScene> for AnyRenderer {
    fn prepare(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        scene: &AnyScene,
        frame: &Frame,
    ) -> Result<()> {
        match (&mut *self, scene) {
            (AnyRenderer::Mesh(r), AnyScene::Mesh(s)) => r.prepare(device, queue, s, frame),
            (AnyRenderer::Points(r), AnyScene::Points(s)) => r.prepare(device, queue, s, frame),
            (AnyRenderer::Volume(r), AnyScene::Volume(s)) => r.prepare(device, queue, s, frame),
            _ => Err(self.mismatch(scene)),
        }
    }

    fn encode(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        scene: &AnyScene,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()> {
        match (&mut *self, scene) {
            (AnyRenderer::Mesh(r), AnyScene::Mesh(s)) => {
                r.encode(device, encoder, s, frame, target)
            }
            (AnyRenderer::Points(r), AnyScene::Points(s)) => {
                r.encode(device, encoder, s, frame, target)
            }
            (AnyRenderer::Volume(r), AnyScene::Volume(s)) => {
                r.encode(device, encoder, s, frame, target)
            }
            _ => Err(self.mismatch(scene)),
        }
    }

    fn atlas(&self) -> Option<&crate::render::atlas::Atlas> {
        match self {
            AnyRenderer::Mesh(r) => r.atlas(),
            AnyRenderer::Points(r) => r.atlas(),
            AnyRenderer::Volume(r) => r.atlas(),
        }
    }
}
