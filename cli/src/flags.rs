//! Library errors in the command line's words: the library names a parameter and its advice in
//! its own terms ("sampling step", "use Visibility::Exact"); here the message also names the
//! flag that sets the parameter (`--step`) and gives the advice as flags (`--visibility exact`).

use autostereo::advice::Setting;
use autostereo::Param;

/// The flag that sets the library parameter `param`, where one does: one exhaustive `match`,
/// so a parameter added to the library without a decision here does not compile. `None`: the
/// CLI sets the parameter from a file or computes it (a calibration's values, the target
/// textures), or its errors already name the flag (`--tf FILE`, `--display SPEC`).
pub fn flag_of(param: Param) -> Option<&'static str> {
    Some(match param {
        Param::SamplingStep => "--step",
        Param::SampleSharing => "--share-samples",
        Param::EmptyStride => "--empty-stride",
        Param::ThinAlpha => "--thin-alpha",
        Param::VolumePath => "--path",
        Param::HoleGap => "--hole-gap",
        Param::References => "--references",
        Param::Epsilon => "--epsilon",
        Param::RadiusScale => "--radius-scale",
        Param::ViewScale => "--view-scale",
        Param::Focus => "--focus",
        Param::Depthiness => "--depthiness",
        Param::Separation => "--separation",
        Param::DownsampleFactor => "--downsample",
        Param::Method => "--method",
        Param::MinPsnr => "--min-psnr",
        Param::CameraModel => "--camera",
        Param::LookFrom => "--look-from",
        Param::LookAt => "--look-at",
        Param::Up => "--up",
        Param::FocalDistance => "--focal/--focal-scale",
        Param::Views => "--views",
        Param::ViewClusters => "--clusters",
        Param::Groups => "--groups",
        Param::FieldOfView => "--fov",
        Param::QuiltSize => "--quilt-size",
        Param::FrameRate => "--fps",
        Param::Window => "--window",
        Param::Projection => "--projection",
        Param::Crop => "--crop",
        Param::Clip => "--clip",
        Param::BitRate => "--bitrate",
        Param::Aspect
        | Param::Bands
        | Param::Camera
        | Param::CameraFraming
        | Param::DepthMap
        | Param::Far
        | Param::Fov
        | Param::Gaussians
        | Param::ImageSize
        | Param::LookingGlassCalibration
        | Param::Mesh
        | Param::Near
        | Param::Phase
        | Param::Pitch
        | Param::PointCloud
        | Param::Quilt
        | Param::QuiltAtlas
        | Param::RgbdColorTexture
        | Param::RgbdNearnessTexture
        | Param::SameSurface
        | Param::Scene
        | Param::Size
        | Param::Slant
        | Param::SpatialTarget
        | Param::Splats
        | Param::StereoEyes
        | Param::StereoOutput
        | Param::Target
        | Param::TargetFormat
        | Param::TargetTexture
        | Param::TransferFunction
        | Param::View
        | Param::ViewCone
        | Param::ViewImageSize
        | Param::ViewMatrix
        | Param::VolumeAxes
        | Param::VolumeData
        | Param::VolumeDimensions
        | Param::VolumeRotation
        | Param::VoxelSpacing
        | Param::WindowOffset => return None,
    })
}

/// The command line's words for a setting a library error advises (one exhaustive match: a
/// setting the library adds fails to compile here until it has words).
pub fn setting_words(setting: Setting) -> String {
    use autostereo::VolumePath;
    match setting {
        Setting::Visibility(v) => format!("--visibility {}", v.name()),
        Setting::SplatDepth(d) => format!("--depth {}", d.name()),
        Setting::TileClip(c) => format!("--tile-clip {}", c.name()),
        Setting::VolumePath(VolumePath::RayMarch) => "--path compute".into(),
        Setting::VolumePath(VolumePath::Slices(_)) => "--path slices".into(),
        Setting::Downsample(n) => format!("--downsample {n}"),
        Setting::MaxMemory => "--max-memory".into(),
        Setting::RawHeaderBytes(n) => format!("--raw-header {n}"),
        Setting::RawLayout => "--raw-dims X,Y,Z and --raw-type".into(),
        Setting::QuiltGrid => "--quilt COLSxROWS".into(),
        Setting::DepthResample => "--depth-resample".into(),
    }
}

/// The command line that reads `file`, data of `kind`.
pub fn reader_of(kind: autostereo::DataKind, file: &str) -> String {
    use autostereo::DataKind;
    let command = match kind {
        DataKind::Mesh => "mesh",
        DataKind::Points => "points",
        DataKind::Volume => "volume",
        DataKind::Image => return "`autostereo rgbd` or `autostereo interleave`".into(),
        DataKind::Gaussians => "gaussians",
    };
    format!("`autostereo {command} {file}`")
}

