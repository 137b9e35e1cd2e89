//! `autostereo-bench`: single pass (every path and mode), N-pass, single view and the per-view
//! duplication methods (tiled, layered, MRT) side by side in one process on one adapter, for volumes, point splats and meshes; speed/accuracy trade-offs
//! against the N-pass high-quality render; what a scene that skips a feature saves. `--report
//! DIR` writes DIR/BENCHMARKS.md (+ PNG plots with the `plots` feature).

mod approximations;
mod gaussians;
mod plan;
mod plot;
mod report;
mod rows;
mod scenes;
mod schedule;
mod targets;
mod tradeoffs;
mod view_scale;
mod warping;

use autostereo::render::Renderer;
use std::path::PathBuf;
use std::time::Instant;

use anyhow::{Context, Result};
use autostereo::target::SpatialTarget;
use autostereo::timing::{median, FrameTimer};
use schedule::{count_measurements, estimate_seconds, measured};
use serde::{Deserialize, Serialize};

/// The CLI's progress bars (one file for both tools).
#[path = "../../cli/src/progress.rs"]
mod progress;

/// Most timed frames per measurement (`--frames`), as the CLI's commands take.
pub const MAX_FRAMES: u32 = 100_000;

/// The GPU the bench measures on (`WGPU_BACKEND` / `WGPU_ADAPTER_NAME` pick it).
fn gpu() -> Result<autostereo::gpu::GpuContext> {
    autostereo::gpu::GpuContext::new(&Default::default()).context("setting up the GPU")
}
use plan::run_name;
pub use plan::Plan;
use scenes::{BenchScene, Kind, MethodEntry};

/// What `--help` shows after the flags.
pub const EXAMPLES: &str = "Examples:
  autostereo-bench --quick
  autostereo-bench --gaussians --frames 1 --report docs/gaussians";

/// What to measure and where to write it.
#[derive(clap::Args)]
pub struct BenchArgs {
    /// A smaller matrix (256², N = 2, 8, 64, the smaller data sets) that finishes in minutes.
    #[arg(long)]
    quick: bool,
    /// Print all results as one JSON object on stdout.
    #[arg(long)]
    json: bool,
    /// Write DIR/BENCHMARKS.md (and DIR/images/bench_*.png when built with the `plots` feature).
    #[arg(long)]
    report: Option<PathBuf>,
    /// Write the report from a saved `--json` output instead of measuring (re-plotting; the
    /// flags that choose what to measure do not apply).
    #[arg(
        long,
        requires = "report",
        conflicts_with_all = [
            "quick", "duplication", "sweep", "warp", "view_scale", "volumes", "gaussians",
            "frames", "data",
        ]
    )]
    from_json: Option<PathBuf>,
    /// Only the comparison with per-view duplication: every method on the paper's display
    /// (N = 8) at 512² and 1920×1080, the dragon res2 mesh and the full dragon points, no
    /// trade-off studies (issue 13's targets in minutes rather than hours).
    #[arg(long, conflicts_with = "quick")]
    duplication: bool,
    /// Only time against N: every method (duplication and N-pass included) at N = 1, 2, 4, …,
    /// 64 at 256², the quick run's points and mesh and the full-size head, no studies.
    #[arg(long, conflicts_with_all = ["quick", "duplication"])]
    sweep: bool,
    /// Only depth-image warping against every other method: N = 8 and 45 at 512², the quick
    /// run's points and mesh and the full-size head, timed beside every method, and the warp's
    /// accuracy for R = 1, 2, 3 and N/2 references (PSNR, share off > 2/255, hole share).
    #[arg(long, conflicts_with_all = ["quick", "duplication", "sweep"])]
    warp: bool,
    /// Only per-view resolution: N = 8 at 512², the quick run's points and mesh and the
    /// full-size head, every method timed, and the n-pass, tiled and layered methods at view
    /// scales 1, ¾, ½, ⅓, ¼ against the full-size N-pass (time, PSNR, share off > 2/255).
    #[arg(long, conflicts_with_all = ["quick", "duplication", "sweep", "warp"])]
    view_scale: bool,
    /// Only volumes: the head and brainsmall at 512², N = 8 and 64, every method, and the
    /// single pass's sample sharing (`--share-samples` TAU = 0.25 … 4 voxels: time, PSNR and
    /// share off > 2/255 against the exact single pass).
    #[arg(long, conflicts_with_all = ["quick", "duplication", "sweep", "warp", "view_scale"])]
    volumes: bool,
    /// Only 3D Gaussian splats: a generated scene of 131,072 Gaussians, every method at
    /// N = 8, 45 and 100 at 512² and a 16" panel's 3840×2160 (45 views), the depth sort alone
    /// (GPU against CPU), GPU memory and the single pass's PSNR against the N-pass.
    #[arg(long, conflicts_with_all = ["quick", "duplication", "sweep", "warp", "view_scale", "volumes"])]
    gaussians: bool,
    /// Timed frames per measurement (after 2 warm-up frames).
    #[arg(long, default_value_t = 20, value_parser = clap::value_parser!(u32).range(1..=i64::from(MAX_FRAMES)))]
    frames: u32,
    /// Where `data/fetch` put the real data sets (brainsmall.den, the dragon, the bunny); the
    /// bench uses generated stand-ins for those it does not find there and says so.
    #[arg(long, value_name = "DIR", default_value = "data/fetched")]
    data: PathBuf,
}

