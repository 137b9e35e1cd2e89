//! A camera as a user describes it (the views' spread, the focal plane, the field of view, the
//! model, an optional explicit eye), and the one rule that turns it into a
//! [`MultiViewCamera`] for a scene's bounds on a display: what every command, the viewer and
//! the Python package frame a scene with.

use glam::Vec3;

use super::{Bounds, CameraModel, MultiViewCamera};
use crate::display::Display;
use crate::error::Result;

/// How the views spread: the separation of adjacent views, or the distance between the
/// outermost ones (separation = baseline / (N − 1), so the span stays when N changes).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Spread {
    /// Adjacent views this far apart, scene units (negative reverses their order).
    Separation(f32),
    /// The outermost views this far apart (negative reverses their order).
    Baseline(f32),
}

/// Where the focal (zero-disparity) plane is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Focal {
    /// At this distance from the centre camera.
    Distance(f32),
    /// At this multiple of the framing's distance (to the bounds' centre or the look-at).
    Scale(f32),
}

/// Which side of a scene the centre camera looks from, in the renderer's world (x right, y
/// up, z toward the viewer; for a scan, its anterior view is the front: docs/VOLUMES.md).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Side {
    /// From +z (the default framing), up +y.
    Front,
    /// From −z, up +y.
    Back,
    /// From −x, up +y.
    Left,
    /// From +x, up +y.
    Right,
    /// From +y looking down, the front (+z) at the image's bottom.
    Top,
    /// From −y looking up, the front at the image's top.
    Bottom,
}

impl Side {
    /// The direction from the scene toward the camera, and the image's up.
    pub fn direction_and_up(self) -> (Vec3, Vec3) {
        match self {
            Side::Front => (Vec3::Z, Vec3::Y),
            Side::Back => (-Vec3::Z, Vec3::Y),
            Side::Left => (-Vec3::X, Vec3::Y),
            Side::Right => (Vec3::X, Vec3::Y),
            Side::Top => (Vec3::Y, -Vec3::Z),
            Side::Bottom => (-Vec3::Y, Vec3::Z),
        }
    }
}

/// A multi-view camera as described, before it meets a scene and a display.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraSettings {
    /// Default: a Looking Glass calibration's view cone, else 5 % of the bounding radius.
    pub spread: Option<Spread>,
    /// Default: through the bounds' centre, or through `look_at`.
    pub focal: Option<Focal>,
    /// Vertical field of view, degrees.
    pub fov_degrees: f32,
    /// How the N cameras look (default: skewed frusta sharing the focal window).
    pub model: CameraModel,
    /// The centre camera's position (default: the framing's, on the +z side of the bounds).
    pub look_from: Option<Vec3>,
    /// What the centre camera looks at (default: the bounds' centre).
    pub look_at: Option<Vec3>,
    /// The world direction up in the image (default +y).
    pub up: Option<Vec3>,
    /// Look from this side of the scene, at the framing's distance (`look_from` and `up`
    /// override what it sets).
    pub side: Option<Side>,
}

impl Default for CameraSettings {
    fn default() -> Self {
        Self {
            spread: None,
            focal: None,
            fov_degrees: 30.0,
            model: CameraModel::Skewed,
            look_from: None,
            look_at: None,
            up: None,
            side: None,
        }
    }
}

impl CameraSettings {
    /// The point the centre camera looks at: `look_at`, else the centre of `bounds` (what the
    /// viewer orbits about).
    pub fn pivot(&self, bounds: Bounds) -> Vec3 {
        self.look_at.unwrap_or(bounds.center())
    }

    /// The camera for `bounds` on `display` at `size` pixels: the framing, or an explicit eye
    /// where any of `look_from`/`look_at`/`up` is given (what is not given is the framing's);
    /// without a spread, a display's view cone (a Looking Glass calibration's `viewCone`)
    /// spreads the views. Validated.
    pub fn camera(
        &self,
        bounds: Bounds,
        display: &Display,
        size: [u32; 2],
    ) -> Result<MultiViewCamera> {
        let views = display.views();
        let aspect = size[0] as f32 / size[1] as f32;
        let separation = match self.spread {
            Some(Spread::Baseline(b)) if views > 1 => Some(b / (views - 1) as f32),
            Some(Spread::Baseline(_)) => Some(0.0),
            Some(Spread::Separation(s)) => Some(s),
            None => None,
        };
        let fov = self.fov_degrees.to_radians();
        let framing = || MultiViewCamera::framing(bounds, views, separation, fov, aspect);
        let explicit = self.look_from.is_some()
            || self.look_at.is_some()
            || self.up.is_some()
            || self.side.is_some();
        let mut camera = if explicit {
            let pivot = self.pivot(bounds);
            let (from, side_up) = match (self.look_from, self.side) {
                (Some(from), side) => (from, side.map(|s| s.direction_and_up().1)),
                (None, Some(side)) => {
                    // The framing's distance, from the chosen side of the pivot.
                    let distance = framing()?.eye_position().distance(bounds.center());
                    let (toward, up) = side.direction_and_up();
                    (pivot + toward * distance, Some(up))
                }
                (None, None) => (framing()?.eye_position(), None),
            };
            MultiViewCamera::looking_at(
                bounds,
                from,
                pivot,
                self.up.or(side_up).unwrap_or(Vec3::Y),
                views,
                separation,
                fov,
                aspect,
            )?
        } else {
            framing()?
        };
        match self.focal {
            Some(Focal::Distance(d)) => camera.focal_distance = d,
            Some(Focal::Scale(s)) => camera.focal_distance *= s,
            None => {}
        }
        camera.model = self.model;
        if let (None, Some(cone)) = (separation, display.view_cone()) {
            camera.spread_over_cone(cone)?;
        }
        camera.validate()?;
        Ok(camera)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each side puts the centre camera on that side of the scene at the front framing's
    /// distance, the image's up as the side says.
    #[test]
    fn a_side_looks_from_that_side_at_the_framings_distance() {
        let bounds = Bounds {
            min: Vec3::new(-1.0, -2.0, -0.5),
            max: Vec3::new(3.0, 1.0, 0.5),
        };
        let display = Display::parse("hubner8").unwrap();
        let front = CameraSettings::default()
            .camera(bounds, &display, [64, 48])
            .unwrap();
        let distance = front.eye_position().distance(bounds.center());
        for side in [
            Side::Front,
            Side::Back,
            Side::Left,
            Side::Right,
            Side::Top,
            Side::Bottom,
        ] {
            let settings = CameraSettings {
                side: Some(side),
                ..Default::default()
            };
            let camera = settings.camera(bounds, &display, [64, 48]).unwrap();
            let (toward, up) = side.direction_and_up();
            let eye = camera.eye_position() - bounds.center();
            assert!(
                (eye.length() - distance).abs() < 1e-3 * distance,
                "{side:?}"
            );
            assert!(eye.normalize().abs_diff_eq(toward, 1e-4), "{side:?}: {eye}");
            // The image's up, in the world: the eye-to-world transform of +y.
            let world_up = camera.eye_from_world.inverse().transform_vector3(Vec3::Y);
            assert!(
                world_up.normalize().abs_diff_eq(up, 1e-4),
                "{side:?}: up {world_up}"
            );
        }
        // The front is the default framing.
        let same = CameraSettings {
            side: Some(Side::Front),
            ..Default::default()
        };
        let camera = same.camera(bounds, &display, [64, 48]).unwrap();
        assert!(camera
            .eye_position()
            .abs_diff_eq(front.eye_position(), 1e-3));
    }
}
