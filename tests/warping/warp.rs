//! Depth-image warping of reference views (`--method warp`) for meshes, points and volumes:
//! with every view a reference it is the N-pass bit for bit (both paths); with fewer it stays
//! within its measured accuracy; disocclusions are filled from the background side; bad
//! options are refused by name.

use crate::common;

use autostereo::frame::Frame;
use autostereo::image_io::compare;
use autostereo::mesh::MeshNPass;
use autostereo::mesh::{Mesh, MeshBuffers};
use autostereo::points::{GroupCount, PointCloud, SplatScene};
use autostereo::points::{PointSplatter, SplatOptions};
use autostereo::render::{Method, Renderer};
use autostereo::volume::VolumeRaycaster;
use autostereo::volume::VolumeSettings;
use autostereo::warp::{ReferenceRenderer, SceneWarp, WarpOptions, WarpPath};
use glam::Vec3;

/// (display spec, image size): N = 2, 8 per pixel and per subpixel, 45.
const DISPLAYS: &[(&str, [u32; 2])] = &[
    ("slanted:2,2.5,1/3,0.1", [64, 48]),
    ("hubner8", [96, 64]),
    ("lenticular:8", [96, 64]),
    ("slanted:45,7.5,1/6,0.2", [80, 60]),
];

fn warp<S: ?Sized>(
    references: impl ReferenceRenderer<S> + 'static,
    options: WarpOptions,
) -> SceneWarp<S> {
    let device = common::gpu().device.clone();
    SceneWarp::new(&device, Box::new(references), options).unwrap()
}

fn options(references: u32, path: WarpPath) -> WarpOptions {
    WarpOptions {
        references,
        path,
        ..Default::default()
    }
}

/// With R = N every view is a reference: the warp copies it, equal to the N-pass bit for
/// bit, on both paths.
fn assert_exact_with_every_view<S: ?Sized>(
    name: &str,
    scene: &S,
    frame_of: impl Fn(&str, [u32; 2]) -> Frame,
    oracle: &mut dyn Renderer<S>,
    references: impl Fn() -> Box<dyn ReferenceRenderer<S>>,
) {
    for &(spec, size) in DISPLAYS {
        let frame = frame_of(spec, size);
        let n = frame.camera.views;
        let expected = common::render(oracle, scene, &frame);
        for path in [WarpPath::Direct, WarpPath::PerView] {
            let device = common::gpu().device.clone();
            let mut warp = SceneWarp::new(&device, references(), options(n, path)).unwrap();
            let image = common::render(&mut warp, scene, &frame);
            let diff = compare(&image, &expected).unwrap();
            if diff.max_abs_err != 0 {
                let saved = common::save_diff(&format!("warp_{name}_{n}"), &image, &expected);
                panic!("{name} {spec} {path:?}: {diff:?} ({})", saved.display());
            }
        }
    }
}

fn mesh_frame(mesh: &Mesh, spec: &str, size: [u32; 2]) -> Frame {
    common::frame(mesh.bounds().unwrap(), spec, 0.15, 1.0, size)
}

#[test]
fn mesh_warp_with_every_view_a_reference_is_the_npass() {
    let mesh = Mesh::torus_scene();
    let device = common::gpu().device.clone();
    let buffers = MeshBuffers::new(&device, &mesh).unwrap();
    let mut npass = MeshNPass::new(&device, Method::NPass).unwrap();
    assert_exact_with_every_view(
        "mesh",
        &buffers,
        |spec, size| mesh_frame(&mesh, spec, size),
        &mut npass,
        || Box::new(MeshNPass::new(&device, Method::Warp).unwrap()),
    );
}

#[test]
fn points_warp_with_every_view_a_reference_is_the_npass() {
    let (splats, _) = PointCloud::torus_scene().complete(1.0).unwrap();
    let device = common::gpu().device.clone();
    let scene = SplatScene::new(&device, &splats, GroupCount::Auto).unwrap();
    let options = SplatOptions::for_scene(&scene, 0.01);
    let mut npass = PointSplatter::new(&device, Method::NPass, options).unwrap();
    let bounds = splats.bounds().unwrap();
    assert_exact_with_every_view(
        "points",
        &scene,
        |spec, size| common::frame(bounds, spec, 0.15, 1.0, size),
        &mut npass,
        || Box::new(PointSplatter::new(&device, Method::Warp, options).unwrap()),
    );
}

#[test]
fn volume_warp_with_every_view_a_reference_is_the_npass() {
    let (scene, bounds) = common::head_scene();
    let device = common::gpu().device.clone();
    let mut npass =
        VolumeRaycaster::new(&device, Method::NPass, VolumeSettings::default()).unwrap();
    assert_exact_with_every_view(
        "volume",
        &scene,
        |spec, size| common::frame(bounds, spec, 0.15, 1.0, size),
        &mut npass,
        || {
            Box::new(
                VolumeRaycaster::new(&device, Method::Warp, VolumeSettings::default()).unwrap(),
            )
        },
    );
}