/// The K = 3 display with N views of the N sweep: the slanted lens of the paper's display
/// (`hubner8` is exactly `slanted:8,8,2/3,7/6`, docs/DESIGN.md §1).
pub fn sweep_display(n: u32) -> String {
    if n == 8 {
        "hubner8".into()
    } else {
        format!("slanted:{n},8,2/3,7/6")
    }
}

/// Whether `display` is one of the N sweep's.
pub fn in_sweep(display: &str) -> bool {
    display.starts_with("slanted") || display == "hubner8"
}

/// One timed measurement.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Row {
    pub primitive: String,
    pub scene: String,
    pub display: String,
    pub views: u32,
    pub views_per_pixel: u32,
    pub size: [u32; 2],
    pub method: String,
    pub kind: Kind,
    pub ms: f64,
    pub frames: u32,
}

#[derive(Serialize, Deserialize)]
pub struct Results {
    pub adapter: String,
    pub cpu: String,
    pub command: String,
    pub quick: bool,
    /// A `--duplication` run.
    #[serde(default)]
    pub duplication: bool,
    /// A `--sweep` run.
    #[serde(default)]
    pub sweep: bool,
    /// A `--warp` run.
    #[serde(default)]
    pub warp: bool,
    /// A `--view-scale` run.
    #[serde(default)]
    pub view_scale: bool,
    /// A `--volumes` run.
    #[serde(default)]
    pub volumes: bool,
    pub frames: u32,
    /// Frames per trade-off and economy measurement.
    pub study_frames: u32,
    /// The N sweep's image size and the largest N-pass N (volumes: always the sweep's largest).
    pub size: [u32; 2],
    pub npass_max_views: u32,
    pub timing: String,
    pub seconds: f64,
    pub scenes: Vec<(String, String, String)>,
    pub rows: Vec<Row>,
    pub tradeoffs: Vec<tradeoffs::Tradeoff>,
    pub economy: Vec<tradeoffs::Economy>,
    /// Measurements that could not run (e.g. over the memory budget): what, and why.
    #[serde(default)]
    pub failures: Vec<(String, String)>,
}

impl Results {
    /// `quick`, `duplication`, `sweep` or `full`.
    pub fn run_name(&self) -> &'static str {
        run_name(
            self.quick,
            self.duplication,
            self.sweep,
            self.warp,
            self.view_scale,
            self.volumes,
        )
    }
}

pub(crate) fn cpu_name() -> String {
    std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_string())
        })
        .map(|m| {
            format!(
                "{m}, {} threads",
                std::thread::available_parallelism().map_or(1, |n| n.get())
            )
        })
        .unwrap_or_else(|| "unknown CPU".into())
}

/// Make `--report DIR`'s folders (DIR and DIR/images), the error naming the flag and the path:
/// a DIR that is a file (`--report rep/BENCHMARKS.md`) said only "Not a directory (os error
/// 20)".
fn report_dir(dir: &std::path::Path) -> Result<()> {
    if dir.exists() && !dir.is_dir() {
        anyhow::bail!(
            "--report {}: is a file, and --report takes a folder (DIR/BENCHMARKS.md is written \
             in it); give its folder, e.g. --report {}",
            dir.display(),
            dir.parent()
                .filter(|p| !p.as_os_str().is_empty())
                .map_or(".".into(), |p| p.display().to_string())
        );
    }
    let images = dir.join("images");
    std::fs::create_dir_all(&images).with_context(|| {
        format!(
            "--report {}: cannot create the folder {}",
            dir.display(),
            images.display()
        )
    })
}

/// Say so where the report was written without its charts (a build without `plots`): the
/// charts of an earlier report in that folder are no longer linked from it.
fn plots_note() {
    if !cfg!(feature = "plots") {
        eprintln!(
            "note: built without the `plots` feature, so the report has its tables but no charts \
             (cargo run --release -p autostereo-bench --features plots -- …)"
        );
    }
}

