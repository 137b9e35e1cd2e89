//! 3D Gaussian splats on the GPU against the CPU reference of graphdeco's rules
//! (tests/common/gaussians_reference.rs): every N-pass view matches it, the single pass matches
//! the N-pass, the views share one depth order (asserted for skewed and parallel cameras), the
//! GPU and CPU sorts render alike, and a toe-in camera is refused with the reason.

use crate::common;

use autostereo::camera::CameraModel;
use autostereo::frame::Frame;
use autostereo::gaussians::{GaussianOptions, GaussianScene, GaussianSplatter, Gaussians, SortOn};
use autostereo::image_io::{compare, RgbImage};
use autostereo::render::{Method, Renderer};
use common::gaussians_reference::{self, ViewCamera};
use common::graphdeco::Lcg;
use glam::{Quat, Vec3};

/// `n` overlapping, anisotropic Gaussians with SH degree 3 in a unit ball.
fn scene(n: usize, seed: u64) -> Gaussians {
    let mut r = Lcg(seed);
    let mut g = Gaussians {
        sh_degree: 3,
        ..Default::default()
    };
    for _ in 0..n {
        g.positions.push(Vec3::new(
            r.range(-1.0, 1.0),
            r.range(-0.8, 0.8),
            r.range(-1.0, 1.0),
        ));
        g.scales.push(Vec3::new(
            r.range(0.02, 0.25),
            r.range(0.02, 0.12),
            r.range(0.01, 0.08),
        ));
        let axis = Vec3::new(r.range(-1.0, 1.0), r.range(-1.0, 1.0), r.range(-1.0, 1.0));
        g.rotations.push(Quat::from_axis_angle(
            axis.normalize_or(Vec3::Y),
            r.range(0.0, 6.0),
        ));
        g.opacities.push(r.range(0.3, 1.0));
        g.sh.push([r.range(-1.2, 1.2), r.range(-1.2, 1.2), r.range(-1.2, 1.2)]);
        for _ in 1..16 {
            g.sh.push([r.range(-0.3, 0.3), r.range(-0.3, 0.3), r.range(-0.3, 0.3)]);
        }
    }
    g.validate().unwrap();
    g
}

fn upload(g: &Gaussians) -> GaussianScene {
    let ctx = common::gpu();
    GaussianScene::new(&ctx.device, g).unwrap()
}

fn splatter(method: Method, sort: SortOn) -> GaussianSplatter {
    let ctx = common::gpu();
    let options = GaussianOptions {
        sort,
        ..Default::default()
    };
    GaussianSplatter::new(&ctx.device, method, options).unwrap()
}

const SIZE: [u32; 2] = [72, 48];

fn frame_for(g: &Gaussians, spec: &str, model: CameraModel) -> Frame {
    let mut frame = common::frame(g.bounds().unwrap(), spec, 0.08, 1.0, SIZE);
    frame.camera.model = model;
    frame
}

/// The reference image of view `i` of `frame`, 8 bits per channel as the GPU stores it.
fn reference_view(g: &Gaussians, frame: &Frame, i: u32) -> RgbImage {
    let image = gaussians_reference::render(
        g,
        &ViewCamera::of(&frame.camera, i),
        frame.size,
        frame.background,
    );
    let mut out = RgbImage::new(frame.size[0], frame.size[1]);
    for (o, p) in out.data.chunks_exact_mut(3).zip(&image.rgba) {
        for c in 0..3 {
            o[c] = (p[c].clamp(0.0, 1.0) * 255.0).round() as u8;
        }
    }
    out
}

#[test]
fn every_npass_view_matches_the_cpu_reference() {
    let g = scene(80, 7);
    let gpu = upload(&g);
    let mut npass = splatter(Method::NPass, SortOn::Gpu);
    for view in [0, 3, 7] {
        // view:8,V puts view V on every pixel: the N-pass's layer V at full resolution.
        let frame = frame_for(&g, &format!("view:8,{view}"), CameraModel::Skewed);
        let image = common::render(&mut npass, &gpu, &frame);
        let reference = reference_view(&g, &frame, view);
        let diff = compare(&image, &reference).unwrap();
        eprintln!("view {view}: {diff:?}");
        common::save_diff(&format!("gaussians_view{view}"), &image, &reference);
        if diff.psnr_db < 40.0 {
            common::save_diff(&format!("gaussians_view{view}"), &image, &reference);
        }
        assert!(diff.psnr_db >= 40.0, "view {view}: {diff:?}");
        // Not a blank image agreeing with a blank reference.
        let lit = reference.data.iter().filter(|&&v| v > 40).count();
        assert!(
            lit > reference.data.len() / 10,
            "view {view}: {lit} lit subpixels"
        );
    }
}

#[test]
fn the_single_pass_matches_the_npass() {
    let g = scene(80, 11);
    let gpu = upload(&g);
    let mut single = splatter(Method::SinglePass, SortOn::Gpu);
    // Every subpixel evaluating the SH itself (what scenes too large for the colour table do).
    let mut per_subpixel = {
        let ctx = common::gpu();
        let options = GaussianOptions {
            color_table: false,
            ..Default::default()
        };
        GaussianSplatter::new(&ctx.device, Method::SinglePass, options).unwrap()
    };
    let mut npass = splatter(Method::NPass, SortOn::Gpu);
    for (spec, model) in [
        ("hubner8", CameraModel::Skewed),
        ("slanted:45,7.5,1/6,0.2", CameraModel::Skewed),
        ("lenticular:8", CameraModel::Parallel),
    ] {
        let frame = frame_for(&g, spec, model);
        let a = common::render(&mut single, &gpu, &frame);
        let b = common::render(&mut npass, &gpu, &frame);
        let diff = compare(&a, &b).unwrap();
        eprintln!("{spec} {model:?}: {diff:?}");
        if diff.psnr_db < 40.0 {
            common::save_diff(&format!("gaussians_single_{spec}"), &a, &b);
        }
        assert!(diff.psnr_db >= 40.0, "{spec} {model:?}: {diff:?}");
        let c = common::render(&mut per_subpixel, &gpu, &frame);
        let diff = compare(&c, &b).unwrap();
        eprintln!("{spec} {model:?}, SH per subpixel: {diff:?}");
        assert!(
            diff.psnr_db >= 40.0,
            "{spec} {model:?}, SH per subpixel: {diff:?}"
        );
    }
}

