//! `bench --volumes`: the volume march's approximations, each against the exact path of the
//! same run: sample sharing among a pixel's K rays (`--share-samples TAU`, single pass only),
//! the probing stride through transparent material (`--empty-stride P`) and its thin-material
//! form (`--thin-alpha A`, at stride 8). Per setting: time, PSNR and the share of subpixels off
//! by > 2/255 for the single pass on the paper's display (N = 8); the stride, which applies to
//! every method, also for the single view, the N-pass and the single pass at N = 64.

use std::fmt::Write as _;

use anyhow::Result;
use autostereo::image_io::compare;
use autostereo::render::{AnyScene, Method};
use autostereo::timing::FrameTimer;
use autostereo::volume::VolumeScene;

use super::report::{base_size, find, rows_of};
use super::scenes::{self, AnyRenderer, BenchScene, Kind};
use super::tradeoffs::Tradeoff;
use super::{image, sweep_display, time_frame, Plan, Results};

type Ctx = autostereo::gpu::GpuContext;

/// One approximation and the settings measured.
struct Study {
    name: &'static str,
    /// The command-line flag, and what its value counts.
    flag: &'static str,
    unit: &'static str,
    settings: &'static [f32],
    set: fn(&mut VolumeScene, f32),
    /// Also measured for the single view, the N-pass and the single pass at N = 64.
    every_method: bool,
}

const SHARE: &str = "share samples";
const STRIDE: &str = "empty stride";
/// The stride the thin-material study probes with.
const THIN_STRIDE: u32 = 8;

const STUDIES: [Study; 3] = [
    Study {
        name: SHARE,
        flag: "--share-samples TAU",
        unit: "TAU (voxels)",
        settings: &[0.0, 0.125, 0.25, 0.5, 1.0, 2.0, 4.0],
        set: |s, v| s.share_samples = v,
        every_method: false,
    },
    Study {
        name: STRIDE,
        flag: "--empty-stride P",
        unit: "P (sample planes)",
        settings: &[1.0, 2.0, 4.0, 8.0, 16.0, 32.0],
        set: |s, v| s.empty_stride = v as u32,
        every_method: true,
    },
    Study {
        name: "thin alpha",
        flag: "--empty-stride 8 --thin-alpha A",
        unit: "A (opacity per step)",
        settings: &[0.0, 0.002, 0.005, 0.01, 0.02, 0.05],
        set: |s, v| {
            s.empty_stride = THIN_STRIDE;
            s.thin_alpha = v;
        },
        every_method: false,
    },
];

/// The runs of a study beyond the single pass at N = 8: (suffix of the study name, method,
/// views).
const OTHER_RUNS: [(&str, Method, u32); 3] = [
    (" / single view", Method::SingleView, 8),
    (" / n-pass", Method::NPass, 8),
    (" / N = 64", Method::SinglePass, 64),
];

fn exact(scene: &mut VolumeScene) {
    scene.share_samples = 0.0;
    scene.empty_stride = 1;
    scene.thin_alpha = 0.0;
}

fn volume(scene: &mut BenchScene) -> Option<&mut VolumeScene> {
    match &mut scene.data {
        AnyScene::Volume(v) => Some(v),
        _ => None,
    }
}

/// Every study on every volume.
pub fn measure(
    ctx: &Ctx,
    timer: &FrameTimer,
    scenes: &mut [BenchScene],
    plan: &Plan,
) -> Result<Vec<Tradeoff>> {
    let runs = |s: &Study| 1 + if s.every_method { OTHER_RUNS.len() } else { 0 };
    let total: usize = STUDIES.iter().map(|s| runs(s) * s.settings.len()).sum();
    let bar = crate::progress::bar((scenes.len() * total) as u64, "approximations");
    let mut out = Vec::new();
    for scene in scenes.iter_mut() {
        for study in &STUDIES {
            let mut list = vec![("", Method::SinglePass, 8)];
            if study.every_method {
                list.extend(OTHER_RUNS);
            }
            for (suffix, method, views) in list {
                let display = sweep_display(views);
                let frame = scenes::frame(scene.bounds, &display, plan.size)?;
                let mut renderer = AnyRenderer::new(&ctx.device, &scene.data, method)?;
                let Some(v) = volume(scene) else { break };
                exact(v);
                let reference = image(ctx, scene, &mut renderer, &frame)?;
                for &setting in study.settings {
                    if let Some(v) = volume(scene) {
                        exact(v);
                        (study.set)(v, setting);
                    }
                    let frames = plan.study_frames();
                    let ms = time_frame(ctx, timer, scene, &mut renderer, &frame, frames)?;
                    let d = compare(&image(ctx, scene, &mut renderer, &frame)?, &reference)?;
                    let study = format!("{}{suffix}", study.name);
                    crate::progress::log(
                        &bar,
                        &format!(
                            "  {study} / {} = {setting}: {ms:.1} ms, {:.1} dB, {:.2} % off",
                            scene.name,
                            d.psnr_db,
                            100.0 * d.frac_off_2
                        ),
                    );
                    bar.inc(1);
                    out.push(Tradeoff {
                        study,
                        scene: scene.name.clone(),
                        setting: setting.to_string(),
                        ms,
                        psnr_db: d.psnr_db,
                        frac_off_2: d.frac_off_2,
                        hole_share: None,
                    });
                }
            }
            if let Some(v) = volume(scene) {
                exact(v);
            }
        }
    }
    bar.finish_and_clear();
    Ok(out)
}