/// "one frame" or "median of N frames", as the reports say what each time is.
pub(crate) fn frames_text(frames: u32) -> String {
    match frames {
        1 => "one frame".into(),
        n => format!("median of {n} frames"),
    }
}

/// Write one file of the `--report` folder, the error naming the path.
pub(crate) fn write_report_file(path: &std::path::Path, contents: impl AsRef<[u8]>) -> Result<()> {
    std::fs::write(path, contents)
        .with_context(|| format!("--report: cannot write {}", path.display()))?;
    note_written(path);
    Ok(())
}

/// The files this run wrote (the report, its JSON, its plots), in order, for `--json`'s
/// `written`: the report's modules each write their own plots.
static WRITTEN: std::sync::Mutex<Vec<PathBuf>> = std::sync::Mutex::new(Vec::new());

/// Record `path` as written.
pub(crate) fn note_written(path: &std::path::Path) {
    if let Ok(mut written) = WRITTEN.lock() {
        written.push(path.to_path_buf());
    }
}

/// `results` as one JSON object on stdout, with `written` listing every file the run wrote.
pub(crate) fn print_json(results: &impl Serialize) -> Result<()> {
    let mut value = serde_json::to_value(results)?;
    let written = WRITTEN.lock().map(|w| w.clone()).unwrap_or_default();
    value["written"] = serde_json::json!(written);
    println!("{value}");
    Ok(())
}

pub fn run(args: BenchArgs) -> Result<()> {
    if let Some(dir) = &args.report {
        report_dir(dir)?;
        if let Some(json) = &args.from_json {
            let text = std::fs::read_to_string(json)
                .with_context(|| format!("reading {}", json.display()))?;
            let results: Results = serde_json::from_str(&text).with_context(|| {
                format!(
                    "{} is not a `autostereo-bench --json` output",
                    json.display()
                )
            })?;
            report::write(dir, &results)?;
            eprintln!("wrote {}", dir.join("BENCHMARKS.md").display());
            plots_note();
            if args.json {
                print_json(&serde_json::json!({ "from_json": json }))?;
            }
            return Ok(());
        }
    }
    if args.gaussians {
        return gaussians::run(&args);
    }
    let start = Instant::now();
    let plan = Plan::new(&args);
    let ctx = gpu()?;
    let timer = FrameTimer::new(&ctx.device, &ctx.queue);
    eprintln!("loading scenes…");
    let mut scenes = scenes::scenes(&ctx, &plan)?;
    let mut all_methods = scenes
        .iter()
        .map(|scene| scenes::methods(&ctx.device, scene))
        .collect::<Result<Vec<_>>>()?;
    // Probe: one single-view frame per scene, for the duration estimate.
    let mut probe_ms = Vec::new();
    for (scene, methods) in scenes.iter().zip(&mut all_methods) {
        let sv = methods
            .iter_mut()
            .find(|m| m.kind == Kind::SingleView)
            .expect("every primitive has a single view");
        probe_ms.push(time(&ctx, &timer, scene, sv, "hubner8", plan.size, 1)?);
    }
    let estimate = estimate_seconds(&plan, &scenes, &all_methods, &probe_ms);
    eprintln!(
        "{} run: {} scenes, about {:.0} min on this adapter ({})",
        plan.name(),
        scenes.len(),
        estimate / 60.0,
        ctx.adapter_label()
    );
    let mut rows = Vec::new();
    let mut failures = Vec::new();
    let total = count_measurements(&plan, &scenes, &all_methods);
    let bar = crate::progress::bar(total as u64, "bench");
    for (scene, methods) in scenes.iter().zip(&mut all_methods) {
        for (display, size) in plan.configs() {
            let frame = scenes::frame(scene.bounds, &display, size)?;
            let n = frame.camera.views;
            for (i, m) in methods.iter_mut().enumerate() {
                if !measured(&plan, scene.primitive, m.kind, i == 0, &display, n, size) {
                    continue;
                }
                let ms = match time(&ctx, &timer, scene, m, &display, size, plan.frames) {
                    Ok(ms) => ms,
                    Err(e) => {
                        let what = format!(
                            "{} {} {display} {}x{}: {}",
                            scene.primitive, scene.name, size[0], size[1], m.name
                        );
                        crate::progress::log(&bar, &format!("{what}: not measured: {e:#}"));
                        bar.inc(1);
                        failures.push((what, format!("{e:#}")));
                        continue;
                    }
                };
                rows.push(Row {
                    primitive: scene.primitive.into(),
                    scene: scene.name.clone(),
                    display: display.clone(),
                    views: n,
                    views_per_pixel: frame.display.views_per_pixel(),
                    size,
                    method: m.name.clone(),
                    kind: m.kind,
                    ms,
                    frames: plan.frames,
                });
                bar.inc(1);
                let line = format!(
                    "[{}/{total}] {} {} {display} {}x{}: {} {ms:.1} ms ({:.0} s elapsed)",
                    rows.len(),
                    scene.primitive,
                    scene.name,
                    size[0],
                    size[1],
                    m.name,
                    start.elapsed().as_secs_f64()
                );
                crate::progress::log(&bar, &line);
            }
        }
    }
    bar.finish_and_clear();
    let (tradeoffs, economy) = if plan.warp {
        eprintln!("warp accuracy…");
        (warping::measure(&ctx, &timer, &scenes, &plan)?, Vec::new())
    } else if plan.view_scale {
        eprintln!("view scales…");
        (
            view_scale::measure(&ctx, &timer, &scenes, &plan)?,
            Vec::new(),
        )
    } else if plan.volumes {
        eprintln!("volume approximations…");
        (
            approximations::measure(&ctx, &timer, &mut scenes, &plan)?,
            Vec::new(),
        )
    } else if !plan.studies() {
        (Vec::new(), Vec::new())
    } else {
        eprintln!("speed/accuracy trade-offs…");
        (
            tradeoffs::measure(&ctx, &timer, &mut scenes, &plan)?,
            tradeoffs::economy(&ctx, &timer, &mut scenes, &plan)?,
        )
    };
    let results = Results {
        adapter: ctx.adapter_label(),
        cpu: cpu_name(),
        command: std::env::args().collect::<Vec<_>>().join(" "),
        quick: plan.quick,
        duplication: plan.duplication,
        sweep: plan.sweep,
        warp: plan.warp,
        view_scale: plan.view_scale,
        volumes: plan.volumes,
        frames: plan.frames,
        study_frames: plan.study_frames(),
        size: plan.size,
        npass_max_views: plan.npass_max_views,
        timing: format!("{:?}", timer.source()),
        seconds: start.elapsed().as_secs_f64(),
        scenes: scenes
            .iter()
            .map(|s| (s.primitive.to_string(), s.name.clone(), s.detail.clone()))
            .collect(),
        rows,
        tradeoffs,
        economy,
        failures,
    };
    if let Some(dir) = &args.report {
        let json = dir.join(format!("bench_{}.json", plan.name()));
        write_report_file(&json, serde_json::to_string_pretty(&results)?)?;
        report::write(dir, &results)?;
        eprintln!("wrote {}", dir.join("BENCHMARKS.md").display());
        plots_note();
    }
    if args.json {
        print_json(&results)?;
    }
    eprintln!("done in {:.0} s", results.seconds);
    Ok(())
}

