//! The viewer's scene: a mesh, a point cloud, a volume or Gaussian splats, loaded as the render
//! commands load them (same defaults, so a viewer frame equals the command's image of the same
//! camera).

use std::path::Path;

use anyhow::{bail, Result};
use autostereo::camera::Bounds;
use autostereo::render::Method;
use autostereo::{AnyData, AnyScene, DataKind, LoadOptions, RendererOptions};

use crate::gaussians_cmd::GaussianFlags;
use crate::mesh_cmd::MeshFlags;
use crate::points_cmd::PointFlags;
use crate::volume_cmd::{VolumeDataArgs, VolumeRenderArgs};

/// What a file holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum KindArg {
    /// Triangles (OBJ, PLY with faces, STL, glTF).
    Mesh,
    /// Splats (PLY, LAS/LAZ, or an OBJ's vertices).
    Points,
    /// A volume (every format of `autostereo volume`; the built-in head without a file).
    Volume,
    /// 3D Gaussian splats (graphdeco PLY, `.splat`, `.spz`).
    Gaussians,
}

impl KindArg {
    /// Its name in messages and `--kind`.
    pub fn name(self) -> &'static str {
        match self {
            KindArg::Mesh => "mesh",
            KindArg::Points => "points",
            KindArg::Volume => "volume",
            KindArg::Gaussians => "gaussians",
        }
    }

    /// The library's kind.
    pub fn data_kind(self) -> DataKind {
        match self {
            KindArg::Mesh => DataKind::Mesh,
            KindArg::Points => DataKind::Points,
            KindArg::Volume => DataKind::Volume,
            KindArg::Gaussians => DataKind::Gaussians,
        }
    }

    /// What a scene of this kind is, in a sentence.
    fn noun(self) -> &'static str {
        match self {
            KindArg::Mesh => "a mesh",
            KindArg::Points => "a point cloud",
            KindArg::Volume => "a volume",
            KindArg::Gaussians => "Gaussian splats",
        }
    }

    /// The kind of data the file holds (autostereo::formats::kind: its first bytes, else
    /// its extension; a PLY with faces is a mesh).
    pub fn of(path: &Path) -> Result<Self> {
        Ok(match autostereo::formats::kind(path)? {
            (_, DataKind::Mesh) => KindArg::Mesh,
            (_, DataKind::Points) => KindArg::Points,
            (_, DataKind::Volume) => KindArg::Volume,
            (format, DataKind::Image) => bail!(
                "{}: {format} is an image; `autostereo rgbd` or `autostereo interleave` reads it",
                path.display()
            ),
            (_, DataKind::Gaussians) => KindArg::Gaussians,
        })
    }
}

/// A loaded scene on the GPU and its bounds.
pub struct ViewScene {
    pub scene: AnyScene,
    pub bounds: Bounds,
    /// What the title says.
    pub name: String,
    /// The renderer options the primitive's flags say (the method is set per renderer).
    pub options: RendererOptions,
}

impl ViewScene {
    /// The renderer options for `method`.
    pub fn options(&self, method: Method) -> RendererOptions {
        RendererOptions {
            method,
            ..self.options
        }
    }
}

/// What the viewer reads, with the flags of every primitive (the render commands' own
/// definitions: cli/src/{mesh,points,volume,gaussians}_cmd.rs).
pub struct SceneFlags<'a> {
    pub file: Option<&'a Path>,
    pub kind: Option<KindArg>,
    pub mesh: &'a MeshFlags,
    pub points: &'a PointFlags,
    pub volume_data: &'a VolumeDataArgs,
    pub volume_render: &'a VolumeRenderArgs,
    pub gaussians: &'a GaussianFlags,
}

