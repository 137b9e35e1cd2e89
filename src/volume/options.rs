//! How a volume renderer samples and shades a [`VolumeScene`], and which single-pass path it
//! takes: settings of the renderer (given to [`crate::RendererOptions`] or to the volume
//! renderers' constructors), never of the scene, so that one uploaded volume renders with
//! several settings side by side. Plain values (no GPU, no errors: an error's advice names
//! them, `src/advice.rs`); checked against a scene where the scene is, src/volume/scene.rs.

/// Volume settings: the single pass's path and how every method samples.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct VolumeOptions {
    /// The single pass's path (the other methods always ray-march).
    pub path: VolumePath,
    /// Sampling, shading and the measured approximations.
    pub settings: VolumeSettings,
}

/// How the volume single pass runs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum VolumePath {
    /// Ray marching in a compute pass, exact per channel.
    #[default]
    RayMarch,
    /// The paper's proxy slices (needs dual-source blending).
    Slices(AlphaMode),
}

/// Sampling, shading and the measured approximations of volume rendering. The default is the
/// exact image: half-voxel steps, shading, exact empty-space skipping, no probes, no sharing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VolumeSettings {
    /// Distance between samples along the eye depth, in voxels of the smallest spacing. `None`
    /// (the default): half a voxel, or what keeps a ray within
    /// [`super::MAX_SAMPLES_PER_RAY`] samples ([`VolumeScene::default_step`]). Coarser is faster
    /// and an approximation: pre-integration keeps one voxel within ≈ 44–47 dB of the default
    /// on the head and brainsmall (docs/VOLUMES.md).
    pub step: Option<f32>,
    /// Blinn-Phong shading from the gradients (off: emission-absorption only).
    pub shade: bool,
    /// Jump over space the transfer function makes fully transparent (ray marching; exact: the
    /// image is the same bit for bit, see `src/volume/empty_space.rs`).
    pub skip_empty: bool,
    /// Sample sharing among a pixel's K rays (single pass, ray marching): where every pair of
    /// the rays' samples on a plane lies within this many voxels, they take their mean ray's
    /// samples (`wgsl/volume/shared/share.wgsl`). 0: every ray exact.
    pub share_samples: f32,
    /// Probing stride through transparent material (ray marching, every method; needs
    /// `skip_empty`): after a segment that added nothing, a ray probes this many sample planes
    /// ahead and takes the planes between as transparent where the pre-integrated segment
    /// between the two samples is exactly zero; where it is not, it marches them one by one
    /// (`wgsl/volume/shared/march.wgsl`). An approximation: it misses material thinner than
    /// `empty_stride` samples whose scalars lie outside both ends'. 1: exact.
    pub empty_stride: u32,
    /// With `empty_stride` > 1, probes also go on through thin material: a probe whose
    /// pre-integrated segment adds at most this opacity per sample step becomes one segment
    /// `empty_stride` steps long (opacity `1 − (1 − α)^P`, colour alike). 0: only transparent
    /// material.
    pub thin_alpha: f32,
    /// What a ray shows: the composited classification (direct volume rendering), or a
    /// projection of its scalars (MIP, MinIP, the mean), each through the transfer function's
    /// colour. Ray marching only (every method but the warp).
    pub projection: Projection,
    /// The normalised scalar of [`Projection::Isosurface`]'s surface (in 0..1).
    pub isovalue: f32,
}

/// What a volume ray shows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Projection {
    /// Front-to-back compositing of the classified, shaded samples (direct volume rendering).
    #[default]
    Composite,
    /// Maximum intensity projection: the largest scalar on the ray.
    #[cfg_attr(feature = "clap", value(name = "mip"))]
    Maximum,
    /// Minimum intensity projection: the smallest scalar on the ray (airways, vessels in MR).
    #[cfg_attr(feature = "clap", value(name = "minip"))]
    Minimum,
    /// The mean scalar along the ray (a radiograph-like summation).
    Average,
    /// The first place the ray reaches `VolumeSettings::isovalue`, lit (Blinn-Phong from the
    /// gradient there), in the transfer function's colour at that value (white where it is
    /// transparent).
    #[cfg_attr(feature = "clap", value(name = "iso"))]
    Isosurface,
}

impl Projection {
    /// Lower-case name (CLI, reports).
    pub fn name(self) -> &'static str {
        match self {
            Self::Composite => "composite",
            Self::Maximum => "mip",
            Self::Minimum => "minip",
            Self::Average => "average",
            Self::Isosurface => "iso",
        }
    }

    /// The shader's number for it (`PROJECTION` in wgsl/volume/shared/march.wgsl).
    pub(crate) fn code(self) -> u32 {
        match self {
            Self::Composite => 0,
            Self::Maximum => 1,
            Self::Minimum => 2,
            Self::Average => 3,
            Self::Isosurface => 4,
        }
    }
}

impl Default for VolumeSettings {
    fn default() -> Self {
        Self {
            step: None,
            shade: true,
            skip_empty: true,
            share_samples: 0.0,
            empty_stride: 1,
            thin_alpha: 0.0,
            projection: Projection::Composite,
            isovalue: 0.5,
        }
    }
}

impl VolumeSettings {
    /// The exact image of these settings' step: no probes, no sharing (what an approximation
    /// is measured against).
    pub fn exact(self) -> Self {
        Self {
            share_samples: 0.0,
            empty_stride: 1,
            thin_alpha: 0.0,
            ..self
        }
    }
}

/// How the K views' opacities of one fragment are blended.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum AlphaMode {
    /// One α per pixel, the mean over the K views (the paper; 2007 GPUs had one blend α).
    Paper,
    /// One α per channel (dual-source blending): matches N-pass.
    Exact,
}

impl AlphaMode {
    /// Lower-case name (CLI, reports).
    pub fn name(self) -> &'static str {
        match self {
            Self::Paper => "paper",
            Self::Exact => "exact",
        }
    }
}