/// Median GPU ms of `frames` frames of `method` on `scene` (after 2 warm-up frames).
fn time(
    ctx: &autostereo::gpu::GpuContext,
    timer: &FrameTimer,
    scene: &BenchScene,
    method: &mut MethodEntry,
    display: &str,
    size: [u32; 2],
    frames: u32,
) -> Result<f64> {
    let frame = scenes::frame(scene.bounds, display, size)?;
    time_frame(ctx, timer, scene, &mut method.renderer, &frame, frames)
}

/// One frame of `renderer` on `scene` as an image.
pub(crate) fn image(
    ctx: &autostereo::gpu::GpuContext,
    scene: &BenchScene,
    renderer: &mut autostereo::AnyRenderer,
    frame: &autostereo::frame::Frame,
) -> Result<autostereo::image_io::RgbImage> {
    Ok(autostereo::render::Renderer::render_image(
        renderer,
        &ctx.device,
        &ctx.queue,
        &scene.data,
        frame,
    )?)
}

pub(crate) fn time_frame(
    ctx: &autostereo::gpu::GpuContext,
    timer: &FrameTimer,
    scene: &BenchScene,
    renderer: &mut autostereo::AnyRenderer,
    frame: &autostereo::frame::Frame,
    frames: u32,
) -> Result<f64> {
    let target = SpatialTarget::new(&ctx.device, frame.size)?;
    renderer.prepare(&ctx.device, &ctx.queue, &scene.data, frame)?;
    let mut samples = Vec::new();
    for i in 0..frames + 2 {
        let ms = timer.time_frame(&ctx.device, &ctx.queue, |e| {
            renderer.encode(&ctx.device, e, &scene.data, frame, &target)
        })?;
        if i >= 2 {
            samples.push(ms);
        }
    }
    Ok(median(&samples))
}
