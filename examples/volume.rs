//! The volume API in brief: a built-in data set (or a file), a transfer function, the paper's
//! 8-view display, one single-pass frame, and the N-pass oracle to compare with.
//!
//! `cargo run --release --example volume -- [FILE.nrrd|FILE.den] [out.png]`

use anyhow::Result;
use autostereo::camera::MultiViewCamera;
use autostereo::display::Display;
use autostereo::frame::Frame;
use autostereo::gpu::GpuContext;
use autostereo::image_io::compare;
use autostereo::render::{Method, Renderer};
use autostereo::target::SpatialTarget;
use autostereo::volume::VolumeSettings;
use autostereo::volume::{load, phantom, TransferFunction};
use autostereo::volume::{VolumeRaycaster, VolumeScene};
use glam::Mat4;

fn main() -> Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let ctx = GpuContext::new(&Default::default())?;
    println!("adapter: {}", ctx.adapter_label());

    // Data: a file (NRRD, .den) or the built-in CT-like head.
    let volume = match args.first() {
        Some(path) => load::load_any(path.as_ref())?,
        None => phantom::ct_head(96)?,
    };
    let transfer = TransferFunction::preset("ct-skin")?;

    // Display and camera: the paper's 8-view display; focal plane through the volume's centre.
    let display = Display::parse("hubner8")?;
    let size = [512, 512];
    let camera = MultiViewCamera::framing(
        volume.bounds(),
        display.views(),
        None,
        30f32.to_radians(),
        1.0,
    )?;
    let frame = Frame::new(camera, display, size)?;

    // The scene on the GPU: gradients + scalar in one 3D texture, sampled every half voxel,
    // rotated 30° about y.
    let rotation = Mat4::from_rotation_y(30f32.to_radians());
    let scene = VolumeScene::new(&ctx.device, &ctx.queue, &volume, transfer, rotation)?;

    // One single-pass frame, straight into the spatial image.
    let target = SpatialTarget::new(&ctx.device, size)?;
    let mut single_pass =
        VolumeRaycaster::new(&ctx.device, Method::SinglePass, VolumeSettings::default())?;
    single_pass.render(&ctx.device, &ctx.queue, &scene, &frame, &target)?;
    let image = target.read(&ctx.device, &ctx.queue)?;
    let out = args.get(1).map(String::as_str).unwrap_or("volume.png");
    image.save_png(out.as_ref())?;

    // The N-pass oracle: one render per view, composited with the same mask.
    let reference = SpatialTarget::new(&ctx.device, size)?;
    VolumeRaycaster::new(&ctx.device, Method::NPass, VolumeSettings::default())?.render(
        &ctx.device,
        &ctx.queue,
        &scene,
        &frame,
        &reference,
    )?;
    let diff = compare(&image, &reference.read(&ctx.device, &ctx.queue)?)?;
    println!(
        "wrote {out}; single pass vs N-pass: {:.1} dB PSNR, max error {}",
        diff.psnr_db, diff.max_abs_err
    );
    Ok(())
}
