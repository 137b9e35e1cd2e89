//! `autostereo rgbd`: an RGB-D image (colour + depth map, or one side-by-side file) to any
//! display's spatial image, or any `--output` format (a Looking Glass quilt, per-view PNGs,
//! stereo pairs), by warping.

use std::path::PathBuf;

use anyhow::{bail, Result};
use autostereo::frame::Frame;
use autostereo::render::Renderer;
use autostereo::rgbd::{DepthMapOptions, RgbdImage, RgbdScene};
use autostereo::warp::{RgbdWarp, WarpOptions};

use crate::args::DisplayArgs;
use crate::output::flags::OutputArgs;
use crate::output::say_written;
use crate::parse::parse_size;
use crate::run::Saved;
use crate::run::{report, timed};
use crate::warp_cmd::WarpSynthesisArgs;

#[derive(clap::Args)]
pub struct RgbdArgs {
    /// Colour image, PNG or JPEG (with --sbs: the side-by-side RGB-D image, colour left, depth
    /// right).
    color: PathBuf,
    /// Depth image (PNG, 8 or 16 bit; or JPEG) (its luma; white = near unless --depth-invert).
    #[arg(required_unless_present = "sbs")]
    depth: Option<PathBuf>,
    /// COLOR is one side-by-side image: colour in the left half, depth in the right.
    #[arg(long, conflicts_with = "depth", help_heading = "Input")]
    sbs: bool,
    /// The depth map is black = near (distance rather than nearness).
    #[arg(long, help_heading = "Input")]
    depth_invert: bool,
    /// Resample a depth map of another size than the colour image (bilinear) instead of
    /// refusing it.
    #[arg(long, help_heading = "Input")]
    depth_resample: bool,
    #[command(flatten)]
    memory: crate::args::MemoryArgs,
    #[command(flatten)]
    display: DisplayArgs,
    /// Output size WxH (default: the colour image's).
    #[arg(long, value_parser = parse_size, help_heading = "Display")]
    size: Option<[u32; 2]>,
    /// Depth value (0…1, after --depth-invert) that lands on the display plane.
    #[arg(
        long,
        allow_negative_numbers = true,
        default_value_t = 0.5,
        help_heading = "Camera"
    )]
    focus: f32,
    /// Parallax scale: 1 shifts the nearest depth (focus 0) by 3 % of the width in the
    /// outermost views.
    #[arg(
        long,
        allow_negative_numbers = true,
        default_value_t = 1.0,
        help_heading = "Camera"
    )]
    depthiness: f32,
    #[command(flatten)]
    warp: WarpSynthesisArgs,
    #[command(flatten)]
    output: OutputArgs,
    #[command(flatten)]
    timing: crate::args::FramesArgs,
    /// Renamed --warp-path (direct | per-view), as in --method warp.
    #[arg(long, hide = true)]
    path: Option<String>,
}

pub fn run(args: RgbdArgs) -> Result<()> {
    if let Some(path) = &args.path {
        bail!("--path was renamed: --warp-path {path} (direct | per-view), as with --method warp");
    }
    // The hole mask is an output too: with it alone nothing else need be written.
    args.output
        .check(args.timing.frames.is_some() || args.warp.hole_mask.is_some())?;
    if let Some(out) = args
        .output
        .out
        .as_deref()
        .filter(|o| crate::output::video::is_video(o))
    {
        anyhow::bail!(
            "--out {}: rgbd writes one image (name it .png); videos are render commands' \
             --turntable frames",
            out.display()
        );
    }
    args.warp.check()?;
    let inputs: Vec<&std::path::Path> = [Some(args.color.as_path()), args.depth.as_deref()]
        .into_iter()
        .flatten()
        .collect();
    let mut claims = crate::claims::Claims::new(&inputs);
    claims.check(&crate::claims::given(&[
        (args.output.out.as_deref(), "--out"),
        (args.warp.hole_mask.as_deref(), "--hole-mask"),
    ]))?;
    if args.output.format != crate::output::flags::OutputArg::Spatial {
        args.display
            .check_spatial_only(&args.output.format.name())?;
    }
    let _budget = args.memory.apply();
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
    let options = args.warp.apply(WarpOptions {
        focus: args.focus,
        depthiness: args.depthiness,
        view: None,
        ..WarpOptions::default()
    });
    let ctx = crate::args::gpu()?;
    let (device, queue) = (&ctx.device, &ctx.queue);
    let scene = RgbdScene::new(device, queue, &image)?;
    let mut warp = RgbdWarp::new(device, options)?;
    claims.check(&crate::output::planned(
        &frame,
        &args.output,
        None,
        args.warp.hole_mask.as_deref(),
    )?)?;
    let run = timed(&ctx, &mut warp, &scene, &frame, &args.timing)?;
    let mut saved = Saved {
        written: Vec::new(),
        turntable: None,
        quilt: None,
    };
    if let Some(out) = &args.output.out {
        saved.written = crate::output::write(
            &ctx,
            &mut warp,
            &scene,
            &frame,
            &args.output,
            &mut claims,
            Some(&run.image),
            out,
        )?;
        say_written(args.output.json, &saved.written);
        if args.output.format == crate::output::flags::OutputArg::Quilt {
            let quilt = crate::output::frame_quilt(&frame, &args.output)?;
            if !args.output.json {
                eprintln!("{}", crate::run::quilt_line(&quilt));
            }
            saved.quilt = Some(quilt);
        }
    }
    let mut hole_share = None;
    if let Some(path) = &args.warp.hole_mask {
        warp.set_options(WarpOptions {
            hole_mask: true,
            ..options
        });
        let mask = warp.render_image(device, queue, &scene, &frame)?;
        claims.save_png(&mask, path, "--hole-mask")?;
        let share = crate::warp_cmd::hole_share(&mask);
        hole_share = Some(share);
        if !args.output.json {
            eprintln!(
                "{}: {:.3} % of subpixels filled (disocclusions and edges)",
                path.display(),
                100.0 * share
            );
        }
        saved.written.push(path.clone());
    }
    let fields = serde_json::json!({
        "method": "warp",
        "views": frame.camera.views,
        "views_per_pixel": frame.display.views_per_pixel(),
        "display": args.display.display,
        "size": size,
        "adapter": ctx.adapter_label(),
        "ms": run.ms,
        "timing": run.timing,
        "gpu_bytes": run.gpu_bytes,
        "warp_path": options.path.name(),
        "focus": options.focus,
        "depthiness": options.depthiness,
        "hole_gap": options.hole_gap,
        "hole_share": hole_share,
        "output": args.output.format.name(),
        "written": saved.written,
    });
    let mut fields = fields;
    crate::run::merge(&mut fields, args.timing.fields());
    let summary = format!(
        "rgbd: {}x{} for {} ({} views), {} warp, {:.2} ms/frame ({}, {:?}) on {}",
        size[0],
        size[1],
        args.display.display,
        frame.camera.views,
        options.path.name(),
        run.ms,
        args.timing.described(),
        run.timing,
        ctx.adapter_label()
    );
    report(args.output.json, fields, None, &summary);
    Ok(())
}
