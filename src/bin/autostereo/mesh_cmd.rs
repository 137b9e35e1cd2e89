//! `autostereo mesh`: render a triangle mesh for a multi-view display.

use std::path::PathBuf;

use anyhow::{Context, Result};
use autostereo::mesh::{Mesh, MeshBuffers};
use autostereo::render::{
    CoverBounds, MeshLayered, MeshMrt, MeshNPass, MeshSinglePass, MeshSinglePassOptions, MeshTiled,
    Method, Renderer, TileClip, Visibility,
};

use crate::args::{gpu, RenderArgs};
use crate::run::{compare_with, merge, report, run_fields, run_summary, timed};
use crate::warp_cmd::{hole_report, warp_renderer};

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
pub enum TileClipArg {
    /// Clip distances where the adapter has them, else discard.
    Auto,
    /// Four clip distances per vertex (needs CLIP_DISTANCES).
    ClipDistances,
    /// Discard fragments outside the tile (any adapter).
    Discard,
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
    common: RenderArgs,
    /// Single-pass visibility: auto | compute | atomic | exact (per-subpixel depth) | fast (the
    /// paper's one depth per pixel); auto = compute where 64-bit atomics exist, else exact.
    #[arg(long, value_enum, default_value = "auto")]
    visibility: VisibilityArg,
    /// Single-pass covering-quad bounds: exact (vd·|1 − fd/d| per vertex) or the paper's printed
    /// formula.
    #[arg(long, value_enum, default_value = "exact")]
    bounds: BoundsArg,
    /// Tiled method: how each view's copy is kept inside its tile.
    #[arg(long, value_enum, default_value = "auto")]
    tile_clip: TileClipArg,
    /// Reorder triangles along a Morton curve before rendering (locality; every method).
    #[arg(long)]
    sort_triangles: bool,
}

pub fn run(args: MeshArgs) -> Result<()> {
    args.common.check()?;
    let mut mesh = match &args.obj {
        Some(path) => Mesh::load_obj(path)?,
        None => Mesh::torus_scene(),
    };
    if args.sort_triangles {
        mesh.sort_triangles_spatially();
    }
    let bounds = mesh.bounds().context("the mesh has no vertices")?;
    let frame = args.common.frame(bounds)?;
    let ctx = gpu()?;
    let device = &ctx.device;
    let buffers = MeshBuffers::new(device, &mesh)?;
    let mut renderer = renderer(device, &args)?;
    let run = timed(
        &ctx,
        renderer.as_mut(),
        &buffers,
        &frame,
        args.common.frames,
    )?;
    let turntable = crate::output::save_all(
        &ctx,
        renderer.as_mut(),
        &buffers,
        &frame,
        bounds,
        &args.common,
        &run.image,
    )?;
    let diff = if args.common.compare {
        let mut npass = MeshNPass::new(device, Method::NPass)?;
        Some(compare_with(
            &ctx, &mut npass, &buffers, &frame, &run.image,
        )?)
    } else {
        None
    };
    let method_name = args.common.method.name();
    let mut extra = serde_json::json!({ "triangles": mesh.triangle_count() });
    if args.common.method == Method::Warp {
        let references = MeshNPass::new(device, Method::Warp)?;
        merge(
            &mut extra,
            hole_report(&ctx, &args.common.warp, references, &buffers, &frame)?,
        );
    }
    if let Some(t) = &turntable {
        merge(&mut extra, t.fields());
    }
    let mut fields = run_fields(&ctx, &args.common, &frame, &run, extra);
    if args.common.method == Method::SinglePass {
        fields["visibility"] = single_pass_options(device, &args).visibility.name().into();
        fields["bounds"] = format!("{:?}", args.bounds).to_lowercase().into();
    }
    let summary = format!(
        "{method_name}: {} triangles, {}",
        mesh.triangle_count(),
        run_summary(&ctx, &args.common, &frame, &run)
    );
    report(args.common.json, fields, diff, &summary);
    Ok(())
}

/// The renderer a `--method` selects.
fn renderer(device: &wgpu::Device, args: &MeshArgs) -> Result<Box<dyn Renderer<MeshBuffers>>> {
    Ok(match args.common.method {
        Method::NPass => Box::new(MeshNPass::new(device, Method::NPass)?),
        Method::SingleView => Box::new(MeshNPass::new(device, Method::SingleView)?),
        Method::SinglePass => Box::new(MeshSinglePass::new(
            device,
            single_pass_options(device, args),
        )?),
        Method::Tiled => Box::new(MeshTiled::new(
            device,
            match args.tile_clip {
                TileClipArg::Auto => TileClip::Auto,
                TileClipArg::ClipDistances => TileClip::ClipDistances,
                TileClipArg::Discard => TileClip::Discard,
            },
        )?),
        Method::Layered => Box::new(MeshLayered::new(device)?),
        Method::Mrt => Box::new(MeshMrt::new(device)?),
        Method::Warp => warp_renderer(
            device,
            &args.common.warp,
            MeshNPass::new(device, Method::Warp)?,
        )?,
    })
}

fn single_pass_options(device: &wgpu::Device, args: &MeshArgs) -> MeshSinglePassOptions {
    MeshSinglePassOptions {
        visibility: match args.visibility {
            VisibilityArg::Auto => Visibility::best_exact(device),
            VisibilityArg::Exact => Visibility::Exact,
            VisibilityArg::Atomic => Visibility::Atomic,
            VisibilityArg::Compute => Visibility::Compute,
            VisibilityArg::Fast => Visibility::Fast,
        },
        bounds: match args.bounds {
            BoundsArg::Exact => CoverBounds::Exact,
            BoundsArg::Paper => CoverBounds::Paper,
        },
    }
}
