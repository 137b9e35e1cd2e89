//! Numerical stability at the extremes, for every primitive (mesh, volume, splats): focal plane
//! at the near plane and at 1000× the scene depth, separation 0 and absurd, N = 1 … 256, a window
//! deep inside an 8K panel, geometry at 1000·fd and across the near plane, coordinates around
//! 10⁶, degenerate primitives. Each single-pass image is compared with its N-pass oracle; a
//! non-black background makes any NaN/Inf (written as 0) show up as an error.
//!
//! `cargo test --test stability -- --nocapture` prints the table of docs/STABILITY.md.

use crate::common;

use autostereo::camera::{Bounds, MultiViewCamera};
use autostereo::display::Display;
use autostereo::frame::Frame;
use autostereo::image_io::{compare, ImageDiff, RgbImage};
use autostereo::mesh::{Mesh, MeshBuffers};
use autostereo::points::{GroupCount, PointCloud, SplatScene};
use autostereo::render::{Method, Renderer};
use autostereo::target::SpatialTarget;
use autostereo::volume::VolumeScene;
use autostereo::volume::{generate, TransferFunction, Volume};
use autostereo::{AnyRenderer, AnyScene, RendererOptions};
use glam::{Mat4, Vec3};

const SIZE: [u32; 2] = [48, 40];
const BACKGROUND: [f32; 4] = [0.2, 0.4, 0.6, 1.0];

/// One primitive's scene, uploaded.
struct Primitive {
    name: &'static str,
    scene: AnyScene,
    /// How the N-pass oracle renders: the volume's single pass skips empty space, its oracle
    /// marches every segment, so the extremes test skipping too.
    oracle: RendererOptions,
    bounds: Bounds,
}

fn mesh(offset: Vec3, degenerate: bool) -> Primitive {
    let mut mesh = Mesh::torus(1.0, 0.35, 24, 12, [0.9, 0.6, 0.3, 1.0]);
    if degenerate {
        // Zero-area triangles: a point and a line, plus slivers.
        let base = mesh.positions.len() as u32;
        for p in [
            Vec3::ZERO,
            Vec3::ZERO,
            Vec3::X,
            Vec3::X * 2.0,
            Vec3::new(0.0, 1e-7, 0.0),
        ] {
            mesh.positions.push(p);
            mesh.normals.push(Vec3::Z);
            mesh.colors.push([1.0; 4]);
        }
        mesh.indices.extend([
            base,
            base + 1,
            base + 1,
            base,
            base + 2,
            base + 3,
            base,
            base + 2,
            base + 4,
        ]);
    }
    mesh.transform(Mat4::from_translation(offset) * Mat4::from_rotation_x(0.8));
    let ctx = common::gpu();
    Primitive {
        name: "mesh",
        bounds: mesh.bounds().unwrap(),
        scene: AnyScene::Mesh(MeshBuffers::new(&ctx.device, &mesh).unwrap()),
        oracle: RendererOptions::new(Method::NPass),
    }
}

fn volume(offset: Vec3, degenerate: bool) -> Primitive {
    let volume = if degenerate {
        Volume::new([1, 1, 1], [1.0; 3], vec![0.9]).unwrap()
    } else {
        generate::ct_head(16).unwrap()
    };
    let model = Mat4::from_translation(offset) * Mat4::from_rotation_y(0.5);
    let b = volume.bounds();
    let corners = (0..8).map(|i| {
        let pick = |bit: u32, lo: f32, hi: f32| if i & bit != 0 { hi } else { lo };
        model.transform_point3(Vec3::new(
            pick(1, b.min.x, b.max.x),
            pick(2, b.min.y, b.max.y),
            pick(4, b.min.z, b.max.z),
        ))
    });
    let ctx = common::gpu();
    let tf = TransferFunction::preset("ct-skin").unwrap();
    let scene = VolumeScene::new(&ctx.device, &ctx.queue, &volume, tf, model).unwrap();
    let mut oracle = RendererOptions::new(Method::NPass);
    oracle.volume.settings.skip_empty = false;
    Primitive {
        name: "volume",
        bounds: Bounds::of_points(corners).unwrap(),
        scene: AnyScene::Volume(Box::new(scene)),
        oracle,
    }
}

