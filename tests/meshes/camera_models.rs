//! Camera models (`CameraModel`, `--camera`): skewed (default), parallel (skewed views
//! shifted and cropped), toe-in (turned cameras). Oracles: the N-pass with each model's
//! projection matrices, the skewed render (parallel = skewed outside the uncovered strips),
//! the closed-form projection (toe-in's vertical parallax, rasterised on the CPU).

use crate::common;

use autostereo::camera::{CameraModel, MultiViewCamera};
use autostereo::display::Display;
use autostereo::frame::Frame;
use autostereo::image_io::{compare, RgbImage};
use autostereo::mesh::{Mesh, MeshBuffers};
use autostereo::mesh::{MeshNPass, MeshSinglePass, MeshSinglePassOptions, MeshTiled, TileClip};
use autostereo::points::DEFAULT_EPSILON_FRACTION;
use autostereo::points::{GroupCount, PointCloud, SplatScene};
use autostereo::points::{PointSplatter, SplatOptions};
use autostereo::render::{Method, Renderer};
use autostereo::volume::VolumeRaycaster;
use autostereo::volume::VolumeSettings;
use autostereo::warp::{SceneWarp, WarpOptions};
use glam::{Mat4, Vec2, Vec3};

use super::npass_mesh::FD;

const SIZE: [u32; 2] = [128, 96];
const RED: [f32; 4] = [1.0, 0.0, 0.0, 1.0];

/// World = eye space: the camera at the origin looking down −z, focal plane at z = −10.
fn camera(views: u32, separation: f32, model: CameraModel) -> MultiViewCamera {
    super::npass_mesh::camera(views, separation, SIZE[0] as f32 / SIZE[1] as f32, model)
}

fn frame(spec: &str, separation: f32, model: CameraModel) -> Frame {
    let display = Display::parse(spec).unwrap();
    Frame::new(camera(display.views(), separation, model), display, SIZE).unwrap()
}

/// A torus on the focal plane, a red square in front, and a grey wall behind everything (so
/// the parallel model's uncovered strips have something to hide).
fn scene() -> Mesh {
    let mut mesh = Mesh::torus(1.5, 0.5, 48, 16, [0.5, 0.5, 0.9, 1.0]);
    mesh.transform(Mat4::from_translation(Vec3::new(0.0, 0.0, -FD)));
    mesh.append(&Mesh::rectangle([-1.6, 0.8], [-0.6, 1.8], -6.0, RED));
    mesh.append(&Mesh::rectangle(
        [-30.0, -30.0],
        [30.0, 30.0],
        -30.0,
        [0.4; 4],
    ));
    mesh
}

fn mesh_buffers(mesh: &Mesh) -> MeshBuffers {
    MeshBuffers::new(&common::gpu().device, mesh).unwrap()
}

fn single_pass() -> MeshSinglePass {
    let device = common::gpu().device.clone();
    let options = MeshSinglePassOptions {
        visibility: autostereo::mesh::Visibility::best_exact(&device),
        ..Default::default()
    };
    MeshSinglePass::new(&device, options).unwrap()
}

#[test]
fn every_model_is_the_skewed_one_when_the_views_coincide() {
    let buffers = mesh_buffers(&scene());
    let device = common::gpu().device.clone();
    let skewed = frame("hubner8", 0.0, CameraModel::Skewed);
    for (name, mut r) in [
        (
            "n-pass",
            Box::new(MeshNPass::new(&device, Method::NPass).unwrap()) as Box<dyn Renderer<_>>,
        ),
        ("single pass", Box::new(single_pass())),
    ] {
        let reference = common::render(r.as_mut(), &buffers, &skewed);
        for model in [CameraModel::Parallel, CameraModel::ToeIn] {
            let image = common::render(r.as_mut(), &buffers, &frame("hubner8", 0.0, model));
            assert_eq!(image.data, reference.data, "{model} {name} at separation 0");
        }
    }
}

