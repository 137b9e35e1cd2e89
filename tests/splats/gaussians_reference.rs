//! The CPU reference of the 3D Gaussian splatting rules (tests/common/gaussians_reference.rs),
//! checked on cases whose images are known in closed form: one isotropic Gaussian (peak and
//! falloff), the occlusion order of two, Gaussians behind the camera and before the near
//! plane, and the library camera's skewed views (pixel mapping, zero disparity on the focal
//! plane).

use crate::common;

use autostereo::camera::{Bounds, CameraModel, MultiViewCamera};
use autostereo::gaussians::sh::dc_from_color;
use autostereo::gaussians::Gaussians;
use common::gaussians_reference::{render, ReferenceImage, ViewCamera};
use glam::{DVec3, Mat4, Quat, Vec3};

const BACKGROUND: [f32; 4] = [0.1, 0.2, 0.3, 1.0];

/// Isotropic degree-0 Gaussians of `sigma` at `positions` with `colors` (rgb) and `opacity`.
fn gaussians(positions: &[Vec3], colors: &[[f32; 3]], sigma: f32, opacity: f32) -> Gaussians {
    Gaussians {
        positions: positions.to_vec(),
        scales: vec![Vec3::splat(sigma); positions.len()],
        rotations: vec![Quat::IDENTITY; positions.len()],
        opacities: vec![opacity; positions.len()],
        sh_degree: 0,
        sh: colors.iter().map(|c| c.map(dc_from_color)).collect(),
    }
}

/// A camera at (0, 0, 5) looking at the origin: vertical fov 0.5 rad, near 1, far 20.
fn camera(size: [u32; 2]) -> ViewCamera {
    let aspect = size[0] as f32 / size[1] as f32;
    ViewCamera {
        view: Mat4::look_at_rh(Vec3::new(0.0, 0.0, 5.0), Vec3::ZERO, Vec3::Y).as_dmat4(),
        projection: Mat4::perspective_rh(0.5, aspect, 1.0, 20.0).as_dmat4(),
    }
}

fn rgb(p: [f32; 4]) -> DVec3 {
    DVec3::new(p[0] as f64, p[1] as f64, p[2] as f64)
}

#[test]
fn one_isotropic_gaussian_peak_and_falloff() {
    let size = [65, 65];
    let color = [0.8, 0.4, 0.2];
    let g = gaussians(&[Vec3::ZERO], &[color], 0.1, 0.9);
    let image = render(&g, &camera(size), size, BACKGROUND);
    // Pixel 32's centre (32.5) is the image centre: the peak, α = 0.9.
    let bg = rgb(BACKGROUND);
    let c = DVec3::new(0.8, 0.4, 0.2);
    let peak = image.pixel(32, 32);
    let want = c * 0.9 + bg * 0.1;
    assert!(
        (rgb(peak) - want).abs().max_element() < 1e-6,
        "{peak:?} vs {want}"
    );
    assert!((peak[3] - 0.9).abs() < 1e-6);
    // σ in pixels: fx·σ/d with fx = (H/2)/tan(fov/2); the 2D variance adds 0.3 px².
    let fx = 32.5 / (0.25f64).tan();
    let variance = (fx * 0.1 / 5.0).powi(2) + 0.3;
    // graphdeco's radius: 3√λ_max with λ_max = mid + √max(0.1, mid² − det) (isotropic: √0.1).
    let radius = (3.0 * (variance + 0.1f64.sqrt()).sqrt()).ceil();
    for k in 1..=radius as u32 {
        let alpha = 0.9 * (-0.5 * (k * k) as f64 / variance).exp();
        let want = if alpha < 1.0 / 255.0 {
            bg
        } else {
            c * alpha + bg * (1.0 - alpha)
        };
        for p in [image.pixel(32 + k, 32), image.pixel(32, 32 - k)] {
            assert!(
                (rgb(p) - want).abs().max_element() < 1e-6,
                "offset {k}: {p:?} vs {want}"
            );
        }
    }
    // Beyond the 3σ square: background, nothing covered.
    let outside = 32 + radius as u32 + 1;
    assert_eq!(image.pixel(outside, 32)[3], 0.0);
    assert!((rgb(image.pixel(outside, 32)) - bg).abs().max_element() < 1e-7);
    // Symmetric about the centre.
    for k in 1..6 {
        let (a, b) = (image.pixel(32 - k, 32 + k), image.pixel(32 + k, 32 - k));
        assert!((rgb(a) - rgb(b)).length() < 1e-9);
    }
}

