//! `autostereo mesh`: render a triangle mesh for a multi-view display.

use std::path::PathBuf;

use anyhow::{bail, Context, Result};
use autostereo::camera::MultiViewCamera;
use autostereo::frame::Frame;
use autostereo::image_io::compare;
use autostereo::mesh::{Mesh, MeshBuffers};
use autostereo::render::{
    CoverBounds, MeshBaseline, MeshBaselineMethod, MeshSinglePass, MeshSinglePassOptions, Renderer,
    Visibility,
};
use autostereo::target::SpatialTarget;
use autostereo::timing::{median, FrameTimer};

use crate::args::{check_output, gpu, parse_size, DisplayArgs};

#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Method {
    /// One pass: covering quads, per-subpixel ray-triangle tests.
    SinglePass,
    /// One render per view + mask compositing (the oracle).
    NPass,
    /// The centre view only.
    SingleView,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum VisibilityArg {
    /// The fastest exact mode the adapter supports (atomic, else exact).
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

/// Camera flags shared by the renderers.
#[derive(clap::Args, Clone, Debug)]
pub struct CameraArgs {
    /// Separation of adjacent views, scene units (default: 5 % of the bounding radius).
    #[arg(long)]
    separation: Option<f32>,
    /// Focal distance (default: camera to the bounding-box centre).
    #[arg(long, conflicts_with = "focal_scale")]
    focal: Option<f32>,
    /// Focal distance as a multiple of the default.
    #[arg(long)]
    focal_scale: Option<f32>,
    /// Vertical field of view, degrees.
    #[arg(long, default_value_t = 30.0)]
    fov: f32,
}

impl CameraArgs {
    /// Frame `bounds` with these settings.
    pub fn camera(
        &self,
        bounds: autostereo::camera::Bounds,
        views: u32,
        size: [u32; 2],
    ) -> Result<MultiViewCamera> {
        let aspect = size[0] as f32 / size[1] as f32;
        let mut camera = MultiViewCamera::framing(
            bounds,
            views,
            self.separation,
            self.fov.to_radians(),
            aspect,
        )?;
        if let Some(fd) = self.focal {
            camera.focal_distance = fd;
        }
        if let Some(s) = self.focal_scale {
            camera.focal_distance *= s;
        }
        camera.validate()?;
        Ok(camera)
    }
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
    let (device, queue) = (&ctx.device, &ctx.queue);
    let buffers = MeshBuffers::new(device, &mesh)?;
    let target = SpatialTarget::new(device, args.size)?;
    let mut renderer = renderer(device, &args)?;
    let timer = FrameTimer::new(device, queue);
    let mut times = Vec::new();
    for i in 0..args.frames + 2 {
        let ms = timer.time_frame(device, queue, |encoder| {
            renderer.encode(device, queue, encoder, &buffers, &frame, &target)
        })?;
        if i >= 2 {
            times.push(ms);
        }
    }
    let ms = median(&times);
    let image = target.read(device, queue)?;
    if let Some(out) = &args.out {
        image.save_png(out)?;
    }
    let diff = if args.compare {
        let reference = SpatialTarget::new(device, args.size)?;
        MeshBaseline::new(device, MeshBaselineMethod::NPass)?
            .render(device, queue, &buffers, &frame, &reference)?;
        Some(compare(&image, &reference.read(device, queue)?)?)
    } else {
        None
    };
    let method_name = match args.method {
        Method::NPass => "n-pass",
        Method::SingleView => "single-view",
        Method::SinglePass => "single-pass",
    };
    if args.json {
        let json = serde_json::json!({
            "method": method_name,
            "views": frame.camera.views,
            "views_per_pixel": frame.display.views_per_pixel(),
            "display": args.display.display,
            "size": args.size,
            "adapter": ctx.adapter_label(),
            "ms": ms,
            "frames": args.frames,
            "timing": timer.source(),
            "triangles": mesh.triangle_count(),
            "focal_distance": frame.camera.focal_distance,
            "separation": frame.camera.separation,
        });
        let mut json = json;
        if args.method == Method::SinglePass {
            json["visibility"] = single_pass_options(device, &args).visibility.name().into();
            json["bounds"] = format!("{:?}", args.bounds).to_lowercase().into();
        }
        if let Some(d) = diff {
            json["psnr_db"] = d.psnr_db.into();
            json["max_abs_err"] = d.max_abs_err.into();
            json["frac_off_2"] = d.frac_off_2.into();
        }
        println!("{json}");
    } else {
        eprintln!(
            "{method_name}: {} triangles, {} views, {}x{}, {:.2} ms/frame (median of {}, {:?}) on {}",
            mesh.triangle_count(),
            frame.camera.views,
            args.size[0],
            args.size[1],
            ms,
            args.frames,
            timer.source(),
            ctx.adapter_label()
        );
        if let Some(d) = diff {
            eprintln!(
                "vs n-pass: PSNR {:.2} dB, max abs error {}, {:.4} % of subpixels off by > 2/255",
                d.psnr_db,
                d.max_abs_err,
                100.0 * d.frac_off_2
            );
        }
    }
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