/// The measurement of `study` on `scene` at `setting`.
fn point<'a>(r: &'a Results, study: &str, scene: &str, setting: &str) -> Option<&'a Tradeoff> {
    r.tradeoffs
        .iter()
        .find(|t| t.study == study && t.scene == scene && t.setting == setting)
}

/// The exact single pass of `scene` timed in the stride study's loop (P = 1).
fn exact_ms(r: &Results, scene: &str, suffix: &str) -> Option<f64> {
    point(r, &format!("{STRIDE}{suffix}"), scene, "1").map(|t| t.ms)
}

/// Exact N-pass or single view of the main table (N views, the run's size).
fn exact_row(r: &Results, scene: &str, kind: Kind, views: u32) -> Option<f64> {
    find(
        &rows_of(r, scene, &sweep_display(views), base_size(r)),
        kind,
    )
    .map(|x| x.ms)
}

fn db(psnr: f64) -> String {
    if psnr > 99.0 {
        "exact".into()
    } else {
        format!("{psnr:.1}")
    }
}

fn ratio(a: Option<f64>, b: f64) -> String {
    a.map_or("–".into(), |a| format!("{:.2}", a / b))
}

/// The section of BENCHMARKS.md: a table per study, the fastest setting ≥ 40 dB against the
/// volume targets, and plots of time and PSNR against each setting and of PSNR against time.
pub fn report(md: &mut String, r: &Results, images: &std::path::Path) -> Result<()> {
    use super::plot::{draw, push, Axes, Series};
    writeln!(md, "## Approximations of the volume march\n")?;
    writeln!(
        md,
        "Each against the exact path of the same run, on the paper's display (N = 8), {}×{}: \
         PSNR and the share of subpixels off by more than 2/255 against the exact image of the \
         same method and display; `vs exact` is the time over the exact single pass timed in \
         the same loop; `SV / SP` and `N-pass / SP` divide the *exact* single view's and \
         N-pass's times of the main table by the setting's single pass (the issue's targets: \
         ≥ 0.5 and ≥ 5).\n",
        r.size[0], r.size[1]
    )?;
    let mut pareto: Vec<Series> = Vec::new();
    for study in &STUDIES {
        writeln!(md, "### {} (`{}`)\n", study.name, study.flag)?;
        let wide = study.every_method;
        writeln!(
            md,
            "| volume | {} | ms | vs exact | PSNR dB | off > 2/255 | SV / SP | N-pass / SP |{}",
            study.unit,
            if wide {
                " SV ms, same P | SV / SP, same P | N-pass / SP, same P | N = 64 ms | N = 64 dB | \
                 N-pass / SP, N = 64 |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
            } else {
                "\n|---|---:|---:|---:|---:|---:|---:|---:|"
            }
        )?;
        let (mut time_series, mut psnr_series): (Vec<Series>, Vec<Series>) = (vec![], vec![]);
        for t in r.tradeoffs.iter().filter(|t| t.study == study.name) {
            let x: f64 = t.setting.parse().unwrap_or(0.0);
            let exact = exact_ms(r, &t.scene, "");
            let sv = exact_row(r, &t.scene, Kind::SingleView, 8);
            let npass = exact_row(r, &t.scene, Kind::NPass, 8);
            write!(
                md,
                "| {} | {} | {:.1} | {} | {} | {:.2} % | {} | {} |",
                t.scene,
                t.setting,
                t.ms,
                exact.map_or("–".into(), |e| format!("{:.2}×", t.ms / e)),
                db(t.psnr_db),
                100.0 * t.frac_off_2,
                ratio(sv, t.ms),
                ratio(npass, t.ms),
            )?;
            if wide {
                let other = |suffix: &str| {
                    point(r, &format!("{}{suffix}", study.name), &t.scene, &t.setting)
                };
                let sv_same = other(OTHER_RUNS[0].0);
                let np_same = other(OTHER_RUNS[1].0);
                let wide64 = other(OTHER_RUNS[2].0);
                write!(
                    md,
                    " {} | {} | {} | {} | {} | {} |",
                    sv_same.map_or("–".into(), |s| format!("{:.1}", s.ms)),
                    ratio(sv_same.map(|s| s.ms), t.ms),
                    ratio(np_same.map(|s| s.ms), t.ms),
                    wide64.map_or("–".into(), |s| format!("{:.1}", s.ms)),
                    wide64.map_or("–".into(), |s| db(s.psnr_db)),
                    wide64.map_or("–".into(), |s| ratio(
                        exact_row(r, &t.scene, Kind::NPass, 64),
                        s.ms
                    )),
                )?;
            }
            writeln!(md)?;
            if let Some(e) = exact {
                push(&mut time_series, &t.scene, (x.max(1e-3), t.ms / e));
                if t.psnr_db <= 99.0 {
                    let name = format!("{}: {}", t.scene, study.name);
                    push(&mut pareto, &name, (t.ms / e, t.psnr_db));
                }
            }
            push(
                &mut psnr_series,
                &t.scene,
                (x.max(1e-3), t.psnr_db.min(99.0)),
            );
        }
        writeln!(md)?;
        let stem = study.name.replace(' ', "_");
        for (kind, y, series) in [
            ("time", "ms / exact single pass ms", &time_series),
            ("psnr", "PSNR dB (99: exact)", &psnr_series),
        ] {
            let title = format!("{}: {kind} against the setting", study.name);
            let file = format!("bench_{stem}_{kind}.png");
            let axes = Axes {
                title: &title,
                x: study.unit,
                y,
                log_x: true,
                log_y: false,
                lines: true,
            };
            if draw(&images.join(&file), &axes, series)? {
                writeln!(md, "![{title}](images/{file})\n")?;
            }
        }
    }
    let axes = Axes {
        title: "volume approximations: PSNR against time (exact = 1)",
        x: "ms / exact single pass ms",
        y: "PSNR dB against the exact image",
        log_x: false,
        log_y: false,
        lines: true,
    };
    if draw(
        &images.join("bench_approximations_pareto.png"),
        &axes,
        &pareto,
    )? {
        writeln!(
            md,
            "Up and left is better: a setting is worth having where its curve lies above the \
             others at equal time.\n\n![{}](images/bench_approximations_pareto.png)\n",
            axes.title
        )?;
    }
    targets(md, r)
}

