//! `autostereo-bench --warp`: the warp's accuracy against the N-pass oracle for R = 1, 2, 3 and N/2
//! reference views at N = 8 and 45 (the run's displays), with its time and the share of
//! subpixels it filled rather than saw.

use anyhow::Result;
use autostereo::image_io::compare;
use autostereo::render::Method;
use autostereo::timing::FrameTimer;
use autostereo::warp::{WarpOptions, WarpPath};
use autostereo::{AnyRenderer, RendererOptions};

use super::scenes::{self, BenchScene};
use super::tradeoffs::Tradeoff;
use super::{image, sweep_display, time_frame, Plan};

type Ctx = autostereo::gpu::GpuContext;

/// The warp of `scene`'s primitive with `warp`.
fn warp(device: &wgpu::Device, scene: &BenchScene, warp: WarpOptions) -> Result<AnyRenderer> {
    let options = RendererOptions {
        warp,
        ..RendererOptions::new(Method::Warp)
    };
    Ok(AnyRenderer::new(device, &scene.data, &options)?)
}

/// R = 1, 2, 3, N/2 (distinct, ≤ N) on the direct path, and R = 2 per view.
fn settings(n: u32) -> Vec<(u32, WarpPath)> {
    let mut rs = vec![1, 2, 3, n / 2];
    rs.retain(|&r| r >= 1 && r <= n);
    rs.sort_unstable();
    rs.dedup();
    let mut out: Vec<_> = rs.into_iter().map(|r| (r, WarpPath::Direct)).collect();
    out.push((2, WarpPath::PerView));
    out
}

/// Every setting on every scene at each N of the plan (study `warp N=…`).
pub fn measure(
    ctx: &Ctx,
    timer: &FrameTimer,
    scenes: &[BenchScene],
    plan: &Plan,
) -> Result<Vec<Tradeoff>> {
    let mut out = Vec::new();
    for scene in scenes {
        for &n in &plan.views {
            let frame = scenes::frame(scene.bounds, &sweep_display(n), plan.size)?;
            let npass = RendererOptions::new(Method::NPass);
            let mut npass = AnyRenderer::new(&ctx.device, &scene.data, &npass)?;
            let oracle = image(ctx, scene, &mut npass, &frame)?;
            drop(npass);
            for (references, path) in settings(n) {
                let options = WarpOptions {
                    references,
                    path,
                    ..Default::default()
                };
                let mut r = warp(&ctx.device, scene, options)?;
                let ms = time_frame(ctx, timer, scene, &mut r, &frame, plan.study_frames())?;
                let d = compare(&image(ctx, scene, &mut r, &frame)?, &oracle)?;
                let holes = WarpOptions {
                    hole_mask: true,
                    ..options
                };
                let mask = image(ctx, scene, &mut warp(&ctx.device, scene, holes)?, &frame)?;
                let filled = mask.data.iter().filter(|&&v| v >= 128).count();
                let hole_share = filled as f64 / mask.data.len().max(1) as f64;
                let setting = format!(
                    "R = {references}, {}",
                    match path {
                        WarpPath::Direct => "direct",
                        WarpPath::PerView => "per-view",
                    }
                );
                eprintln!(
                    "  warp / {} N = {n}: {setting}: {ms:.1} ms, {:.1} dB, holes {:.2} %",
                    scene.name,
                    d.psnr_db,
                    100.0 * hole_share
                );
                out.push(Tradeoff {
                    study: format!("warp N={n}"),
                    scene: scene.name.clone(),
                    setting,
                    ms,
                    psnr_db: d.psnr_db,
                    frac_off_2: d.frac_off_2,
                    hole_share: Some(hole_share),
                });
            }
        }
    }
    Ok(out)
}

/// The warp section of BENCHMARKS.md: per scene and N, each setting's time next to the
/// N-pass and the best single pass of the same run, its accuracy and hole share; one plot of
/// PSNR against R.
pub fn report(md: &mut String, r: &super::Results, images: &std::path::Path) -> Result<()> {
    use super::plot::{draw, Axes, Series};
    use super::scenes::Kind;
    use std::fmt::Write as _;
    writeln!(md, "## Depth-image warping against the N-pass oracle\n")?;
    writeln!(
        md,
        "R reference views rendered by the primitive's N-pass passes with their nearness, every \
         view warped from the two references around it (docs/WARPING.md). PSNR and the share of \
         subpixels off by more than 2/255 are against the N-pass image of the same frame; holes \
         are the subpixels filled (disocclusions and image edges) rather than seen. Times are \
         of the same run as the method tables above: N-pass and the best single pass of the \
         same scene, display and size beside them.\n"
    )?;
    writeln!(
        md,
        "| scene | N | setting | ms | PSNR dB | off > 2/255 | holes | N-pass ms | single pass ms |\n\
         |---|---:|---|---:|---:|---:|---:|---:|---:|"
    )?;
    let mut series: Vec<Series> = Vec::new();
    for t in r.tradeoffs.iter().filter(|t| t.hole_share.is_some()) {
        let n: u32 = t.study.trim_start_matches("warp N=").parse().unwrap_or(0);
        let rows: Vec<_> = r
            .rows
            .iter()
            .filter(|x| x.scene == t.scene && x.views == n && x.size == r.size)
            .collect();
        let best = |kind: Kind| {
            rows.iter()
                .filter(|x| x.kind == kind)
                .map(|x| x.ms)
                .min_by(f64::total_cmp)
                .map_or("–".to_string(), |ms| format!("{ms:.1}"))
        };
        writeln!(
            md,
            "| {} | {n} | {} | {:.1} | {:.1} | {:.2} % | {:.2} % | {} | {} |",
            t.scene,
            t.setting,
            t.ms,
            t.psnr_db.min(99.0),
            100.0 * t.frac_off_2,
            100.0 * t.hole_share.unwrap_or(0.0),
            best(Kind::NPass),
            best(Kind::SinglePass),
        )?;
        let Some(references) = t
            .setting
            .strip_prefix("R = ")
            .and_then(|s| s.strip_suffix(", direct"))
            .and_then(|s| s.parse::<f64>().ok())
        else {
            continue;
        };
        let name = format!("{} N = {n}", t.scene);
        let point = (references, t.psnr_db.min(99.0));
        match series.iter_mut().find(|s| s.0 == name) {
            Some(s) => s.1.push(point),
            None => series.push((name, vec![point])),
        }
    }
    writeln!(md)?;
    let file = "bench_warp_psnr.png";
    let axes = Axes {
        title: "warp: PSNR vs reference views R (identical shown as 99 dB)",
        x: "reference views R",
        y: "PSNR dB vs N-pass",
        log_x: true,
        log_y: false,
        lines: true,
    };
    if draw(&images.join(file), &axes, &series)? {
        writeln!(md, "![warp accuracy](images/{file})\n")?;
    }
    Ok(())
}
