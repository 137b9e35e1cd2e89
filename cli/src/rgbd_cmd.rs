//! `autostereo rgbd`: an RGB-D image (colour + depth map, or one side-by-side file) to any
//! display's spatial image, a Looking Glass quilt or per-view PNGs, by warping.

use std::path::PathBuf;

use anyhow::{bail, Context, Result};
use autostereo::frame::Frame;
use autostereo::image_io::RgbImage;
use autostereo::render::quilt::QuiltLayout;
use autostereo::render::Renderer;
use autostereo::rgbd::{DepthMapOptions, RgbdImage, RgbdScene};
use autostereo::target::SpatialTarget;
use autostereo::timing::{median, FrameTimer};
use autostereo::warp::{RgbdWarp, WarpOptions, WarpPath};

use crate::args::{check_output, parse_size, DisplayArgs};

#[derive(clap::Args)]
pub struct RgbdArgs {
    /// Colour image, PNG or JPEG (with --sbs: the side-by-side RGB-D image, colour left, depth
    /// right).
    color: PathBuf,
    /// Depth image (PNG, 8 or 16 bit; or JPEG) (its luma; white = near unless --depth-invert).
    #[arg(required_unless_present = "sbs")]
    depth: Option<PathBuf>,
    /// COLOR is one side-by-side image: colour in the left half, depth in the right.
    #[arg(long, conflicts_with = "depth")]
    sbs: bool,
    /// The depth map is black = near (distance rather than nearness).
    #[arg(long)]
    depth_invert: bool,
    /// Resample a depth map of another size than the colour image (bilinear) instead of
    /// refusing it.
    #[arg(long)]
    depth_resample: bool,
    /// Depth value (0…1, after --depth-invert) that lands on the display plane.
    #[arg(long, allow_negative_numbers = true, default_value_t = 0.5)]
    focus: f32,
    /// Parallax scale: 1 shifts the nearest depth (focus 0) by 3 % of the width in the
    /// outermost views.
    #[arg(long, allow_negative_numbers = true, default_value_t = 1.0)]
    depthiness: f32,
    /// Neighbours warped further apart than this many pixels straddle a disocclusion, filled
    /// from the background side.
    #[arg(long, default_value_t = autostereo::warp::DEFAULT_HOLE_GAP)]
    hole_gap: f32,
    #[command(flatten)]
    display: DisplayArgs,
    /// Output size WxH (default: the colour image's).
    #[arg(long, value_parser = parse_size)]
    size: Option<[u32; 2]>,
    /// Output PNG of the spatial image.
    #[arg(long)]
    out: Option<PathBuf>,
    /// Also write the spatial image's hole mask (white = subpixel filled from the background
    /// side or the edge, not seen) and print the filled share.
    #[arg(long)]
    hole_mask: Option<PathBuf>,
    /// Also write every view as a Looking Glass quilt (PNG; the name gets the
    /// `_qs{cols}x{rows}a{aspect}` suffix).
    #[arg(long)]
    quilt_out: Option<PathBuf>,
    /// Also write every view as DIR/view_NN.png (DIR must exist).
    #[arg(long)]
    views_out: Option<PathBuf>,
    /// Where the warp writes: direct (each subpixel warps its own view into the spatial
    /// image) or per-view (every view into its own image, then the mask compositing).
    #[arg(long, value_enum, default_value = "direct")]
    path: PathArg,
    /// Timed frames of the spatial image (after two warm-up frames); the median is reported.
    #[arg(long, default_value_t = 1, value_parser = crate::args::frames_parser())]
    frames: u32,
    /// CPU memory budget for loading (bytes, or with K/M/G/T, KB…TB or KiB…TiB, all binary:
    /// 1K = 1KB = 1KiB = 1024 bytes; default 8G).
    #[arg(long, value_parser = autostereo::budget::parse_bytes)]
    max_memory: Option<u64>,
}

#[derive(Clone, Copy, clap::ValueEnum)]
enum PathArg {
    Direct,
    PerView,
}

