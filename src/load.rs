//! Path → data: [`load`] opens a file of any format this build reads, tells its primitive by
//! its first bytes, else its extension ([`crate::formats::kind`]), and prepares it as every
//! tool of the project does (a point cloud's missing normals and radii estimated, a volume
//! resampled and classified). [`crate::AnyScene::upload`] puts the result on the GPU. The
//! CLI's commands, its viewer and the Python package all open files here, so a file renders
//! alike in each of them.

use std::path::Path;

use glam::Mat4;

use crate::camera::Bounds;
use crate::error::{Error, Result};
use crate::formats::{DataKind, Format};
use crate::gaussians::Gaussians;
use crate::mesh::Mesh;
use crate::param::Param;
use crate::points::{Completion, GroupCount, PointCloud, Splats};
use crate::volume::load::{load_any, load_raw, RawSpec};
use crate::volume::{TransferFunction, Volume};

/// How [`load`] reads and prepares a file: the primitive (told by the file when `None`) and
/// each primitive's own options (those of other primitives are not read).
#[derive(Clone, Debug, Default)]
pub struct LoadOptions {
    /// Read the file as this kind of data (a PLY's vertices as points, say); `None`: the kind
    /// the file holds.
    pub kind: Option<DataKind>,
    /// Meshes.
    pub mesh: MeshLoad,
    /// Point clouds.
    pub points: PointLoad,
    /// Volumes.
    pub volume: VolumeLoad,
    /// Gaussian splats.
    pub gaussians: GaussianLoad,
    /// The memory budget the reading is checked against; `None`: the current one
    /// ([`crate::budget::Budget::current`]).
    pub budget: Option<crate::budget::Budget>,
}

/// How a mesh is prepared.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MeshLoad {
    /// Reorder the triangles along a Morton curve (locality for every method).
    pub sort_triangles: bool,
}

/// How a point cloud is prepared.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointLoad {
    /// Every splat radius (given or estimated) times this (> 0).
    pub radius_scale: f32,
    /// How the splats are grouped on the GPU ([`crate::points::SplatScene::new`]).
    pub groups: GroupCount,
    /// Keep only the points in this box (world units of the file), before normals and radii
    /// are estimated ([`PointCloud::cropped`]).
    pub crop: Option<crate::camera::Bounds>,
}

/// How Gaussian splats are prepared.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct GaussianLoad {
    /// Keep only the Gaussians whose means lie in this box (world units of the file):
    /// [`Gaussians::cropped`].
    pub crop: Option<crate::camera::Bounds>,
}

impl Default for PointLoad {
    fn default() -> Self {
        Self {
            radius_scale: 1.0,
            groups: GroupCount::Auto,
            crop: None,
        }
    }
}

/// How a volume is read, resampled, classified and placed.
#[derive(Clone, Debug, PartialEq)]
pub struct VolumeLoad {
    /// Read the file as raw voxels so described (formats with a header describe themselves).
    pub raw: Option<RawSpec>,
    /// Voxel spacing overriding the file's.
    pub spacing: Option<[f32; 3]>,
    /// Keep this box of the volume (before `downsample`).
    pub crop: Option<crate::volume::Crop>,
    /// Average blocks of `downsample`³ voxels (1: as read).
    pub downsample: u32,
    /// The classification; `None`: the preset for the scan's modality, else its format
    /// ([`default_preset`]).
    pub transfer: Option<crate::volume::Transfer>,
    /// Placed by this matrix after the volume's own axes.
    pub model: Mat4,
}

impl Default for VolumeLoad {
    fn default() -> Self {
        Self {
            raw: None,
            spacing: None,
            crop: None,
            downsample: 1,
            transfer: None,
            model: Mat4::IDENTITY,
        }
    }
}