/// Parallel: each view is the skewed view, except where its shifted image does not reach
/// (|x_f − vd| > W/2 at the pixel centre): there it is background.
#[test]
fn parallel_views_are_the_skewed_views_with_the_uncovered_strip_empty() {
    let buffers = mesh_buffers(&scene());
    let device = common::gpu().device.clone();
    let separation = 0.26;
    for v in [0, 2, 7] {
        let spec = format!("view:8,{v}");
        let skewed = common::render(
            &mut MeshNPass::new(&device, Method::NPass).unwrap(),
            &buffers,
            &frame(&spec, separation, CameraModel::Skewed),
        );
        let f = frame(&spec, separation, CameraModel::Parallel);
        let cam = &f.camera;
        let vd = cam.view_offset(v);
        let w = cam.focal_window().x;
        let mut strip = 0;
        for (name, mut r) in [
            (
                "n-pass",
                Box::new(MeshNPass::new(&device, Method::NPass).unwrap()) as Box<dyn Renderer<_>>,
            ),
            ("single pass", Box::new(single_pass())),
        ] {
            let image = common::render(r.as_mut(), &buffers, &f);
            strip = 0;
            for x in 0..SIZE[0] {
                let x_f = ((x as f32 + 0.5) / SIZE[0] as f32 - 0.5) * w;
                let cropped = (x_f - vd).abs() > 0.5 * w;
                strip += u32::from(cropped);
                for y in 0..SIZE[1] {
                    for c in 0..3 {
                        let expected = if cropped { 0 } else { skewed.get(x, y, c) };
                        assert_eq!(image.get(x, y, c), expected, "view {v} {name} ({x}, {y})");
                    }
                }
            }
        }
        // 13 pixels per focal-plane unit: view 0's strip is |vd| = 0.91 → 12 columns.
        let expected = (vd.abs() / w * SIZE[0] as f32).round() as u32;
        assert!(
            strip.abs_diff(expected) <= 1,
            "view {v}: strip {strip} vs {expected}"
        );
        assert!(strip > 0, "view {v}: no strip to test");
    }
}

#[test]
fn the_closed_form_projections_converge_where_each_model_says() {
    for model in CameraModel::ALL {
        let cam = camera(8, 0.5, model);
        for p in [Vec3::new(0.0, 0.0, -FD), Vec3::new(2.0, -1.5, -FD)] {
            let spread: f32 = (0..8)
                .map(|i| (cam.project(i, p) - cam.project(0, p)).length())
                .fold(0.0, f32::max);
            // Skewed and parallel: everything on the focal plane; toe-in: the focal point only.
            let converges = model != CameraModel::ToeIn || p.x == 0.0;
            assert_eq!(spread < 1e-5, converges, "{model} {p}: spread {spread}");
        }
        // The matrices agree with the closed form.
        let p = Vec3::new(1.3, 0.7, -14.0);
        for i in [0, 3, 7] {
            let clip = cam.projection(i) * p.extend(1.0);
            let ndc = Vec2::new(clip.x, clip.y) / clip.w;
            let by_matrix = ndc * cam.focal_window() * 0.5;
            let closed = cam.project(i, p);
            assert!((by_matrix - closed).length() < 1e-4, "{model} view {i}");
        }
    }
}

/// The pixels whose centres lie inside the convex quad `corners` (pixel coordinates).
fn covered(corners: &[Vec2; 4]) -> Vec<(u32, u32)> {
    let inside = |p: Vec2| {
        (0..4).all(|k| {
            let (a, b) = (corners[k], corners[(k + 1) % 4]);
            (b - a).perp_dot(p - a) >= 0.0
        }) || (0..4).all(|k| {
            let (a, b) = (corners[k], corners[(k + 1) % 4]);
            (b - a).perp_dot(p - a) <= 0.0
        })
    };
    (0..SIZE[1])
        .flat_map(|y| (0..SIZE[0]).map(move |x| (x, y)))
        .filter(|&(x, y)| inside(Vec2::new(x as f32 + 0.5, y as f32 + 0.5)))
        .collect()
}

