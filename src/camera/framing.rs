//! Framing helpers: place the camera so a bounding box fits, focal plane through its centre.

use glam::{Mat4, Vec3};

use super::{CameraModel, MultiViewCamera};
use crate::error::{Error, Result};

/// Axis-aligned bounding box in world space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    /// Minimum corner.
    pub min: Vec3,
    /// Maximum corner.
    pub max: Vec3,
}

impl Bounds {
    /// Bounds of a set of points; `None` if empty or any coordinate is not finite.
    pub fn of_points(points: impl IntoIterator<Item = Vec3>) -> Option<Self> {
        let mut it = points.into_iter();
        let first = it.next()?;
        let mut b = Bounds {
            min: first,
            max: first,
        };
        for p in it {
            b.min = b.min.min(p);
            b.max = b.max.max(p);
        }
        (b.min.is_finite() && b.max.is_finite()).then_some(b)
    }

    /// Centre of the box.
    pub fn center(&self) -> Vec3 {
        (self.min + self.max) * 0.5
    }

    /// Radius of the bounding sphere around the centre (never 0: a point gets a unit-less 1e-3).
    pub fn radius(&self) -> f32 {
        ((self.max - self.min).length() * 0.5).max(1e-3)
    }
}

impl MultiViewCamera {
    /// A camera on the +z side of `bounds` looking at its centre (up = +y), far enough that the
    /// bounding sphere fits the narrower field of view; focal plane through the centre;
    /// near/far bracket the sphere. Separation `e` defaults to 5 % of the radius when `None`.
    pub fn framing(
        bounds: Bounds,
        views: u32,
        separation: Option<f32>,
        fov_y: f32,
        aspect: f32,
    ) -> Result<Self> {
        if !(fov_y > 0.0 && fov_y < std::f32::consts::PI && aspect.is_finite() && aspect > 0.0) {
            return Err(Error::invalid(
                "field of view",
                format!("fov {fov_y} rad, aspect {aspect}"),
            ));
        }
        let radius = bounds.radius();
        let fov_x = 2.0 * ((fov_y * 0.5).tan() * aspect).atan();
        let half = 0.5 * fov_y.min(fov_x);
        let distance = radius / half.sin();
        let center = bounds.center();
        let eye = center + Vec3::new(0.0, 0.0, distance);
        let camera = MultiViewCamera {
            eye_from_world: Mat4::look_at_rh(eye, center, Vec3::Y),
            views,
            separation: separation.unwrap_or(0.05 * radius),
            focal_distance: distance,
            fov_y,
            aspect,
            near: (distance - 2.0 * radius).max(distance * 0.01),
            far: distance + 2.0 * radius,
            model: CameraModel::Skewed,
            window_offset: glam::Vec2::ZERO,
        };
        // Only the data decides this camera: say so, rather than blame a flag never given.
        camera.validate().map_err(|e| {
            Error::invalid(
                "camera framing",
                format!(
                    "the scene's bounds {:?} .. {:?} (radius {radius}) give no usable camera \
                     ({e}); centre or scale the data",
                    bounds.min, bounds.max
                ),
            )
        })?;
        Ok(camera)
    }

    /// Spread the views over the angle `cone` (radians) as Looking Glass software does with a
    /// calibration's `viewCone`: the outermost views at ±cone/2 as seen from the focal point,
    /// so the baseline is `2·focal_distance·tan(cone/2)` and the separation that over N − 1.
    pub fn spread_over_cone(&mut self, cone: f32) -> Result<()> {
        if !(cone > 0.0 && cone < std::f32::consts::PI) {
            return Err(Error::invalid(
                "view cone",
                format!("{cone} rad: must be between 0 and π"),
            ));
        }
        let baseline = 2.0 * self.focal_distance * (0.5 * cone).tan();
        self.separation = match self.views {
            0 | 1 => 0.0,
            n => baseline / (n - 1) as f32,
        };
        self.validate()
    }

    /// Eye-space depth of the world point `p` (distance in front of the camera plane).
    pub fn depth_of(&self, p: Vec3) -> f32 {
        -(self.eye_from_world.transform_point3(p)).z
    }
}