/// A file's data, prepared, on the CPU.
#[derive(Clone)]
pub enum AnyData {
    /// Triangles.
    Mesh(Mesh),
    /// Splats.
    Points(PointData),
    /// A volume with its classification.
    Volume(Box<VolumeData>),
    /// 3D Gaussian splats.
    Gaussians(Gaussians),
}

/// A point cloud completed into splats.
#[derive(Clone)]
pub struct PointData {
    /// The splats.
    pub splats: Splats,
    /// What was estimated.
    pub completion: Completion,
    /// How they are grouped on the GPU.
    pub groups: GroupCount,
}

/// A volume, its transfer function and its placement.
#[derive(Clone)]
pub struct VolumeData {
    /// The voxels.
    pub volume: Volume,
    /// The classification.
    pub transfer: TransferFunction,
    /// The preset `transfer` is, where it is one chosen by the file's format.
    pub preset: Option<&'static str>,
    /// Placed by this matrix after the volume's own axes.
    pub model: Mat4,
    /// Clipping planes its scene keeps ([`crate::volume::VolumeScene::clip`]); none at load.
    pub clip: Vec<crate::volume::ClipPlane>,
}

impl VolumeData {
    /// The box around what `projection` (`isovalue`: the isosurface's normalised value) shows
    /// of this volume under its transfer function and within its clip planes
    /// ([`Volume::visible_bounds`]), else its whole box: what the CLI's `--fit visible` and
    /// the Python module frame. The flag says which it is (false: nothing is visible).
    pub fn framed_bounds(
        &self,
        projection: crate::volume::Projection,
        isovalue: f32,
    ) -> (crate::camera::Bounds, bool) {
        match self
            .volume
            .visible_bounds(&self.transfer, projection, isovalue, &self.clip)
        {
            Some(bounds) => (bounds, true),
            None => (self.volume.bounds(), false),
        }
    }

    /// `volume` classified by `transfer` (a preset name), placed by `model`.
    pub fn with_preset(volume: Volume, preset: &'static str, model: Mat4) -> Result<Self> {
        Ok(Self {
            transfer: TransferFunction::preset_for(preset, &volume.values)?,
            volume,
            preset: Some(preset),
            model,
            clip: Vec::new(),
        })
    }
}

impl AnyData {
    /// The kind of data it is.
    pub fn kind(&self) -> DataKind {
        match self {
            AnyData::Mesh(_) => DataKind::Mesh,
            AnyData::Points(_) => DataKind::Points,
            AnyData::Volume(_) => DataKind::Volume,
            AnyData::Gaussians(_) => DataKind::Gaussians,
        }
    }

    /// Its bounds in world units (`None` for a mesh without vertices).
    pub fn bounds(&self) -> Option<Bounds> {
        match self {
            AnyData::Mesh(mesh) => mesh.bounds(),
            AnyData::Points(points) => points.splats.bounds(),
            AnyData::Volume(data) => Some(data.volume.bounds()),
            AnyData::Gaussians(gaussians) => gaussians.bounds(),
        }
    }
}

/// The transfer-function preset a volume of `format` gets by default: `mri` for the formats
/// of MR studies (NIfTI, VolPack's MRI brain), else `ct-skin`.
pub fn default_preset(format: Option<Format>) -> &'static str {
    default_preset_for(format, None)
}

/// The preset for a scan of `modality` (where its file says: CT `ct-skin`, MR `mri`), else as
/// [`default_preset`] for its format.
pub fn default_preset_for(
    format: Option<Format>,
    modality: Option<crate::volume::Modality>,
) -> &'static str {
    use crate::volume::Modality;
    match (modality, format) {
        (Some(Modality::Ct), _) => "ct-skin",
        (Some(Modality::Mr), _) | (_, Some(Format::Nifti | Format::Den)) => "mri",
        _ => "ct-skin",
    }
}

