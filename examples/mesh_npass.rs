//! Render the generated torus scene for the paper's 8-view display with the N-pass baseline,
//! then save the spatial image and what view 3 sees.
//!
//! `cargo run --release --example mesh_npass -- out.png`

use anyhow::Result;
use autostereo::camera::MultiViewCamera;
use autostereo::display::Display;
use autostereo::frame::Frame;
use autostereo::gpu::GpuContext;
use autostereo::mesh::{Mesh, MeshBuffers};
use autostereo::render::{MeshBaseline, MeshBaselineMethod, Renderer};
use autostereo::target::SpatialTarget;
use autostereo::views::extract_view;

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

    // GPU resources borrowed from the caller's device.
    let buffers = MeshBuffers::new(&ctx.device, &mesh)?;
    let target = SpatialTarget::new(&ctx.device, size)?;
    let mut renderer = MeshBaseline::new(&ctx.device, MeshBaselineMethod::NPass)?;
    renderer.render(&ctx.device, &ctx.queue, &buffers, &frame, &target)?;

    let spatial = target.read(&ctx.device, &ctx.queue)?;
    spatial.save_png(out.as_ref())?;
    extract_view(&spatial, &frame.display.mask(), 3).save_png("view3.png".as_ref())?;
    println!("wrote {out} and view3.png");
    Ok(())
}
