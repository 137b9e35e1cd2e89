//! CPU reference of the 3D Gaussian splatting rules (docs/GAUSSIANS.md; graphdeco's
//! diff-gaussian-rasterization forward pass) for the GPU renderers' tests: one view at a time,
//! in f64, independent of the library's math — its own SH constants, rotation matrix and
//! covariance; only the data (`Gaussians`) and the camera's matrices come from the library.
//!
//! Per view (its rigid `view` matrix, its off-axis frustum `projection`, as the library's
//! `MultiViewCamera` gives them: [`ViewCamera::of`]):
//! - the pinhole from the projection: `fx = P₀₀·W/2`, `cx = (1 − P₀₂)·W/2`, `fy = P₁₁·H/2`,
//!   `cy = (1 + P₁₂)·H/2`; pixel `u = cx + fx·x/d`, `v = cy − fy·y/d` (`d = −z_eye`, row 0 at
//!   the top, pixel (i, j) covers [i, i+1) × [j, j+1), sampled at its centre);
//! - Gaussians whose mean is not between the near and far planes are skipped;
//! - `Σ = R S Sᵀ Rᵀ`; `Σ' = J W Σ Wᵀ Jᵀ + 0.3·I` (pixels²) with `J = [fx/d, 0, fx·x/d²;
//!   0, −fy/d, −fy·y/d²]`, `x/d` and `y/d` clamped to ±1.3× the frustum's half-extent about
//!   its centre (graphdeco's `1.3·tan(fov/2)`, generalised to skewed frusta: NDC ±1.3);
//! - extent: pixel centres within `r = ceil(3·√λ_max(Σ'))` of the mean along x and y;
//! - colour `max(SH(mean − camera centre) + 0.5, 0)`;
//! - `α = min(0.99, opacity·exp(−½ dᵀΣ'⁻¹d))`, skipped below 1/255 (and where the exponent is
//!   positive); front to back by eye depth `d`; a pixel stops before the Gaussian that would
//!   take its transmittance T below 1e-4;
//! - out: `rgb = Σ colour·α·T + T·background.rgb`, `a = 1 − T` (the coverage; the renderers
//!   store an opaque image, so compare rgb).

use autostereo::camera::{CameraModel, MultiViewCamera};
use autostereo::gaussians::Gaussians;
use glam::{DMat3, DMat4, DQuat, DVec3};

/// One view's camera: world → its eye space (rigid, looking down −z) and eye → wgpu clip
/// space (an off-axis frustum, depth 0..1).
#[derive(Clone, Copy, Debug)]
pub struct ViewCamera {
    pub view: DMat4,
    pub projection: DMat4,
}

impl ViewCamera {
    /// View `i` of `camera`: the library's per-view projection (which carries the view's
    /// offset, and a toe-in camera's turn, after the centre's eye space) split into the view's
    /// own rigid camera and its frustum; asserts that what is left is a frustum.
    pub fn of(camera: &MultiViewCamera, i: u32) -> Self {
        let vd = camera.view_offset(i) as f64;
        let mut rig = DMat4::from_translation(DVec3::new(-vd, 0.0, 0.0));
        if camera.model == CameraModel::ToeIn {
            let angle = vd.atan2(camera.focal_distance as f64);
            rig = DMat4::from_rotation_y(-angle) * rig;
        }
        let projection = camera.projection(i).as_dmat4() * rig.inverse();
        let p = projection;
        let zero = [
            p.y_axis.x, p.x_axis.y, p.x_axis.w, p.y_axis.w, p.w_axis.x, p.w_axis.y,
        ];
        assert!(
            zero.iter().all(|v| v.abs() < 1e-5) && (p.z_axis.w + 1.0).abs() < 1e-6,
            "view {i}: not a frustum: {p}"
        );
        Self {
            view: rig * camera.eye_from_world.as_dmat4(),
            projection,
        }
    }

    /// Near and far distances of the frustum.
    fn near_far(&self) -> (f64, f64) {
        let p = self.projection;
        (p.w_axis.z / p.z_axis.z, p.w_axis.z / (p.z_axis.z + 1.0))
    }
}

/// An RGBA f32 image, row 0 at the top.
#[derive(Clone, Debug)]
pub struct ReferenceImage {
    pub size: [u32; 2],
    pub rgba: Vec<[f32; 4]>,
}

