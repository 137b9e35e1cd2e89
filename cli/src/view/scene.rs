//! The viewer's scene: a mesh, a point cloud or a volume, loaded as the render commands load
//! them (same defaults, so a viewer frame equals the command's image of the same camera).

use std::path::{Path, PathBuf};

use anyhow::{bail, Result};
use autostereo::camera::Bounds;
use autostereo::mesh::{Mesh, MeshBuffers};
use autostereo::points::{GroupCount, PointCloud, SplatScene};
use autostereo::volume::{load::load_any, phantom, TransferFunction, VolumeScene};
use autostereo::AnyScene;
use glam::Mat4;

/// What a file holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum KindArg {
    /// Triangles (OBJ).
    Mesh,
    /// Splats (PLY, or an OBJ's vertices).
    Points,
    /// A volume (NRRD, .den; the built-in head without a file).
    Volume,
}

impl KindArg {
    /// The kind of data the file holds (autostereo::formats::kind: its first bytes, else
    /// its extension; a PLY with faces is a mesh).
    pub fn of(path: &Path) -> Result<Self> {
        use autostereo::formats::DataKind;
        Ok(match autostereo::formats::kind(path)? {
            (_, DataKind::Mesh) => KindArg::Mesh,
            (_, DataKind::Points) => KindArg::Points,
            (_, DataKind::Volume) => KindArg::Volume,
            (format, DataKind::Image) => bail!(
                "{}: {format} is an image; `autostereo rgbd` or `autostereo interleave` reads it",
                path.display()
            ),
        })
    }
}

/// A loaded scene on the GPU and its bounds.
pub struct ViewScene {
    pub scene: AnyScene,
    pub bounds: Bounds,
    /// What the title says.
    pub name: String,
}

/// Load `file` as `kind` (from the extension when `None`); no file: the built-in volume.
pub fn load(
    ctx: &autostereo::gpu::GpuContext,
    file: Option<&PathBuf>,
    kind: Option<KindArg>,
) -> Result<ViewScene> {
    let kind = match (file, kind) {
        (_, Some(k)) => k,
        (Some(path), None) => KindArg::of(path)?,
        (None, None) => KindArg::Volume,
    };
    let name = file.map_or_else(
        || format!("built-in {kind:?}").to_lowercase(),
        |p| p.display().to_string(),
    );
    let (device, queue) = (&ctx.device, &ctx.queue);
    let (scene, bounds) = match kind {
        KindArg::Mesh => {
            let mesh = match file {
                Some(path) => Mesh::load(path)?,
                None => Mesh::torus_scene(),
            };
            let Some(bounds) = mesh.bounds() else {
                bail!("{name}: the mesh has no vertices");
            };
            (AnyScene::Mesh(MeshBuffers::new(device, &mesh)?), bounds)
        }
        KindArg::Points => {
            let cloud = match file {
                Some(path) => PointCloud::load(path)?,
                None => PointCloud::torus_scene(),
            };
            let (splats, _) = cloud.complete(1.0)?;
            let bounds = splats.bounds().expect("complete() rejects empty clouds");
            let scene = SplatScene::new(device, &splats, GroupCount::Auto)?;
            (AnyScene::Points(scene), bounds)
        }
        KindArg::Volume => {
            let (volume, tf) = match file {
                Some(path) => (load_any(path)?, crate::volume_cmd::default_preset(path)),
                None => (phantom::ct_head(96)?, "ct-skin"),
            };
            let tf = TransferFunction::preset(tf)?;
            let scene = VolumeScene::new(device, queue, &volume, tf, Mat4::IDENTITY)?;
            (AnyScene::Volume(Box::new(scene)), volume.bounds())
        }
    };
    Ok(ViewScene {
        scene,
        bounds,
        name,
    })
}
