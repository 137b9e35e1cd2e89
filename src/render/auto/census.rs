//! What a frame asks of the renderers, counted on the CPU before anything is drawn: the inputs
//! of the cost model in [`super::costs`]. Counted with the centre camera: the per-view
//! differences are the disparity the single pass's covering rectangles already include.

use glam::{Vec2, Vec3};

use crate::camera::{Bounds, MultiViewCamera};
use crate::frame::Frame;
use crate::mesh::Mesh;

/// A mesh's screen work in one frame, in pixels of the spatial image.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct MeshCensus {
    /// Triangles with a part in front of the near plane.
    pub triangles: u64,
    /// Their projected areas in the centre view, summed (depth complexity included), clipped to
    /// the image: what each view's rasteriser fills.
    pub triangle_pixels: f64,
    /// Their covering rectangles (the centre bounds widened by every view's disparity,
    /// docs/DESIGN.md §3), summed and clipped to the image: what the single pass visits.
    pub cover_pixels: f64,
}

/// The share of the image the scene's bounds cover in the centre view, in 0..=1: the rays
/// that reach the scene.
pub fn bounds_coverage(frame: &Frame, bounds: Bounds) -> f64 {
    let corners = (0..8).map(|i| {
        Vec3::new(
            if i & 1 == 0 {
                bounds.min.x
            } else {
                bounds.max.x
            },
            if i & 2 == 0 {
                bounds.min.y
            } else {
                bounds.max.y
            },
            if i & 4 == 0 {
                bounds.min.z
            } else {
                bounds.max.z
            },
        )
    });
    let camera = &frame.camera;
    let eye: Vec<Vec3> = corners
        .map(|p| camera.eye_from_world.transform_point3(p))
        .collect();
    if eye.iter().any(|q| -q.z < camera.near) {
        return 1.0; // the camera is inside or near the box: every ray may reach it
    }
    let px: Vec<Vec2> = eye.iter().map(|&q| pixel(camera, frame.size, q)).collect();
    let rect = Rect::around(&px).clipped(frame.size);
    (rect.area() / (frame.size[0] as f64 * frame.size[1] as f64)).clamp(0.0, 1.0)
}

impl MeshCensus {
    /// `mesh`'s work in `frame`.
    pub fn of(mesh: &Mesh, frame: &Frame) -> Self {
        let camera = &frame.camera;
        let eye: Vec<Vec3> = mesh
            .positions
            .iter()
            .map(|&p| camera.eye_from_world.transform_point3(p))
            .collect();
        let focal = camera.focal_window().x as f64;
        let to_pixels = frame.size[0] as f64 / focal;
        let mut census = Self::default();
        for tri in mesh.indices.chunks_exact(3) {
            let q = [0, 1, 2].map(|k| eye.get(tri[k] as usize).copied());
            let [Some(a), Some(b), Some(c)] = q else {
                continue;
            };
            // Vertices behind the near plane are taken at it: a count, not a clip.
            let depths = [a, b, c].map(|v| (-v.z).max(camera.near));
            if [a, b, c].iter().all(|v| -v.z < camera.near) {
                continue;
            }
            let on_near = |v: Vec3, d: f32| Vec3::new(v.x, v.y, -d);
            let verts = [
                on_near(a, depths[0]),
                on_near(b, depths[1]),
                on_near(c, depths[2]),
            ];
            let px = verts.map(|v| pixel(camera, frame.size, v));
            let centre = Rect::around(&px);
            let spread = verts
                .iter()
                .map(|v| spread(camera, -v.z) as f64 * to_pixels)
                .fold(0.0, f64::max);
            let cover = Rect {
                lo: [centre.lo[0] - spread, centre.lo[1]],
                hi: [centre.hi[0] + spread, centre.hi[1]],
            };
            let area = 0.5 * ((px[1] - px[0]).perp_dot(px[2] - px[0]) as f64).abs();
            let visible = centre.clipped(frame.size).area() / centre.area().max(f64::MIN_POSITIVE);
            census.triangles += 1;
            census.triangle_pixels += area * visible.min(1.0);
            // Each row and column a rectangle touches is visited: at least one of each.
            census.cover_pixels += cover.touched(frame.size);
        }
        census
    }
}

/// How far a vertex at depth `d` moves from the centre view's projection to the outermost
/// view's, focal-plane units: `vd·|1 − fd/d|` for the sheared and parallel cameras (the
/// toe-in ones turn, taken alike here); the covering rectangle widens by it on each side.
fn spread(camera: &MultiViewCamera, d: f32) -> f32 {
    camera.max_offset() * (1.0 - camera.focal_distance / d).abs()
}

/// Eye-space `q` in the centre view, pixel coordinates of a `size` image.
fn pixel(camera: &MultiViewCamera, size: [u32; 2], q: Vec3) -> Vec2 {
    camera.focal_to_pixel(camera.project_offset(0.0, q), size)
}

/// An axis-aligned rectangle in pixels.
#[derive(Clone, Copy, Debug)]
struct Rect {
    lo: [f64; 2],
    hi: [f64; 2],
}

impl Rect {
    fn around(points: &[Vec2]) -> Self {
        let mut r = Rect {
            lo: [f64::INFINITY; 2],
            hi: [f64::NEG_INFINITY; 2],
        };
        for p in points {
            for (k, v) in [p.x as f64, p.y as f64].into_iter().enumerate() {
                r.lo[k] = r.lo[k].min(v);
                r.hi[k] = r.hi[k].max(v);
            }
        }
        r
    }

    fn clipped(self, size: [u32; 2]) -> Self {
        let max = [size[0] as f64, size[1] as f64];
        Rect {
            lo: [0, 1].map(|k| self.lo[k].clamp(0.0, max[k])),
            hi: [0, 1].map(|k| self.hi[k].clamp(0.0, max[k])),
        }
    }

    fn area(&self) -> f64 {
        (self.hi[0] - self.lo[0]).max(0.0) * (self.hi[1] - self.lo[1]).max(0.0)
    }

    /// Whole pixels of a `size` image the rectangle touches.
    fn touched(&self, size: [u32; 2]) -> f64 {
        let max = [size[0] as f64, size[1] as f64];
        let side = |k: usize| {
            let (lo, hi) = (self.lo[k], self.hi[k]);
            if !(hi >= lo && hi >= 0.0 && lo < max[k]) {
                return 0.0;
            }
            let first = lo.max(0.0).floor();
            (hi.min(max[k]).ceil().max(first + 1.0) - first).min(max[k] - first)
        };
        side(0) * side(1)
    }
}
