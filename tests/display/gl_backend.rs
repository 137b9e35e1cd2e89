//! The GL path (llvmpipe here) renders too: its WGSL mask equals the Rust mask and its N-pass
//! image matches the default adapter's.

use crate::common;

use autostereo::camera::MultiViewCamera;
use autostereo::display::{Display, DisplayKind};
use autostereo::frame::Frame;
use autostereo::gpu::{GpuContext, GpuOptions};
use autostereo::image_io::{compare, RgbImage};
use autostereo::mesh::MeshNPass;
use autostereo::mesh::{Mesh, MeshBuffers};
use autostereo::render::{MaskImageRenderer, Method, Renderer};
use autostereo::target::SpatialTarget;
use autostereo::volume::VolumeSettings;

/// One GL context per process, shared by the tests (docs/DESIGN.md §7: a second device from the same
/// GL adapter makes the first render zeros).
fn gl() -> std::sync::MutexGuard<'static, GpuContext> {
    static GL: std::sync::OnceLock<std::sync::Mutex<GpuContext>> = std::sync::OnceLock::new();
    GL.get_or_init(|| {
        let gl = GpuContext::new(&GpuOptions {
            backends: Some(wgpu::Backends::GL),
            adapter_name: None,
        })
        .expect("the GL backend (llvmpipe) must be available");
        std::sync::Mutex::new(gl)
    })
    .lock()
    .unwrap_or_else(|poisoned| poisoned.into_inner())
}

fn render_npass(ctx: &GpuContext, frame: &Frame, mesh: &Mesh) -> RgbImage {
    let buffers = MeshBuffers::new(&ctx.device, mesh).unwrap();
    let target = SpatialTarget::new(&ctx.device, frame.size).unwrap();
    let mut renderer = MeshNPass::new(&ctx.device, Method::NPass).unwrap();
    renderer
        .render(&ctx.device, &ctx.queue, &buffers, frame, &target)
        .unwrap();
    target.read(&ctx.device, &ctx.queue).unwrap()
}

#[test]
fn gl_backend_renders_masks_and_meshes() {
    let gl = gl();
    assert_eq!(gl.info().backend, wgpu::Backend::Gl);

    let display = Display::new(DisplayKind::Hubner8)
        .unwrap()
        .with_origin([3, 9]);
    let size = [640, 360];
    let image = MaskImageRenderer::new(&gl.device)
        .unwrap()
        .render(&gl.device, &gl.queue, &display, size)
        .unwrap();
    let mask = display.mask();
    for y in 0..size[1] {
        for x in 0..size[0] {
            for c in 0..3 {
                assert_eq!(
                    image.get(x, y, c) as u32,
                    mask.view(x, y, c),
                    "GL mask ({x},{y},{c})"
                );
            }
        }
    }

    let mesh = Mesh::torus_scene();
    let camera = MultiViewCamera::framing(mesh.bounds().unwrap(), 8, None, 0.5, 1.0).unwrap();
    let frame = Frame::new(camera, display, [128, 128]).unwrap();
    let on_gl = render_npass(&gl, &frame, &mesh);
    let reference = render_npass(&common::gpu(), &frame, &mesh);
    let diff = compare(&on_gl, &reference).unwrap();
    assert!(
        on_gl.data.iter().filter(|&&v| v > 0).count() > 1000,
        "GL image is empty"
    );
    if diff.psnr_db < 40.0 {
        panic!(
            "GL vs default adapter {diff:?}: {}",
            common::save_diff("gl", &on_gl, &reference).display()
        );
    }
}

