//! `--crop-box X0,Y0,Z0,X1,Y1,Z1`: the box of world space (the file's units) whose points or
//! Gaussians are kept, for the `points`, `gaussians` and `view` commands (one flag for both
//! primitives, so the viewer has it once). The library drops the rest at load
//! (`autostereo::PointLoad::crop`, `autostereo::GaussianLoad::crop`).

use autostereo::camera::Bounds;
use glam::Vec3;

/// The crop box flag.
#[derive(clap::Args, Clone, Copy, Debug, Default, PartialEq)]
pub struct CropBoxArgs {
    /// Keep only the points or Gaussians inside the box X0,Y0,Z0 to X1,Y1,Z1, world units of
    /// the file (floaters around a capture, stray returns of a scan), before normals and radii
    /// are estimated and the camera frames the rest.
    #[arg(long, value_name = "X0,Y0,Z0,X1,Y1,Z1", value_parser = parse_crop_box, allow_hyphen_values = true)]
    pub crop_box: Option<Bounds>,
}

fn parse_crop_box(value: &str) -> Result<Bounds, String> {
    let v: Vec<f32> = value
        .split(',')
        .map(|p| p.trim().parse::<f32>().ok().filter(|x| x.is_finite()))
        .collect::<Option<_>>()
        .filter(|v: &Vec<f32>| v.len() == 6)
        .ok_or_else(|| {
            format!("'{value}' is not X0,Y0,Z0,X1,Y1,Z1: six finite numbers, the box's corners")
        })?;
    let (min, max) = (Vec3::new(v[0], v[1], v[2]), Vec3::new(v[3], v[4], v[5]));
    if !min.cmple(max).all() {
        return Err(format!(
            "'{value}': each of X0,Y0,Z0 must be at most X1,Y1,Z1 (the near corner first)"
        ));
    }
    Ok(Bounds { min, max })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_box_is_two_corners_near_first() {
        let b = parse_crop_box("-1,-2,-3,1,2,3").unwrap();
        assert_eq!(b.min, Vec3::new(-1.0, -2.0, -3.0));
        assert!(parse_crop_box("1,0,0,0,1,1")
            .unwrap_err()
            .contains("at most"));
        assert!(parse_crop_box("1,2,3").is_err());
        assert!(parse_crop_box("0,0,0,1,1,inf").is_err());
    }
}
