//! `autostereo gaussians`: render 3D Gaussian splats (graphdeco `.ply`, antimatter15 `.splat`,
//! Niantic `.spz`; a generated scene when no file is given).

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::Result;
use autostereo::gaussians::{GaussianOptions, GaussianScene, Gaussians, SortOn};
use autostereo::render::Method;
use autostereo::RendererOptions;

use crate::args::{gpu, RenderArgs};
use crate::run::{render_and_save, report, run_summary, Rendered};

#[derive(clap::Args)]
pub struct GaussiansArgs {
    /// graphdeco 3DGS PLY, antimatter15 `.splat` or Niantic `.spz` (told by the first bytes,
    /// else the extension); a generated torus of Gaussians around a ball when omitted.
    file: Option<PathBuf>,
    #[command(flatten)]
    common: RenderArgs,
    #[command(flatten, next_help_heading = "Method")]
    gaussians: GaussianFlags,
    #[command(flatten)]
    crop: crate::crop_box_arg::CropBoxArgs,
}

/// How Gaussian splats are rendered: the flags `gaussians` and `view` share.
#[derive(clap::Args, Clone, Debug, PartialEq)]
pub struct GaussianFlags {
    /// Where the depth sort runs each frame: gpu (a bitonic sort in compute passes) or cpu
    /// (sorted on the CPU and uploaded).
    #[arg(long, value_enum, default_value = "gpu")]
    sort: SortOn,
    /// Single pass: every subpixel evaluates the SH itself instead of reading a colour table
    /// filled once per Gaussian and view (the same image, 8 bytes per Gaussian and view less
    /// memory; slower at few views, faster at a hundred: docs/GAUSSIANS.md; scenes whose table
    /// would not fit a storage binding do this by themselves).
    #[arg(long)]
    sh_per_subpixel: bool,
}

impl GaussianFlags {
    /// Refuse what the chosen method would ignore.
    pub fn check(&self, method: Method) -> Result<()> {
        if self.sh_per_subpixel && method != Method::SinglePass {
            anyhow::bail!(
                "--sh-per-subpixel: only the single pass reads a colour table per subpixel \
                 (the {method} method evaluates each view's colours once per view); drop it or \
                 use --method single-pass"
            );
        }
        Ok(())
    }

    /// The Gaussians in `file`, the generated scene without one.
    pub fn load(
        &self,
        file: Option<&Path>,
        crop: crate::crop_box_arg::CropBoxArgs,
    ) -> Result<Gaussians> {
        let gaussians = match file {
            Some(path) => {
                crate::progress::during(&crate::progress::loading(path), || Gaussians::load(path))?
            }
            None => builtin_scene(),
        };
        Ok(match crop.crop_box {
            Some(keep) => gaussians.cropped(keep)?,
            None => gaussians,
        })
    }

    /// The Gaussian options the flags say.
    pub fn options(&self) -> GaussianOptions {
        GaussianOptions {
            sort: self.sort,
            color_table: !self.sh_per_subpixel,
        }
    }
}

/// Gaussians in the scene without a file (`Gaussians::generated`: a capture-like torus and
/// ground disc, SH degree 3; the bench renders the same scene at 131,072).
pub const BUILTIN_GAUSSIANS: usize = 4096;

/// The scene without a file.
pub fn builtin_scene() -> Gaussians {
    Gaussians::generated(BUILTIN_GAUSSIANS)
}

pub fn run(args: GaussiansArgs) -> Result<()> {
    let mut plan = args.common.plan(
        args.file.as_deref(),
        autostereo::DataKind::Gaussians,
        crate::warp_cmd::WarpArgs::default(),
    )?;
    plan.check_flags(&autostereo::gaussians::METHODS, |m| args.gaussians.check(m))?;
    let start = Instant::now();
    let gaussians = args.gaussians.load(args.file.as_deref(), args.crop)?;
    let load_ms = start.elapsed().as_secs_f64() * 1e3;
    gaussians.validate()?;
    let bounds = gaussians
        .bounds()
        .expect("validate() refuses empty and non-finite Gaussians");
    let frame = plan.decide(
        plan.frame(bounds)?,
        bounds,
        |_| autostereo::render::auto::Workload::Gaussians,
        &autostereo::gaussians::METHODS,
        |m| args.gaussians.check(m),
    )?;
    let ctx = gpu()?;
    let device = &ctx.device;
    let options = RendererOptions {
        gaussians: args.gaussians.options(),
        ..plan.options
    };
    // Before the upload: a method without a Gaussian path is refused at once.
    let mut renderer = options.gaussians_renderer(device)?;
    let scene = GaussianScene::new(device, &gaussians)?;
    let (count, sh_degree) = (gaussians.len(), gaussians.sh_degree);
    drop(gaussians);
    let sort = args.gaussians.sort.name();
    let extra = serde_json::json!({
        "gaussians": count,
        "sh_degree": sh_degree,
        "sort": sort,
        "load_ms": load_ms,
    });
    let npass = RendererOptions {
        method: Method::NPass,
        ..options
    };
    let Rendered { run, fields, diff } = render_and_save(
        &ctx,
        &mut plan,
        &options,
        renderer.as_mut(),
        |o| o.gaussians_renderer(device),
        npass,
        &scene,
        &frame,
        bounds,
        extra,
    )?;
    let summary = format!(
        "{}: {count} Gaussians (SH degree {sh_degree}, loaded in {load_ms:.0} ms), {sort} sort, {}",
        plan.method.name(),
        run_summary(&ctx, &plan, &frame, &run)
    );
    report(plan.output.json, fields, diff, &summary);
    Ok(())
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_builtin_scene_is_valid_and_the_same_every_time() {
        let a = super::builtin_scene();
        a.validate().unwrap();
        assert_eq!(a, super::builtin_scene());
        assert_eq!(a.len(), super::BUILTIN_GAUSSIANS);
    }
}
