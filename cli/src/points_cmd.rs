//! `autostereo points`: render a point cloud as splats (a generated torus scene when no file is
//! given).

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{bail, Result};
use autostereo::points::SplatDepth;
use autostereo::points::{GroupCount, PointCloud, SplatScene, Splats};
use autostereo::render::Method;
use autostereo::{PointOptions, RendererOptions};

use crate::args::{gpu, RenderArgs};
use crate::run::{render_and_save, report, run_summary, Rendered};

#[derive(clap::Args)]
pub struct PointsArgs {
    /// PLY (ASCII or binary), LAS/LAZ, or OBJ (its vertices); a generated torus scene when
    /// omitted.
    file: Option<PathBuf>,
    #[command(flatten)]
    common: RenderArgs,
    #[command(flatten)]
    warp: crate::warp_cmd::WarpArgs,
    #[command(flatten, next_help_heading = "Method")]
    points: PointFlags,
    #[command(flatten)]
    crop: crate::crop_box_arg::CropBoxArgs,
}

/// How a point cloud is prepared and rendered: the flags `points` and `view` share.
#[derive(clap::Args, Clone, Debug, PartialEq)]
pub struct PointFlags {
    /// ε of the ε-z compositing, as a fraction of the scene's depth extent (bounding diameter).
    #[arg(long, default_value_t = autostereo::points::DEFAULT_EPSILON_FRACTION, allow_negative_numbers = true)]
    epsilon: f32,
    /// Splat groups: `auto` (no overlap inside a group) or a fixed count K.
    #[arg(long, default_value = "auto", value_parser = parse_groups)]
    groups: GroupCount,
    /// Multiply every splat radius (given or estimated) by S.
    #[arg(long, default_value_t = 1.0, allow_negative_numbers = true)]
    radius_scale: f32,
    /// Single-pass depth per group image: exact (per subpixel) or the paper's (per pixel).
    #[arg(long, value_enum, default_value = "exact")]
    depth: SplatDepth,
}

impl PointFlags {
    /// Refuse what `method` would ignore, then [`Self::check_values`].
    pub fn check(&self, method: Method) -> Result<()> {
        if self.depth != SplatDepth::Exact && method != Method::SinglePass {
            bail!(
                "--depth: only the single pass keeps one depth per group image (the {method} \
                 method renders each view with its own depth); drop it or use --method \
                 single-pass"
            );
        }
        self.check_values()
    }

    /// Refuse what would render nothing or nonsense (the viewer, which cycles methods, checks
    /// only this).
    pub fn check_values(&self) -> Result<()> {
        if !(self.epsilon.is_finite() && self.epsilon >= 0.0) {
            bail!("--epsilon {}: must be finite and ≥ 0", self.epsilon);
        }
        if !(self.radius_scale.is_finite() && self.radius_scale > 0.0) {
            bail!(
                "--radius-scale {}: the radius scale must be a finite number > 0 (0 draws nothing)",
                self.radius_scale
            );
        }
        Ok(())
    }

    /// How the library prepares a point cloud (`autostereo::load`).
    pub fn load_options(&self, crop: crate::crop_box_arg::CropBoxArgs) -> autostereo::PointLoad {
        autostereo::PointLoad {
            radius_scale: self.radius_scale,
            groups: self.groups,
            crop: crop.crop_box,
        }
    }

    /// `cloud` cropped and completed into splats as the flags say.
    pub fn complete(
        &self,
        cloud: &PointCloud,
        crop: crate::crop_box_arg::CropBoxArgs,
    ) -> Result<autostereo::PointData> {
        Ok(autostereo::complete(cloud, &self.load_options(crop))?)
    }

    /// The cloud in `file`, the generated torus scene without one.
    fn cloud(file: Option<&Path>) -> Result<PointCloud> {
        Ok(match file {
            Some(path) => {
                crate::progress::during(&crate::progress::loading(path), || PointCloud::load(path))?
            }
            None => PointCloud::torus_scene(),
        })
    }

    /// The scene on the GPU.
    pub fn scene(&self, device: &wgpu::Device, splats: &Splats) -> Result<SplatScene> {
        Ok(SplatScene::new(device, splats, self.groups)?)
    }

    /// The point options the flags say.
    pub fn options(&self) -> PointOptions {
        PointOptions {
            depth: self.depth,
            epsilon_fraction: self.epsilon,
        }
    }
}

fn parse_groups(s: &str) -> Result<GroupCount, String> {
    if s == "auto" {
        return Ok(GroupCount::Auto);
    }
    match s.parse::<u32>() {
        Ok(k) if k >= 1 => Ok(GroupCount::Fixed(k)),
        _ => Err(format!("'{s}' is neither 'auto' nor a group count ≥ 1")),
    }
}

pub fn run(args: PointsArgs) -> Result<()> {
    let mut plan = args.common.plan(
        args.file.as_deref(),
        autostereo::DataKind::Points,
        args.warp,
    )?;
    plan.check_flags(&autostereo::points::METHODS, |m| args.points.check(m))?;
    let start = Instant::now();
    let cloud = PointFlags::cloud(args.file.as_deref())?;
    let load_ms = start.elapsed().as_secs_f64() * 1e3;
    let autostereo::PointData {
        splats, completion, ..
    } = args.points.complete(&cloud, args.crop)?;
    drop(cloud);
    let bounds = splats.bounds().expect("complete() rejects empty clouds");
    let frame = plan.decide(
        plan.frame(bounds)?,
        bounds,
        |_| autostereo::render::auto::Workload::Points,
        &autostereo::points::METHODS,
        |m| args.points.check(m),
    )?;
    let ctx = gpu()?;
    let device = &ctx.device;
    let scene = args.points.scene(device, &splats)?;
    let options = RendererOptions {
        points: args.points.options(),
        ..plan.options
    };
    let splat_options = options.points.for_scene(&scene);
    let mut renderer = options.points_renderer(device, &scene)?;
    let extra = serde_json::json!({
        "depth": splat_options.depth.name(),
        "points": splats.len(),
        "load_ms": load_ms,
        "normals_estimated": completion.normals_estimated,
        "radii_estimated": completion.radii_estimated,
        "estimate_ms": completion.estimate_ms,
        "groups": scene.groups(),
        "group_conflicts": scene.conflicts,
        "grouping_ms": scene.grouping_ms,
        "epsilon": splat_options.epsilon,
        "median_radius": scene.median_radius,
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
        |o| o.points_renderer(device, &scene),
        npass,
        &scene,
        &frame,
        bounds,
        extra,
    )?;
    let method_name = plan.method.name();
    let estimated = match (completion.normals_estimated, completion.radii_estimated) {
        (false, false) => String::new(),
        (n, r) => format!(
            " ({}{}{} estimated in {:.0} ms)",
            if n { "normals" } else { "" },
            if n && r { " + " } else { "" },
            if r { "radii" } else { "" },
            completion.estimate_ms
        ),
    };
    let summary = format!(
        "{method_name} ({} depth): {} points{estimated}, {} groups ({} conflicts, {:.0} ms), {}",
        splat_options.depth.name(),
        splats.len(),
        scene.groups(),
        scene.conflicts,
        scene.grouping_ms,
        run_summary(&ctx, &plan, &frame, &run)
    );
    report(plan.output.json, fields, diff, &summary);
    Ok(())
}
