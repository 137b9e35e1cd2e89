//! The parameters the library checks, as a type: an [`crate::Error::InvalidParameter`] names
//! one, so that a tool says which of its own settings was wrong (the CLI maps each to its flag
//! in one exhaustive `match`: cli/src/flags.rs) without reading the message.

/// A parameter the library validates.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Param {
    /// The camera's aspect ratio.
    Aspect,
    /// Banding a frame too large for one pass.
    Bands,
    /// A camera (its matrices or its spec).
    Camera,
    /// How the camera frames the scene's bounds.
    CameraFraming,
    /// The multi-view camera model.
    CameraModel,
    /// An RGB-D depth map.
    DepthMap,
    /// A Looking Glass depthiness.
    Depthiness,
    /// Voxels averaged per block side on loading.
    DownsampleFactor,
    /// The volume's probing stride through transparent material.
    EmptyStride,
    /// The ε of the splats' ε-z compositing.
    Epsilon,
    /// The far clipping distance.
    Far,
    /// A field of view given in degrees.
    FieldOfView,
    /// The distance to the zero-disparity plane.
    FocalDistance,
    /// A Looking Glass focus.
    Focus,
    /// The camera's vertical field of view in radians.
    Fov,
    /// A 3D Gaussian scene.
    Gaussians,
    /// The splat group count.
    Groups,
    /// The warp's hole gap.
    HoleGap,
    /// A CPU image's size.
    ImageSize,
    /// The point the camera looks at.
    LookAt,
    /// The point the camera looks from.
    LookFrom,
    /// A Looking Glass calibration's values.
    LookingGlassCalibration,
    /// A mesh.
    Mesh,
    /// A rendering method.
    Method,
    /// The PSNR floor of `Method` auto.
    MinPsnr,
    /// The near clipping distance.
    Near,
    /// A slanted lens's phase.
    Phase,
    /// A slanted lens's pitch.
    Pitch,
    /// A point cloud.
    PointCloud,
    /// A quilt's layout or image.
    Quilt,
    /// A quilt atlas's textures.
    QuiltAtlas,
    /// A quilt image's size in pixels.
    QuiltSize,
    /// A volume's display window (width, level).
    Window,
    /// What a volume ray shows (compositing or a projection).
    Projection,
    /// A box of the data to keep.
    Crop,
    /// Clipping planes of a volume.
    Clip,
    /// A video's frames per second.
    FrameRate,
    /// A video's bit rate.
    BitRate,
    /// The factor on every splat radius.
    RadiusScale,
    /// The warp's reference views.
    References,
    /// The caller's RGB-D colour texture.
    RgbdColorTexture,
    /// The caller's RGB-D nearness texture.
    RgbdNearnessTexture,
    /// The warp's same-surface tolerance.
    SameSurface,
    /// The volume's sample-sharing tolerance.
    SampleSharing,
    /// The volume's ray-marching step.
    SamplingStep,
    /// The scene given to a renderer.
    Scene,
    /// The camera's eye separation.
    Separation,
    /// A frame's size.
    Size,
    /// A slanted lens's slant.
    Slant,
    /// The spatial image target.
    SpatialTarget,
    /// Point splats.
    Splats,
    /// The two views of a stereo output.
    StereoEyes,
    /// A stereo output's images.
    StereoOutput,
    /// A render target.
    Target,
    /// A render target's texture format.
    TargetFormat,
    /// The caller's target texture.
    TargetTexture,
    /// The volume's thin-material opacity.
    ThinAlpha,
    /// A volume's transfer function.
    TransferFunction,
    /// The camera's up direction.
    Up,
    /// A view index.
    View,
    /// A display's view cone.
    ViewCone,
    /// The size of per-view images.
    ViewImageSize,
    /// The single pass's view clusters.
    ViewClusters,
    /// A camera's view matrix.
    ViewMatrix,
    /// The per-view image scale.
    ViewScale,
    /// The number of views.
    Views,
    /// A volume's voxel axes.
    VolumeAxes,
    /// A volume's voxel values.
    VolumeData,
    /// A volume's dimensions.
    VolumeDimensions,
    /// The volume rendering path.
    VolumePath,
    /// A volume's rotation.
    VolumeRotation,
    /// A volume's voxel spacing.
    VoxelSpacing,
    /// A window's offset on the desktop.
    WindowOffset,
}