/// Fewer references approximate: error falls as R grows, and R = 2 at N = 8 stays above the
/// bound measured on this scene (36.4 dB at 128², hubner8, both backends; docs/WARPING.md has
/// the dragon).
#[test]
fn mesh_warp_accuracy_grows_with_references() {
    let mesh = Mesh::torus_scene();
    let device = common::gpu().device.clone();
    let buffers = MeshBuffers::new(&device, &mesh).unwrap();
    let frame = mesh_frame(&mesh, "hubner8", [128, 128]);
    let mut npass = MeshNPass::new(&device, Method::NPass).unwrap();
    let expected = common::render(&mut npass, &buffers, &frame);
    let psnr: Vec<f64> = [1, 2, 4, 8]
        .iter()
        .map(|&r| {
            let references = MeshNPass::new(&device, Method::Warp).unwrap();
            let mut warp = warp(references, options(r, WarpPath::Direct));
            let image = common::render(&mut warp, &buffers, &frame);
            compare(&image, &expected).unwrap().psnr_db
        })
        .collect();
    assert!(psnr.windows(2).all(|w| w[0] < w[1]), "{psnr:?}");
    assert!(psnr[1] >= 34.0, "R = 2: {psnr:?}");
    assert_eq!(psnr[3], 1000.0, "R = N is exact: {psnr:?}");
}

/// A flat square in front of a larger one, warped from the centre view only: the outer views
/// see the back square beside the front one where the centre saw the front one. Those
/// disocclusions must be filled with the back square's colour (no background-coloured cracks
/// inside the back square), and the hole mask must mark them.
#[test]
fn disocclusions_are_filled_from_the_background_side() {
    let square = |z: f32, half: f32, color: [f32; 4]| {
        let corners = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)];
        let positions: Vec<Vec3> = corners
            .iter()
            .map(|&(x, y)| Vec3::new(x * half, y * half, z))
            .collect();
        Mesh {
            normals: vec![Vec3::Z; 4],
            colors: vec![color; 4],
            indices: vec![0, 1, 2, 0, 2, 3],
            positions,
            ..Mesh::default()
        }
    };
    let back = square(-0.5, 1.0, [1.0, 0.0, 0.0, 1.0]);
    let front = square(0.5, 0.3, [0.0, 1.0, 0.0, 1.0]);
    let mut scene = back.clone();
    let base = scene.positions.len() as u32;
    scene.positions.extend(&front.positions);
    scene.normals.extend(&front.normals);
    scene.colors.extend(&front.colors);
    scene.indices.extend(front.indices.iter().map(|i| i + base));
    let device = common::gpu().device.clone();
    let buffers = MeshBuffers::new(&device, &scene).unwrap();
    // A wide separation, so the outer views move the front square by several pixels.
    let frame = common::frame(scene.bounds().unwrap(), "lenticular:8", 0.6, 1.0, [96, 96]);
    let one = options(1, WarpPath::Direct);
    let references = MeshNPass::new(&device, Method::Warp).unwrap();
    let image = common::render(&mut warp(references, one), &buffers, &frame);
    let references = MeshNPass::new(&device, Method::Warp).unwrap();
    let holes = WarpOptions {
        hole_mask: true,
        ..one
    };
    let mask = common::render(&mut warp(references, holes), &buffers, &frame);
    // The back square's interior on screen, a margin away from its edges (the edges of the
    // image have no source in the outer views): pixels where the back square is the
    // background of every view.
    let mut npass = MeshNPass::new(&device, Method::NPass).unwrap();
    let oracle = common::render(&mut npass, &buffers, &frame);
    let (w, h) = (frame.size[0] as usize, frame.size[1] as usize);
    let mut inside = 0;
    let mut filled = 0;
    for y in h / 4..3 * h / 4 {
        for x in w / 4..3 * w / 4 {
            let i = (y * w + x) * 3;
            let seen = &oracle.data[i..i + 3];
            if seen.iter().all(|&v| v < 8) {
                continue; // background in the oracle too
            }
            inside += 1;
            let px = &image.data[i..i + 3];
            assert!(
                px.iter().any(|&v| v > 32),
                "a background-coloured crack at ({x}, {y}): {px:?} (oracle {seen:?})"
            );
            filled += usize::from(mask.data[i] >= 128);
        }
    }
    assert!(inside > w * h / 8, "the squares are not in view: {inside}");
    assert!(filled > 0, "no disocclusion was marked");
}

#[test]
fn bad_references_are_refused_by_name() {
    let mesh = Mesh::torus_scene();
    let device = common::gpu().device.clone();
    let buffers = MeshBuffers::new(&device, &mesh).unwrap();
    let frame = mesh_frame(&mesh, "lenticular:8", [32, 32]);
    for r in [0, 9] {
        let references = MeshNPass::new(&device, Method::Warp).unwrap();
        let mut warp = warp(references, options(r, WarpPath::Direct));
        let ctx = common::gpu();
        let error = warp
            .prepare(&ctx.device, &ctx.queue, &buffers, &frame)
            .unwrap_err()
            .to_string();
        assert!(
            error.contains("references") && error.contains('8'),
            "{error}"
        );
    }
    // A reference renderer is not a frame renderer.
    let mut references = MeshNPass::new(&device, Method::Warp).unwrap();
    let ctx = common::gpu();
    let error = references
        .prepare(&ctx.device, &ctx.queue, &buffers, &frame)
        .unwrap_err()
        .to_string();
    assert!(error.contains("SceneWarp"), "{error}");
    let bad = WarpOptions {
        hole_gap: 0.5,
        ..Default::default()
    };
    let references = Box::new(MeshNPass::new(&device, Method::Warp).unwrap());
    let error = SceneWarp::new(&ctx.device, references, bad).err().unwrap();
    assert!(error.to_string().contains("hole gap"), "{error}");
}
