//! `autostereo views`: look at a spatial image on an ordinary screen.

use std::path::PathBuf;

use anyhow::{bail, Result};
use autostereo::image_io::RgbImage;
use autostereo::views::{anaglyph, extract_view};

use crate::args::DisplayArgs;
use crate::parse::check_output;

#[derive(clap::Args)]
pub struct ViewsArgs {
    /// The spatial (interleaved) PNG.
    spatial: PathBuf,
    #[command(flatten)]
    memory: crate::args::MemoryArgs,
    #[command(flatten)]
    display: DisplayArgs,
    /// Extract what an eye in view zone I sees.
    #[arg(long, value_name = "I", conflicts_with = "eyes")]
    view: Option<u32>,
    /// Red/cyan anaglyph of views L (left eye, red) and R (right eye), the pair --eyes names in
    /// every command (formerly --anaglyph L,R, still accepted).
    #[arg(long, value_name = "L,R", alias = "anaglyph", value_parser = crate::parse::parse_eyes)]
    eyes: Option<[u32; 2]>,
    /// Output PNG.
    #[arg(long, value_name = "F.png", help_heading = "Output")]
    out: PathBuf,
    /// Print one JSON object with the display, the views taken and the file written
    /// (`written`).
    #[arg(long, help_heading = "Output")]
    json: bool,
}

pub fn run(args: ViewsArgs) -> Result<()> {
    check_output(&args.out)?;
    crate::claims::Claims::new(&[args.spatial.as_path()]).check(&[(args.out.clone(), "--out")])?;
    let _budget = args.memory.apply();
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
    let out = match (args.view, args.eyes) {
        (Some(v), None) => {
            check(v)?;
            extract_view(&spatial, &mask, v)
        }
        (None, Some([l, r])) => {
            if l == r {
                bail!("--eyes {l},{r}: one view for both eyes has no depth; give two views L,R");
            }
            check(l)?;
            check(r)?;
            anaglyph(&spatial, &mask, l, r)
        }
        _ => bail!("give one of --view I (one view) or --eyes L,R (a red/cyan anaglyph)"),
    };
    out.save_png(&args.out)?;
    let fields = serde_json::json!({
        "display": args.display.display,
        "views": n,
        "view": args.view,
        "eyes": args.eyes,
    });
    crate::output::report_written(args.json, fields, &[args.out]);
    Ok(())
}
