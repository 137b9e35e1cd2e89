//! `--method warp` in the render commands: its flags, its renderer, and the hole share it
//! reports.

use std::path::PathBuf;

use anyhow::{bail, Result};
use autostereo::frame::Frame;
use autostereo::gpu::GpuContext;
use autostereo::render::{Method, Renderer};
use autostereo::target::SpatialTarget;
use autostereo::warp::{WarpOptions, WarpPath};
use autostereo::RendererOptions;

#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum WarpPathArg {
    /// Straight into the spatial image (each subpixel warps its own view).
    Direct,
    /// Beck's way: N view images, then the mask compositing.
    PerView,
}

/// The warp method's flags (refused with any other method).
#[derive(clap::Args)]
pub struct WarpArgs {
    /// With --method warp: reference views R, 1 … N, spread evenly over the views (default 2:
    /// the outermost views; 1: the centre view).
    #[arg(long)]
    pub references: Option<u32>,
    /// With --method warp: neighbours warped further apart than this many pixels straddle a
    /// disocclusion, filled from the background side (default 2).
    #[arg(long)]
    pub hole_gap: Option<f32>,
    /// With --method warp: direct (straight into the spatial image) or per-view (N view
    /// images first, then the mask compositing).
    #[arg(long, value_enum)]
    pub warp_path: Option<WarpPathArg>,
    /// With --method warp: also write the hole mask (255 on subpixels that were filled rather
    /// than seen by a reference) as PNG; the report gives its share either way.
    #[arg(long)]
    pub hole_mask: Option<PathBuf>,
}

impl WarpArgs {
    /// Refuse warp flags with another method, and bad values, before loading anything.
    pub fn check(&self, method: Method) -> Result<()> {
        let given = [
            ("--references", self.references.is_some()),
            ("--hole-gap", self.hole_gap.is_some()),
            ("--warp-path", self.warp_path.is_some()),
            ("--hole-mask", self.hole_mask.is_some()),
        ];
        if let Some((flag, _)) = given.iter().find(|(_, set)| *set) {
            if method != Method::Warp {
                bail!("{flag}: only with --method warp (the method is {method})");
            }
        }
        if self.references == Some(0) {
            bail!("--references 0: at least one reference view");
        }
        if let Some(path) = &self.hole_mask {
            crate::args::check_output(path)?;
        }
        WarpOptions::from(self).check()?;
        Ok(())
    }

    /// The library options these flags say.
    pub fn options(&self) -> WarpOptions {
        WarpOptions::from(self)
    }
}

impl From<&WarpArgs> for WarpOptions {
    fn from(args: &WarpArgs) -> Self {
        let default = WarpOptions::default();
        WarpOptions {
            references: args.references.unwrap_or(default.references),
            hole_gap: args.hole_gap.unwrap_or(default.hole_gap),
            path: match args.warp_path {
                Some(WarpPathArg::PerView) => WarpPath::PerView,
                Some(WarpPathArg::Direct) | None => WarpPath::Direct,
            },
            ..default
        }
    }
}

/// The report fields of a warp: R, the path, what depth the references carry, and the share
/// of subpixels filled rather than seen (from a hole-mask render of the renderer `build` makes
/// from `options`, written where asked).
pub fn hole_report<S: ?Sized>(
    ctx: &GpuContext,
    args: &WarpArgs,
    options: &RendererOptions,
    build: impl FnOnce(&RendererOptions) -> autostereo::Result<Box<dyn Renderer<S>>>,
    scene: &S,
    frame: &Frame,
) -> Result<serde_json::Value> {
    let mut options = *options;
    options.warp.hole_mask = true;
    let mut warp = build(&options)?;
    let target = SpatialTarget::new(&ctx.device, frame.size)?;
    warp.render(&ctx.device, &ctx.queue, scene, frame, &target)?;
    let mask = target.read(&ctx.device, &ctx.queue)?;
    if let Some(path) = &args.hole_mask {
        mask.save_png(path)?;
    }
    let filled = mask.data.iter().filter(|&&v| v >= 128).count();
    Ok(serde_json::json!({
        "references": options.warp.references,
        "warp_path": format!("{:?}", options.warp.path).to_lowercase(),
        "warp": warp.describe(),
        "hole_share": filled as f64 / mask.data.len().max(1) as f64,
    }))
}
