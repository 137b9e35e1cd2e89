//! A box that keeps points or Gaussians (`PointLoad::crop`, `GaussianLoad::crop`): what lies
//! outside — floaters around a capture, a scanner's stray returns — is dropped at load, before
//! normals and radii are estimated and before the framing sees the bounds.

use glam::Vec3;

use super::Bounds;
use crate::error::{Error, Result};
use crate::param::Param;

impl Bounds {
    /// `p` lies in the box (faces included).
    pub fn contains(&self, p: Vec3) -> bool {
        p.cmpge(self.min).all() && p.cmple(self.max).all()
    }

    /// The indices of `positions` inside this box as a crop box: refused where the box is no
    /// box (not finite, min above max) or keeps none of them, `what` naming them ("points").
    pub(crate) fn kept(&self, positions: &[Vec3], what: &str) -> Result<Vec<usize>> {
        let fail = |reason: String| Err(Error::invalid(Param::Crop, reason));
        if !(self.min.is_finite() && self.max.is_finite() && self.min.cmple(self.max).all()) {
            return fail(format!(
                "{:?} to {:?}: not a box (finite corners, each min ≤ max)",
                self.min.to_array(),
                self.max.to_array()
            ));
        }
        let kept: Vec<usize> = (0..positions.len())
            .filter(|&i| self.contains(positions[i]))
            .collect();
        if kept.is_empty() {
            let all = Bounds::of_points(positions.iter().copied());
            return fail(format!(
                "{:?} to {:?} keeps none of the {} {what}{}",
                self.min.to_array(),
                self.max.to_array(),
                positions.len(),
                all.map_or_else(String::new, |b| format!(
                    " (they lie within {:?} to {:?})",
                    b.min.to_array(),
                    b.max.to_array()
                ))
            ));
        }
        Ok(kept)
    }
}

/// The elements of `values` at `kept` (an attribute of the kept points).
pub(crate) fn pick<T: Copy>(values: &[T], kept: &[usize]) -> Vec<T> {
    kept.iter().map(|&i| values[i]).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gaussians::Gaussians;
    use crate::points::PointCloud;

    /// A unit-cube cloud of 27 points and two floaters far out.
    fn cloud_with_floaters() -> PointCloud {
        let mut positions = Vec::new();
        for i in 0..27 {
            positions.push(Vec3::new((i % 3) as f32, (i / 3 % 3) as f32, (i / 9) as f32) * 0.5);
        }
        positions.push(Vec3::new(40.0, 0.0, 0.0));
        positions.push(Vec3::new(0.0, -30.0, 5.0));
        let n = positions.len();
        PointCloud {
            colors: Some((0..n).map(|i| [i as f32 / n as f32; 3]).collect()),
            radii: Some((0..n).map(|i| i as f32).collect()),
            normals: None,
            positions,
        }
    }

    #[test]
    fn a_crop_box_drops_the_floaters_and_keeps_each_points_attributes() {
        let cloud = cloud_with_floaters();
        let keep = Bounds {
            min: Vec3::splat(-0.1),
            max: Vec3::splat(1.0),
        };
        let cropped = cloud.cropped(keep).unwrap();
        assert_eq!(cropped.len(), 27);
        assert_eq!(cropped.positions[..], cloud.positions[..27]);
        assert_eq!(
            cropped.colors.as_deref(),
            Some(&cloud.colors.as_ref().unwrap()[..27])
        );
        assert_eq!(
            cropped.radii.as_deref(),
            Some(&cloud.radii.as_ref().unwrap()[..27])
        );
        assert_eq!(cropped.bounds().unwrap().max, Vec3::splat(1.0));
    }

    #[test]
    fn a_crop_box_keeps_each_gaussians_own_coefficients() {
        let all = Gaussians::generated(64);
        let centre = all.bounds().unwrap().center();
        let keep = Bounds {
            min: Vec3::new(f32::MIN, f32::MIN, f32::MIN),
            max: Vec3::new(centre.x, f32::MAX, f32::MAX),
        };
        let kept = all.cropped(keep).unwrap();
        assert!(!kept.is_empty() && kept.len() < all.len());
        kept.validate().unwrap();
        let mut j = 0;
        for i in 0..all.len() {
            if all.positions[i].x <= centre.x {
                assert_eq!(kept.positions[j], all.positions[i]);
                assert_eq!(kept.opacities[j], all.opacities[i]);
                assert_eq!(kept.sh_of(j), all.sh_of(i));
                j += 1;
            }
        }
        assert_eq!(j, kept.len());
    }

    #[test]
    fn a_box_that_keeps_nothing_or_is_no_box_is_refused_naming_the_crop_box() {
        let cloud = cloud_with_floaters();
        let empty = Bounds {
            min: Vec3::splat(100.0),
            max: Vec3::splat(101.0),
        };
        let error = cloud.cropped(empty).unwrap_err().to_string();
        assert!(
            error.contains("crop box") && error.contains("keeps none of the 29 points"),
            "{error}"
        );
        assert!(error.contains("they lie within"), "{error}");
        let inverted = Bounds {
            min: Vec3::ONE,
            max: Vec3::ZERO,
        };
        let error = cloud.cropped(inverted).unwrap_err().to_string();
        assert!(error.contains("not a box"), "{error}");
    }
}
