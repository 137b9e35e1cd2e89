//! `autostereo-bench --volumes`: the volume march's approximations, each against the exact path of the
//! same run: sample sharing among a pixel's K rays (`--share-samples TAU`, single pass only)
//! and the probes through transparent material (`--empty-stride P`), also through thin
//! material (`--thin-alpha A`), at the scene's sampling distance and at coarser ones (`--step
//! S`, voxels; the exact image is sampled at the scene's, by default half a voxel). Per setting:
//! time, PSNR and the share of subpixels off by more than 2/255 for the single pass on the
//! paper's display (N = 8); the probes, which apply to every method, also for the single view,
//! the N-pass and the single pass at N = 64, timed one after the other per setting so that the
//! ratios between them are side by side.

use std::fmt::Write as _;

use anyhow::Result;
use autostereo::image_io::compare;
use autostereo::render::Method;
use autostereo::timing::FrameTimer;
use autostereo::volume::VolumeSettings;
use autostereo::{AnyRenderer, AnyScene, RendererOptions, VolumeOptions};

use super::rows::{base_size, find, rows_of};
use super::scenes::{self, BenchScene, Kind};
use super::tradeoffs::Tradeoff;
use super::{image, sweep_display, time_frame, Plan, Results};

type Ctx = autostereo::gpu::GpuContext;

/// One setting of the approximations (everything else exact).
#[derive(Clone, Copy)]
enum Knob {
    Share(f32),
    /// `step`: the sampling distance in voxels, `None` the default (the exact image's).
    Probe {
        stride: u32,
        thin: f32,
        step: Option<f32>,
    },
}

impl Knob {
    /// The renderer options of this setting for `method`.
    fn options(self, method: Method) -> RendererOptions {
        let exact = VolumeSettings::default();
        let settings = match self {
            Self::Share(tau) => VolumeSettings {
                share_samples: tau,
                ..exact
            },
            Self::Probe { stride, thin, step } => VolumeSettings {
                empty_stride: stride,
                thin_alpha: thin,
                step,
                ..exact
            },
        };
        RendererOptions {
            volume: VolumeOptions {
                settings,
                ..Default::default()
            },
            ..RendererOptions::new(method)
        }
    }

    /// The setting as the tables show it (and the results file keeps it).
    fn label(self) -> String {
        match self {
            Self::Share(tau) => tau.to_string(),
            Self::Probe { stride, thin, step } => {
                let mut label = stride.to_string();
                if thin > 0.0 {
                    label += &format!(", A = {thin}");
                }
                if let Some(step) = step {
                    label += &format!(", step {step}");
                }
                label
            }
        }
    }

    /// The command-line flags of the setting.
    fn flags(self) -> String {
        match self {
            Self::Share(tau) => format!("--share-samples {tau}"),
            Self::Probe { stride, thin, step } => {
                let mut flags = format!("--empty-stride {stride}");
                if thin > 0.0 {
                    flags += &format!(" --thin-alpha {thin}");
                }
                if let Some(step) = step {
                    flags += &format!(" --step {step}");
                }
                flags
            }
        }
    }
}

/// One approximation and the settings measured; the first setting is the exact path.
struct Study {
    name: &'static str,
    flags: &'static str,
    /// What the x axis of its plots counts (the settings without a thin-material threshold).
    unit: &'static str,
    knobs: Vec<Knob>,
    /// Also measured for the single view, the N-pass and the single pass at N = 64.
    every_method: bool,
}

const PROBES: &str = "probes";

fn studies() -> [Study; 2] {
    let probe = |stride, thin| Knob::Probe {
        stride,
        thin,
        step: None,
    };
    let coarse = |step, stride, thin| Knob::Probe {
        stride,
        thin,
        step: Some(step),
    };
    let mut probes: Vec<Knob> = [1, 2, 4, 8, 16, 32].map(|p| probe(p, 0.0)).into();
    probes.extend([0.002, 0.005, 0.01, 0.02, 0.05].map(|a| probe(8, a)));
    probes.extend([probe(4, 0.02), probe(16, 0.02)]);
    // Coarser sampling: pre-integration keeps a one-voxel step close to the exact image, and
    // the probes and thin steps go on from there.
    probes.extend([1, 2, 3, 4].map(|p| coarse(1.0, p, 0.0)));
    probes.extend([1, 2, 4].map(|p| coarse(1.5, p, 0.0)));
    probes.extend([coarse(1.0, 4, 0.02), coarse(0.75, 4, 0.0)]);
    [
        Study {
            name: "share samples",
            flags: "--share-samples TAU",
            unit: "TAU (voxels)",
            knobs: [0.0, 0.125, 0.25, 0.5, 1.0, 2.0, 4.0]
                .map(Knob::Share)
                .into(),
            every_method: false,
        },
        Study {
            name: PROBES,
            flags: "--empty-stride P [--thin-alpha A] [--step S]",
            unit: "P (sample planes)",
            knobs: probes,
            every_method: true,
        },
    ]
}

