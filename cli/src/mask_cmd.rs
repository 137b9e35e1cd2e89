//! `autostereo mask`: the display mask as a view-index PNG.

use std::path::PathBuf;

use anyhow::Result;
use autostereo::image_io::RgbImage;
use autostereo::render::MaskImageRenderer;

use crate::args::{check_output, gpu, parse_size, DisplayArgs};

#[derive(clap::Args)]
pub struct MaskArgs {
    #[command(flatten)]
    display: DisplayArgs,
    /// Window size WxH in pixels.
    #[arg(long, value_parser = parse_size)]
    size: [u32; 2],
    /// Evaluate the WGSL mask on the GPU instead of the Rust one (they must agree).
    #[arg(long)]
    gpu: bool,
    /// Output PNG (RGB8, channel = view index).
    #[arg(long)]
    out: PathBuf,
}

pub fn run(args: MaskArgs) -> Result<()> {
    check_output(&args.out)?;
    let display = args.display.display()?;
    let [w, h] = args.size;
    let image = if args.gpu {
        let ctx = gpu()?;
        MaskImageRenderer::new(&ctx.device)?.render(&ctx.device, &ctx.queue, &display, args.size)?
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
    Ok(())
}