fn mean_y(pixels: &[(u32, u32)]) -> f64 {
    pixels.iter().map(|&(_, y)| y as f64 + 0.5).sum::<f64>() / pixels.len() as f64
}

/// The focal-plane point of eye-space (x, y, −depth) in the toe-in camera at `vd`, written out:
/// the camera turned by φ = atan(vd/fd), its depth `d·cos φ − (x − vd)·sin φ`, so
/// `y_f = y·fd / (d·cos φ − (x − vd)·sin φ)` (skewed: `y_f = y·fd/d`, the same in every view).
fn toe_in_formula(x: f32, y: f32, depth: f32, vd: f32) -> Vec2 {
    let phi = (vd / FD).atan();
    let local_depth = depth * phi.cos() - (x - vd) * phi.sin();
    let local_x = (x - vd) * phi.cos() + depth * phi.sin();
    Vec2::new(local_x, y) * (FD / local_depth)
}

/// Toe-in: a marker off the vertical centre line is seen higher by the camera nearer to it.
/// The rendered marker's mean row in the two outermost views is that of the marker's corners
/// placed by [`toe_in_formula`] and rasterised on the CPU (pixel centres inside), so the
/// measured vertical parallax is the formula's; skewed cameras have none.
#[test]
fn toe_in_vertical_parallax_matches_its_formula() {
    let (lo, hi) = ([2.8, 2.0], [3.4, 2.6]);
    let depth = 14.0;
    let mut marker = Mesh::rectangle(lo, hi, -depth, RED);
    marker.append(&Mesh::rectangle(
        [-30.0, -30.0],
        [30.0, 30.0],
        -30.0,
        [0.0, 0.0, 0.3, 1.0],
    ));
    let buffers = mesh_buffers(&marker);
    let device = common::gpu().device.clone();
    let separation = 1.0;
    let mut parallax = Vec::new();
    for model in [CameraModel::Skewed, CameraModel::ToeIn] {
        let mut rows = Vec::new();
        for v in [0u32, 7] {
            let f = frame(&format!("view:8,{v}"), separation, model);
            let cam = &f.camera;
            let image = common::render(
                &mut MeshNPass::new(&device, Method::NPass).unwrap(),
                &buffers,
                &f,
            );
            let red: Vec<(u32, u32)> = (0..SIZE[1])
                .flat_map(|y| (0..SIZE[0]).map(move |x| (x, y)))
                .filter(|&(x, y)| image.get(x, y, 0) > 128 && image.get(x, y, 2) < 64)
                .collect();
            assert!(red.len() > 20, "{model} view {v}: marker not found");
            let vd = cam.view_offset(v);
            let corner = |x: f32, y: f32| {
                let focal = match model {
                    CameraModel::ToeIn => toe_in_formula(x, y, depth, vd),
                    _ => cam.project(v, Vec3::new(x, y, -depth)),
                };
                cam.focal_to_pixel(focal, SIZE)
            };
            let quad = [
                corner(lo[0], lo[1]),
                corner(hi[0], lo[1]),
                corner(hi[0], hi[1]),
                corner(lo[0], hi[1]),
            ];
            let (rendered, formula) = (mean_y(&red), mean_y(&covered(&quad)));
            assert!(
                (rendered - formula).abs() < 0.05,
                "{model} view {v}: rendered mean row {rendered:.3}, formula's {formula:.3}"
            );
            rows.push(rendered);
        }
        parallax.push(rows[1] - rows[0]);
    }
    assert!(
        parallax[0].abs() < 1e-9,
        "skewed cameras: no vertical parallax"
    );
    assert!(
        parallax[1].abs() > 2.0,
        "toe-in parallax {} px: too small to test",
        parallax[1]
    );
}