impl Param {
    /// Every parameter.
    pub const ALL: [Param; 73] = [
        Param::Aspect,
        Param::Bands,
        Param::Camera,
        Param::CameraFraming,
        Param::CameraModel,
        Param::DepthMap,
        Param::Depthiness,
        Param::DownsampleFactor,
        Param::EmptyStride,
        Param::Epsilon,
        Param::Far,
        Param::FieldOfView,
        Param::FocalDistance,
        Param::Focus,
        Param::Fov,
        Param::Gaussians,
        Param::Groups,
        Param::HoleGap,
        Param::ImageSize,
        Param::LookAt,
        Param::LookFrom,
        Param::LookingGlassCalibration,
        Param::Mesh,
        Param::Method,
        Param::MinPsnr,
        Param::Near,
        Param::Phase,
        Param::Pitch,
        Param::PointCloud,
        Param::Quilt,
        Param::QuiltAtlas,
        Param::QuiltSize,
        Param::Window,
        Param::Projection,
        Param::Crop,
        Param::Clip,
        Param::FrameRate,
        Param::BitRate,
        Param::RadiusScale,
        Param::References,
        Param::RgbdColorTexture,
        Param::RgbdNearnessTexture,
        Param::SameSurface,
        Param::SampleSharing,
        Param::SamplingStep,
        Param::Scene,
        Param::Separation,
        Param::Size,
        Param::Slant,
        Param::SpatialTarget,
        Param::Splats,
        Param::StereoEyes,
        Param::StereoOutput,
        Param::Target,
        Param::TargetFormat,
        Param::TargetTexture,
        Param::ThinAlpha,
        Param::TransferFunction,
        Param::Up,
        Param::View,
        Param::ViewCone,
        Param::ViewImageSize,
        Param::ViewClusters,
        Param::ViewMatrix,
        Param::ViewScale,
        Param::Views,
        Param::VolumeAxes,
        Param::VolumeData,
        Param::VolumeDimensions,
        Param::VolumePath,
        Param::VolumeRotation,
        Param::VoxelSpacing,
        Param::WindowOffset,
    ];

    /// Its name in messages ("sampling step").
    pub fn name(self) -> &'static str {
        match self {
            Param::Aspect => "aspect",
            Param::Bands => "bands",
            Param::Camera => "camera",
            Param::CameraFraming => "camera framing",
            Param::CameraModel => "camera model",
            Param::DepthMap => "depth map",
            Param::Depthiness => "depthiness",
            Param::DownsampleFactor => "downsample factor",
            Param::EmptyStride => "probing stride through transparent material",
            Param::Epsilon => "epsilon",
            Param::Far => "far",
            Param::FieldOfView => "field of view",
            Param::FocalDistance => "focal distance",
            Param::Focus => "focus",
            Param::Fov => "fov",
            Param::Gaussians => "gaussians",
            Param::Groups => "groups",
            Param::HoleGap => "hole gap",
            Param::ImageSize => "image size",
            Param::LookAt => "look-at",
            Param::LookFrom => "look-from",
            Param::LookingGlassCalibration => "Looking Glass calibration",
            Param::Mesh => "mesh",
            Param::Method => "method",
            Param::MinPsnr => "PSNR floor",
            Param::Near => "near",
            Param::Phase => "phase",
            Param::Pitch => "pitch",
            Param::PointCloud => "point cloud",
            Param::Quilt => "quilt",
            Param::QuiltAtlas => "quilt atlas",
            Param::QuiltSize => "quilt size",
            Param::Window => "window",
            Param::Projection => "projection",
            Param::Crop => "crop box",
            Param::Clip => "clipping planes",
            Param::FrameRate => "frame rate",
            Param::BitRate => "bit rate",
            Param::RadiusScale => "radius scale",
            Param::References => "references",
            Param::RgbdColorTexture => "RGB-D colour texture",
            Param::RgbdNearnessTexture => "RGB-D nearness texture",
            Param::SameSurface => "same surface",
            Param::SampleSharing => "sample sharing tolerance",
            Param::SamplingStep => "sampling step",
            Param::Scene => "scene",
            Param::Separation => "separation",
            Param::Size => "size",
            Param::Slant => "slant",
            Param::SpatialTarget => "spatial target",
            Param::Splats => "splats",
            Param::StereoEyes => "stereo eyes",
            Param::StereoOutput => "stereo output",
            Param::Target => "target",
            Param::TargetFormat => "target format",
            Param::TargetTexture => "target texture",
            Param::ThinAlpha => "thin-material opacity",
            Param::TransferFunction => "transfer function",
            Param::Up => "up",
            Param::View => "view",
            Param::ViewCone => "view cone",
            Param::ViewImageSize => "view image size",
            Param::ViewClusters => "view clusters",
            Param::ViewMatrix => "view matrix",
            Param::ViewScale => "view scale",
            Param::Views => "views",
            Param::VolumeAxes => "volume axes",
            Param::VolumeData => "volume data",
            Param::VolumeDimensions => "volume dimensions",
            Param::VolumePath => "volume path",
            Param::VolumeRotation => "volume rotation",
            Param::VoxelSpacing => "voxel spacing",
            Param::WindowOffset => "window offset",
        }
    }
}

impl std::fmt::Display for Param {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}
