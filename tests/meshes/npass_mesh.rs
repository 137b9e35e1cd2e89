//! The N-pass mesh baseline: per-view parallax measured from the images, compositing against
//! the CPU mask, and the degenerate configurations that must equal the single view.

use crate::common;

use autostereo::camera::{CameraModel, MultiViewCamera};
use autostereo::display::{Display, DisplayKind};
use autostereo::frame::Frame;
use autostereo::image_io::RgbImage;
use autostereo::mesh::MeshNPass;
use autostereo::mesh::{Mesh, MeshBuffers};
use autostereo::readback::read_texture_rgba8;
use autostereo::render::{Method, Renderer};
use autostereo::target::SpatialTarget;
use glam::{Mat4, Vec3};

const SIZE: [u32; 2] = [256, 256];
/// The focal distance of [`camera`].
pub(crate) const FD: f32 = 10.0;

/// Camera at the world origin looking down −z (world = eye space), focal plane at z = −10
/// ([`FD`]), 40° vertical field of view (tests/meshes/camera_models.rs uses it too).
pub(crate) fn camera(
    views: u32,
    separation: f32,
    aspect: f32,
    model: CameraModel,
) -> MultiViewCamera {
    MultiViewCamera {
        eye_from_world: Mat4::IDENTITY,
        views,
        separation,
        focal_distance: FD,
        fov_y: 40f32.to_radians(),
        aspect,
        near: 1.0,
        far: 40.0,
        model,
        window_offset: glam::Vec2::ZERO,
    }
}

const RED: [f32; 4] = [1.0, 0.0, 0.0, 1.0];
const GREEN: [f32; 4] = [0.0, 1.0, 0.0, 1.0];

/// A torus on the focal plane, a red square in front of it (d = 6), a green rectangle behind
/// (d = 16); both markers stay unoccluded and inside the image in every view.
fn scene() -> Mesh {
    let mut mesh = Mesh::torus(1.5, 0.5, 48, 16, [0.5, 0.5, 0.9, 1.0]);
    mesh.transform(Mat4::from_translation(Vec3::new(0.0, 0.0, -FD)));
    mesh.append(&Mesh::rectangle([-1.6, 0.8], [-0.6, 1.8], -6.0, RED));
    mesh.append(&Mesh::rectangle([3.0, -4.5], [5.0, -3.0], -16.0, GREEN));
    mesh
}

fn frame(views: u32, separation: f32) -> Frame {
    let display = Display::new(DisplayKind::Slanted {
        views,
        pitch: views as f64,
        slant: 0.5,
        phase: 0.25,
    })
    .unwrap();
    Frame::new(
        camera(views, separation, 1.0, CameraModel::default()),
        display,
        SIZE,
    )
    .unwrap()
}

fn npass() -> MeshNPass {
    MeshNPass::new(&common::gpu().device, Method::NPass).unwrap()
}

fn render(frame: &Frame, renderer: &mut MeshNPass) -> RgbImage {
    let ctx = common::gpu();
    let buffers = MeshBuffers::new(&ctx.device, &scene()).unwrap();
    let target = SpatialTarget::new(&ctx.device, frame.size).unwrap();
    renderer
        .render(&ctx.device, &ctx.queue, &buffers, frame, &target)
        .unwrap();
    target.read(&ctx.device, &ctx.queue).unwrap()
}

/// Centroid x of the pixels where channel `c` dominates the other two by 0.3.
fn centroid_x(image: &RgbImage, c: u32) -> f64 {
    let (mut sum, mut count) = (0.0, 0usize);
    for y in 0..image.height {
        for x in 0..image.width {
            let v = |k: u32| image.get(x, y, k) as i32;
            let others = (0..3).filter(|&k| k != c).map(v).max().unwrap();
            if v(c) - others > 76 {
                sum += x as f64 + 0.5;
                count += 1;
            }
        }
    }
    assert!(count > 200, "marker of channel {c} not found ({count} px)");
    sum / count as f64
}