pub fn run(args: RgbdArgs) -> Result<()> {
    for path in [&args.out, &args.quilt_out, &args.hole_mask]
        .into_iter()
        .flatten()
    {
        check_output(path)?;
    }
    if let Some(dir) = &args.views_out {
        if !dir.is_dir() {
            bail!("--views-out {}: no such directory", dir.display());
        }
    }
    let outputs = [&args.out, &args.quilt_out, &args.views_out, &args.hole_mask];
    if outputs.iter().all(|o| o.is_none()) {
        bail!("nothing to write: give --out, --quilt-out, --views-out or --hole-mask");
    }
    if let Some(bytes) = args.max_memory {
        autostereo::budget::set_max_memory(bytes);
    }
    let depth_options = DepthMapOptions {
        invert: args.depth_invert,
        resample: args.depth_resample,
    };
    let image = match &args.depth {
        Some(depth) => RgbdImage::load(&args.color, depth, depth_options)?,
        None => RgbdImage::load_side_by_side(&args.color, depth_options)?,
    };
    let size = args.size.unwrap_or(image.size());
    let frame = Frame::for_display(args.display.display()?, size)?;
    let options = WarpOptions {
        focus: args.focus,
        depthiness: args.depthiness,
        hole_gap: args.hole_gap,
        view: None,
        path: match args.path {
            PathArg::Direct => WarpPath::Direct,
            PathArg::PerView => WarpPath::PerView,
        },
        ..WarpOptions::default()
    };
    let ctx = crate::args::gpu()?;
    let (device, queue) = (&ctx.device, &ctx.queue);
    let scene = RgbdScene::new(device, queue, &image)?;
    let mut warp = RgbdWarp::new(device, options)?;
    let target = SpatialTarget::new(device, size)?;
    if let Some(out) = &args.out {
        warp.prepare(device, queue, &scene, &frame)?;
        let timer = FrameTimer::new(device, queue);
        let mut samples = Vec::new();
        for i in 0..args.frames + 2 {
            let ms = timer.time_frame(device, queue, |encoder| {
                warp.encode(device, encoder, &scene, &frame, &target)
            })?;
            if i >= 2 {
                samples.push(ms);
            }
        }
        target.read(device, queue)?.save_png(out)?;
        eprintln!(
            "{}: {}x{} for {} ({} views), {:?} warp, {:.2} ms/frame (median of {}, {:?})",
            out.display(),
            size[0],
            size[1],
            args.display.display,
            frame.camera.views,
            options.path,
            median(&samples),
            args.frames,
            timer.source()
        );
    }
    if let Some(path) = &args.hole_mask {
        warp.set_options(WarpOptions {
            hole_mask: true,
            ..options
        });
        warp.render(device, queue, &scene, &frame, &target)?;
        let mask = target.read(device, queue)?;
        let filled = mask.data.iter().filter(|&&v| v > 127).count();
        mask.save_png(path)?;
        eprintln!(
            "{}: {:.3} % of subpixels filled (disocclusions and edges)",
            path.display(),
            100.0 * filled as f64 / mask.data.len() as f64
        );
        warp.set_options(options);
    }
    if args.quilt_out.is_none() && args.views_out.is_none() {
        return Ok(());
    }
    let views = frame.camera.views;
    let layout = QuiltLayout::for_views(views, size);
    let quilt_size = layout.size();
    let mut quilt = args
        .quilt_out
        .as_ref()
        .map(|_| {
            RgbImage::check_size(quilt_size[0], quilt_size[1])?;
            Ok::<_, autostereo::Error>(RgbImage::new(quilt_size[0], quilt_size[1]))
        })
        .transpose()?;
    for v in 0..views {
        warp.set_options(WarpOptions {
            view: Some(v),
            path: WarpPath::Direct,
            ..options
        });
        warp.render(device, queue, &scene, &frame, &target)?;
        let view = target.read(device, queue)?;
        if let Some(dir) = &args.views_out {
            let path = dir.join(format!("view_{v:02}.png"));
            view.save_png(&path)
                .with_context(|| format!("writing view {v}"))?;
        }
        if let Some(quilt) = &mut quilt {
            let [x0, y0] = layout.tile_origin(v);
            for y in 0..size[1] {
                for x in 0..size[0] {
                    for c in 0..3 {
                        quilt.set(x0 + x, y0 + y, c, view.get(x, y, c));
                    }
                }
            }
        }
    }
    if let (Some(path), Some(quilt)) = (&args.quilt_out, &quilt) {
        let path = layout.file_name(path);
        quilt.save_png(&path)?;
        eprintln!("quilt {}", path.display());
    }
    if let Some(dir) = &args.views_out {
        eprintln!("{views} views in {}", dir.display());
    }
    Ok(())
}