fn points(offset: Vec3, degenerate: bool) -> Primitive {
    let mut cloud = PointCloud::sphere(1500, Vec3::ZERO, 1.0, Some(0.8));
    if degenerate {
        // Grazing splats (normals ⟂ the view direction), coincident points, zero radius.
        let n = cloud.len();
        for (i, normal) in cloud.normals.iter_mut().flatten().enumerate() {
            if i % 3 == 0 {
                *normal = Vec3::new(normal.x, normal.y, 0.0)
                    .try_normalize()
                    .unwrap_or(Vec3::X);
            }
        }
        let radii = cloud.radii.as_mut().unwrap();
        radii[n / 2] = 0.0;
        let p = cloud.positions[7];
        cloud.positions[8] = p;
        cloud.positions[9] = p;
    }
    for p in &mut cloud.positions {
        *p += offset;
    }
    let (splats, _) = cloud.complete(1.0).unwrap();
    let ctx = common::gpu();
    Primitive {
        name: "points",
        bounds: splats.bounds().unwrap(),
        scene: AnyScene::Points(SplatScene::new(&ctx.device, &splats, GroupCount::Auto).unwrap()),
        oracle: RendererOptions::new(Method::NPass),
    }
}

/// Single pass and N-pass images of `p` for `frame`.
fn render_pair(p: &Primitive, frame: &Frame) -> (RgbImage, RgbImage) {
    let ctx = common::gpu();
    let (device, queue) = (&ctx.device, &ctx.queue);
    let target = SpatialTarget::new(device, frame.size).unwrap();
    let run = |options: &RendererOptions| -> RgbImage {
        AnyRenderer::new(device, &p.scene, options)
            .unwrap()
            .render(device, queue, &p.scene, frame, &target)
            .unwrap();
        target.read(device, queue).unwrap()
    };
    (
        run(&RendererOptions::new(Method::SinglePass)),
        run(&p.oracle),
    )
}

/// An extreme: how it changes the default frame.
struct Extreme {
    name: &'static str,
    display: &'static str,
    origin: [i32; 2],
    /// (camera, bounds radius) → modified camera.
    camera: fn(&mut MultiViewCamera, f32),
}

fn extremes() -> Vec<Extreme> {
    let e = |name, display, camera| Extreme {
        name,
        display,
        origin: [0, 0],
        camera,
    };
    vec![
        e("default", "hubner8", |_, _| {}),
        e("focal at near plane", "hubner8", |c, _| {
            c.focal_distance = c.near * 1.0001
        }),
        e("focal at 1000× depth", "hubner8", |c, r| {
            c.focal_distance = 1000.0 * 2.0 * r
        }),
        e("separation 0", "hubner8", |c, _| c.separation = 0.0),
        e("separation 100× radius", "hubner8", |c, r| {
            c.separation = 100.0 * r
        }),
        e("N = 1", "lenticular:1", |_, _| {}),
        e("N = 2", "lenticular:2", |_, _| {}),
        e("N = 256 (subpixel)", "slanted:256,8,2/3,7/6", |_, _| {}),
        Extreme {
            name: "8K panel, window at (7000, 4000)",
            display: "hubner8",
            origin: [7000, 4000],
            camera: |_, _| {},
        },
        // Separation scaled with fd, else every view's parallax puts the scene off screen.
        e("geometry at 1000·fd", "hubner8", |c, _| {
            c.focal_distance /= 1000.0;
            c.separation /= 1000.0;
        }),
        e("crossing the near plane", "hubner8", |c, _| {
            c.near = c.focal_distance
        }),
    ]
}

