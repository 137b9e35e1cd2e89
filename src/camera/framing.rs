//! Framing helpers: place the camera so a bounding box fits, focal plane through its centre.

use glam::{Mat4, Vec3};

use super::{CameraModel, MultiViewCamera};
use crate::error::{Error, Result};
use crate::param::Param;

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

/// The caller's own numbers, refused by name before a camera is made of them: a field of view
/// in degrees as well as radians (what a user types), a separation that is not finite (the
/// caller's to fix, not the data's: `framing` blames the bounds for the rest).
fn check_lens(fov_y: f32, aspect: f32, separation: Option<f32>) -> Result<()> {
    if !(fov_y > 0.0 && fov_y < std::f32::consts::PI && aspect.is_finite() && aspect > 0.0) {
        return Err(Error::invalid(
            Param::FieldOfView,
            format!(
                "{}° ({fov_y} rad) at aspect {aspect}: the vertical field of view must be \
                 between 0 and 180°, the aspect positive",
                fov_y.to_degrees()
            ),
        ));
    }
    if let Some(e) = separation.filter(|e| !e.is_finite()) {
        return Err(Error::invalid(
            Param::Separation,
            format!("{e}: must be finite"),
        ));
    }
    Ok(())
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
        check_lens(fov_y, aspect, separation)?;
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
                Param::CameraFraming,
                format!(
                    "the scene's bounds {:?} .. {:?} (radius {radius}) give no usable camera \
                     ({e}); centre or scale the data",
                    bounds.min, bounds.max
                ),
            )
        })?;
        Ok(camera)
    }

    /// The centre camera at `from` looking at `at` with `up` towards the image's top (an
    /// explicit camera, for scenes whose own axes do not suit [`MultiViewCamera::framing`]: a
    /// capture with y down, say). The focal plane passes through `at` (focal distance
    /// `|at − from|`); near and far bracket the bounding sphere of `bounds` seen from `from` as
    /// `framing` brackets it (from this camera's [`MultiViewCamera::framing`] eye and centre the
    /// same planes), the near plane kept ahead of the eye when `from` is inside the scene.
    /// Separation `e` defaults to 5 % of the bounding radius when `None`. Refused by name: a
    /// non-finite point or vector, `from` = `at`, `up` zero or parallel to the view direction,
    /// and a scene wholly behind the camera.
    #[allow(clippy::too_many_arguments)]
    pub fn looking_at(
        bounds: Bounds,
        from: Vec3,
        at: Vec3,
        up: Vec3,
        views: u32,
        separation: Option<f32>,
        fov_y: f32,
        aspect: f32,
    ) -> Result<Self> {
        check_lens(fov_y, aspect, separation)?;
        for (name, v) in [
            (Param::LookFrom, from),
            (Param::LookAt, at),
            (Param::Up, up),
        ] {
            if !v.is_finite() {
                return Err(Error::invalid(name, format!("{v}: must be finite")));
            }
        }
        let view = at - from;
        let focal_distance = view.length();
        // Points so far apart that the distance overflows f32 (its square past f32::MAX) leave
        // no view direction: blame the farther point, not `up`.
        if !focal_distance.is_finite() {
            let (name, point, other_name, other) =
                match at.abs().max_element() >= from.abs().max_element() {
                    true => (Param::LookAt, at, Param::LookFrom, from),
                    false => (Param::LookFrom, from, Param::LookAt, at),
                };
            return Err(Error::invalid(
                name,
                format!(
                    "{point} is too far from the {other_name} point {other}: their distance \
                     must be under {:e} world units (bring the points nearer)",
                    f32::MAX.sqrt()
                ),
            ));
        }
        // Relative to the points' own size, so that far-off coordinates still compare.
        let scale = from.abs().max(at.abs()).max_element().max(bounds.radius());
        if focal_distance <= 1e-6 * scale {
            return Err(Error::invalid(
                Param::LookAt,
                format!("{at} is the look-from point {from}: the camera looks nowhere"),
            ));
        }
        let forward = view / focal_distance;
        if up.length() <= 0.0 {
            return Err(Error::invalid(
                Param::Up,
                "the zero vector has no direction",
            ));
        }
        if forward.cross(up.normalize()).length() < 1e-4 {
            return Err(Error::invalid(
                Param::Up,
                format!(
                    "{up} is parallel to the view direction {forward} (look-from {from} to \
                     look-at {at}): it must point across it, towards the image's top"
                ),
            ));
        }
        let radius = bounds.radius();
        let centre = forward.dot(bounds.center() - from);
        if centre + radius <= 0.0 {
            return Err(Error::invalid(
                Param::LookAt,
                format!(
                    "looking from {from} towards {at}, the scene's bounds {:?} .. {:?} are \
                     wholly behind the camera",
                    bounds.min, bounds.max
                ),
            ));
        }
        let camera = MultiViewCamera {
            eye_from_world: Mat4::look_at_rh(from, at, up),
            views,
            separation: separation.unwrap_or(0.05 * radius),
            focal_distance,
            fov_y,
            aspect,
            near: (centre - 2.0 * radius).max(0.01 * centre.max(radius)),
            far: centre + 2.0 * radius,
            model: CameraModel::Skewed,
            window_offset: glam::Vec2::ZERO,
        };
        camera.validate()?;
        Ok(camera)
    }

    /// Where the centre camera of this camera is, world space.
    pub fn eye_position(&self) -> Vec3 {
        self.eye_from_world.inverse().transform_point3(Vec3::ZERO)
    }

    /// Spread the views over the angle `cone` (radians) as Looking Glass software does with a
    /// calibration's `viewCone`: the outermost views at ±cone/2 as seen from the focal point,
    /// so the baseline is `2·focal_distance·tan(cone/2)` and the separation that over N − 1.
    pub fn spread_over_cone(&mut self, cone: f32) -> Result<()> {
        if !(cone > 0.0 && cone < std::f32::consts::PI) {
            return Err(Error::invalid(
                Param::ViewCone,
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
