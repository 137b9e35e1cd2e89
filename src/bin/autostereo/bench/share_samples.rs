//! `bench --volumes`: the single pass's sample sharing among a pixel's K rays
//! (`VolumeScene::share_samples`, `wgsl/volume/shared/share.wgsl`) on the paper's display at
//! N = 8: time, PSNR and the share of subpixels off by > 2/255 against the exact single pass of
//! the same run, per tolerance TAU.

use std::fmt::Write as _;

use anyhow::Result;
use autostereo::image_io::compare;
use autostereo::render::{AnyScene, Method};
use autostereo::timing::FrameTimer;

use super::scenes::{self, AnyRenderer, BenchScene, Kind};
use super::tradeoffs::Tradeoff;
use super::{image, time_frame, Plan};

type Ctx = autostereo::gpu::GpuContext;

/// The tolerances measured, in voxels (0: the exact path, timed again beside the others).
const TAUS: [f32; 7] = [0.0, 0.125, 0.25, 0.5, 1.0, 2.0, 4.0];

const STUDY: &str = "share samples";

/// Every tolerance on every volume (study `share samples`, setting `TAU`).
pub fn measure(
    ctx: &Ctx,
    timer: &FrameTimer,
    scenes: &mut [BenchScene],
    plan: &Plan,
) -> Result<Vec<Tradeoff>> {
    let mut out = Vec::new();
    let bar = crate::progress::bar((scenes.len() * TAUS.len()) as u64, STUDY);
    for scene in scenes.iter_mut() {
        let frame = scenes::frame(scene.bounds, super::report::PAPER_DISPLAY, plan.size)?;
        let mut sp = AnyRenderer::new(&ctx.device, &scene.data, Method::SinglePass)?;
        set_tolerance(scene, 0.0);
        let exact = image(ctx, scene, &mut sp, &frame)?;
        for tau in TAUS {
            set_tolerance(scene, tau);
            let ms = time_frame(ctx, timer, scene, &mut sp, &frame, plan.study_frames())?;
            let d = compare(&image(ctx, scene, &mut sp, &frame)?, &exact)?;
            crate::progress::log(
                &bar,
                &format!(
                    "  {STUDY} / {} TAU = {tau}: {ms:.1} ms, {:.1} dB, {:.2} % off",
                    scene.name,
                    d.psnr_db,
                    100.0 * d.frac_off_2
                ),
            );
            bar.inc(1);
            out.push(Tradeoff {
                study: STUDY.into(),
                scene: scene.name.clone(),
                setting: tau.to_string(),
                ms,
                psnr_db: d.psnr_db,
                frac_off_2: d.frac_off_2,
                hole_share: None,
            });
        }
        set_tolerance(scene, 0.0);
    }
    bar.finish_and_clear();
    Ok(out)
}

fn set_tolerance(scene: &mut BenchScene, tau: f32) {
    if let AnyScene::Volume(v) = &mut scene.data {
        v.share_samples = tau;
    }
}

/// The sample-sharing section of BENCHMARKS.md: per volume and TAU the time (and its ratio to
/// the exact single pass timed beside it), the accuracy against the exact image, and the
/// single view of the same run; plots of time and PSNR against TAU.
pub fn report(md: &mut String, r: &super::Results, images: &std::path::Path) -> Result<()> {
    use super::plot::{draw, push, Axes, Series};
    writeln!(md, "## Sample sharing among a pixel's K rays\n")?;
    writeln!(
        md,
        "`--share-samples TAU`: where the samples of a pixel's K = 3 rays on a sample plane all \
         lie within TAU voxels of each other (an interval of planes around the focal plane, \
         where the views converge), the rays take their mean ray's samples instead of their \
         own (`wgsl/volume/shared/share.wgsl`). Paper's display (N = 8), {}×{}. PSNR and the \
         share of subpixels off by more than 2/255 are against the exact single pass (TAU = 0) \
         of the same run; `vs exact` is the time over the exact single pass timed in the same \
         loop; SV / SP is the single view's time over the setting's (≥ 0.5 is the issue's \
         target).\n",
        r.size[0], r.size[1]
    )?;
    writeln!(
        md,
        "| volume | TAU voxels | ms | vs exact | PSNR dB | off > 2/255 | SV / SP |\n\
         |---|---:|---:|---:|---:|---:|---:|"
    )?;
    let (mut time_series, mut psnr_series): (Vec<Series>, Vec<Series>) = (Vec::new(), Vec::new());
    let points = r.tradeoffs.iter().filter(|t| t.study == STUDY);
    for t in points.clone() {
        let tau: f64 = t.setting.parse().unwrap_or(0.0);
        let exact = points
            .clone()
            .find(|u| u.scene == t.scene && u.setting == "0")
            .map(|u| u.ms);
        let sv = r
            .rows
            .iter()
            .find(|x| {
                x.scene == t.scene
                    && x.kind == Kind::SingleView
                    && x.display == super::report::PAPER_DISPLAY
            })
            .map(|x| x.ms);
        writeln!(
            md,
            "| {} | {tau} | {:.1} | {} | {} | {:.2} % | {} |",
            t.scene,
            t.ms,
            exact.map_or("–".into(), |e| format!("{:.2}×", t.ms / e)),
            if t.psnr_db > 99.0 {
                "exact".to_string()
            } else {
                format!("{:.1}", t.psnr_db)
            },
            100.0 * t.frac_off_2,
            sv.map_or("–".into(), |s| format!("{:.2}", s / t.ms)),
        )?;
        if tau > 0.0 {
            if let Some(e) = exact {
                push(&mut time_series, &t.scene, (tau, t.ms / e));
            }
            push(&mut psnr_series, &t.scene, (tau, t.psnr_db));
        }
    }
    writeln!(md)?;
    for (file, title, y, series) in [
        (
            "bench_share_samples_time.png",
            "sample sharing: time relative to the exact single pass",
            "ms / exact ms",
            &time_series,
        ),
        (
            "bench_share_samples_psnr.png",
            "sample sharing: PSNR against the exact single pass",
            "PSNR dB",
            &psnr_series,
        ),
    ] {
        let axes = Axes {
            title,
            x: "TAU (voxels)",
            y,
            log_x: true,
            log_y: false,
            lines: true,
        };
        if draw(&images.join(file), &axes, series)? {
            writeln!(md, "![{title}](images/{file})\n")?;
        }
    }
    Ok(())
}
