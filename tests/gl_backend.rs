//! The GL path (llvmpipe here) renders too: its WGSL mask equals the Rust mask and its N-pass
//! image matches the default adapter's.

mod common;

use autostereo::camera::MultiViewCamera;
use autostereo::display::{Display, DisplayKind};
use autostereo::frame::Frame;
use autostereo::gpu::{GpuContext, GpuOptions};
use autostereo::image_io::{compare, RgbImage};
use autostereo::mesh::{Mesh, MeshBuffers};
use autostereo::render::{MaskImageRenderer, MeshBaseline, MeshBaselineMethod, Renderer};
use autostereo::target::SpatialTarget;

fn render_npass(ctx: &GpuContext, frame: &Frame, mesh: &Mesh) -> RgbImage {
    let buffers = MeshBuffers::new(&ctx.device, mesh).unwrap();
    let target = SpatialTarget::new(&ctx.device, frame.size).unwrap();
    let mut renderer = MeshBaseline::new(&ctx.device, MeshBaselineMethod::NPass).unwrap();
    renderer
        .render(&ctx.device, &ctx.queue, &buffers, frame, &target)
        .unwrap();
    target.read(&ctx.device, &ctx.queue).unwrap()
}

#[test]
fn gl_backend_renders_masks_and_meshes() {
    let gl = GpuContext::new(&GpuOptions {
        backends: Some(wgpu::Backends::GL),
        adapter_name: None,
    })
    .expect("the GL backend (llvmpipe) must be available");
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