/// Every single-pass renderer runs on GL too (meshes pick the atomic-free exact mode there) and
/// matches its N-pass oracle on the same adapter.
#[test]
fn gl_backend_runs_the_single_pass_renderers() {
    use autostereo::mesh::{MeshSinglePass, MeshSinglePassOptions, Visibility};
    use autostereo::render::Method;
    use autostereo::volume::{generate, TransferFunction};
    use autostereo::volume::{AlphaMode, VolumeRaycaster, VolumeScene, VolumeSlicer};

    let gl = gl();
    let (device, queue) = (&gl.device, &gl.queue);
    let read = |target: &SpatialTarget| target.read(device, queue).unwrap();

    let mesh = Mesh::torus_scene();
    let camera = MultiViewCamera::framing(mesh.bounds().unwrap(), 8, None, 0.5, 1.0).unwrap();
    let frame = Frame::new(camera, Display::parse("hubner8").unwrap(), [96, 96]).unwrap();
    let visibility = Visibility::best_exact(device);
    assert_eq!(visibility, Visibility::Exact, "GL has no 64-bit atomics");
    let buffers = MeshBuffers::new(device, &mesh).unwrap();
    let target = SpatialTarget::new(device, frame.size).unwrap();
    let options = MeshSinglePassOptions {
        visibility,
        ..Default::default()
    };
    MeshSinglePass::new(device, options)
        .unwrap()
        .render(device, queue, &buffers, &frame, &target)
        .unwrap();
    let single = read(&target);
    let diff = compare(&single, &render_npass(&gl, &frame, &mesh)).unwrap();
    assert!(diff.frac_off_2 <= 0.001, "GL mesh single pass: {diff:?}");

    let volume = generate::ct_head(32).unwrap();
    let tf = TransferFunction::preset("ct-skin").unwrap();
    let scene =
        VolumeScene::new(device, queue, &volume, tf, glam::Mat4::from_rotation_y(0.5)).unwrap();
    let camera = MultiViewCamera::framing(volume.bounds(), 8, None, 0.5, 1.0).unwrap();
    let frame = Frame::new(camera, Display::parse("hubner8").unwrap(), [96, 96]).unwrap();
    let render = |renderer: &mut dyn Renderer<VolumeScene>| {
        let target = SpatialTarget::new(device, frame.size).unwrap();
        renderer
            .render(device, queue, &scene, &frame, &target)
            .unwrap();
        read(&target)
    };
    let npass = render(
        &mut VolumeRaycaster::new(device, Method::NPass, VolumeSettings::default()).unwrap(),
    );
    let compute = render(
        &mut VolumeRaycaster::new(device, Method::SinglePass, VolumeSettings::default()).unwrap(),
    );
    let slices = render(
        &mut VolumeSlicer::new(device, AlphaMode::Exact, VolumeSettings::default()).unwrap(),
    );
    assert!(
        npass.data.iter().filter(|&&v| v > 8).count() > 1000,
        "GL volume is empty"
    );
    for (name, image) in [("compute", compute), ("slices", slices)] {
        let diff = compare(&image, &npass).unwrap();
        assert!(diff.psnr_db >= 45.0, "GL volume {name}: {diff:?}");
    }
}

/// Splats on GL: both depth modes' pipelines build and the exact single pass equals the GL
/// N-pass.
#[test]
fn gl_backend_splats_points() {
    use autostereo::points::{GroupCount, PointCloud, SplatScene};
    use autostereo::points::{PointSplatter, SplatDepth, SplatOptions};
    use autostereo::render::Method;

    let gl = gl();
    let (device, queue) = (&gl.device, &gl.queue);
    let (splats, _) = PointCloud::torus_scene().complete(1.0).unwrap();
    let scene = SplatScene::new(device, &splats, GroupCount::Auto).unwrap();
    let camera = MultiViewCamera::framing(splats.bounds().unwrap(), 8, None, 0.5, 1.0).unwrap();
    let frame = Frame::new(camera, Display::parse("hubner8").unwrap(), [96, 96]).unwrap();
    let render = |method, depth| {
        let options = SplatOptions {
            depth,
            ..SplatOptions::for_scene(&scene, 0.01)
        };
        let target = SpatialTarget::new(device, frame.size).unwrap();
        PointSplatter::new(device, method, options)
            .unwrap()
            .render(device, queue, &scene, &frame, &target)
            .unwrap();
        target.read(device, queue).unwrap()
    };
    let npass = render(Method::NPass, SplatDepth::Exact);
    assert!(
        npass.data.iter().filter(|&&v| v > 8).count() > 1000,
        "GL splats are empty"
    );
    let exact = compare(&render(Method::SinglePass, SplatDepth::Exact), &npass).unwrap();
    assert!(exact.psnr_db >= 45.0, "GL splats exact: {exact:?}");
    let paper = compare(&render(Method::SinglePass, SplatDepth::Paper), &npass).unwrap();
    assert!(paper.psnr_db >= 20.0, "GL splats paper: {paper:?}");
}
