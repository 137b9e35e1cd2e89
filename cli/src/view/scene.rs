//! The viewer's scene: a mesh, a point cloud, a volume or Gaussian splats, loaded as the render
//! commands load them (same defaults, so a viewer frame equals the command's image of the same
//! camera).

use std::path::Path;

use anyhow::{bail, Result};
use autostereo::camera::Bounds;
use autostereo::gaussians::GaussianScene;
use autostereo::mesh::MeshBuffers;
use autostereo::render::Method;
use autostereo::{AnyScene, RendererOptions};

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
        use autostereo::formats::DataKind;
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

/// Load the scene the flags say; no file: the built-in volume (or the kind's generated scene).
pub fn load(ctx: &autostereo::gpu::GpuContext, flags: &SceneFlags) -> Result<ViewScene> {
    flags.check()?;
    let kind = flags.kind()?;
    let file = flags.file;
    let name = file.map_or_else(
        || format!("built-in {}", kind.name()),
        |p| p.display().to_string(),
    );
    let device = &ctx.device;
    let mut options = RendererOptions::default();
    let (scene, bounds) = match kind {
        KindArg::Mesh => {
            let mesh = flags.mesh.load(file)?;
            let Some(bounds) = mesh.bounds() else {
                bail!("{name}: the mesh has no vertices");
            };
            options.mesh = flags.mesh.options();
            (AnyScene::Mesh(MeshBuffers::new(device, &mesh)?), bounds)
        }
        KindArg::Points => {
            flags.points.check_values()?;
            let (splats, _) = flags.points.load(file)?;
            let bounds = splats.bounds().expect("complete() rejects empty clouds");
            let scene = flags.points.scene(device, &splats)?;
            options.points = flags.points.options();
            (AnyScene::Points(scene), bounds)
        }
        KindArg::Volume => {
            let (volume, scene) = flags.volume_data.scene(ctx, file)?;
            let step = flags.volume_render.step(&volume);
            options.volume = flags.volume_render.options(step);
            options.volume.settings.validate_for(&scene)?;
            (AnyScene::Volume(Box::new(scene)), volume.bounds())
        }
        KindArg::Gaussians => {
            let gaussians = flags.gaussians.load(file)?;
            let scene = GaussianScene::new(device, &gaussians)?;
            options.gaussians = flags.gaussians.options();
            let bounds = scene.bounds;
            (AnyScene::Gaussians(scene), bounds)
        }
    };
    Ok(ViewScene {
        scene,
        bounds,
        name,
        options,
    })
}