/// The volume targets at the fastest stride keeping ≥ 40 dB at N = 8 and N = 64.
fn targets(md: &mut String, r: &Results) -> Result<()> {
    writeln!(md, "### The volume targets at a setting ≥ 40 dB\n")?;
    writeln!(
        md,
        "Per volume, the fastest `--empty-stride` whose single pass keeps ≥ 40 dB against the \
         exact image at N = 8 and at N = 64, against the *exact* N-pass and single view (the \
         issue's targets), and, for comparison, against the N-pass and single view at the same \
         stride (the stride speeds every method up).\n"
    )?;
    writeln!(
        md,
        "| volume | P | N-pass / SP, N = 8 (≥ 5) | N-pass / SP, N = 64 (≥ 30) | SV / SP (≥ 0.5) | \
         status | same P: N-pass / SP, N = 8 | same P: SV / SP |\n\
         |---|---:|---:|---:|---:|---|---:|---:|"
    )?;
    let mut names: Vec<&str> = r
        .tradeoffs
        .iter()
        .filter(|t| t.study == STRIDE)
        .map(|t| t.scene.as_str())
        .collect();
    names.dedup();
    for scene in names {
        let candidates = r.tradeoffs.iter().filter(|t| {
            t.study == STRIDE
                && t.scene == scene
                && t.psnr_db >= 40.0
                && point(r, &format!("{STRIDE} / N = 64"), scene, &t.setting)
                    .is_some_and(|w| w.psnr_db >= 40.0)
        });
        let Some(best) = candidates.min_by(|a, b| a.ms.total_cmp(&b.ms)) else {
            continue;
        };
        let other = |suffix: &str| {
            point(r, &format!("{STRIDE}{suffix}"), scene, &best.setting).map(|t| t.ms)
        };
        let n8 = exact_row(r, scene, Kind::NPass, 8).map(|n| n / best.ms);
        let n64 = exact_row(r, scene, Kind::NPass, 64)
            .zip(other(" / N = 64"))
            .map(|(n, s)| n / s);
        let sv = exact_row(r, scene, Kind::SingleView, 8).map(|s| s / best.ms);
        let met = n8.is_some_and(|v| v >= 5.0)
            && n64.is_some_and(|v| v >= 30.0)
            && sv.is_some_and(|v| v >= 0.5);
        let show = |v: Option<f64>| v.map_or("–".into(), |v| format!("{v:.2}"));
        writeln!(
            md,
            "| {scene} | {} | {} | {} | {} | {} | {} | {} |",
            best.setting,
            show(n8),
            show(n64),
            show(sv),
            if met { "met" } else { "**missed**" },
            ratio(other(" / n-pass"), best.ms),
            ratio(other(" / single view"), best.ms),
        )?;
    }
    writeln!(md)?;
    Ok(())
}
