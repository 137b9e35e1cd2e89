//! `autostereo mesh`: render a triangle mesh for a multi-view display.

use std::path::PathBuf;

use anyhow::{bail, Context, Result};
use autostereo::frame::Frame;
use autostereo::mesh::{Mesh, MeshBuffers};
use autostereo::render::{
    CoverBounds, MeshBaseline, MeshBaselineMethod, MeshSinglePass, MeshSinglePassOptions, Renderer,
    Visibility,
};

use crate::args::{check_output, gpu, parse_size, CameraArgs, DisplayArgs, Method};
use crate::run::{compare_with, report, timed};

#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum VisibilityArg {
    /// The fastest exact mode the adapter supports (compute, else exact).
    Auto,
    /// Per-subpixel depth by subpixel-resolution rasterisation (any adapter).
    Exact,
    /// Per-subpixel depth with 64-bit atomics.
    Atomic,
    /// Software (compute-pass) rasterisation of the covering rectangles, 64-bit atomics.
    Compute,
    /// The paper's one depth per pixel (approximate).
    Fast,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum BoundsArg {
    Exact,
    Paper,
}

#[derive(clap::Args)]
pub struct MeshArgs {
    /// OBJ file; a generated torus scene when omitted.
    obj: Option<PathBuf>,
    #[command(flatten)]
    display: DisplayArgs,
    #[command(flatten)]
    camera: CameraArgs,
    /// Image size WxH in pixels.
    #[arg(long, value_parser = parse_size, default_value = "512x512")]
    size: [u32; 2],
    /// Rendering method.
    #[arg(long, value_enum, default_value = "single-pass")]
    method: Method,
    /// Single-pass visibility: auto | exact | atomic (per-subpixel depth) | fast (the paper's).
    #[arg(long, value_enum, default_value = "auto")]
    visibility: VisibilityArg,
    /// Single-pass covering-quad bounds: exact (DESIGN §3) or the paper's printed formula.
    #[arg(long, value_enum, default_value = "exact")]
    bounds: BoundsArg,
    /// Reorder triangles along a Morton curve before rendering (locality; every method).
    #[arg(long)]
    sort_triangles: bool,
    /// Also render N-pass and report psnr_db, max_abs_err, frac_off_2 against it.
    #[arg(long)]
    compare: bool,
    /// Timed frames (after two warm-up frames); the median is reported.
    #[arg(long, default_value_t = 1)]
    frames: u32,
    /// Output PNG of the spatial image.
    #[arg(long)]
    out: Option<PathBuf>,
    /// Print one JSON object with the run's parameters and timing on stdout.
    #[arg(long)]
    json: bool,
}

pub fn run(args: MeshArgs) -> Result<()> {
    if let Some(out) = &args.out {
        check_output(out)?;
    }
    if args.frames == 0 {
        bail!("--frames must be at least 1");
    }
    let display = args.display.display()?;
    let mut mesh = match &args.obj {
        Some(path) => Mesh::load_obj(path)?,
        None => Mesh::torus_scene(),
    };
    if args.sort_triangles {
        mesh.sort_triangles_spatially();
    }
    let bounds = mesh.bounds().context("the mesh has no vertices")?;
    let camera = args.camera.camera(bounds, display.views(), args.size)?;
    let frame = Frame::new(camera, display, args.size)?;
    let ctx = gpu()?;
    let device = &ctx.device;
    let buffers = MeshBuffers::new(device, &mesh)?;
    let mut renderer = renderer(device, &args)?;
    let run = timed(&ctx, renderer.as_mut(), &buffers, &frame, args.frames)?;
    if let Some(out) = &args.out {
        run.image.save_png(out)?;
    }
    let diff = if args.compare {
        let mut npass = MeshBaseline::new(device, MeshBaselineMethod::NPass)?;
        Some(compare_with(
            &ctx, &mut npass, &buffers, &frame, &run.image,
        )?)
    } else {
        None
    };
    let method_name = args.method.name();
    let mut fields = serde_json::json!({
        "method": method_name,
        "views": frame.camera.views,
        "views_per_pixel": frame.display.views_per_pixel(),
        "display": args.display.display,
        "size": args.size,
        "adapter": ctx.adapter_label(),
        "ms": run.ms,
        "frames": args.frames,
        "timing": run.timing,
        "triangles": mesh.triangle_count(),
        "focal_distance": frame.camera.focal_distance,
        "separation": frame.camera.separation,
    });
    if args.method == Method::SinglePass {
        fields["visibility"] = single_pass_options(device, &args).visibility.name().into();
        fields["bounds"] = format!("{:?}", args.bounds).to_lowercase().into();
    }
    let summary = format!(
        "{method_name}: {} triangles, {} views, {}x{}, {:.2} ms/frame (median of {}, {:?}) on {}",
        mesh.triangle_count(),
        frame.camera.views,
        args.size[0],
        args.size[1],
        run.ms,
        args.frames,
        run.timing,
        ctx.adapter_label()
    );
    report(args.json, fields, diff, &summary);
    Ok(())
}

/// The renderer a `--method` selects.
fn renderer(device: &wgpu::Device, args: &MeshArgs) -> Result<Box<dyn Renderer<MeshBuffers>>> {
    Ok(match args.method {
        Method::NPass => Box::new(MeshBaseline::new(device, MeshBaselineMethod::NPass)?),
        Method::SingleView => Box::new(MeshBaseline::new(device, MeshBaselineMethod::SingleView)?),
        Method::SinglePass => Box::new(MeshSinglePass::new(
            device,
            single_pass_options(device, args),
        )?),
    })
}

fn single_pass_options(device: &wgpu::Device, args: &MeshArgs) -> MeshSinglePassOptions {
    MeshSinglePassOptions {
        visibility: match args.visibility {
            VisibilityArg::Auto => Visibility::best_exact(device),
            VisibilityArg::Exact => Visibility::Exact,
            VisibilityArg::Atomic => Visibility::ExactAtomic,
            VisibilityArg::Compute => Visibility::Compute,
            VisibilityArg::Fast => Visibility::Fast,
        },
        bounds: match args.bounds {
            BoundsArg::Exact => CoverBounds::Exact,
            BoundsArg::Paper => CoverBounds::Paper,
        },
    }
}
