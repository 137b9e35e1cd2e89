//! The camera flags every render command and the viewer share (`--separation`, `--baseline`,
//! `--focal`, `--fov`, `--camera`, `--look-from/--look-at/--up`), and their parsers.

use autostereo::camera::{CameraSettings, Focal, Spread};
use clap::builder::TypedValueParser;

/// Camera flags shared by the renderers.
#[derive(clap::Args, Clone, Debug)]
#[command(next_help_heading = "Camera")]
pub struct CameraArgs {
    /// Separation of adjacent views, scene units (default: a Looking Glass calibration's
    /// viewCone, else 5 % of the bounding radius); negative reverses the views' order
    /// (`--separation -0.1`).
    #[arg(long, conflicts_with = "baseline", allow_negative_numbers = true)]
    separation: Option<f32>,
    /// Distance between the outermost views instead (separation = B / (N − 1)): keeps the
    /// views' span fixed when N changes, as on a display whose views share one viewing cone;
    /// negative reverses the views' order as --separation does.
    #[arg(long, allow_negative_numbers = true)]
    baseline: Option<f32>,
    /// Focal distance (default: camera to the bounding-box centre, or to --look-at).
    #[arg(long, conflicts_with = "focal_scale", allow_negative_numbers = true)]
    focal: Option<f32>,
    /// Focal distance as a multiple of the default.
    #[arg(long, allow_negative_numbers = true)]
    focal_scale: Option<f32>,
    /// Vertical field of view, degrees, between 0 and 180 (exclusive).
    #[arg(long, default_value_t = 30.0, value_parser = parse_fov, allow_negative_numbers = true)]
    fov: f32,
    /// Camera model: skewed (sheared frusta sharing the focal window; what displays expect) |
    /// parallel (unsheared, images shifted to converge on the focal plane, the uncovered
    /// strips background) | toe-in (cameras turned to the focal point: keystone and vertical
    /// parallax). docs/USAGE.md "Cameras".
    #[arg(long, default_value = "skewed", value_parser = camera_model_parser())]
    camera: autostereo::camera::CameraModel,
    /// Put the centre camera at X,Y,Z (world units; default: the framing's, on the +z side
    /// of the bounds' centre, far enough for the bounding sphere to fit the view).
    #[arg(long, value_name = "X,Y,Z", value_parser = parse_vec3, allow_hyphen_values = true)]
    look_from: Option<glam::Vec3>,
    /// Point the centre camera at X,Y,Z (default: the bounds' centre); the focal plane passes
    /// through it unless --focal or --focal-scale says otherwise.
    #[arg(long, value_name = "X,Y,Z", value_parser = parse_vec3, allow_hyphen_values = true)]
    look_at: Option<glam::Vec3>,
    /// The world direction that is up in the image (default 0,1,0; 0,-1,0 for a capture with
    /// y down).
    #[arg(long, value_name = "X,Y,Z", value_parser = parse_vec3, allow_hyphen_values = true)]
    up: Option<glam::Vec3>,
    /// Look from this side of the scene at the framing's distance: front (+z, the default),
    /// back, left (−x), right, top (+y, the front at the bottom), bottom. For a scan the front
    /// is its anterior view (the patient faces you). --look-from and --up override it.
    #[arg(long = "view", value_enum, value_name = "SIDE")]
    side: Option<autostereo::camera::Side>,
}

/// `--fov DEGREES`: the vertical field of view, refused in the user's units (degrees) outside
/// (0, 180).
pub fn parse_fov(s: &str) -> Result<f32, String> {
    let deg: f32 = s
        .trim()
        .parse()
        .map_err(|_| format!("'{s}' is not a number of degrees (e.g. 30)"))?;
    if !(deg.is_finite() && deg > 0.0 && deg < 180.0) {
        return Err(format!(
            "--fov {s}: the vertical field of view must be between 0 and 180 degrees \
             (exclusive), e.g. 30"
        ));
    }
    Ok(deg)
}

/// `X,Y,Z` → a vector of three finite numbers (`-1,2,-3` too: the flags allow a leading
/// hyphen).
pub fn parse_vec3(s: &str) -> Result<glam::Vec3, String> {
    let parts: Vec<&str> = s.split(',').collect();
    let bad = || format!("'{s}' is not three comma-separated numbers X,Y,Z");
    let [x, y, z] = parts[..] else {
        return Err(bad());
    };
    let v = [x, y, z].map(|p| p.trim().parse::<f32>());
    let [Ok(x), Ok(y), Ok(z)] = v else {
        return Err(bad());
    };
    let v = glam::Vec3::new(x, y, z);
    if !v.is_finite() {
        return Err(format!("'{s}': every coordinate must be finite"));
    }
    Ok(v)
}

/// `--camera NAME`.
fn camera_model_parser(
) -> impl clap::builder::TypedValueParser<Value = autostereo::camera::CameraModel> {
    use autostereo::camera::CameraModel;
    clap::builder::PossibleValuesParser::new(CameraModel::ALL.map(|m| m.name())).map(|name| {
        name.parse::<CameraModel>()
            .expect("one of the possible values")
    })
}

impl CameraArgs {
    /// The camera these flags describe (the library frames it: `CameraSettings::camera`).
    pub fn settings(&self) -> CameraSettings {
        CameraSettings {
            spread: match (self.separation, self.baseline) {
                (Some(s), _) => Some(Spread::Separation(s)),
                (None, Some(b)) => Some(Spread::Baseline(b)),
                (None, None) => None,
            },
            focal: match (self.focal, self.focal_scale) {
                (Some(d), _) => Some(Focal::Distance(d)),
                (None, Some(s)) => Some(Focal::Scale(s)),
                (None, None) => None,
            },
            fov_degrees: self.fov,
            model: self.camera,
            look_from: self.look_from,
            look_at: self.look_at,
            up: self.up,
            side: self.side,
        }
    }
}
