//! One type that hides the primitive: a scene of any kind and a renderer of any primitive and
//! method, for viewers and tools that take whatever file they are given.

use crate::error::{Error, Result};
use crate::frame::Frame;
use crate::gaussians::GaussianScene;
use crate::load::AnyData;
use crate::mesh::MeshBuffers;
use crate::options::RendererOptions;
use crate::param::Param;
use crate::points::SplatScene;
use crate::render::Renderer;
use crate::rgbd::RgbdScene;
use crate::target::SpatialTarget;
use crate::volume::VolumeScene;

/// A scene of any primitive, on the GPU.
pub enum AnyScene {
    /// Triangles.
    Mesh(MeshBuffers),
    /// Splats.
    Points(SplatScene),
    /// A volume with its classification.
    Volume(Box<VolumeScene>),
    /// A colour image with its depth map.
    Rgbd(RgbdScene),
    /// 3D Gaussian splats.
    Gaussians(GaussianScene),
}

impl AnyScene {
    /// `data` on the GPU: the scene its primitive's renderers take.
    pub fn upload(device: &wgpu::Device, queue: &wgpu::Queue, data: &AnyData) -> Result<Self> {
        Ok(match data {
            AnyData::Mesh(mesh) => AnyScene::Mesh(MeshBuffers::new(device, mesh)?),
            AnyData::Points(points) => {
                AnyScene::Points(SplatScene::new(device, &points.splats, points.groups)?)
            }
            AnyData::Volume(v) => {
                let mut scene =
                    VolumeScene::new(device, queue, &v.volume, v.transfer.clone(), v.model)?;
                scene.clip = v.clip.clone();
                AnyScene::Volume(Box::new(scene))
            }
            AnyData::Gaussians(gaussians) => {
                AnyScene::Gaussians(GaussianScene::new(device, gaussians)?)
            }
        })
    }

    /// `mesh`, `points`, `volume` or `rgbd`.
    pub fn primitive(&self) -> &'static str {
        match self {
            AnyScene::Mesh(_) => "mesh",
            AnyScene::Points(_) => "points",
            AnyScene::Volume(_) => "volume",
            AnyScene::Rgbd(_) => "rgbd",
            AnyScene::Gaussians(_) => "gaussians",
        }
    }
}

/// A renderer of one primitive, behind one type. Renders only scenes of its primitive.
pub enum AnyRenderer {
    /// Any mesh renderer.
    Mesh(Box<dyn Renderer<MeshBuffers>>),
    /// Any splat renderer.
    Points(Box<dyn Renderer<SplatScene>>),
    /// Any volume renderer.
    Volume(Box<dyn Renderer<VolumeScene>>),
    /// The RGB-D warp.
    Rgbd(Box<dyn Renderer<RgbdScene>>),
    /// Any 3D Gaussian splat renderer.
    Gaussians(Box<dyn Renderer<GaussianScene>>),
}

impl AnyRenderer {
    /// The renderer `options` describe for `scene`'s primitive (a method the primitive does not
    /// have is refused with the reason).
    pub fn new(device: &wgpu::Device, scene: &AnyScene, options: &RendererOptions) -> Result<Self> {
        Ok(match scene {
            AnyScene::Mesh(_) => AnyRenderer::Mesh(options.mesh_renderer(device)?),
            AnyScene::Points(splats) => {
                AnyRenderer::Points(options.points_renderer(device, splats)?)
            }
            AnyScene::Volume(_) => AnyRenderer::Volume(options.volume_renderer(device)?),
            AnyScene::Rgbd(_) => AnyRenderer::Rgbd(options.rgbd_renderer(device)?),
            AnyScene::Gaussians(_) => AnyRenderer::Gaussians(options.gaussians_renderer(device)?),
        })
    }

    /// `mesh`, `points`, `volume` or `rgbd`.
    pub fn primitive(&self) -> &'static str {
        match self {
            AnyRenderer::Mesh(_) => "mesh",
            AnyRenderer::Points(_) => "points",
            AnyRenderer::Volume(_) => "volume",
            AnyRenderer::Rgbd(_) => "rgbd",
            AnyRenderer::Gaussians(_) => "gaussians",
        }
    }

    fn mismatch(&self, scene: &AnyScene) -> Error {
        Error::invalid(
            Param::Scene,
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
            (AnyRenderer::Rgbd(r), AnyScene::Rgbd(s)) => r.prepare(device, queue, s, frame),
            (AnyRenderer::Gaussians(r), AnyScene::Gaussians(s)) => {
                r.prepare(device, queue, s, frame)
            }
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
            (AnyRenderer::Rgbd(r), AnyScene::Rgbd(s)) => {
                r.encode(device, encoder, s, frame, target)
            }
            (AnyRenderer::Gaussians(r), AnyScene::Gaussians(s)) => {
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
            AnyRenderer::Rgbd(r) => r.atlas(),
            AnyRenderer::Gaussians(r) => r.atlas(),
        }
    }

    fn describe(&self) -> Option<String> {
        match self {
            AnyRenderer::Mesh(r) => r.describe(),
            AnyRenderer::Points(r) => r.describe(),
            AnyRenderer::Volume(r) => r.describe(),
            AnyRenderer::Rgbd(r) => r.describe(),
            AnyRenderer::Gaussians(r) => r.describe(),
        }
    }
}