/// The runs of a study beyond the single pass at N = 8: (suffix of the study name, method,
/// views).
const OTHER_RUNS: [(&str, Method, u32); 3] = [
    (" / single view", Method::SingleView, 8),
    (" / n-pass", Method::NPass, 8),
    (" / N = 64", Method::SinglePass, 64),
];

/// One run of a study: its method, frame and exact image.
struct Run {
    study: String,
    method: Method,
    frame: autostereo::frame::Frame,
    exact: autostereo::image_io::RgbImage,
}

/// Every study on every volume; per setting, its runs one after the other.
pub fn measure(
    ctx: &Ctx,
    timer: &FrameTimer,
    scenes: &mut [BenchScene],
    plan: &Plan,
) -> Result<Vec<Tradeoff>> {
    let studies = studies();
    let runs = |s: &Study| 1 + if s.every_method { OTHER_RUNS.len() } else { 0 };
    let total: usize = studies.iter().map(|s| runs(s) * s.knobs.len()).sum();
    let bar = crate::progress::bar((scenes.len() * total) as u64, "approximations");
    let mut out = Vec::new();
    for scene in scenes.iter_mut() {
        if !matches!(scene.data, AnyScene::Volume(_)) {
            continue;
        }
        for study in &studies {
            let mut list = vec![("", Method::SinglePass, 8)];
            if study.every_method {
                list.extend(OTHER_RUNS);
            }
            let mut runs = Vec::new();
            for (suffix, method, views) in list {
                let frame = scenes::frame(scene.bounds, &sweep_display(views), plan.size)?;
                let options = study.knobs[0].options(method);
                let mut renderer = AnyRenderer::new(&ctx.device, &scene.data, &options)?;
                let exact = image(ctx, scene, &mut renderer, &frame)?;
                let study = format!("{}{suffix}", study.name);
                runs.push(Run {
                    study,
                    method,
                    frame,
                    exact,
                });
            }
            for knob in &study.knobs {
                for run in runs.iter_mut() {
                    let options = knob.options(run.method);
                    let mut renderer = AnyRenderer::new(&ctx.device, &scene.data, &options)?;
                    let frames = plan.study_frames();
                    let ms = time_frame(ctx, timer, scene, &mut renderer, &run.frame, frames)?;
                    let picture = image(ctx, scene, &mut renderer, &run.frame)?;
                    let d = compare(&picture, &run.exact)?;
                    crate::progress::log(
                        &bar,
                        &format!(
                            "  {} / {} / {}: {ms:.1} ms, {:.1} dB, {:.2} % off",
                            run.study,
                            scene.name,
                            knob.flags(),
                            d.psnr_db,
                            100.0 * d.frac_off_2
                        ),
                    );
                    bar.inc(1);
                    out.push(Tradeoff {
                        study: run.study.clone(),
                        scene: scene.name.clone(),
                        setting: knob.label(),
                        ms,
                        psnr_db: d.psnr_db,
                        frac_off_2: d.frac_off_2,
                        hole_share: None,
                    });
                }
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

/// The exact path of `study` (its first setting) on `scene`, timed in the same loop.
fn exact_ms(r: &Results, study: &Study, suffix: &str, scene: &str) -> Option<f64> {
    let name = format!("{}{suffix}", study.name);
    point(r, &name, scene, &study.knobs[0].label()).map(|t| t.ms)
}

/// The exact single view or N-pass of `views` views: timed in the probes' loop where it was
/// (N = 8), else the main table's (N = 64).
fn exact_of(r: &Results, scene: &str, kind: Kind, views: u32) -> Option<f64> {
    let suffix = match (kind, views) {
        (Kind::SingleView, 8) => Some(OTHER_RUNS[0].0),
        (Kind::NPass, 8) => Some(OTHER_RUNS[1].0),
        _ => None,
    };
    let in_loop = suffix.and_then(|s| point(r, &format!("{PROBES}{s}"), scene, "1"));
    in_loop.map(|t| t.ms).or_else(|| {
        find(
            &rows_of(r, scene, &sweep_display(views), base_size(r)),
            kind,
        )
        .map(|x| x.ms)
    })
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

/// The plot series a setting belongs to, and its x (the settings without a thin-material
/// threshold: TAU or P).
fn series_of(knob: Knob) -> (String, Option<f64>) {
    match knob {
        Knob::Share(tau) => ("share samples".into(), Some(f64::from(tau))),
        Knob::Probe { stride, thin, step } => {
            let mut name = String::from("empty stride");
            if thin > 0.0 {
                name += " + thin alpha";
            }
            if let Some(step) = step {
                name += &format!(", step {step}");
            }
            (name, (thin == 0.0).then_some(f64::from(stride)))
        }
    }
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
         N-pass's times by the setting's single pass (the issue's targets: ≥ 0.5 and ≥ 5); \
         they come from the probes' loop, where each setting's single pass, single view, N-pass \
         and single pass at N = 64 are timed one after the other (the N = 64 N-pass from the \
         main table). Single measurements on this machine drift by up to 1.5× within a run: \
         compare neighbouring rows, not far ones.\n",
        r.size[0], r.size[1]
    )?;
    let mut pareto: Vec<Series> = Vec::new();
    for study in &studies() {
        writeln!(md, "### {} (`{}`)\n", study.name, study.flags)?;
        let wide = study.every_method;
        writeln!(
            md,
            "| volume | setting | ms | vs exact | PSNR dB | off > 2/255 | SV / SP | N-pass / SP |{}",
            if wide {
                " SV ms, same setting | SV / SP, same setting | N-pass / SP, same setting | \
                 N = 64 ms | N = 64 dB | N-pass / SP, N = 64 |\n\
                 |---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
            } else {
                "\n|---|---|---:|---:|---:|---:|---:|---:|"
            }
        )?;
        let (mut time_series, mut psnr_series): (Vec<Series>, Vec<Series>) = (vec![], vec![]);
        let mut scenes: Vec<&str> = r.tradeoffs.iter().map(|t| t.scene.as_str()).collect();
        scenes.dedup();
        for scene in scenes {
            let exact = exact_ms(r, study, "", scene);
            let sv = exact_of(r, scene, Kind::SingleView, 8);
            let npass = exact_of(r, scene, Kind::NPass, 8);
            for &knob in &study.knobs {
                let Some(t) = point(r, study.name, scene, &knob.label()) else {
                    continue;
                };
                write!(
                    md,
                    "| {scene} | {} | {:.1} | {} | {} | {:.2} % | {} | {} |",
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
                        point(r, &format!("{}{suffix}", study.name), scene, &t.setting)
                    };
                    let (sv_same, np_same) = (other(OTHER_RUNS[0].0), other(OTHER_RUNS[1].0));
                    let wide64 = other(OTHER_RUNS[2].0);
                    let npass64 = exact_of(r, scene, Kind::NPass, 64);
                    write!(
                        md,
                        " {} | {} | {} | {} | {} | {} |",
                        sv_same.map_or("–".into(), |s| format!("{:.1}", s.ms)),
                        ratio(sv_same.map(|s| s.ms), t.ms),
                        ratio(np_same.map(|s| s.ms), t.ms),
                        wide64.map_or("–".into(), |s| format!("{:.1}", s.ms)),
                        wide64.map_or("–".into(), |s| db(s.psnr_db)),
                        wide64.map_or("–".into(), |s| ratio(npass64, s.ms)),
                    )?;
                }
                writeln!(md)?;
                let (series, x) = series_of(knob);
                // The settings along x at the default step are the volume's own line.
                let line = if series == series_of(study.knobs[0]).0 {
                    scene.to_string()
                } else {
                    format!("{scene}, {series}")
                };
                if let Some(e) = exact {
                    if t.psnr_db <= 99.0 {
                        push(
                            &mut pareto,
                            &format!("{scene}: {series}"),
                            (t.ms / e, t.psnr_db),
                        );
                    }
                    if let Some(x) = x {
                        push(&mut time_series, &line, (x.max(1e-3), t.ms / e));
                    }
                }
                if let Some(x) = x {
                    push(&mut psnr_series, &line, (x.max(1e-3), t.psnr_db.min(99.0)));
                }
            }
        }
        writeln!(md)?;
        let stem = study.name.replace(' ', "_");
        for (kind, y, series) in [
            ("time", "ms / exact single pass ms", &time_series),
            ("psnr", "PSNR dB (99: exact)", &psnr_series),
        ] {
            let title = format!("{}: {kind} against {}", study.name, study.unit);
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
        lines: false,
    };
    if draw(
        &images.join("bench_approximations_pareto.png"),
        &axes,
        &pareto,
    )? {
        writeln!(
            md,
            "Up and left is better: at equal time, the setting with the higher PSNR.\n\n\
             ![{}](images/bench_approximations_pareto.png)\n",
            axes.title
        )?;
    }
    targets(md, r)
}

/// The volume targets at the fastest probe setting that keeps ≥ 40 dB at N = 8 and N = 64.
fn targets(md: &mut String, r: &Results) -> Result<()> {
    writeln!(md, "### The volume targets at a setting ≥ 40 dB\n")?;
    writeln!(
        md,
        "Per volume, the fastest setting of the probes (`--empty-stride`, with or without \
         `--thin-alpha`, at the default or a coarser `--step`) whose single pass keeps ≥ 40 dB \
         against the exact image at N = 8 and at N = 64, against the *exact* N-pass and single \
         view (the issue's targets), and, for comparison, against the N-pass and single view at \
         the same setting (the probes speed every method up).\n"
    )?;
    writeln!(
        md,
        "| volume | setting | PSNR dB | N-pass / SP, N = 8 (≥ 5) | N-pass / SP, N = 64 (≥ 30) | \
         SV / SP (≥ 0.5) | status | same setting: N-pass / SP, N = 8 | same setting: SV / SP |\n\
         |---|---|---:|---:|---:|---:|---|---:|---:|"
    )?;
    let studies = studies();
    let probes = studies
        .iter()
        .find(|s| s.name == PROBES)
        .expect("the probe study");
    let mut scenes: Vec<&str> = r.tradeoffs.iter().map(|t| t.scene.as_str()).collect();
    scenes.dedup();
    for scene in scenes {
        let other =
            |suffix: &str, knob: Knob| point(r, &format!("{PROBES}{suffix}"), scene, &knob.label());
        let candidates = probes.knobs.iter().filter_map(|&knob| {
            let t = other("", knob)?;
            let wide = other(OTHER_RUNS[2].0, knob)?;
            (t.psnr_db >= 40.0 && wide.psnr_db >= 40.0).then_some((knob, t, wide))
        });
        let Some((knob, best, wide)) = candidates.min_by(|a, b| a.1.ms.total_cmp(&b.1.ms)) else {
            continue;
        };
        let n8 = exact_of(r, scene, Kind::NPass, 8).map(|n| n / best.ms);
        let n64 = exact_of(r, scene, Kind::NPass, 64).map(|n| n / wide.ms);
        let sv = exact_of(r, scene, Kind::SingleView, 8).map(|s| s / best.ms);
        let met = n8.is_some_and(|v| v >= 5.0)
            && n64.is_some_and(|v| v >= 30.0)
            && sv.is_some_and(|v| v >= 0.5);
        let show = |v: Option<f64>| v.map_or("–".into(), |v| format!("{v:.2}"));
        writeln!(
            md,
            "| {scene} | `{}` | {:.1} | {} | {} | {} | {} | {} | {} |",
            knob.flags(),
            best.psnr_db,
            show(n8),
            show(n64),
            show(sv),
            if met { "met" } else { "**missed**" },
            ratio(other(OTHER_RUNS[1].0, knob).map(|t| t.ms), best.ms),
            ratio(other(OTHER_RUNS[0].0, knob).map(|t| t.ms), best.ms),
        )?;
    }
    writeln!(md)?;
    Ok(())
}
