//! `autostereo interleave`: a Looking Glass quilt or quilt video (views rendered anywhere) →
//! the spatial image or video of any display.

use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};
use autostereo::frame::Frame;
use autostereo::image_io::RgbImage;
use autostereo::render::atlas::{Atlas, QuiltInterleaver};
use autostereo::render::quilt::QuiltLayout;
use autostereo::render::quilt_image::QuiltImage;
use autostereo::render::quilt_views;
use autostereo::target::SpatialTarget;

use crate::args::DisplayArgs;
use autostereo::video::{VideoReader, VideoWriter};

use crate::output::video::is_video;
use crate::parse::{check_output_or_video, parse_size};

#[derive(clap::Args)]
pub struct InterleaveArgs {
    /// The quilt image (PNG or JPEG) or quilt video (MP4 H.264, GIF) in Looking Glass's
    /// convention: view 0 bottom-left, left → right then bottom → top; its grid from the name
    /// (`…_qs{cols}x{rows}a{aspect}.png`) unless --quilt gives it; tiles of floor(W/cols) x
    /// floor(H/rows) from the bottom-left, any remainder ignored, each stretched to the name's
    /// aspect.
    quilt: PathBuf,
    /// The quilt's grid, COLSxROWS (overrides the name).
    #[arg(long = "quilt", value_name = "COLSxROWS", value_parser = parse_size, help_heading = "Input")]
    grid: Option<[u32; 2]>,
    #[command(flatten)]
    memory: crate::args::MemoryArgs,
    #[command(flatten)]
    display: DisplayArgs,
    /// Output size WxH (default: a Looking Glass calibration's panel, else one tile's height at
    /// the quilt's aspect).
    #[arg(long, value_parser = parse_size, help_heading = "Display")]
    size: Option<[u32; 2]>,
    /// Output: a PNG of the spatial image; for a quilt video, a spatial video (F.mp4, F.gif)
    /// or numbered PNG frames `{stem}_{k:04}.png`.
    #[arg(long, value_name = "F.png", help_heading = "Output")]
    out: PathBuf,
    #[command(flatten)]
    video: crate::output::video::VideoArgs,
    /// Print one JSON object with the run's parameters and the files written (`written`) on
    /// stdout.
    #[arg(long, help_heading = "Output")]
    json: bool,
}

/// A quilt image, or a quilt video's frames.
enum Quilts {
    Image(Option<RgbImage>),
    Video(VideoReader),
}

impl Quilts {
    fn open(path: &Path) -> Result<Self> {
        Ok(match is_video(path) {
            true => Quilts::Video(VideoReader::open(path)?),
            false => Quilts::Image(Some(RgbImage::load(path)?)),
        })
    }

    fn next(&mut self) -> Result<Option<RgbImage>> {
        Ok(match self {
            Quilts::Image(image) => image.take(),
            Quilts::Video(video) => video.next_frame()?,
        })
    }
}

/// What turns one quilt into the spatial image: the display's views picked from its tiles,
/// an atlas, the interleaver and its target.
struct Interleaving<'a> {
    ctx: &'a autostereo::gpu::GpuContext,
    interleaver: QuiltInterleaver,
    target: SpatialTarget,
    frame: Frame,
    layout: QuiltLayout,
    /// The quilt views shown, where the quilt has more than the display.
    picked: Option<Vec<u32>>,
}

impl Interleaving<'_> {
    fn spatial(&mut self, tiles: RgbImage) -> Result<RgbImage> {
        let (device, queue) = (&self.ctx.device, &self.ctx.queue);
        let image = match &self.picked {
            Some(picked) => quilt_views::pick_tiles(&tiles, &self.layout, picked),
            None => tiles,
        };
        let atlas = Atlas::from_image(device, queue, &image, self.layout)?;
        self.interleaver
            .render(device, queue, &atlas, &self.frame, &self.target)?;
        Ok(self.target.read(device, queue)?)
    }
}

