//! `autostereo mask`: the display mask as a view-index PNG.

use std::path::PathBuf;

use anyhow::Result;
use autostereo::image_io::RgbImage;
use autostereo::render::MaskImageRenderer;

use crate::args::{gpu, DisplayArgs};
use crate::parse::{check_output, parse_size};

#[derive(clap::Args)]
pub struct MaskArgs {
    #[command(flatten)]
    display: DisplayArgs,
    /// Image size WxH in pixels (default: a Looking Glass calibration's panel, else 512x512).
    #[arg(long, value_parser = parse_size, help_heading = "Display")]
    size: Option<[u32; 2]>,
    /// Evaluate the WGSL mask on the GPU instead of the Rust one (they must agree).
    #[arg(long)]
    gpu: bool,
    /// Output PNG (RGB8, channel = view index).
    #[arg(long, value_name = "F.png", help_heading = "Output")]
    out: PathBuf,
    /// Print one JSON object with the display, the size and the file written (`written`).
    #[arg(long, help_heading = "Output")]
    json: bool,
}

pub fn run(args: MaskArgs) -> Result<()> {
    check_output(&args.out)?;
    let display = args.display.display()?;
    let size = crate::args::image_size(args.size, &display);
    let [w, h] = size;
    // In the flag's words (the library's says "invalid image size", no flag), for either path.
    let pixels = u64::from(w) * u64::from(h);
    let most = autostereo::image_io::MAX_IMAGE_PIXELS;
    if pixels > most {
        anyhow::bail!(
            "--size {w}x{h}: {pixels} pixels, more than {most}, the most a mask image holds \
             (W×H ≤ {most}, e.g. --size {side}x{side})",
            side = (most as f64).sqrt() as u64
        );
    }
    let image = if args.gpu {
        let ctx = gpu()?;
        MaskImageRenderer::new(&ctx.device)?.render(&ctx.device, &ctx.queue, &display, size)?
    } else {
        RgbImage::check_size(w, h)?;
        let mask = display.mask();
        let mut image = RgbImage::new(w, h);
        for y in 0..h {
            for x in 0..w {
                for c in 0..3 {
                    image.set(x, y, c, mask.view(x, y, c) as u8);
                }
            }
        }
        image
    };
    image.save_png(&args.out)?;
    let fields = serde_json::json!({
        "display": args.display.display,
        "views": display.views(),
        "size": size,
        "gpu": args.gpu,
    });
    crate::output::report_written(args.json, fields, &[args.out]);
    Ok(())
}
