//! `autostereo interleave`: a Looking Glass quilt (views rendered anywhere) → the spatial image
//! of any display.

use std::path::PathBuf;

use anyhow::Result;
use autostereo::frame::Frame;
use autostereo::image_io::RgbImage;
use autostereo::render::atlas::{Atlas, QuiltInterleaver};
use autostereo::render::quilt::QuiltLayout;
use autostereo::target::SpatialTarget;

use crate::args::{check_output, parse_size, DisplayArgs};

#[derive(clap::Args)]
pub struct InterleaveArgs {
    /// The quilt image (PNG or JPEG): view 0 bottom-left, left → right then bottom → top; its grid from the
    /// name (`…_qs{cols}x{rows}a{aspect}.png`) unless --quilt gives it.
    quilt: PathBuf,
    /// The quilt's grid, COLSxROWS (overrides the name).
    #[arg(long = "quilt", value_name = "COLSxROWS", value_parser = parse_size)]
    grid: Option<[u32; 2]>,
    #[command(flatten)]
    display: DisplayArgs,
    /// Output size WxH (default: a Looking Glass calibration's panel, else one tile's size).
    #[arg(long, value_parser = parse_size)]
    size: Option<[u32; 2]>,
    /// Output PNG of the spatial image.
    #[arg(long)]
    out: PathBuf,
}

pub fn run(args: InterleaveArgs) -> Result<()> {
    check_output(&args.out)?;
    let display = args.display.display()?;
    let image = RgbImage::load(&args.quilt)?;
    let name = args
        .quilt
        .file_name()
        .map_or_else(String::new, |n| n.to_string_lossy().into_owned());
    let layout = QuiltLayout::for_image(
        &name,
        [image.width, image.height],
        args.grid,
        display.views(),
    )?;
    // A Looking Glass's panel, else the quilt's tile.
    let size = args.size.or(display.panel_size()).unwrap_or(layout.tile);
    let frame = Frame::for_display(display, size)?;
    let ctx = crate::args::gpu()?;
    let (device, queue) = (&ctx.device, &ctx.queue);
    let atlas = Atlas::from_image(device, queue, &image, layout)?;
    let target = SpatialTarget::new(device, size)?;
    QuiltInterleaver::new(device)?.render(device, queue, &atlas, &frame, &target)?;
    target.read(device, queue)?.save_png(&args.out)?;
    eprintln!(
        "{}: {}x{} for {} from a {}x{} quilt of {} views",
        args.out.display(),
        size[0],
        size[1],
        args.display.display,
        layout.cols,
        layout.rows,
        layout.views
    );
    Ok(())
}
