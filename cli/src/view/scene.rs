//! The viewer's scene from its flags: a mesh, a point cloud, a volume or Gaussian splats, loaded
//! as the render commands load them (same defaults, so a viewer frame equals the command's image
//! of the same camera).

use std::path::Path;

use anyhow::{bail, Result};
use autostereo::{AnyData, DataKind, LoadOptions, RendererOptions};

use crate::gaussians_cmd::GaussianFlags;
use crate::mesh_cmd::MeshFlags;
use crate::points_cmd::PointFlags;
use crate::volume_cmd::{VolumeDataArgs, VolumeRenderArgs};

/// The kind of scene `path` holds (autostereo::formats::kind: its first bytes, else its
/// extension; a PLY with faces is a mesh); an image is no scene.
fn kind_of(path: &Path) -> Result<DataKind> {
    match autostereo::formats::kind(path)? {
        (format, DataKind::Image) => bail!(
            "{}: {format} is an image; `autostereo rgbd` or `autostereo interleave` reads it",
            path.display()
        ),
        (_, kind) => Ok(kind),
    }
}

/// What the viewer reads, with the flags of every primitive (the render commands' own
/// definitions: cli/src/{mesh,points,volume,gaussians}_cmd.rs).
pub struct SceneFlags<'a> {
    pub file: Option<&'a Path>,
    pub kind: Option<DataKind>,
    pub mesh: &'a MeshFlags,
    pub points: &'a PointFlags,
    pub volume_data: &'a VolumeDataArgs,
    pub volume_render: &'a VolumeRenderArgs,
    pub gaussians: &'a GaussianFlags,
    pub crop: crate::crop_box_arg::CropBoxArgs,
}

impl SceneFlags<'_> {
    /// The kind of scene these flags load.
    pub fn kind(&self) -> Result<DataKind> {
        Ok(match (self.file, self.kind) {
            (_, Some(k)) => k,
            (Some(path), None) => kind_of(path)?,
            (None, None) => DataKind::Volume,
        })
    }

    /// Refuse flags of a primitive the scene is not (they would be ignored silently).
    /// `given`: the `view` command's matches, which tell a flag typed from its default.
    pub fn check(&self, given: &clap::ArgMatches) -> Result<()> {
        use crate::args::flags_given;
        let kind = self.kind()?;
        if self.crop.crop_box.is_some() && !matches!(kind, DataKind::Points | DataKind::Gaussians) {
            bail!(
                "--crop-box keeps the points or Gaussians in a box, and the scene is {} (a \
                 volume's box is --crop)",
                kind.article()
            );
        }
        let groups = [
            (DataKind::Mesh, flags_given::<MeshFlags>(given)),
            (DataKind::Points, flags_given::<PointFlags>(given)),
            (
                DataKind::Volume,
                [
                    flags_given::<VolumeDataArgs>(given),
                    flags_given::<VolumeRenderArgs>(given),
                ]
                .concat(),
            ),
            (DataKind::Gaussians, flags_given::<GaussianFlags>(given)),
        ];
        for (other, flags) in groups {
            let Some(flag) = flags.first().filter(|_| other != kind) else {
                continue;
            };
            let what = self
                .file
                .map_or_else(|| "the built-in scene".into(), |p| p.display().to_string());
            bail!(
                "{flag} is a flag of `autostereo {}`, but {what} is {}: it applies to {} only \
                 (`--kind {}` or such a file)",
                other.name(),
                kind.article(),
                other.article(),
                other.name(),
            );
        }
        Ok(())
    }
}

/// Load the scene the flags say: a file by the library's [`autostereo::load`]; no file: the
/// built-in volume (or the kind's generated scene). With the renderer options the primitive's
/// flags say. `flags` are checked (`SceneFlags::check`) first.
pub fn load(flags: &SceneFlags) -> Result<autostereo_viewer::Scene> {
    let kind = flags.kind()?;
    let file = flags.file;
    let name = file.map_or_else(
        || format!("built-in {}", kind.name()),
        |p| p.display().to_string(),
    );
    if kind == DataKind::Points {
        flags.points.check_values()?;
    }
    let data = match (file, kind) {
        (Some(path), _) => {
            let options = LoadOptions {
                kind: Some(kind),
                mesh: flags.mesh.load_options(),
                points: flags.points.load_options(flags.crop),
                volume: flags.volume_data.volume_load()?,
                gaussians: autostereo::GaussianLoad {
                    crop: flags.crop.crop_box,
                },
                budget: None,
            };
            let mut data = autostereo::load(path, &options)?;
            if let AnyData::Volume(v) = &mut data {
                v.clip = flags.volume_data.clip_planes(&v.volume);
            }
            data
        }
        (None, DataKind::Mesh) => AnyData::Mesh(flags.mesh.load(None)?),
        (None, DataKind::Points) => AnyData::Points(
            flags
                .points
                .complete(&autostereo::points::PointCloud::torus_scene(), flags.crop)?,
        ),
        (None, DataKind::Volume) => AnyData::Volume(Box::new(flags.volume_data.load(None)?)),
        (None, DataKind::Gaussians) => AnyData::Gaussians(flags.gaussians.load(None, flags.crop)?),
        (None, DataKind::Image) => bail!("an image is no scene to view (`--kind` offers none)"),
    };
    let framed = match &data {
        AnyData::Volume(v) => Some(flags.volume_render.framed(v)?),
        _ => None,
    };
    let mut options = RendererOptions::default();
    match &data {
        AnyData::Mesh(_) => options.mesh = flags.mesh.options(),
        AnyData::Points(_) => options.points = flags.points.options(),
        AnyData::Volume(data) => {
            options.volume = flags
                .volume_render
                .options(flags.volume_render.step(&data.volume))
        }
        AnyData::Gaussians(_) => options.gaussians = flags.gaussians.options(),
    }
    let scene = autostereo_viewer::Scene::new(data, options, name)?;
    Ok(match framed {
        Some(bounds) => scene.with_bounds(bounds),
        None => scene,
    })
}