#[test]
fn the_views_share_the_centres_depth_order() {
    let g = scene(200, 3);
    let gpu = upload(&g);
    let mut single = splatter(Method::SinglePass, SortOn::Gpu);
    for model in [CameraModel::Skewed, CameraModel::Parallel] {
        let frame = frame_for(&g, "slanted:45,7.5,1/6,0.2", model);
        let centre = frame.camera.eye_from_world;
        let order_of = |view: &glam::DMat4| {
            let mut depths: Vec<(f64, u32)> = g
                .positions
                .iter()
                .enumerate()
                .map(|(i, p)| (-view.transform_point3(p.as_dvec3()).z, i as u32))
                .collect();
            depths.sort_by(|a, b| b.0.total_cmp(&a.0));
            depths
        };
        let centre_order = order_of(&centre.as_dmat4());
        for v in 0..frame.camera.views {
            let view = ViewCamera::of(&frame.camera, v).view;
            let order = order_of(&view);
            for (a, b) in order.iter().zip(&centre_order) {
                assert_eq!(a.1, b.1, "{model:?} view {v}: another order");
                assert!(
                    (a.0 - b.0).abs() <= 1e-9 * a.0.abs(),
                    "{model:?} view {v}: depth"
                );
            }
        }
        // The GPU's one sort is that order.
        common::render(&mut single, &gpu, &frame);
        let ctx = common::gpu();
        let sorted = single.last_order(&ctx.device, &ctx.queue, &gpu).unwrap();
        let expected: Vec<u32> = centre_order.iter().map(|(_, i)| *i).collect();
        assert_eq!(sorted, expected, "{model:?}");
    }
}

#[test]
fn the_gpu_and_cpu_sorts_render_alike() {
    let g = scene(300, 5);
    let gpu = upload(&g);
    let frame = frame_for(&g, "hubner8", CameraModel::Skewed);
    let a = common::render(&mut splatter(Method::SinglePass, SortOn::Gpu), &gpu, &frame);
    let b = common::render(&mut splatter(Method::SinglePass, SortOn::Cpu), &gpu, &frame);
    let diff = compare(&a, &b).unwrap();
    assert_eq!(diff.max_abs_err, 0, "{diff:?}");
}

#[test]
fn the_single_view_is_the_centre_camera() {
    let g = scene(80, 13);
    let gpu = upload(&g);
    // Nine views: view 4 is the centre camera (offset 0).
    let lens = frame_for(&g, "lenticular:9", CameraModel::Skewed);
    let single_view = common::render(&mut splatter(Method::SingleView, SortOn::Gpu), &gpu, &lens);
    let frame = frame_for(&g, "view:9,4", CameraModel::Skewed);
    let reference = reference_view(&g, &frame, 4);
    let diff = compare(&single_view, &reference).unwrap();
    assert!(diff.psnr_db >= 40.0, "{diff:?}");
}

#[test]
fn a_toe_in_camera_is_refused_with_the_reason() {
    let g = scene(10, 1);
    let gpu = upload(&g);
    let frame = frame_for(&g, "hubner8", CameraModel::ToeIn);
    let ctx = common::gpu();
    let target = autostereo::target::SpatialTarget::new(&ctx.device, frame.size).unwrap();
    for method in [Method::SinglePass, Method::NPass] {
        let mut r = GaussianSplatter::new(&ctx.device, method, GaussianOptions::default()).unwrap();
        let e = r
            .render(&ctx.device, &ctx.queue, &gpu, &frame, &target)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("toe-in") && e.contains("skewed or parallel"),
            "{e}"
        );
    }
}

#[test]
fn methods_without_a_gaussian_path_are_refused_by_name() {
    let ctx = common::gpu();
    for method in [Method::Layered, Method::Mrt, Method::Warp] {
        let e = GaussianSplatter::new(&ctx.device, method, GaussianOptions::default())
            .err()
            .unwrap()
            .to_string();
        assert!(
            e.contains(method.name()) && e.contains("single-pass"),
            "{e}"
        );
    }
}

#[test]
fn the_tiled_quilt_matches_the_npass() {
    let g = scene(80, 17);
    let gpu = upload(&g);
    let mut tiled = splatter(Method::Tiled, SortOn::Gpu);
    let mut npass = splatter(Method::NPass, SortOn::Gpu);
    for scale in [1.0, 0.5] {
        let mut frame = frame_for(&g, "slanted:45,7.5,1/6,0.2", CameraModel::Skewed);
        frame.view_scale = [scale; 2];
        let a = common::render(&mut tiled, &gpu, &frame);
        let b = common::render(&mut npass, &gpu, &frame);
        let diff = compare(&a, &b).unwrap();
        eprintln!("tiled at view scale {scale}: {diff:?}");
        assert!(diff.psnr_db >= 40.0, "view scale {scale}: {diff:?}");
        // The quilt holds every view in its tile.
        let layout = &tiled
            .atlas()
            .expect("the tiled method renders a quilt")
            .layout;
        assert_eq!(layout.views, 45);
        assert_eq!(layout.tile, frame.view_size());
    }
}
