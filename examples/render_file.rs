//! The library's one path from a file to a spatial image: `autostereo::load` (any format; the
//! primitive told by the file), `AnyScene::upload`, `AnyRenderer` (any primitive, any method),
//! the paper's 8-view display, one single-pass frame and the N-pass oracle to compare with.
//! Without a file: the built-in CT-like head.
//!
//! `cargo run --release --example render_file -- [FILE] [out.png]`

use anyhow::Result;
use autostereo::camera::MultiViewCamera;
use autostereo::display::Display;
use autostereo::frame::Frame;
use autostereo::gpu::GpuContext;
use autostereo::image_io::compare;
use autostereo::render::Method;
use autostereo::volume::generate;
use autostereo::{AnyData, AnyRenderer, AnyScene, LoadOptions, Renderer, RendererOptions};
use autostereo::{VolumeData, VolumeLoad};
use glam::Mat4;

fn main() -> Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let ctx = GpuContext::new(&Default::default())?;
    println!("adapter: {}", ctx.adapter_label());

    // Data: any file this build reads (a volume turned 30° about y), or the built-in head.
    let rotation = Mat4::from_rotation_y(30f32.to_radians());
    let data = match args.first() {
        Some(path) => {
            let options = LoadOptions {
                volume: VolumeLoad {
                    model: rotation,
                    ..VolumeLoad::default()
                },
                ..LoadOptions::default()
            };
            autostereo::load(path.as_ref(), &options)?
        }
        None => AnyData::Volume(Box::new(VolumeData::with_preset(
            generate::ct_head(96)?,
            "ct-skin",
            rotation,
        )?)),
    };
    let bounds = data
        .bounds()
        .ok_or_else(|| anyhow::anyhow!("nothing to render"))?;
    println!("{}: {:?}", data.kind().name(), bounds);

    // Display and camera: the paper's 8-view display; focal plane through the data's centre.
    let display = Display::parse("hubner8")?;
    let size = [512, 512];
    let camera = MultiViewCamera::framing(bounds, display.views(), None, 30f32.to_radians(), 1.0)?;
    let frame = Frame::new(camera, display, size)?;

    // The scene on the GPU, and one single-pass frame straight into the spatial image.
    let scene = AnyScene::upload(&ctx.device, &ctx.queue, &data)?;
    let mut single_pass = AnyRenderer::new(
        &ctx.device,
        &scene,
        &RendererOptions::new(Method::SinglePass),
    )?;
    let image = single_pass.render_image(&ctx.device, &ctx.queue, &scene, &frame)?;
    let out = args.get(1).map(String::as_str).unwrap_or("spatial.png");
    image.save_png(out.as_ref())?;

    // The N-pass oracle: one render per view, composited with the same mask.
    let mut npass = AnyRenderer::new(&ctx.device, &scene, &RendererOptions::new(Method::NPass))?;
    let reference = npass.render_image(&ctx.device, &ctx.queue, &scene, &frame)?;
    let diff = compare(&image, &reference)?;
    println!(
        "wrote {out}; single pass vs N-pass: {:.1} dB PSNR, max error {}",
        diff.psnr_db, diff.max_abs_err
    );
    Ok(())
}