/// Every model, single pass (and for toe-in the per-view duplication) against the N-pass of
/// the same model: meshes, points, volumes.
#[test]
fn single_pass_matches_npass_for_every_camera_model() {
    let device = common::gpu().device.clone();
    let assert_close = |name: &str, image: &RgbImage, oracle: &RgbImage| {
        let diff = compare(image, oracle).unwrap();
        if diff.frac_off_2 > 0.001 {
            let path = common::save_diff(&name.replace(' ', "_"), image, oracle);
            panic!("{name}: {diff:?} (diff {})", path.display());
        }
    };
    let buffers = mesh_buffers(&scene());
    let (splats, _) = PointCloud::torus_scene().complete(1.0).unwrap();
    let points = SplatScene::new(&device, &splats, GroupCount::Auto).unwrap();
    let options = SplatOptions::for_scene(&points, DEFAULT_EPSILON_FRACTION);
    let (volume, volume_bounds) = common::head_scene();
    let mut skewed_images: Vec<RgbImage> = Vec::new();
    for model in CameraModel::ALL {
        let mut images = Vec::new();
        // Meshes.
        let f = frame("hubner8", 0.26, model);
        let oracle = common::render(
            &mut MeshNPass::new(&device, Method::NPass).unwrap(),
            &buffers,
            &f,
        );
        assert_close(
            &format!("mesh {model} single pass"),
            &common::render(&mut single_pass(), &buffers, &f),
            &oracle,
        );
        let mut tiled = MeshTiled::new(&device, TileClip::Discard).unwrap();
        assert_close(
            &format!("mesh {model} tiled"),
            &common::render(&mut tiled, &buffers, &f),
            &oracle,
        );
        images.push(oracle);
        // Points.
        let mut f = common::frame(splats.bounds().unwrap(), "hubner8", 0.3, 1.0, [96, 64]);
        f.camera.model = model;
        let splat = |m| PointSplatter::new(&device, m, options).unwrap();
        let oracle = common::render(&mut splat(Method::NPass), &points, &f);
        for m in [Method::SinglePass, Method::Tiled] {
            let image = common::render(&mut splat(m), &points, &f);
            assert_close(&format!("points {model} {m}"), &image, &oracle);
        }
        images.push(oracle);
        // Volumes.
        let mut f = common::frame(volume_bounds, "hubner8", 0.3, 1.0, [64, 64]);
        f.camera.model = model;
        let ray = |m| VolumeRaycaster::new(&device, m, VolumeSettings::default()).unwrap();
        let oracle = common::render(&mut ray(Method::NPass), &volume, &f);
        for m in [Method::SinglePass, Method::Tiled] {
            let image = common::render(&mut ray(m), &volume, &f);
            assert_close(&format!("volume {model} {m}"), &image, &oracle);
        }
        images.push(oracle);
        if model == CameraModel::Skewed {
            skewed_images = images;
        } else {
            for (image, skewed) in images.iter().zip(&skewed_images) {
                let diff = compare(image, skewed).unwrap();
                assert!(
                    diff.frac_off_2 > 0.002,
                    "{model} renders the skewed image: {diff:?}"
                );
            }
        }
    }
}

/// The warp cannot render a toe-in camera: refused naming the model (the command line's
/// refusal of it: cli/tests/accuracy/camera_models.rs).
#[test]
fn models_a_method_cannot_render_are_refused_by_the_renderer() {
    let ctx = common::gpu();
    let buffers = MeshBuffers::new(&ctx.device, &scene()).unwrap();
    let f = frame("hubner8", 0.26, CameraModel::ToeIn);
    let references = MeshNPass::new(&ctx.device, Method::Warp).unwrap();
    let mut warp =
        SceneWarp::new(&ctx.device, Box::new(references), WarpOptions::default()).unwrap();
    let error = warp
        .prepare(&ctx.device, &ctx.queue, &buffers, &f)
        .unwrap_err()
        .to_string();
    assert!(
        error.contains("toe-in") && error.contains("camera"),
        "{error}"
    );
}
