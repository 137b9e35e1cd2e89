//! Clipping planes of a volume ([`VolumeScene::clip`]): half-spaces that every method keeps,
//! tested where a ray's samples are chosen (`wgsl/volume/shared/march.wgsl` narrows the ray's
//! span, `wgsl/volume/slices.wgsl` drops segments outside), so the single pass and the
//! baselines cut exactly alike. Unlike [`super::Crop`], which keeps a box of the data at load,
//! planes are part of the scene: a viewer moves them every frame without a new upload.

use glam::{Vec3, Vec4};

use super::VolumeScene;
use crate::error::{Error, Result};
use crate::param::Param;

/// Most clipping planes a scene may have (the shader's uniform array).
pub const MAX_CLIP_PLANES: usize = 6;

/// A half-space of a volume to keep: the points `p` with `normal · p ≤ offset`, `p` in the
/// spacing's units (mm for a scan) from the volume's first voxel's corner along its voxel
/// axes — the frame of [`super::Crop::World`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClipPlane {
    /// Points out of the kept side; any length but zero.
    pub normal: Vec3,
    /// Where the plane is: `normal · p` on it.
    pub offset: f32,
}

impl ClipPlane {
    /// Keep `p` with `normal · p ≤ offset`.
    pub fn new(normal: Vec3, offset: f32) -> Self {
        Self { normal, offset }
    }

    /// The same plane given in voxel coordinates (`normal · v ≤ offset`, `v = p / spacing`,
    /// voxel `i` spanning `i … i + 1`) for a volume of this `spacing`.
    pub fn from_voxels(normal: Vec3, offset: f32, spacing: Vec3) -> Self {
        Self {
            normal: normal / spacing,
            offset,
        }
    }

    /// The plane over texture coordinates `t` (the box is `[0, 1]³`, `p = t · extent`):
    /// `xyz · t ≤ w`, what the shader tests.
    pub(crate) fn in_texture(self, extent: Vec3) -> Vec4 {
        (self.normal * extent).extend(self.offset)
    }
}

/// Check `planes`: at most [`MAX_CLIP_PLANES`], each finite with a nonzero normal.
pub(crate) fn check_planes(planes: &[ClipPlane]) -> Result<()> {
    if planes.len() > MAX_CLIP_PLANES {
        return Err(Error::invalid(
            Param::Clip,
            format!(
                "{} planes: at most {MAX_CLIP_PLANES} (a crop box keeps a box with none)",
                planes.len()
            ),
        ));
    }
    for (i, plane) in planes.iter().enumerate() {
        let finite = plane.normal.is_finite() && plane.offset.is_finite();
        if !finite || plane.normal.length_squared() == 0.0 {
            return Err(Error::invalid(
                Param::Clip,
                format!(
                    "plane {i}: normal {:?}, offset {}: the normal must be finite and nonzero, \
                     the offset finite",
                    plane.normal.to_array(),
                    plane.offset
                ),
            ));
        }
    }
    Ok(())
}

/// The scene's planes for the shader: texture-space planes, the unused ones keeping everything.
pub(crate) fn texture_planes(scene: &VolumeScene) -> ([[f32; 4]; MAX_CLIP_PLANES], u32) {
    let mut out = [[0.0, 0.0, 0.0, 1.0]; MAX_CLIP_PLANES];
    for (slot, plane) in out.iter_mut().zip(&scene.clip) {
        *slot = plane.in_texture(scene.extent).to_array();
    }
    (out, scene.clip.len().min(MAX_CLIP_PLANES) as u32)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_plane_in_voxels_cuts_where_the_voxel_boundary_is() {
        let spacing = Vec3::new(0.5, 2.0, 1.0);
        let plane = ClipPlane::from_voxels(Vec3::Y, 10.0, spacing);
        // Voxel boundary y = 10 is 20 mm from the corner.
        let p = Vec3::new(3.0, 20.0, 1.0);
        assert!((plane.normal.dot(p) - plane.offset).abs() < 1e-6);
        let extent = Vec3::new(8.0, 40.0, 4.0);
        let t = plane.in_texture(extent);
        assert!((t.truncate().dot(p / extent) - t.w).abs() < 1e-6);
    }

    #[test]
    fn impossible_planes_are_refused() {
        let ok = ClipPlane::new(Vec3::X, 1.0);
        assert!(check_planes(&[ok; MAX_CLIP_PLANES]).is_ok());
        assert!(check_planes(&[ok; MAX_CLIP_PLANES + 1]).is_err());
        assert!(check_planes(&[ClipPlane::new(Vec3::ZERO, 1.0)]).is_err());
        assert!(check_planes(&[ClipPlane::new(Vec3::X, f32::NAN)]).is_err());
    }
}
