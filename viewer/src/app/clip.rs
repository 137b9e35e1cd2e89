//! The viewer's own clipping plane of a volume (keys `c`, `9`, `0`): one plane across an axis
//! of the volume's box, added to the planes the scene came with (`--clip`), so a radiologist
//! can sweep a cut through the scan live. The library applies it in every method
//! (src/volume/clip.rs).

use autostereo::volume::ClipPlane;
use glam::Vec3;

/// Where the key-driven plane is: across voxel axis `axis % 3`, keeping the part below it
/// (`axis < 3`) or above it, at `position` of the box (0 to 1).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(super) struct KeyClip {
    /// 0 … 5 (x, y, z below; x, y, z above), or `None`: no plane.
    axis: Option<usize>,
    position: f32,
}

/// How far one key press moves the plane, as a fraction of the box.
const STEP: f32 = 0.05;

impl KeyClip {
    /// Key `c`: the next axis and side (off → x → y → z → −x → −y → −z → off), the plane
    /// starting at the box's middle.
    pub fn next_axis(&mut self) {
        self.axis = match self.axis {
            None => Some(0),
            Some(5) => None,
            Some(a) => Some(a + 1),
        };
        self.position = 0.5;
    }

    /// Keys `9` (−1) and `0` (+1): move the plane along its axis.
    pub fn nudge(&mut self, direction: f32) {
        self.position = (self.position + direction * STEP).clamp(0.0, 1.0);
    }

    /// `base` with this plane added for a box of `extent` (the scene's, in the volume's
    /// units), within the library's plane limit (the key plane replaces the last given one
    /// when `base` is full).
    pub fn planes(&self, base: &[ClipPlane], extent: Vec3) -> Vec<ClipPlane> {
        let mut planes = base.to_vec();
        if let Some(axis) = self.axis {
            let mut normal = Vec3::ZERO;
            let sign = if axis < 3 { 1.0 } else { -1.0 };
            normal[axis % 3] = sign;
            let plane = ClipPlane::new(normal, sign * self.position * extent[axis % 3]);
            planes.truncate(autostereo::volume::MAX_CLIP_PLANES - 1);
            planes.push(plane);
        }
        planes
    }

    /// What the title says about it.
    pub fn describe(&self) -> Option<String> {
        let axis = self.axis?;
        let side = if axis < 3 { "<" } else { ">" };
        Some(format!(
            "clip {}{side}{:.0}%",
            ["x", "y", "z"][axis % 3],
            self.position * 100.0
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_key_plane_cycles_moves_and_keeps_the_given_planes() {
        let extent = Vec3::new(10.0, 20.0, 40.0);
        let given = [ClipPlane::new(Vec3::X, 3.0)];
        let mut clip = KeyClip::default();
        assert_eq!(clip.planes(&given, extent), given);
        clip.next_axis();
        clip.next_axis(); // y, below the middle
        clip.nudge(1.0);
        let planes = clip.planes(&given, extent);
        assert_eq!(planes[0], given[0]);
        assert_eq!(planes[1], ClipPlane::new(Vec3::Y, 0.55 * 20.0));
        assert_eq!(clip.describe().as_deref(), Some("clip y<55%"));
        for _ in 0..3 {
            clip.next_axis(); // −y: keep above
        }
        assert_eq!(
            clip.planes(&[], extent)[0],
            ClipPlane::new(-Vec3::Y, -0.5 * 20.0)
        );
        for _ in 0..40 {
            clip.nudge(-1.0);
        }
        assert_eq!(clip.position, 0.0);
        clip.next_axis();
        clip.next_axis();
        assert_eq!(clip.describe(), None);
        let full = [ClipPlane::new(Vec3::Z, 1.0); autostereo::volume::MAX_CLIP_PLANES];
        clip.next_axis();
        assert_eq!(clip.planes(&full, extent).len(), full.len());
    }
}
