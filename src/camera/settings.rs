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
        let explicit = self.look_from.is_some() || self.look_at.is_some() || self.up.is_some();
        let mut camera = if explicit {
            let from = match self.look_from {
                Some(from) => from,
                None => framing()?.eye_position(),
            };
            MultiViewCamera::looking_at(
                bounds,
                from,
                self.pivot(bounds),
                self.up.unwrap_or(Vec3::Y),
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
