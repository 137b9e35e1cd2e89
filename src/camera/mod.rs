//! Multi-view camera (docs/DESIGN.md §2): N cameras offset along eye-space +x, set up by one of
//! three models (Yalçın & Çapın): sheared frusta sharing one window on the focal plane (the
//! default), parallel frusta with their images shifted to converge there, or cameras turned
//! towards the focal point.

pub(crate) mod crop_box;
mod framing;
mod gpu;
mod orbit;
mod settings;

pub use framing::Bounds;
pub use gpu::{CameraUniform, ViewUniform};
pub use orbit::Orbit;
pub use settings::{CameraSettings, Focal, Side, Spread};

use glam::{Mat4, Vec2, Vec3, Vec4};

use crate::display::check_views;
use crate::error::{Error, Result};
use crate::param::Param;

/// How the N cameras at offsets `vd_i` look at the scene.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum CameraModel {
    /// Off-axis (sheared) frusta through one shared window on the focal plane: the image a
    /// multi-view display expects, and what every method renders by default.
    #[default]
    Skewed,
    /// Unsheared parallel frusta, each image shifted horizontally by its focal-plane
    /// disparity so the views converge on the focal plane: inside the shifted image the same
    /// rays as `Skewed`, and the strip the shift uncovers (|vd_i| wide on the focal plane, at
    /// the image's edge) is empty: background.
    Parallel,
    /// Cameras turned about their vertical axis towards the focal point (0, 0, −fd), each with
    /// the centre's symmetric frustum: the images converge at the focal point only and show
    /// keystone and vertical parallax (docs/DESIGN.md §2).
    ToeIn,
}

impl CameraModel {
    /// Every model, in the order of the CLI's `--camera`.
    pub const ALL: [CameraModel; 3] = [Self::Skewed, Self::Parallel, Self::ToeIn];

    /// The CLI name.
    pub fn name(self) -> &'static str {
        match self {
            Self::Skewed => "skewed",
            Self::Parallel => "parallel",
            Self::ToeIn => "toe-in",
        }
    }

    /// The WGSL constant (`CAMERA_*` in `wgsl/shared/camera.wgsl`).
    pub(crate) fn gpu(self) -> u32 {
        match self {
            Self::Skewed => 0,
            Self::Parallel => 1,
            Self::ToeIn => 2,
        }
    }
}

impl std::str::FromStr for CameraModel {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        Self::ALL
            .into_iter()
            .find(|m| m.name() == s)
            .ok_or_else(|| {
                Error::invalid(Param::Camera, format!("'{s}': skewed, parallel or toe-in"))
            })
    }
}

impl std::fmt::Display for CameraModel {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// The centre camera plus the multi-view configuration.
#[derive(Clone, Debug, PartialEq)]
pub struct MultiViewCamera {
    /// World → centre eye space (right-handed, looking down −z). Rigid (rotation +
    /// translation): splat radii and volume steps are used in eye space unscaled.
    pub eye_from_world: Mat4,
    /// Number of views N.
    pub views: u32,
    /// Separation e of adjacent views, eye-space units.
    pub separation: f32,
    /// Distance fd from the camera plane to the focal plane.
    pub focal_distance: f32,
    /// Vertical field of view of the centre view, radians.
    pub fov_y: f32,
    /// Width / height of the image.
    pub aspect: f32,
    /// Near clipping distance.
    pub near: f32,
    /// Far clipping distance.
    pub far: f32,
    /// How the views' cameras are set up.
    pub model: CameraModel,
    /// Where the rendered image's window sits on the focal plane: its centre relative to the
    /// camera axis, eye-space units (y up). Zero for a whole image; a band of a frame rendered
    /// in pieces ([`crate::frame::Frame::band`]) is an off-centre part of the whole window.
    pub window_offset: Vec2,
}

impl MultiViewCamera {
    /// Check every parameter; each failure names the parameter.
    pub fn validate(&self) -> Result<()> {
        check_views(self.views)?;
        let positive = |name: Param, v: f32| {
            if v.is_finite() && v > 0.0 {
                Ok(())
            } else {
                Err(Error::invalid(
                    name,
                    format!("{v}: must be a positive finite number"),
                ))
            }
        };
        positive(Param::FocalDistance, self.focal_distance)?;
        positive(Param::Aspect, self.aspect)?;
        positive(Param::Near, self.near)?;
        if !self.separation.is_finite() {
            return Err(Error::invalid(Param::Separation, "must be finite"));
        }
        if !(self.fov_y > 0.0 && self.fov_y < std::f32::consts::PI) {
            return Err(Error::invalid(
                Param::Fov,
                format!("{} rad: must be in (0, π)", self.fov_y),
            ));
        }
        if !(self.far.is_finite() && self.far > self.near) {
            return Err(Error::invalid(
                Param::Far,
                format!(
                    "{}: must be finite and beyond near = {}",
                    self.far, self.near
                ),
            ));
        }
        if !self.eye_from_world.is_finite() {
            return Err(Error::invalid(
                Param::ViewMatrix,
                "contains NaN or infinity",
            ));
        }
        if !self.window_offset.is_finite() {
            return Err(Error::invalid(Param::WindowOffset, "must be finite"));
        }
        Ok(())
    }

    /// Camera offset `vd_i = (i − (N−1)/2)·e` of view `i` along eye +x.
    pub fn view_offset(&self, i: u32) -> f32 {
        (i as f32 - (self.views as f32 - 1.0) * 0.5) * self.separation
    }

    /// Largest |vd_i| over the views: `(N−1)/2·|e|`.
    pub fn max_offset(&self) -> f32 {
        (self.views as f32 - 1.0) * 0.5 * self.separation.abs()
    }

