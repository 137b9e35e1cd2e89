//! Mouse navigation: orbit around the point the camera looks at (--look-at, else the scene's
//! centre), zoom towards it, pan across the view; applied to the command line's camera (the
//! framing, or --look-from/--look-at/--up) as rigid motions (the renderers need a rigid view
//! matrix).

use autostereo::camera::MultiViewCamera;
use glam::{Mat4, Vec2, Vec3};

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