/// Open the file at `path` as `options` say. A file of a kind that is not rendered (an image)
/// or of another kind than `options.kind` is refused with [`Error::WrongKind`], naming the
/// kind it holds.
pub fn load(path: &Path, options: &LoadOptions) -> Result<AnyData> {
    match &options.budget {
        Some(budget) => budget.in_scope(|| load_in_budget(path, options)),
        None => load_in_budget(path, options),
    }
}

/// [`load`] against the current budget.
fn load_in_budget(path: &Path, options: &LoadOptions) -> Result<AnyData> {
    let kind = match (options.kind, &options.volume.raw) {
        (Some(kind), _) => kind,
        (None, Some(_)) => DataKind::Volume,
        (None, None) => crate::formats::kind(path)?.1,
    };
    match kind {
        DataKind::Mesh => {
            let mut mesh = Mesh::load(path)?;
            if options.mesh.sort_triangles {
                mesh.sort_triangles_spatially();
            }
            Ok(AnyData::Mesh(mesh))
        }
        DataKind::Points => {
            let cloud = PointCloud::load(path)?;
            Ok(AnyData::Points(complete(&cloud, &options.points)?))
        }
        DataKind::Volume => Ok(AnyData::Volume(Box::new(volume(path, &options.volume)?))),
        DataKind::Gaussians => {
            let gaussians = Gaussians::load(path)?;
            Ok(AnyData::Gaussians(match options.gaussians.crop {
                Some(keep) => gaussians.cropped(keep)?,
                None => gaussians,
            }))
        }
        DataKind::Image => Err(Error::WrongKind {
            path: path.into(),
            holds: DataKind::Image,
            wanted: None,
            detail: crate::formats::detect(path)?.to_string(),
        }),
    }
}

/// `cloud` completed into splats as `options` say.
pub fn complete(cloud: &PointCloud, options: &PointLoad) -> Result<PointData> {
    let cropped = options.crop.map(|keep| cloud.cropped(keep)).transpose()?;
    let (splats, completion) = cropped
        .as_ref()
        .unwrap_or(cloud)
        .complete(options.radius_scale)?;
    Ok(PointData {
        splats,
        completion,
        groups: options.groups,
    })
}

/// The volume at `path`, raw when `options.raw` describes it, resampled and classified.
fn volume(path: &Path, options: &VolumeLoad) -> Result<VolumeData> {
    let mut volume = match &options.raw {
        Some(spec) => load_raw(path, spec)?,
        None => load_any(path)?,
    };
    if let Some(spacing) = options.spacing {
        let values = volume.values.clone();
        volume = Volume::new(volume.dims, spacing, volume.data)?
            .with_axes(volume.axes)?
            .with_values(values);
    }
    if let Some(crop) = options.crop {
        volume = volume.cropped(crop)?;
    }
    volume = resampled(volume, options.downsample)?.with_robust_range();
    let (transfer, preset) = match &options.transfer {
        Some(choice) => choice.resolve(&volume.values)?,
        None => {
            let format = match options.raw {
                Some(_) => Some(Format::Raw),
                None => crate::formats::detect(path).ok(),
            };
            let preset = default_preset_for(format, volume.values.modality);
            (
                TransferFunction::preset_for(preset, &volume.values)?,
                Some(preset),
            )
        }
    };
    Ok(VolumeData {
        volume,
        transfer,
        preset,
        model: options.model,
        clip: Vec::new(),
    })
}

/// `volume` averaged over blocks of `factor`³ voxels, refused where no side would keep two.
pub fn resampled(volume: Volume, factor: u32) -> Result<Volume> {
    if factor <= 1 {
        return Ok(volume);
    }
    let smallest = volume.dims.into_iter().min().unwrap_or(0);
    if factor.saturating_mul(2) > smallest {
        return Err(Error::invalid(
            Param::DownsampleFactor,
            format!(
                "{factor}: the volume's smallest side, {smallest} voxels, would keep fewer \
                 than 2 (nothing to render); at most {}",
                (smallest / 2).max(1)
            ),
        ));
    }
    volume.downsample(factor)
}