impl SceneFlags<'_> {
    /// The kind of scene these flags load.
    pub fn kind(&self) -> Result<KindArg> {
        Ok(match (self.file, self.kind) {
            (_, Some(k)) => k,
            (Some(path), None) => KindArg::of(path)?,
            (None, None) => KindArg::Volume,
        })
    }

    /// Refuse flags of a primitive the scene is not (they would be ignored silently).
    pub fn check(&self) -> Result<()> {
        let kind = self.kind()?;
        use crate::args::{defaults_of, flags_given_of};
        // The flags' names are looked up only for the refusal.
        fn volume_flags() -> Vec<String> {
            [
                flags_given_of::<VolumeDataArgs>(),
                flags_given_of::<VolumeRenderArgs>(),
            ]
            .concat()
        }
        type FlagsGiven = fn() -> Vec<String>;
        let given: [(KindArg, bool, FlagsGiven); 4] = [
            (
                KindArg::Mesh,
                *self.mesh != defaults_of::<MeshFlags>(),
                flags_given_of::<MeshFlags>,
            ),
            (
                KindArg::Points,
                *self.points != defaults_of::<PointFlags>(),
                flags_given_of::<PointFlags>,
            ),
            (
                KindArg::Volume,
                *self.volume_data != defaults_of::<VolumeDataArgs>()
                    || *self.volume_render != defaults_of::<VolumeRenderArgs>(),
                volume_flags,
            ),
            (
                KindArg::Gaussians,
                *self.gaussians != defaults_of::<GaussianFlags>(),
                flags_given_of::<GaussianFlags>,
            ),
        ];
        for (other, set, flags) in given {
            if set && other != kind {
                let what = self
                    .file
                    .map_or_else(|| "the built-in scene".into(), |p| p.display().to_string());
                let named = match flags().first() {
                    Some(flag) => format!("{flag} is a flag of `autostereo {}`", other.name()),
                    None => format!("flags of `autostereo {}` were given", other.name()),
                };
                bail!(
                    "{named}, but {what} is {}: it applies to {} only (`--kind {}` or such a \
                     file)",
                    kind.noun(),
                    other.noun(),
                    other.name(),
                );
            }
        }
        Ok(())
    }
}

/// Load the scene the flags say: a file by the library's [`autostereo::load`]; no file: the
/// built-in volume (or the kind's generated scene).
pub fn load(ctx: &autostereo::gpu::GpuContext, flags: &SceneFlags) -> Result<ViewScene> {
    flags.check()?;
    let kind = flags.kind()?;
    let file = flags.file;
    let name = file.map_or_else(
        || format!("built-in {}", kind.name()),
        |p| p.display().to_string(),
    );
    if kind == KindArg::Points {
        flags.points.check_values()?;
    }
    let data = match (file, kind) {
        (Some(path), _) => {
            let options = LoadOptions {
                kind: Some(kind.data_kind()),
                mesh: flags.mesh.load_options(),
                points: flags.points.load_options(),
                volume: flags.volume_data.volume_load()?,
            };
            autostereo::load(path, &options)?
        }
        (None, KindArg::Mesh) => AnyData::Mesh(flags.mesh.load(None)?),
        (None, KindArg::Points) => AnyData::Points(
            flags
                .points
                .complete(&autostereo::points::PointCloud::torus_scene())?,
        ),
        (None, KindArg::Volume) => AnyData::Volume(Box::new(flags.volume_data.load(None)?)),
        (None, KindArg::Gaussians) => AnyData::Gaussians(flags.gaussians.load(None)?),
    };
    let Some(bounds) = data.bounds() else {
        bail!("{name}: the mesh has no vertices");
    };
    let scene = AnyScene::upload(&ctx.device, &ctx.queue, &data)?;
    let mut options = RendererOptions::default();
    match &scene {
        AnyScene::Mesh(_) => options.mesh = flags.mesh.options(),
        AnyScene::Points(_) => options.points = flags.points.options(),
        AnyScene::Volume(volume) => {
            let AnyData::Volume(data) = &data else {
                unreachable!("a volume scene is uploaded from volume data")
            };
            options.volume = flags
                .volume_render
                .options(flags.volume_render.step(&data.volume));
            options.volume.settings.validate_for(volume)?;
        }
        AnyScene::Gaussians(_) => options.gaussians = flags.gaussians.options(),
        AnyScene::Rgbd(_) => unreachable!("the viewer loads no RGB-D scene"),
    }
    Ok(ViewScene {
        scene,
        bounds,
        name,
        options,
    })
}