#[test]
fn views_shift_as_the_camera_formula_predicts() {
    let views = 8;
    let frame = frame(views, 0.2);
    let mut renderer = npass();
    render(&frame, &mut renderer);
    let ctx = common::gpu();
    let layers = renderer.view_layers().expect("N-pass allocates layers");
    let cam = &frame.camera;
    let px_per_unit = SIZE[0] as f64 / cam.focal_window().x as f64;
    // (channel, left edge, right edge) of each marker, all corners at the marker's depth.
    let markers = [
        (0, Vec3::new(-1.6, 1.3, -6.0), Vec3::new(-0.6, 1.3, -6.0)),
        (1, Vec3::new(3.0, -3.7, -16.0), Vec3::new(5.0, -3.7, -16.0)),
    ];
    for (channel, left, right) in markers {
        let depth = -left.z as f64;
        let mut shifts = Vec::new();
        for i in 0..views {
            let rgba = read_texture_rgba8(&ctx.device, &ctx.queue, &layers.texture, i).unwrap();
            let measured = centroid_x(&RgbImage::from_rgba(SIZE, &rgba), channel);
            // The rasteriser covers the pixels whose centre lies in [x0, x1): their mean centre
            // is (⌈x0 − ½⌉ + ⌈x1 − ½⌉)/2. Exact, unless an edge sits on a pixel centre.
            let x0 = cam.focal_to_pixel(cam.project(i, left), SIZE).x as f64;
            let x1 = cam.focal_to_pixel(cam.project(i, right), SIZE).x as f64;
            let predicted = ((x0 - 0.5).ceil() + (x1 - 0.5).ceil()) / 2.0;
            let on_centre = |x: f64| ((x - 0.5) - (x - 0.5).round()).abs() < 1e-3;
            let tolerance = if on_centre(x0) || on_centre(x1) {
                0.5
            } else {
                1e-3
            };
            assert!(
                (measured - predicted).abs() <= tolerance,
                "marker at d={depth}, view {i}: measured x {measured:.3}, predicted {predicted:.3}"
            );
            shifts.push(measured);
        }
        // Mean per-view step = e·(1 − fd/d) in pixels: against the camera offset in front of the
        // focal plane, with it behind. Edge quantisation bounds the error by 1 px / (N − 1).
        let step = (shifts[views as usize - 1] - shifts[0]) / (views - 1) as f64;
        let expected = cam.separation as f64 * (1.0 - FD as f64 / depth) * px_per_unit;
        assert!(
            (step - expected).abs() < 1.0 / (views - 1) as f64,
            "d={depth}: step {step:.3} px vs {expected:.3}"
        );
        assert!(expected.abs() > 1.0, "the test must use a visible parallax");
    }
}

/// For N = 8, and for the layer counts wgpu's GL backend would take for a plain 2D texture
/// (N = 1) or a cube map (N = 6 square layers) unless the layers are padded: on GL both read
/// back zeros through the compositor's `texture_2d_array` (docs/DESIGN.md §7).
#[test]
fn composite_equals_cpu_mask_applied_to_the_view_layers() {
    assert_eq!(SIZE[0], SIZE[1], "square layers, as a cube map would be");
    for views in [8, 6, 1] {
        let frame = frame(views, 0.2);
        let mut renderer = npass();
        let spatial = render(&frame, &mut renderer);
        let ctx = common::gpu();
        let layers = renderer.view_layers().unwrap();
        let images: Vec<RgbImage> = (0..views)
            .map(|i| {
                RgbImage::from_rgba(
                    SIZE,
                    &read_texture_rgba8(&ctx.device, &ctx.queue, &layers.texture, i).unwrap(),
                )
            })
            .collect();
        let mask = frame.display.mask();
        let mut expected = RgbImage::new(SIZE[0], SIZE[1]);
        for y in 0..SIZE[1] {
            for x in 0..SIZE[0] {
                for c in 0..3 {
                    expected.set(x, y, c, images[mask.view(x, y, c) as usize].get(x, y, c));
                }
            }
        }
        let lit = spatial.data.iter().filter(|&&v| v > 0).count();
        assert!(lit > spatial.data.len() / 20, "N = {views}: image is empty");
        if spatial != expected {
            panic!(
                "N = {views}: composite differs from the CPU mask: {}",
                common::save_diff("composite", &spatial, &expected).display()
            );
        }
        // The layers differ from each other (otherwise this test proves nothing).
        if views > 1 {
            assert_ne!(images[0], images[views as usize - 1], "N = {views}");
        }
    }
}

#[test]
fn zero_separation_or_one_view_equals_single_view() {
    let mut renderer = npass();
    let mut single_view = MeshNPass::new(&common::gpu().device, Method::SingleView).unwrap();
    for (views, separation) in [(8, 0.0), (1, 0.3)] {
        let frame = frame(views, separation);
        let npass = render(&frame, &mut renderer);
        let single = render(&frame, &mut single_view);
        if npass != single {
            panic!(
                "N={views} e={separation}: {}",
                common::save_diff("degenerate", &npass, &single).display()
            );
        }
    }
}
