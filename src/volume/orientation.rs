//! Where a volume is: one convention for every format (docs/VOLUMES.md "Where a volume is").
//!
//! A file with a patient geometry (NIfTI's sform/qform, NRRD's `space` with `space
//! directions`, MetaImage's `TransformMatrix`, DICOM's position and orientation) gives each
//! voxel axis a direction in the patient's world. Those worlds are turned into RAS+ (+x toward
//! the patient's Right, +y Anterior, +z Superior; DICOM's and ITK's LPS+ has x and y the other
//! way), and RAS+ is shown as a radiologist's anterior view: the patient faces the viewer,
//! superior up, the patient's right on the screen's left. A file without one (VolPack `.den`,
//! raw voxels, NRRD without `space`) keeps its voxel axes on the screen's x (right), y (up) and
//! z (toward the viewer). VTK image data has no patient frame: its world is the screen's (as
//! ParaView shows it), so a `.vti`'s `Direction` columns are the screen axes themselves. Only the
//! axes' directions are used: the renderer centres the box, so the origin moves nothing on
//! screen.

use glam::{Mat3, Vec3};

use crate::error::{Error, Result};
use crate::param::Param;

/// The renderer's world from RAS+: screen x = the patient's left (−R), y = superior, z =
/// anterior (toward the viewer).
pub const RAS_TO_SCREEN: Mat3 = Mat3::from_cols(
    Vec3::new(-1.0, 0.0, 0.0),
    Vec3::new(0.0, 0.0, 1.0),
    Vec3::new(0.0, 1.0, 0.0),
);

/// RAS+ from LPS+ (DICOM, ITK's MetaImage): x and y flip.
pub const LPS_TO_RAS: Mat3 = Mat3::from_diagonal(Vec3::new(-1.0, -1.0, 1.0));

/// How far from orthonormal a file's axes may be (direction cosines stored as text or f32).
const TOLERANCE: f32 = 1e-3;

/// The screen axes of voxel axes whose directions in RAS+ are the columns of `ras` (any
/// length: a file's direction times its spacing): each normalised, then turned to the screen.
/// Refused when they are not orthogonal (a sheared grid is not a box).
pub fn screen_axes_from_ras(ras: Mat3) -> Result<Mat3> {
    let columns = [ras.x_axis, ras.y_axis, ras.z_axis];
    let mut unit = [Vec3::ZERO; 3];
    for (a, c) in columns.iter().enumerate() {
        unit[a] = c.try_normalize().ok_or_else(|| {
            Error::invalid(
                Param::VolumeAxes,
                format!("voxel axis {a} has no direction ({c})"),
            )
        })?;
    }
    let axes = RAS_TO_SCREEN * Mat3::from_cols(unit[0], unit[1], unit[2]);
    check_axes(axes)?;
    Ok(axes)
}

/// Orthonormal, finite axes (columns of unit length at right angles; a mirror is allowed).
pub fn check_axes(axes: Mat3) -> Result<()> {
    let c = [axes.x_axis, axes.y_axis, axes.z_axis];
    let unit = c
        .iter()
        .all(|v| v.is_finite() && (v.length() - 1.0).abs() <= TOLERANCE);
    let orthogonal = (0..3).all(|i| c[i].dot(c[(i + 1) % 3]).abs() <= TOLERANCE);
    if unit && orthogonal {
        return Ok(());
    }
    Err(Error::invalid(
        Param::VolumeAxes,
        format!(
            "{:?}: the voxel axes must be unit directions at right angles (a sheared or \
             degenerate grid)",
            c.map(|v| v.to_array())
        ),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ras_is_seen_from_the_front_with_superior_up() {
        // A voxel grid along R, A, S: i to the screen's left, j toward the viewer, k up.
        let axes = screen_axes_from_ras(Mat3::from_diagonal(Vec3::new(0.5, 0.5, 2.0))).unwrap();
        assert_eq!(axes.x_axis, Vec3::new(-1.0, 0.0, 0.0));
        assert_eq!(axes.y_axis, Vec3::new(0.0, 0.0, 1.0));
        assert_eq!(axes.z_axis, Vec3::new(0.0, 1.0, 0.0));
        // LPS's grid (DICOM) shows the same anatomy: i toward the patient's left = screen right.
        let lps = screen_axes_from_ras(LPS_TO_RAS).unwrap();
        assert_eq!(lps.x_axis, Vec3::X);
        assert_eq!(lps.y_axis, Vec3::new(0.0, 0.0, -1.0));
        assert!(
            RAS_TO_SCREEN.determinant() > 0.0,
            "a rotation, not a mirror"
        );
    }

    #[test]
    fn sheared_and_degenerate_axes_are_refused() {
        let sheared = Mat3::from_cols(Vec3::X, Vec3::new(0.3, 1.0, 0.0), Vec3::Z);
        assert!(screen_axes_from_ras(sheared)
            .unwrap_err()
            .to_string()
            .contains("right angles"));
        let flat = Mat3::from_cols(Vec3::X, Vec3::ZERO, Vec3::Z);
        assert!(screen_axes_from_ras(flat)
            .unwrap_err()
            .to_string()
            .contains("no direction"));
    }
}