#[test]
fn the_nearer_gaussian_covers_the_farther_in_any_order() {
    let size = [33, 33];
    let (red, blue) = ([1.0, 0.0, 0.0], [0.0, 0.0, 1.0]);
    let near = Vec3::new(0.0, 0.0, 1.0);
    let far = Vec3::new(0.0, 0.0, -1.0);
    // Listed far first: the renderer sorts by eye depth.
    let g = gaussians(&[far, near], &[blue, red], 0.2, 1.0);
    let image = render(&g, &camera(size), size, BACKGROUND);
    let centre = rgb(image.pixel(16, 16));
    // α is capped at 0.99: red 0.99, blue 0.99 of what is left, then the background.
    let want = DVec3::new(0.99, 0.0, 0.0099) + rgb(BACKGROUND) * 0.0001;
    assert!(
        (centre - want).abs().max_element() < 1e-6,
        "{centre} vs {want}"
    );
    let swapped = gaussians(&[far, near], &[red, blue], 0.2, 1.0);
    let centre = rgb(render(&swapped, &camera(size), size, BACKGROUND).pixel(16, 16));
    assert!(centre.z > 0.98 && centre.x < 0.011, "{centre}");
}

#[test]
fn transmittance_stops_before_it_falls_below_1e_4() {
    let size = [17, 17];
    // Three layers of α = 0.99: after two T = 1e-4 (not below it); the third would take it
    // to 1e-6, so it is not drawn.
    let layers = [0.5, 0.0, -0.5].map(|z| Vec3::new(0.0, 0.0, z));
    let colors = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let g = gaussians(&layers, &colors, 0.3, 1.0);
    let p = render(&g, &camera(size), size, [0.0; 4]).pixel(8, 8);
    assert!(p[2] < 1e-6, "the third layer is not drawn: {p:?}");
    assert!((p[1] as f64 - 0.0099).abs() < 1e-6, "{p:?}");
}

#[test]
fn gaussians_behind_the_camera_or_before_the_near_plane_are_skipped() {
    let size = [33, 33];
    let behind = Vec3::new(0.0, 0.0, 6.0);
    let too_near = Vec3::new(0.0, 0.0, 4.5); // depth 0.5 < near = 1
    let g = gaussians(&[behind, too_near], &[[1.0; 3]; 2], 0.5, 1.0);
    let image = render(&g, &camera(size), size, BACKGROUND);
    for p in &image.rgba {
        assert_eq!(p[3], 0.0);
        assert!((rgb(*p) - rgb(BACKGROUND)).abs().max_element() < 1e-7);
    }
}

/// Skewed views of the library's camera: a Gaussian on the focal plane sits at the same pixel
/// in every view (the mapping agrees with the camera's own `project` and `focal_to_pixel`),
/// one nearer moves by its disparity, and view-dependent colour follows each view's centre.
#[test]
fn skewed_views_of_the_library_camera() {
    let size = [96, 64];
    let bounds = Bounds {
        min: Vec3::splat(-1.0),
        max: Vec3::splat(1.0),
    };
    let camera = MultiViewCamera::framing(bounds, 5, Some(0.3), 0.6, 1.5).unwrap();
    assert_eq!(camera.model, CameraModel::Skewed);
    let eye_at = |p: Vec3| camera.eye_from_world.transform_point3(p);
    let on_focal = Vec3::new(0.3, 0.2, 0.0);
    let nearer = Vec3::new(-0.4, -0.3, 1.0);
    for i in 0..5 {
        let view = ViewCamera::of(&camera, i);
        for p in [on_focal, nearer] {
            let g = gaussians(&[p], &[[1.0; 3]], 0.02, 0.99);
            let image = render(&g, &view, size, [0.0; 4]);
            let want = camera.focal_to_pixel(camera.project(i, eye_at(p)), size);
            let (at, _) = image
                .rgba
                .iter()
                .enumerate()
                .max_by(|a, b| a.1[3].total_cmp(&b.1[3]))
                .unwrap();
            let got = [(at % 96) as f32 + 0.5, (at / 96) as f32 + 0.5];
            assert!(
                (got[0] - want.x).abs() <= 0.5 && (got[1] - want.y).abs() <= 0.5,
                "view {i}: peak at {got:?}, camera says {want}"
            );
        }
        // The camera centre is the view's: view i sits at vd_i along the centre's eye x.
        let centre = view.view.inverse().transform_point3(DVec3::ZERO);
        let want = camera.eye_from_world.inverse().transform_point3(Vec3::new(
            camera.view_offset(i),
            0.0,
            0.0,
        ));
        assert!((centre - want.as_dvec3()).length() < 1e-4);
    }
    // Degree 1 with only the x coefficient: the colour differs between the outer views.
    let mut g = gaussians(&[Vec3::ZERO], &[[0.5; 3]], 0.05, 0.99);
    g.sh_degree = 1;
    g.sh = vec![[0.0; 3], [0.0; 3], [0.0; 3], [1.0; 3]];
    let shade = |i: u32| {
        let image: ReferenceImage = render(&g, &ViewCamera::of(&camera, i), size, [0.0; 4]);
        image.pixel(48, 32)[0]
    };
    // −C1·x·c₃: from the leftmost view the mean lies towards +x (darker), from the rightmost
    // towards −x (brighter).
    let (left, right) = (shade(0), shade(4));
    assert!(right > left + 1e-3, "{left} vs {right}");
}
