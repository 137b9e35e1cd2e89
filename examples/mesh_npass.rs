//! Render the generated torus scene for the paper's 8-view display with the N-pass baseline,
//! save the spatial image and what view 3 sees, then render the same frame with the single-pass
//! renderer and compare it with the N-pass oracle.
//!
//! `cargo run --release --example mesh_npass -- out.png`

use anyhow::Result;
use autostereo::camera::MultiViewCamera;
use autostereo::display::Display;
use autostereo::frame::Frame;
use autostereo::gpu::GpuContext;
use autostereo::image_io::compare;
use autostereo::mesh::{Mesh, MeshBuffers, Visibility};
use autostereo::render::Method;
use autostereo::views::extract_view;
use autostereo::{AnyRenderer, AnyScene, MeshOptions, Renderer, RendererOptions};

fn main() -> Result<()> {
    let out = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "spatial.png".into());
    let ctx = GpuContext::new(&Default::default())?;
    println!("adapter: {}", ctx.adapter_label());

    // Scene and display.
    let mesh = Mesh::torus_scene();
    let display = Display::parse("hubner8")?;
    let size = [512, 512];

    // Camera: frame the bounding box; focal plane through its centre; 8 views.
    let bounds = mesh.bounds().expect("non-empty mesh");
    let camera = MultiViewCamera::framing(bounds, display.views(), None, 30f32.to_radians(), 1.0)?;
    let frame = Frame::new(camera, display, size)?;

    // GPU resources borrowed from the caller's device; one renderer type for every method.
    let scene = AnyScene::Mesh(MeshBuffers::new(&ctx.device, &mesh)?);
    let mut npass = AnyRenderer::new(&ctx.device, &scene, &RendererOptions::new(Method::NPass))?;
    let spatial = npass.render_image(&ctx.device, &ctx.queue, &scene, &frame)?;
    spatial.save_png(out.as_ref())?;
    extract_view(&spatial, &frame.display.mask(), 3).save_png("view3.png".as_ref())?;
    println!("wrote {out} and view3.png");

    // The single pass: same frame, one geometry pass; the best exact visibility mode this
    // adapter supports.
    let visibility = Visibility::best_exact(&ctx.device);
    let options = RendererOptions {
        mesh: MeshOptions {
            visibility: Some(visibility),
            ..MeshOptions::default()
        },
        ..RendererOptions::new(Method::SinglePass)
    };
    let mut single_pass = AnyRenderer::new(&ctx.device, &scene, &options)?;
    let image = single_pass.render_image(&ctx.device, &ctx.queue, &scene, &frame)?;
    let diff = compare(&image, &spatial)?;
    println!(
        "single pass ({visibility:?}) vs N-pass: PSNR {:.1} dB, max abs error {}",
        diff.psnr_db, diff.max_abs_err
    );
    Ok(())
}