    /// Size (W, H) of the shared window on the focal plane, eye-space units.
    pub fn focal_window(&self) -> Vec2 {
        let h = 2.0 * self.focal_distance * (self.fov_y * 0.5).tan();
        Vec2::new(h * self.aspect, h)
    }

    /// Projection (wgpu clip space, depth 0..1 of the camera's own depth) of the camera at
    /// eye-space offset `vd`. Skewed and parallel (the parallel model's shifted image is the
    /// skewed one, cropped): `Frustum(l, r, b, t, near, far) · Translate(−vd, 0, 0)` with
    /// `l, r = (∓W/2 − vd)·near/fd`. Toe-in: the centre's symmetric frustum
    /// `· RotateY(−φ) · Translate(−vd, 0, 0)`, `φ = atan(vd / fd)`.
    pub fn projection_for_offset(&self, vd: f32) -> Mat4 {
        let window = self.focal_window();
        let c = self.window_offset;
        let s = self.near / self.focal_distance;
        let (b, t) = ((c.y - window.y * 0.5) * s, (c.y + window.y * 0.5) * s);
        let to_camera = Mat4::from_translation(Vec3::new(-vd, 0.0, 0.0));
        if self.model == CameraModel::ToeIn {
            let (l, r) = ((c.x - window.x * 0.5) * s, (c.x + window.x * 0.5) * s);
            let turn = Mat4::from_rotation_y(-self.toe_in_angle(vd));
            return frustum(l, r, b, t, self.near, self.far) * turn * to_camera;
        }
        let (l, r) = (
            (c.x - window.x * 0.5 - vd) * s,
            (c.x + window.x * 0.5 - vd) * s,
        );
        frustum(l, r, b, t, self.near, self.far) * to_camera
    }

    /// The toe-in camera at offset `vd`'s turn about +y towards the focal point, radians:
    /// `atan(vd / fd)` (a camera right of the centre turns left).
    pub fn toe_in_angle(&self, vd: f32) -> f32 {
        vd.atan2(self.focal_distance)
    }

    /// Whether the camera at `vd` sees the focal-plane abscissa `x_f` (the parallel model's
    /// shifted image covers `|x_f − vd| ≤ W/2`; the other models see their whole image).
    pub fn sees(&self, vd: f32, x_f: f32) -> bool {
        self.model != CameraModel::Parallel || (x_f - vd).abs() <= 0.5 * self.focal_window().x
    }

    /// Projection of view `i` (eye space → clip space).
    pub fn projection(&self, i: u32) -> Mat4 {
        self.projection_for_offset(self.view_offset(i))
    }

    /// Closed form of the projection of eye-space point `p` by the camera at offset `vd`, in
    /// the focal-plane coordinates of its image. Skewed and parallel: `x_f = p.x·fd/d +
    /// vd·(1 − fd/d)`, `y_f = p.y·fd/d`, `d = −p.z`. Toe-in: `q = RotateY(−φ)·(p − (vd, 0, 0))`,
    /// `(x_f, y_f) = q.xy·fd/(−q.z)`, so `y_f = p.y·fd / (d·cos φ − (p.x − vd)·sin φ)`: the
    /// vertical parallax of a point off the vertical centre line.
    pub fn project_offset(&self, vd: f32, p: Vec3) -> Vec2 {
        if self.model == CameraModel::ToeIn {
            let q = Mat4::from_rotation_y(-self.toe_in_angle(vd))
                .transform_point3(p - Vec3::new(vd, 0.0, 0.0));
            return q.truncate() * (self.focal_distance / -q.z);
        }
        let d = -p.z;
        let k = self.focal_distance / d;
        Vec2::new(p.x * k + vd * (1.0 - k), p.y * k)
    }

    /// Closed-form projection of eye-space `p` in view `i` (focal-plane coordinates).
    pub fn project(&self, i: u32, p: Vec3) -> Vec2 {
        self.project_offset(self.view_offset(i), p)
    }

    /// Focal-plane coordinates → continuous pixel coordinates of a `size` image
    /// (pixel (x, y) covers [x, x+1) × [y, y+1); y top-down).
    pub fn focal_to_pixel(&self, f: Vec2, size: [u32; 2]) -> Vec2 {
        let (w, c) = (self.focal_window(), self.window_offset);
        Vec2::new(
            ((f.x - c.x) / w.x + 0.5) * size[0] as f32,
            (0.5 - (f.y - c.y) / w.y) * size[1] as f32,
        )
    }

    /// The same camera with `views` views (separation unchanged).
    pub fn with_views(mut self, views: u32) -> Self {
        self.views = views;
        self
    }

    /// GPU uniform for an image of `size` pixels.
    pub fn uniform(&self, size: [u32; 2]) -> CameraUniform {
        CameraUniform::new(self, size)
    }

    /// Per-view uniform (N-pass): projection and offset of a camera at `vd`.
    pub fn view_uniform(&self, vd: f32) -> ViewUniform {
        ViewUniform::new(self.projection_for_offset(vd), vd)
    }
}

/// Right-handed off-axis frustum with wgpu's 0..1 depth range.
fn frustum(l: f32, r: f32, b: f32, t: f32, n: f32, f: f32) -> Mat4 {
    Mat4::from_cols(
        Vec4::new(2.0 * n / (r - l), 0.0, 0.0, 0.0),
        Vec4::new(0.0, 2.0 * n / (t - b), 0.0, 0.0),
        Vec4::new((r + l) / (r - l), (t + b) / (t - b), f / (n - f), -1.0),
        Vec4::new(0.0, 0.0, n * f / (n - f), 0.0),
    )
}

#[cfg(test)]
mod tests;
