//! Point splats on the GPU: single pass against the N-pass oracle (same kernel, ε and groups)
//! with normals given and estimated, focal plane in front of / through / behind, N = 2, 8, 64;
//! separation 0 against the single view; degenerate splats without NaN.

mod common;

use autostereo::camera::MultiViewCamera;
use autostereo::display::Display;
use autostereo::frame::Frame;
use autostereo::image_io::{compare, RgbImage};
use autostereo::points::{GroupCount, PointCloud, SplatScene, Splats};
use autostereo::render::{PointSplatter, Renderer, SplatDepth, SplatMethod, SplatOptions};
use autostereo::target::SpatialTarget;
use glam::Vec3;

const SIZE: [u32; 2] = [96, 80];

fn splats(cloud: &PointCloud) -> Splats {
    cloud.complete(1.0).unwrap().0
}

fn scene(splats: &Splats) -> SplatScene {
    let ctx = common::gpu();
    SplatScene::new(&ctx.device, splats, GroupCount::Auto).unwrap()
}

/// A frame looking at `splats` with `separation_share` × radius between views and the focal
/// plane at `focal_scale` × the framing distance.
fn frame(splats: &Splats, spec: &str, separation_share: f32, focal_scale: f32) -> Frame {
    let display = Display::parse(spec).unwrap();
    let bounds = splats.bounds().unwrap();
    let mut camera = MultiViewCamera::framing(
        bounds,
        display.views(),
        Some(separation_share * bounds.radius()),
        0.6,
        SIZE[0] as f32 / SIZE[1] as f32,
    )
    .unwrap();
    camera.focal_distance *= focal_scale;
    Frame::new(camera, display, SIZE).unwrap()
}

fn render(scene: &SplatScene, frame: &Frame, method: SplatMethod, depth: SplatDepth) -> RgbImage {
    let ctx = common::gpu();
    let target = SpatialTarget::new(&ctx.device, frame.size).unwrap();
    let options = SplatOptions {
        depth,
        ..SplatOptions::for_scene(scene, 0.01)
    };
    PointSplatter::new(&ctx.device, method, options)
        .unwrap()
        .render(&ctx.device, &ctx.queue, scene, frame, &target)
        .unwrap();
    target.read(&ctx.device, &ctx.queue).unwrap()
}

fn lit(image: &RgbImage) -> usize {
    image.data.iter().filter(|&&v| v > 8).count()
}

fn torus() -> PointCloud {
    let mut t = PointCloud::torus(1.0, 0.35, 160, 48, Some(0.8));
    for p in &mut t.positions {
        *p = glam::Quat::from_rotation_x(0.9) * *p;
    }
    for n in t.normals.iter_mut().flatten() {
        *n = glam::Quat::from_rotation_x(0.9) * *n;
    }
    t
}

fn without_normals_and_radii(mut cloud: PointCloud) -> PointCloud {
    cloud.normals = None;
    cloud.radii = None;
    cloud
}

#[test]
fn exact_single_pass_matches_npass_with_normals_given_and_estimated() {
    let clouds = [
        (
            "sphere",
            PointCloud::sphere(6000, Vec3::ZERO, 1.0, Some(0.8)),
        ),
        ("torus", torus()),
        (
            "sphere-est",
            without_normals_and_radii(PointCloud::sphere(6000, Vec3::ZERO, 1.0, None)),
        ),
        ("torus-est", without_normals_and_radii(torus())),
    ];
    for (name, cloud) in &clouds {
        let s = splats(cloud);
        let scene = scene(&s);
        for (spec, focal) in [
            ("hubner8", 0.8),
            ("hubner8", 1.0),
            ("hubner8", 1.3),
            ("slanted:64,8,0.667,1.17", 1.0),
            ("lenticular:2", 1.0),
        ] {
            let f = frame(&s, spec, 0.05, focal);
            let single = render(&scene, &f, SplatMethod::SinglePass, SplatDepth::Exact);
            let npass = render(&scene, &f, SplatMethod::NPass, SplatDepth::Exact);
            let d = compare(&single, &npass).unwrap();
            let tag = format!("points-{name}-{}-f{focal}", spec.replace([':', ','], "_"));
            eprintln!(
                "{tag}: {:.1} dB, {} groups, lit {}",
                d.psnr_db,
                scene.groups(),
                lit(&npass)
            );
            assert!(
                lit(&npass) > single.data.len() / 10,
                "{tag}: scene not in view"
            );
            if d.psnr_db < 35.0 {
                panic!(
                    "{tag}: {:.1} dB < 35 ({})",
                    d.psnr_db,
                    common::save_diff(&tag, &single, &npass).display()
                );
            }
        }
    }
}
