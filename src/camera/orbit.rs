//! Orbiting a camera: turn around the point it looks at (the pivot: `--look-at`, else the
//! scene's centre), zoom towards it, pan across the view, as rigid motions of a camera
//! [`CameraSettings`](super::CameraSettings) made (the renderers need a rigid view matrix).
//! The viewer's mouse drives it; the Python package's `Camera.orbit` sets it in degrees.

use glam::{Mat4, Vec2, Vec3};

use super::MultiViewCamera;

/// Radians per pixel of drag.
const TURN_PER_PIXEL: f32 = 0.01;
/// Pitch stays short of straight up or down (the orbit would flip over).
const MAX_PITCH: f32 = 1.5;

/// Where the user has moved the camera from its framing. The default is the framing itself.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Orbit {
    /// Turn about the vertical axis through the centre, radians.
    pub yaw: f32,
    /// Turn about the horizontal axis through the centre, radians.
    pub pitch: f32,
    /// Distance to the centre halves per unit (negative: further away).
    pub zoom: f32,
    /// Sideways and vertical shift in units of the centre's distance.
    pub pan: Vec2,
}

impl Orbit {
    /// The camera carried `yaw` degrees around the pivot's vertical axis (positive: toward
    /// the scene's right, +x; 90 looks from the right) and `pitch` degrees over it (positive:
    /// up; 90 looks down from the top with the front at the image's bottom, as
    /// [`Side::Top`](super::Side::Top)). The world turns the other way under the camera.
    pub fn degrees(yaw: f32, pitch: f32) -> Self {
        Self {
            yaw: -yaw.to_radians(),
            pitch: pitch.to_radians(),
            ..Self::default()
        }
    }

    /// A drag of (dx, dy) pixels with the orbit button.
    pub fn turn(&mut self, dx: f32, dy: f32) {
        self.yaw += dx * TURN_PER_PIXEL;
        self.pitch = (self.pitch + dy * TURN_PER_PIXEL).clamp(-MAX_PITCH, MAX_PITCH);
    }

    /// A drag of (dx, dy) pixels with the pan button, in a window `height` pixels tall.
    pub fn slide(&mut self, dx: f32, dy: f32, height: f32) {
        self.pan += Vec2::new(dx, -dy) / height.max(1.0);
    }

    /// `steps` wheel notches (positive: closer).
    pub fn dolly(&mut self, steps: f32) {
        self.zoom = (self.zoom + 0.1 * steps).clamp(-4.0, 4.0);
    }

    /// `base` (the starting camera, looking at `centre`) moved by this orbit, turning about
    /// `centre` and about `base`'s own up and right axes. The focal plane,
    /// near and far keep their distances relative to the centre's.
    pub fn apply(&self, base: &MultiViewCamera, centre: Vec3) -> MultiViewCamera {
        if *self == Orbit::default() {
            return base.clone();
        }
        let c = base.eye_from_world.transform_point3(centre);
        let distance = -c.z;
        let scale = (-self.zoom).exp2();
        let turn = Mat4::from_translation(c)
            * Mat4::from_rotation_x(self.pitch)
            * Mat4::from_rotation_y(self.yaw)
            * Mat4::from_translation(-c);
        let dolly = Mat4::from_translation(Vec3::new(0.0, 0.0, distance * (1.0 - scale)));
        let pan = Mat4::from_translation((self.pan * distance * scale).extend(0.0));
        MultiViewCamera {
            eye_from_world: pan * dolly * turn * base.eye_from_world,
            focal_distance: base.focal_distance * scale,
            near: base.near * scale,
            far: base.far,
            ..base.clone()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera::{Bounds, CameraSettings, Side};
    use crate::display::Display;

    /// `Orbit::degrees(90, 0)` looks from the right, `(0, 90)` from the top: the same eye and
    /// image axes as the sides.
    #[test]
    fn orbit_degrees_turn_the_camera_to_the_sides() {
        let bounds = Bounds {
            min: Vec3::new(-1.0, -2.0, -0.5),
            max: Vec3::new(3.0, 1.0, 0.5),
        };
        let display = Display::parse("hubner8").unwrap();
        let camera = |side| {
            let settings = CameraSettings {
                side,
                ..Default::default()
            };
            settings.camera(bounds, &display, [64, 48]).unwrap()
        };
        let front = camera(None);
        for (orbit, side) in [
            (Orbit::degrees(90.0, 0.0), Side::Right),
            (Orbit::degrees(-90.0, 0.0), Side::Left),
            (Orbit::degrees(0.0, 90.0), Side::Top),
            (Orbit::degrees(0.0, -90.0), Side::Bottom),
            (Orbit::degrees(180.0, 0.0), Side::Back),
        ] {
            let turned = orbit.apply(&front, bounds.center());
            let expected = camera(Some(side));
            let (a, b) = (turned.eye_from_world, expected.eye_from_world);
            assert!(a.abs_diff_eq(b, 1e-4), "{side:?}: {a} vs {b}");
        }
    }
}