impl ReferenceImage {
    /// Pixel (x, y).
    pub fn pixel(&self, x: u32, y: u32) -> [f32; 4] {
        self.rgba[(y * self.size[0] + x) as usize]
    }
}

// graphdeco's real SH constants (`auxiliary.h`), in f64.
const C0: f64 = 0.28209479177387814;
const C1: f64 = 0.4886025119029199;
const C2: [f64; 5] = [
    1.0925484305920792,
    -1.0925484305920792,
    0.31539156525252005,
    -1.0925484305920792,
    0.5462742152960396,
];
const C3: [f64; 7] = [
    -0.5900435899266435,
    2.890611442640554,
    -0.4570457994644658,
    0.3731763325901154,
    -0.4570457994644658,
    1.445305721320277,
    -0.5900435899266435,
];

/// The SH sum for unit `dir` (graphdeco's `computeColorFromSH` before the + 0.5).
fn sh_sum(degree: u32, c: &[[f32; 3]], dir: DVec3) -> DVec3 {
    let k = |i: usize| DVec3::new(c[i][0] as f64, c[i][1] as f64, c[i][2] as f64);
    let (x, y, z) = (dir.x, dir.y, dir.z);
    let mut s = C0 * k(0);
    if degree > 0 {
        s += -C1 * y * k(1) + C1 * z * k(2) - C1 * x * k(3);
    }
    if degree > 1 {
        let (xx, yy, zz, xy, yz, xz) = (x * x, y * y, z * z, x * y, y * z, x * z);
        s += C2[0] * xy * k(4)
            + C2[1] * yz * k(5)
            + C2[2] * (2.0 * zz - xx - yy) * k(6)
            + C2[3] * xz * k(7)
            + C2[4] * (xx - yy) * k(8);
        if degree > 2 {
            s += C3[0] * y * (3.0 * xx - yy) * k(9)
                + C3[1] * xy * z * k(10)
                + C3[2] * y * (4.0 * zz - xx - yy) * k(11)
                + C3[3] * z * (2.0 * zz - 3.0 * xx - 3.0 * yy) * k(12)
                + C3[4] * x * (4.0 * zz - xx - yy) * k(13)
                + C3[5] * z * (xx - yy) * k(14)
                + C3[6] * x * (xx - 3.0 * yy) * k(15);
        }
    }
    s
}

/// The rotation matrix of quaternion (w, x, y, z), normalised here.
fn rotation_matrix(q: DQuat) -> DMat3 {
    let q = q.normalize();
    let (w, x, y, z) = (q.w, q.x, q.y, q.z);
    DMat3::from_cols(
        DVec3::new(
            1.0 - 2.0 * (y * y + z * z),
            2.0 * (x * y + w * z),
            2.0 * (x * z - w * y),
        ),
        DVec3::new(
            2.0 * (x * y - w * z),
            1.0 - 2.0 * (x * x + z * z),
            2.0 * (y * z + w * x),
        ),
        DVec3::new(
            2.0 * (x * z + w * y),
            2.0 * (y * z - w * x),
            1.0 - 2.0 * (x * x + y * y),
        ),
    )
}

/// One Gaussian projected into the view.
struct Projected {
    depth: f64,
    /// Mean in pixels.
    u: f64,
    v: f64,
    /// Inverse of the 2D covariance: (a, b, c) of [[a, b], [b, c]].
    conic: [f64; 3],
    radius: f64,
    color: DVec3,
    opacity: f64,
}

