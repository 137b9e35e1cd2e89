//! `autostereo views`: look at a spatial image on an ordinary screen.

use std::path::PathBuf;

use anyhow::{bail, Result};
use autostereo::image_io::RgbImage;
use autostereo::views::{anaglyph, extract_view};

use crate::args::{check_output, parse_pair, DisplayArgs};

#[derive(clap::Args)]
pub struct ViewsArgs {
    /// The spatial (interleaved) PNG.
    spatial: PathBuf,
    #[command(flatten)]
    display: DisplayArgs,
    /// Extract what an eye in view zone I sees.
    #[arg(long, conflicts_with = "anaglyph")]
    view: Option<u32>,
    /// Red/cyan anaglyph of views I (left eye, red) and J (right eye).
    #[arg(long, value_parser = parse_pair)]
    anaglyph: Option<[u32; 2]>,
    /// Output PNG.
    #[arg(long)]
    out: PathBuf,
}

pub fn run(args: ViewsArgs) -> Result<()> {
    check_output(&args.out)?;
    let display = args.display.display()?;
    let mask = display.mask();
    let n = mask.views();
    let spatial = RgbImage::load(&args.spatial)?;
    let check = |v: u32| -> Result<()> {
        if v >= n {
            bail!(
                "view {v} does not exist: the display has views 0..{}",
                n - 1
            );
        }
        Ok(())
    };
    let out = match (args.view, args.anaglyph) {
        (Some(v), None) => {
            check(v)?;
            extract_view(&spatial, &mask, v)
        }
        (None, Some([l, r])) => {
            check(l)?;
            check(r)?;
            anaglyph(&spatial, &mask, l, r)
        }
        _ => bail!("give one of --view I or --anaglyph I,J"),
    };
    out.save_png(&args.out)?;
    Ok(())
}
