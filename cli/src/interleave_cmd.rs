//! `autostereo interleave`: a Looking Glass quilt (views rendered anywhere) → the spatial image
//! of any display.

use std::path::PathBuf;

use anyhow::{bail, Result};
use autostereo::frame::Frame;
use autostereo::image_io::RgbImage;
use autostereo::render::atlas::{Atlas, QuiltInterleaver};
use autostereo::render::quilt::QuiltLayout;
use autostereo::target::SpatialTarget;

use crate::args::DisplayArgs;
use crate::parse::{check_output, parse_size};

#[derive(clap::Args)]
pub struct InterleaveArgs {
    /// The quilt image (PNG or JPEG): view 0 bottom-left, left → right then bottom → top; its grid from the
    /// name (`…_qs{cols}x{rows}a{aspect}.png`) unless --quilt gives it.
    quilt: PathBuf,
    /// The quilt's grid, COLSxROWS (overrides the name).
    #[arg(long = "quilt", value_name = "COLSxROWS", value_parser = parse_size, help_heading = "Input")]
    grid: Option<[u32; 2]>,
    #[command(flatten)]
    memory: crate::args::MemoryArgs,
    #[command(flatten)]
    display: DisplayArgs,
    /// Output size WxH (default: a Looking Glass calibration's panel, else one tile's size).
    #[arg(long, value_parser = parse_size, help_heading = "Display")]
    size: Option<[u32; 2]>,
    /// Output PNG of the spatial image.
    #[arg(long, value_name = "F.png", help_heading = "Output")]
    out: PathBuf,
    /// Print one JSON object with the run's parameters and the files written (`written`) on
    /// stdout.
    #[arg(long, help_heading = "Output")]
    json: bool,
}

pub fn run(args: InterleaveArgs) -> Result<()> {
    check_output(&args.out)?;
    crate::claims::Claims::new(&[args.quilt.as_path()]).check(&[(args.out.clone(), "--out")])?;
    let _budget = args.memory.apply();
    let display = args.display.display()?;
    let image = RgbImage::load(&args.quilt)?;
    let name = args
        .quilt
        .file_name()
        .map_or_else(String::new, |n| n.to_string_lossy().into_owned());
    // The grid and tiles first; the quilt's views are its tiles up to the last that is not
    // all black (Looking Glass quilts may leave the last tiles empty).
    let grid = QuiltLayout::for_image(&name, [image.width, image.height], args.grid, 1)?;
    let n = display.views();
    let q = quilt_views(&image, &grid).max(n.min(grid.cols * grid.rows));
    if q < n {
        bail!(
            "{}: a {}x{} grid cannot hold {n} views: the quilt has {q} views, the display {} \
             shows {n} (a quilt needs at least as many views as the display)",
            args.quilt.display(),
            grid.cols,
            grid.rows,
            args.display.display
        );
    }
    let layout = QuiltLayout { views: n, ..grid };
    // Fewer display views than the quilt's: N views spread across the quilt's cone (not its
    // first N, one edge of it), copied into tiles 0..N of the quilt the atlas is made of.
    let picked = spread_views(n, q);
    let image = if q > n {
        let list: Vec<String> = picked.iter().map(u32::to_string).collect();
        if !args.json {
            eprintln!(
                "the quilt has {q} views, the display {n}: using quilt views {}",
                list.join(", ")
            );
        }
        pick_tiles(&image, &layout, &picked)
    } else {
        image
    };
    // A Looking Glass's panel, else the quilt's tile.
    let size = args.size.or(display.panel_size()).unwrap_or(layout.tile);
    let frame = Frame::for_display(display, size)?;
    let ctx = crate::args::gpu()?;
    let (device, queue) = (&ctx.device, &ctx.queue);
    let atlas = Atlas::from_image(device, queue, &image, layout)?;
    let target = SpatialTarget::new(device, size)?;
    QuiltInterleaver::new(device)?.render(device, queue, &atlas, &frame, &target)?;
    target.read(device, queue)?.save_png(&args.out)?;
    if args.json {
        let fields = serde_json::json!({
            "display": args.display.display,
            "views": n,
            "size": size,
            "adapter": ctx.adapter_label(),
            "quilt": args.quilt,
            "quilt_grid": [layout.cols, layout.rows],
            "quilt_tile": layout.tile,
            "quilt_views": q,
            "quilt_views_used": picked,
            "written": [&args.out],
        });
        println!("{fields}");
    } else {
        eprintln!(
            "wrote {}: {}x{} for {} from a {}x{} quilt of {} views",
            args.out.display(),
            size[0],
            size[1],
            args.display.display,
            layout.cols,
            layout.rows,
            q
        );
    }
    Ok(())
}

/// The views a quilt of `grid` holds: its tiles up to the last one that is not all black.
fn quilt_views(image: &RgbImage, grid: &QuiltLayout) -> u32 {
    let tiles = grid.cols * grid.rows;
    (0..tiles)
        .rev()
        .find(|&t| {
            let [x0, y0] = grid.tile_origin(t);
            (y0..y0 + grid.tile[1]).any(|y| {
                let row = (y as usize * image.width as usize + x0 as usize) * 3;
                image.data[row..row + grid.tile[0] as usize * 3]
                    .iter()
                    .any(|&b| b != 0)
            })
        })
        .map_or(0, |t| t + 1)
}

/// The `n` quilt views of `q` (n ≤ q) a display of `n` views shows: view i ←
/// round(i·(q−1)/(n−1)), spread across the quilt's cone; one view: the middle.
fn spread_views(n: u32, q: u32) -> Vec<u32> {
    if n == 1 {
        return vec![(q - 1) / 2];
    }
    (0..n)
        .map(|i| {
            let num = u64::from(i) * u64::from(q - 1);
            let den = u64::from(n - 1);
            ((2 * num + den) / (2 * den)) as u32
        })
        .collect()
}

/// A quilt of `layout` whose tile i is `image`'s tile `picked[i]` (same grid).
fn pick_tiles(image: &RgbImage, layout: &QuiltLayout, picked: &[u32]) -> RgbImage {
    let mut out = RgbImage::new(image.width, image.height);
    let row_bytes = layout.tile[0] as usize * 3;
    for (i, &t) in picked.iter().enumerate() {
        let [dx, dy] = layout.tile_origin(i as u32);
        let [sx, sy] = layout.tile_origin(t);
        for y in 0..layout.tile[1] {
            let src = ((sy + y) as usize * image.width as usize + sx as usize) * 3;
            let dst = ((dy + y) as usize * image.width as usize + dx as usize) * 3;
            out.data[dst..dst + row_bytes].copy_from_slice(&image.data[src..src + row_bytes]);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::spread_views;

    #[test]
    fn views_spread_across_the_cone() {
        assert_eq!(spread_views(8, 45), [0, 6, 13, 19, 25, 31, 38, 44]);
        assert_eq!(spread_views(8, 8), (0..8).collect::<Vec<_>>());
        assert_eq!(spread_views(1, 45), [22]);
        assert_eq!(spread_views(2, 45), [0, 44]);
    }
}