fn frame_for(bounds: Bounds, extreme: &Extreme) -> Frame {
    let display = Display::parse(extreme.display)
        .unwrap()
        .with_origin(extreme.origin);
    let mut camera = MultiViewCamera::framing(
        bounds,
        display.views(),
        None,
        0.6,
        SIZE[0] as f32 / SIZE[1] as f32,
    )
    .unwrap();
    (extreme.camera)(&mut camera, bounds.radius());
    let mut frame = Frame::new(camera, display, SIZE).unwrap();
    frame.background = BACKGROUND;
    frame
}

/// Worst share of subpixels off by > 2/255 each primitive may show (exact methods; rounding
/// of different but equivalent arithmetic at silhouettes and sample boundaries).
fn bound(primitive: &str, case: &str) -> f64 {
    match (primitive, case) {
        // f32 eye coordinates of a scene 10⁶ units out keep ~0.06 units: both methods see the
        // same quantised geometry, but round it in a different order (documented bound).
        (_, "coordinates around 1e6") => 0.05,
        // The cut: the N-pass clipper and the rays' depth ≥ near test round differently there.
        (_, "crossing the near plane") => 0.005,
        _ => 0.002,
    }
}

fn check(
    p: &Primitive,
    case: &str,
    frame: &Frame,
    rows: &mut Vec<String>,
    failures: &mut Vec<String>,
) {
    let (single, npass) = render_pair(p, frame);
    let d: ImageDiff = compare(&single, &npass).unwrap();
    let lit = npass
        .data
        .chunks(3)
        .filter(|px| px != &[51, 102, 153])
        .count();
    rows.push(format!(
        "| {} | {case} | {} | {:.1} | {} | {:.4} % |",
        p.name,
        lit,
        d.psnr_db,
        d.max_abs_err,
        100.0 * d.frac_off_2
    ));
    // Every renderer here writes background (51, 102, 153) or a lit colour ≥ 1/255 per channel:
    // a 0 is a NaN/Inf that reached the target, even one the two methods share.
    let zeros = single
        .data
        .iter()
        .chain(&npass.data)
        .filter(|&&v| v == 0)
        .count();
    if zeros > 0 {
        failures.push(format!(
            "{} / {case}: {zeros} zero subpixels (NaN/Inf?)",
            p.name
        ));
    }
    if d.frac_off_2 > bound(p.name, case) {
        let path = common::save_diff(
            &format!(
                "stability-{}-{}",
                p.name,
                case.replace([' ', ',', '(', ')', '·', '×', '='], "_")
            ),
            &single,
            &npass,
        );
        failures.push(format!("{} / {case}: {d:?} ({})", p.name, path.display()));
    }
}

#[test]
fn every_primitive_is_stable_at_the_extremes() {
    let mut rows = vec![
        "| primitive | extreme | covered px (N-pass) | PSNR dB | max abs err | off > 2/255 |"
            .to_string(),
        "|---|---|---:|---:|---:|---:|".to_string(),
    ];
    let mut failures = Vec::new();
    type Make = fn(Vec3, bool) -> Primitive;
    let makers: [Make; 3] = [mesh, volume, points];
    for make in makers {
        let p = make(Vec3::ZERO, false);
        for extreme in extremes() {
            let frame = frame_for(p.bounds, &extreme);
            check(&p, extreme.name, &frame, &mut rows, &mut failures);
        }
        let far = make(Vec3::splat(1e6), false);
        let frame = frame_for(far.bounds, &extremes()[0]);
        check(
            &far,
            "coordinates around 1e6",
            &frame,
            &mut rows,
            &mut failures,
        );
        let degenerate = make(Vec3::ZERO, true);
        let frame = frame_for(degenerate.bounds, &extremes()[0]);
        check(
            &degenerate,
            "degenerate primitives",
            &frame,
            &mut rows,
            &mut failures,
        );
    }
    eprintln!("{}", rows.join("\n"));
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
