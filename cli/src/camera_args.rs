//! The camera flags every render command and the viewer share (`--separation`, `--baseline`,
//! `--focal`, `--fov`, `--camera`, `--look-from/--look-at/--up`), and their parsers.

use anyhow::Result;
use autostereo::camera::MultiViewCamera;
use autostereo::display::Display;
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
    /// The point the centre camera looks at: --look-at, else the centre of `bounds` (the
    /// viewer orbits about it).
    pub fn pivot(&self, bounds: autostereo::camera::Bounds) -> glam::Vec3 {
        self.look_at.unwrap_or(bounds.center())
    }

    /// Frame `bounds` with these settings for `display`: without --separation or --baseline,
    /// a display's view cone (a Looking Glass calibration's `viewCone`) spreads the views.
    pub fn camera(
        &self,
        bounds: autostereo::camera::Bounds,
        display: &Display,
        size: [u32; 2],
    ) -> Result<MultiViewCamera> {
        let views = display.views();
        let aspect = size[0] as f32 / size[1] as f32;
        let separation = match self.baseline {
            Some(b) if views > 1 => Some(b / (views - 1) as f32),
            Some(_) => Some(0.0),
            None => self.separation,
        };
        let fov = self.fov.to_radians();
        let framing = || MultiViewCamera::framing(bounds, views, separation, fov, aspect);
        let mut camera = if self.look_from.is_some() || self.look_at.is_some() || self.up.is_some()
        {
            // An explicit camera: what is not given is the framing's.
            let from = match self.look_from {
                Some(from) => from,
                None => framing()?.eye_position(),
            };
            MultiViewCamera::looking_at(
                bounds,
                from,
                self.pivot(bounds),
                self.up.unwrap_or(glam::Vec3::Y),
                views,
                separation,
                fov,
                aspect,
            )?
        } else {
            framing()?
        };
        if let Some(fd) = self.focal {
            camera.focal_distance = fd;
        }
        if let Some(s) = self.focal_scale {
            camera.focal_distance *= s;
        }
        camera.model = self.camera;
        if let (None, Some(cone)) = (separation, display.view_cone()) {
            camera.spread_over_cone(cone)?;
        }
        camera.validate()?;
        Ok(camera)
    }
}