/// Project Gaussian `i` (None: culled).
fn project(g: &Gaussians, i: usize, camera: &ViewCamera, size: [u32; 2]) -> Option<Projected> {
    let (w, h) = (size[0] as f64, size[1] as f64);
    let p = camera.projection;
    let (p00, p02, p11, p12) = (p.x_axis.x, p.z_axis.x, p.y_axis.y, p.z_axis.y);
    let (fx, cx) = (p00 * w / 2.0, (1.0 - p02) * w / 2.0);
    let (fy, cy) = (p11 * h / 2.0, (1.0 + p12) * h / 2.0);
    let (near, far) = camera.near_far();
    let mean = g.positions[i].as_dvec3();
    let e = camera.view.transform_point3(mean);
    let d = -e.z;
    if !(d > near && d < far) {
        return None;
    }
    let xd = (e.x / d).clamp((p02 - 1.3) / p00, (p02 + 1.3) / p00);
    let yd = (e.y / d).clamp((p12 - 1.3) / p11, (p12 + 1.3) / p11);
    let j0 = DVec3::new(fx / d, 0.0, fx * xd / d);
    let j1 = DVec3::new(0.0, -fy / d, -fy * yd / d);
    let q = g.rotations[i];
    let r = rotation_matrix(DQuat::from_xyzw(
        q.x as f64, q.y as f64, q.z as f64, q.w as f64,
    ));
    let m = r * DMat3::from_diagonal(g.scales[i].as_dvec3());
    let sigma = m * m.transpose();
    let wm = DMat3::from_mat4(camera.view);
    let eye_sigma = wm * sigma * wm.transpose();
    let a = j0.dot(eye_sigma * j0) + 0.3;
    let b = j0.dot(eye_sigma * j1);
    let c = j1.dot(eye_sigma * j1) + 0.3;
    let det = a * c - b * b;
    if det <= 0.0 {
        return None;
    }
    let mid = 0.5 * (a + c);
    let spread = (mid * mid - det).max(0.1).sqrt();
    let radius = (3.0 * (mid + spread).max(mid - spread).sqrt()).ceil();
    let centre = camera.view.inverse().transform_point3(DVec3::ZERO);
    let dir = (mean - centre).normalize();
    let k = (g.sh_degree as usize + 1).pow(2);
    let sum = sh_sum(g.sh_degree, &g.sh[i * k..(i + 1) * k], dir);
    Some(Projected {
        depth: d,
        u: cx + fx * e.x / d,
        v: cy - fy * e.y / d,
        conic: [c / det, -b / det, a / det],
        radius,
        color: (sum + DVec3::splat(0.5)).max(DVec3::ZERO),
        opacity: g.opacities[i] as f64,
    })
}

/// Render `g` as seen by `camera` into a `size` image over `background` (the rules above).
pub fn render(
    g: &Gaussians,
    camera: &ViewCamera,
    size: [u32; 2],
    background: [f32; 4],
) -> ReferenceImage {
    let mut splats: Vec<Projected> = (0..g.positions.len())
        .filter_map(|i| project(g, i, camera, size))
        .collect();
    splats.sort_by(|a, b| a.depth.total_cmp(&b.depth));
    let pixels = (size[0] * size[1]) as usize;
    let mut color = vec![DVec3::ZERO; pixels];
    let mut transmittance = vec![1.0f64; pixels];
    let mut done = vec![false; pixels];
    for s in &splats {
        // Pixel centres x + 0.5 within [u − r, u + r].
        let range = |centre: f64, extent: u32| {
            let lo = (centre - s.radius - 0.5).ceil().max(0.0);
            let hi = (centre + s.radius - 0.5).floor().min(extent as f64 - 1.0);
            (lo as i64, hi as i64)
        };
        let (x0, x1) = range(s.u, size[0]);
        let (y0, y1) = range(s.v, size[1]);
        for y in y0..=y1 {
            for x in x0..=x1 {
                let at = (y as u32 * size[0] + x as u32) as usize;
                if done[at] {
                    continue;
                }
                let (dx, dy) = (x as f64 + 0.5 - s.u, y as f64 + 0.5 - s.v);
                let [ca, cb, cc] = s.conic;
                let power = -0.5 * (ca * dx * dx + cc * dy * dy) - cb * dx * dy;
                if power > 0.0 {
                    continue;
                }
                let alpha = (s.opacity * power.exp()).min(0.99);
                if alpha < 1.0 / 255.0 {
                    continue;
                }
                let t = transmittance[at];
                let next = t * (1.0 - alpha);
                if next < 1e-4 {
                    done[at] = true;
                    continue;
                }
                color[at] += s.color * alpha * t;
                transmittance[at] = next;
            }
        }
    }
    let bg = DVec3::new(
        background[0] as f64,
        background[1] as f64,
        background[2] as f64,
    );
    let rgba = color
        .iter()
        .zip(&transmittance)
        .map(|(c, &t)| {
            let out = *c + bg * t;
            [out.x as f32, out.y as f32, out.z as f32, (1.0 - t) as f32]
        })
        .collect();
    ReferenceImage { size, rgba }
}