/// `error` and its causes as `{:#}` prints them, each invalid library parameter prefixed with
/// its flag.
pub fn describe(error: &anyhow::Error) -> String {
    let parts: Vec<String> = error
        .chain()
        .map(|cause| match cause.downcast_ref::<autostereo::Error>() {
            Some(autostereo::Error::InvalidParameter { param, .. }) => match flag_of(*param) {
                Some(flag) => format!("{flag}: {cause}"),
                None => cause.to_string(),
            },
            // A file of another kind: the command that reads it, with the file.
            Some(autostereo::Error::WrongKind {
                path,
                holds,
                wanted,
                detail,
            }) => {
                let name = path.display();
                let not = wanted.map_or(String::new(), |w| format!(", not {}", w.article()));
                format!(
                    "{name}: this is {} ({detail}){not}: {} reads it",
                    holds.article(),
                    reader_of(*holds, &name.to_string())
                )
            }
            // Every display spec the user types is `--display`'s.
            Some(autostereo::Error::DisplaySpec { spec, reason }) => {
                format!("--display {spec}: {reason}")
            }
            // The frame is the image `--size` asked for (the views of an unbandable frame,
            // or the window's): named as the user typed it, the library's advice after it.
            Some(autostereo::Error::SubpixelWidth { size: [w, h], .. }) => {
                format!("--size {w}x{h}: {cause}")
            }
            // The frame is as large as `--size` asked for.
            Some(autostereo::Error::LimitExceeded {
                param: Some(Param::ImageSize),
                limit,
                ..
            }) => format!("{cause} (--size: at most {limit} pixels a side on this adapter)"),
            // A count a flag sets, over what the adapter takes: the flag and the most it takes.
            Some(autostereo::Error::LimitExceeded {
                param: Some(param),
                limit,
                ..
            }) => match flag_of(*param) {
                Some(flag) => format!("{flag}: {cause} (at most {flag} {limit} on this adapter)"),
                None => cause.to_string(),
            },
            _ => cause.to_string(),
        })
        .zip(error.chain())
        .map(|(text, cause)| in_cli_words(text, cause))
        .collect();
    printable(&parts.join(": "))
}

/// `text`, the message of `cause`, with the settings a library error advises in the command
/// line's words.
fn in_cli_words(text: String, cause: &(dyn std::error::Error + 'static)) -> String {
    let Some(error) = cause.downcast_ref::<autostereo::Error>() else {
        return text;
    };
    error.advice().iter().fold(text, |text, advice| {
        text.replace(&advice.to_string(), &advice.words(setting_words))
    })
}

/// `text` with its control characters but line breaks escaped: whatever a message quotes (a
/// file's bytes, an OS error, a wgpu message), printing it never moves the cursor, rings or
/// retitles the terminal.
fn printable(text: &str) -> String {
    text.chars()
        .map(|c| match c.is_control() && c != '\n' {
            true => c.escape_debug().to_string(),
            false => c.to_string(),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_invalid_parameter_is_named_by_its_flag() {
        let settings = autostereo::volume::VolumeSettings {
            empty_stride: 0,
            ..Default::default()
        };
        let error = anyhow::Error::from(settings.validate().unwrap_err()).context("volume");
        let text = describe(&error);
        assert!(
            text.starts_with("volume: --empty-stride: invalid probing stride"),
            "{text}"
        );
        let plain = anyhow::anyhow!("no such file");
        assert_eq!(describe(&plain), "no such file");
    }

    /// The advice in a library error is said in flags, from its typed settings; a message that
    /// merely contains a library term is left as it is.
    #[test]
    fn advice_is_said_in_flags() {
        use autostereo::render::quilt_image::QuiltImage;
        let error = QuiltImage::read("scan.png", [8, 8], None, 4).unwrap_err();
        let text = describe(&anyhow::Error::from(error));
        assert!(
            text.contains("or give the grid (--quilt COLSxROWS)") && !text.contains("QuiltImage"),
            "{text}"
        );
        let plain = anyhow::anyhow!("X needs Y; use Visibility::Exact");
        assert_eq!(describe(&plain), "X needs Y; use Visibility::Exact");
    }

    /// Every flag the advice's words name is a flag of some command.
    #[test]
    fn every_setting_is_said_with_a_real_flag() {
        use autostereo::mesh::{TileClip, Visibility};
        use autostereo::points::SplatDepth;
        use autostereo::VolumePath;
        use clap::CommandFactory;
        let cli = crate::Cli::command();
        let longs: std::collections::BTreeSet<String> = cli
            .get_subcommands()
            .flat_map(|c| c.get_arguments().filter_map(|a| a.get_long()))
            .map(|l| format!("--{l}"))
            .collect();
        let settings = [
            Setting::Visibility(Visibility::Exact),
            Setting::SplatDepth(SplatDepth::Paper),
            Setting::TileClip(TileClip::Discard),
            Setting::VolumePath(VolumePath::RayMarch),
            Setting::Downsample(2),
            Setting::MaxMemory,
            Setting::RawHeaderBytes(16),
            Setting::RawLayout,
            Setting::QuiltGrid,
            Setting::DepthResample,
        ];
        for setting in settings {
            let words = setting_words(setting);
            let flags: Vec<&str> = words.split(' ').filter(|w| w.starts_with("--")).collect();
            assert!(!flags.is_empty(), "{setting}: {words}");
            for flag in flags {
                assert!(longs.contains(flag), "{setting}: {flag} is no flag");
            }
        }
    }

    /// Every flag a parameter maps to is a flag of some command (a renamed flag fails here).
    #[test]
    fn every_parameter_maps_to_a_real_flag() {
        use clap::CommandFactory;
        let cli = crate::Cli::command();
        let mut longs = std::collections::BTreeSet::new();
        for command in cli.get_subcommands() {
            for arg in command.get_arguments() {
                if let Some(long) = arg.get_long() {
                    longs.insert(format!("--{long}"));
                }
            }
        }
        for param in Param::ALL {
            for flag in flag_of(param).into_iter().flat_map(|f| f.split('/')) {
                assert!(
                    longs.contains(flag),
                    "{param}: {flag} is no flag of any command"
                );
            }
        }
        assert_eq!(flag_of(Param::SamplingStep), Some("--step"));
        assert_eq!(
            flag_of(Param::TargetTexture),
            None,
            "set by an embedder, not a flag"
        );
    }

    #[test]
    fn control_characters_are_escaped() {
        let raw = anyhow::anyhow!("line '\u{1b}[31mred\u{7}\r'\nnext");
        assert_eq!(describe(&raw), "line '\\u{1b}[31mred\\u{7}\\r'\nnext");
    }
}