pub fn run(args: InterleaveArgs) -> Result<()> {
    check_output_or_video(&args.out)?;
    args.video.check(Some(&args.out))?;
    let mut claims = crate::claims::Claims::new(&[args.quilt.as_path()]);
    claims.check(&[(args.out.clone(), "--out")])?;
    let (video_in, video_out) = (is_video(&args.quilt), is_video(&args.out));
    if video_out && !video_in {
        bail!(
            "--out {}: a spatial video is made of a quilt video ({} is one quilt: interleave it to \
             a .png)",
            args.out.display(),
            args.quilt.display()
        );
    }
    let _budget = args.memory.apply();
    let display = args.display.display()?;
    let mut quilts = Quilts::open(&args.quilt)?;
    let first = quilts
        .next()?
        .with_context(|| format!("{}: no frames", args.quilt.display()))?;
    let name = args
        .quilt
        .file_name()
        .map_or_else(String::new, |n| n.to_string_lossy().into_owned());
    // The grid and tiles first (Looking Glass's rule: whole-pixel tiles from the bottom-left,
    // the remainder ignored, any tile aspect); the quilt's views are its tiles up to the last
    // that is not all black (Looking Glass quilts may leave the last tiles empty).
    let read = QuiltImage::read(&name, [first.width, first.height], args.grid, 1)?;
    let tiles = read.tiles(&first)?;
    let grid = read.layout;
    let n = display.views();
    let q = quilt_views::views_held(&tiles, &grid).max(n.min(grid.cols * grid.rows));
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
    let picked = quilt_views::spread_views(n, q);
    if q > n && !args.json {
        let list: Vec<String> = picked.iter().map(u32::to_string).collect();
        eprintln!(
            "the quilt has {q} views, the display {n}: using quilt views {}",
            list.join(", ")
        );
    }
    // A Looking Glass's panel, else the quilt's tile at the aspect its views are shown at.
    let shown = [
        ((layout.tile[1] as f32 * read.aspect).round() as u32).clamp(1, 16384),
        layout.tile[1],
    ];
    let size = args.size.or(display.panel_size()).unwrap_or(shown);
    if let Some(format) = autostereo::video::VideoFormat::of_path(&args.out) {
        format.check_size(&args.out, size)?;
    }
    let ctx = crate::args::gpu()?;
    let mut interleaving = Interleaving {
        ctx: &ctx,
        interleaver: QuiltInterleaver::new(&ctx.device)?,
        target: SpatialTarget::new(&ctx.device, size)?,
        frame: Frame::for_display(display, size)?,
        layout,
        picked: (q > n).then_some(picked.clone()),
    };
    let mut written = Vec::new();
    let mut frames = 0u32;
    if let Quilts::Video(video) = &quilts {
        let fps = video.fps();
        let bar = crate::progress::bar(u64::from(video.frames()), "interleaving");
        let mut writer = match video_out {
            true => Some(VideoWriter::create(
                &args.out,
                size,
                &args.video.settings(fps.max(1.0)),
            )?),
            false => None,
        };
        let mut next = Some(first);
        while let Some(quilt) = next {
            let spatial = interleaving.spatial(read.tiles(&quilt)?)?;
            match &mut writer {
                Some(writer) => writer.push(&spatial)?,
                None => {
                    let path = crate::output::names::numbered(&args.out, frames, false);
                    claims.save_png(&spatial, &path, "--out")?;
                    written.push(path);
                }
            }
            frames += 1;
            bar.inc(1);
            next = quilts.next()?;
        }
        if let Some(writer) = writer {
            bar.set_message("encoding");
            writer.finish()?;
            written.push(args.out.clone());
        }
        bar.finish_and_clear();
    } else {
        claims.save_png(&interleaving.spatial(tiles)?, &args.out, "--out")?;
        written.push(args.out.clone());
        frames = 1;
    }
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
            "quilt_size": read.size,
            "quilt_aspect": read.aspect,
            "quilt_zoom": read.zoom,
            "quilt_focus": read.focus,
            "frames": frames,
            "written": written,
        });
        println!("{fields}");
    } else {
        eprintln!(
            "interleaved {frames} frame(s): {}x{} for {} from a {}x{} quilt of {} views",
            size[0], size[1], args.display.display, layout.cols, layout.rows, q
        );
        crate::output::say_written(false, &written);
    }
    Ok(())
}
