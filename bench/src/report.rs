//! DIR/BENCHMARKS.md from a run's results (plots in DIR/images when built with `plots`).

use std::fmt::Write as _;
use std::path::Path;

use anyhow::Result;

use super::plot::{draw, Axes, Series};
use super::rows::{base_size, find, rows_of, PAPER_DISPLAY};
use super::scenes::Kind;
use super::Results;

pub fn write(dir: &Path, r: &Results) -> Result<()> {
    let mut md = String::new();
    let size = base_size(r);
    let images = dir.join("images");
    writeln!(md, "# Benchmarks\n")?;
    writeln!(
        md,
        "Produced by `cargo run --release --features autostereo-bench/plots -- {}` in {:.1} min (the full run \
         states its expected duration when it starts; without the `plots` feature the report has \
         its tables but no plots). The numbers are saved next to this file as `bench_{}.json`; \
         `autostereo-bench --report DIR --from-json FILE` re-plots them.\n",
        r.command
            .split_whitespace()
            .skip(1)
            .collect::<Vec<_>>()
            .join(" "),
        r.seconds / 60.0,
        r.run_name(),
    )?;
    writeln!(md, "- adapter: {}", r.adapter)?;
    writeln!(md, "- CPU: {}", r.cpu)?;
    writeln!(
        md,
        "- {} run, {} after 2 warm-up frames per measurement ({} for the trade-off and \
         economy studies), GPU time from {}",
        r.run_name(),
        super::frames_text(r.frames),
        r.study_frames,
        r.timing
    )?;
    writeln!(
        md,
        "- every method of a primitive runs in one process on one adapter; the views span a fixed \
         baseline (that of the default 8-view camera); ratios compare runs of the same table.\n"
    )?;
    writeln!(md, "| primitive | scene | data |\n|---|---|---|")?;
    for (p, name, detail) in &r.scenes {
        writeln!(md, "| {p} | {name} | {detail} |")?;
    }

    writeln!(md, "\n## The paper's charts on this adapter\n")?;
    writeln!(
        md,
        "Charts 1–4 of the paper (fps of SV, 8-view N-pass and single pass at 512², N = 8, the 8×12 \
         wavelength-selective display), redone here at {}×{}: Chart 1/2 volumes, Chart 3 point \
         splatting, Chart 4 triangle meshes. `N-pass / SP` > 1 means the single pass is faster.\n",
        size[0], size[1]
    )?;
    for (chart, primitive) in [
        ("Charts 1–2", "volume"),
        ("Chart 3", "points"),
        ("Chart 4", "mesh"),
    ] {
        writeln!(md, "**{chart} ({primitive})**\n")?;
        writeln!(md, "| scene | method | ms | fps | N-pass / this | this / SV |\n|---|---|---:|---:|---:|---:|")?;
        for (p, name, _) in &r.scenes {
            if p != primitive {
                continue;
            }
            let rows = rows_of(r, name, PAPER_DISPLAY, size);
            let npass = find(&rows, Kind::NPass).map(|x| x.ms);
            let sv = find(&rows, Kind::SingleView).map(|x| x.ms);
            for x in &rows {
                writeln!(
                    md,
                    "| {name} | {} | {:.1} | {:.2} | {} | {} |",
                    x.method,
                    x.ms,
                    1e3 / x.ms,
                    npass.map_or("–".into(), |n| format!("{:.2}×", n / x.ms)),
                    sv.map_or("–".into(), |s| format!("{:.2}×", x.ms / s)),
                )?;
            }
        }
        writeln!(md)?;
    }

    writeln!(md, "## Time against the number of views\n")?;
    writeln!(
        md,
        "Slanted subpixel display (`slanted:N,8,2/3,7/6`, K = 3; N = 8 is `hubner8`) at {}×{}; N-pass up to N = {}. \
         The single pass should stay flat, N-pass grow linearly.\n",
        size[0],
        size[1],
        r.npass_max_views
    )?;
    for primitive in ["volume", "points", "mesh"] {
        let mut series: Vec<Series> = Vec::new();
        writeln!(md, "| {primitive} scene | method | {} |", views_header(r))?;
        writeln!(md, "|---|---|{}", "---:|".repeat(views_list(r).len()))?;
        for (_, name, _) in r.scenes.iter().filter(|s| s.0 == primitive) {
            let mut methods: Vec<String> = r
                .rows
                .iter()
                .filter(|x| {
                    &x.scene == name && super::in_sweep(&x.display) && x.kind != Kind::SingleView
                })
                .map(|x| x.method.clone())
                .collect();
            methods.dedup();
            methods.sort();
            methods.dedup();
            for m in methods {
                let mut cells = Vec::new();
                let mut pts = Vec::new();
                for n in views_list(r) {
                    let row = r.rows.iter().find(|x| {
                        &x.scene == name
                            && x.method == m
                            && x.views == n
                            && super::in_sweep(&x.display)
                            && x.size == size
                    });
                    cells.push(row.map_or("–".into(), |x| format!("{:.0}", x.ms)));
                    if let Some(x) = row {
                        pts.push((n as f64, x.ms));
                    }
                }
                writeln!(md, "| {name} | {m} | {} |", cells.join(" | "))?;
                series.push((format!("{name}: {m}"), pts));
            }
        }
        // Single view has no N: draw it flat for reference.
        for (_, name, _) in r.scenes.iter().filter(|s| s.0 == primitive) {
            if let Some(sv) = find(&rows_of(r, name, PAPER_DISPLAY, size), Kind::SingleView) {
                let ns = views_list(r);
                series.push((
                    format!("{name}: single view"),
                    vec![(ns[0] as f64, sv.ms), (*ns.last().unwrap() as f64, sv.ms)],
                ));
            }
        }
        let file = format!("bench_time_vs_n_{primitive}.png");
        let axes = Axes {
            title: &format!("{primitive}: ms per frame vs N"),
            x: "views N",
            y: "ms per frame",
            log_x: true,
            log_y: true,
            lines: true,
        };
        if draw(&images.join(&file), &axes, &series)? {
            writeln!(md, "\n![{primitive}: time vs N](images/{file})")?;
        }
        writeln!(md)?;
    }

    if let Some(extra) = r.rows.iter().find(|x| x.size != size).map(|x| x.size) {
        writeln!(md, "## {}×{}\n", extra[0], extra[1])?;
        writeln!(
            md,
            "| scene | method | ms | N-pass / this | this / SV |\n|---|---|---:|---:|---:|"
        )?;
        for (_, name, _) in &r.scenes {
            let rows = rows_of(r, name, PAPER_DISPLAY, extra);
            let npass = find(&rows, Kind::NPass).map(|x| x.ms);
            let sv = find(&rows, Kind::SingleView).map(|x| x.ms);
            for x in &rows {
                writeln!(
                    md,
                    "| {name} | {} | {:.1} | {} | {} |",
                    x.method,
                    x.ms,
                    npass.map_or("–".into(), |n| format!("{:.2}×", n / x.ms)),
                    sv.map_or("–".into(), |s| format!("{:.2}×", x.ms / s))
                )?;
            }
        }
        writeln!(md)?;
    }

    super::targets::targets(&mut md, r)?;
    super::targets::duplication(&mut md, r)?;
    if r.view_scale {
        super::view_scale::report(&mut md, r, &images)?;
    } else if r.volumes {
        super::approximations::report(&mut md, r, &images)?;
    } else if r.tradeoffs.iter().any(|t| t.hole_share.is_none()) {
        tradeoffs(&mut md, r, &images)?;
        economy(&mut md, r)?;
    }
    if r.tradeoffs.iter().any(|t| t.hole_share.is_some()) {
        super::warping::report(&mut md, r, &images)?;
    }
    if !r.failures.is_empty() {
        writeln!(md, "## Not measured\n")?;
        writeln!(md, "| measurement | why |\n|---|---|")?;
        for (what, why) in &r.failures {
            writeln!(md, "| {what} | {} |", why.replace('|', "\\|"))?;
        }
        writeln!(md)?;
    }
    // The quick run's report is docs/BENCHMARKS.md; every other run's lives in a folder below.
    let up = if r.quick { "" } else { "../" };
    if r.quick {
        writeln!(
            md,
            "## Runs of their own\n\n\
             - every method against per-view duplication, 512² and 1920×1080: \
             [duplication/BENCHMARKS.md](duplication/BENCHMARKS.md) (`autostereo-bench --duplication`)\n\
             - time against N = 1…64: [sweep/BENCHMARKS.md](sweep/BENCHMARKS.md) (`autostereo-bench --sweep`)\n\
             - depth-image warping: [warp/BENCHMARKS.md](warp/BENCHMARKS.md) (`autostereo-bench --warp`)\n\
             - per-view resolution (`--view-scale`), time and PSNR per scale: \
             [view_scale/BENCHMARKS.md](view_scale/BENCHMARKS.md) (`autostereo-bench --view-scale`)\n\
             - volumes at N = 8 and 64 with the volume march's approximations \
             (`--empty-stride`, `--thin-alpha`, `--step`, `--share-samples`) and the volume targets at a \
             setting ≥ 40 dB: [volumes/BENCHMARKS.md](volumes/BENCHMARKS.md) \
             (`autostereo-bench --volumes`)\n\
             - the full matrix: [full/BENCHMARKS.md](full/BENCHMARKS.md) (`bench`)\n"
        )?;
    }
    writeln!(
        md,
        "## Numerical stability\n\nThe stability suite (`tests/meshes/stability.rs`, run by CI) and its table: \
         [STABILITY.md]({up}STABILITY.md).\n"
    )?;
    super::write_report_file(&dir.join("BENCHMARKS.md"), md)?;
    Ok(())
}

fn views_list(r: &Results) -> Vec<u32> {
    let mut v: Vec<u32> = r
        .rows
        .iter()
        .filter(|x| super::in_sweep(&x.display))
        .map(|x| x.views)
        .collect();
    v.sort();
    v.dedup();
    v
}

fn views_header(r: &Results) -> String {
    views_list(r)
        .iter()
        .map(|n| format!("N = {n}"))
        .collect::<Vec<_>>()
        .join(" | ")
}

fn tradeoffs(md: &mut String, r: &Results, images: &Path) -> Result<()> {
    writeln!(md, "## Speed/accuracy trade-offs\n")?;
    writeln!(
        md,
        "Single pass on the paper's display (N = 8, K = 3), against the N-pass high-quality render \
         (volumes: N-pass at ¼-voxel steps; splats: N-pass with automatic groups and ε = 0.01; \
         meshes: N-pass). PSNR 1000 = identical.\n"
    )?;
    let advice = [
        ("volume sampling", "Steps up to ½ voxel stay close to the ¼-voxel reference; the compute path is the fastest and exact per channel; the slice path with the paper's averaged α loses accuracy at colour edges — pick compute at ½ voxel (the default), coarser steps only for previews."),
        ("splat depth", "Exact depth (one per subpixel) matches N-pass; the paper's mean depth per pixel costs about the same here and loses accuracy at silhouettes — keep exact."),
        ("splat epsilon", "ε must exceed the depth spread of one surface's overlapping splats and stay below the gap between surfaces. The reference uses ε = 0.01, so that row matches it by construction; the others show how far the image moves: too small shows splat seams, too large blends hidden surfaces through. 0.01 of the scene depth is the default."),
        ("splat groups", "Fewer groups are faster (one pass per group) but overlapping splats in a group z-cull each other instead of blending. The reference uses automatic groups, so that row matches it by construction; the others show what fixed small counts cost in accuracy for their speed."),
        ("mesh visibility", "All exact modes match N-pass; compute is the fastest where 64-bit atomics exist, exact (subpixel raster) elsewhere; fast (the paper's one depth per pixel) is approximate and not faster on a software rasteriser; the paper's printed bounds clip far geometry."),
    ];
    for (study, text) in advice {
        let points: Vec<&super::tradeoffs::Tradeoff> =
            r.tradeoffs.iter().filter(|t| t.study == study).collect();
        if points.is_empty() {
            continue;
        }
        writeln!(md, "### {study} ({})\n", points[0].scene)?;
        writeln!(
            md,
            "| setting | ms | PSNR dB | off > 2/255 |\n|---|---:|---:|---:|"
        )?;
        let mut series: Vec<Series> = Vec::new();
        for t in &points {
            let (group, label) = match t.setting.split_once('|') {
                Some((path, step)) => (path.to_string(), format!("{path}, step {step} voxel")),
                None => (study.to_string(), t.setting.clone()),
            };
            writeln!(
                md,
                "| {label} | {:.1} | {:.1} | {:.3} % |",
                t.ms,
                t.psnr_db.min(99.0),
                100.0 * t.frac_off_2
            )?;
            match series.iter_mut().find(|s| s.0 == group) {
                Some(s) => s.1.push((t.ms, t.psnr_db.min(99.0))),
                None => series.push((group, vec![(t.ms, t.psnr_db.min(99.0))])),
            }
        }
        writeln!(md, "\n{text}\n")?;
        let file = format!("bench_tradeoff_{}.png", study.replace(' ', "_"));
        let axes = Axes {
            title: &format!("{study}: PSNR vs ms (identical shown as 99 dB)"),
            x: "ms per frame",
            y: "PSNR dB vs reference",
            log_x: false,
            log_y: false,
            lines: study == "volume sampling",
        };
        if draw(&images.join(&file), &axes, &series)? {
            writeln!(md, "![{study}](images/{file})\n")?;
        }
    }
    Ok(())
}

/// Share of the time a left-out feature saves, percent.
fn saved_percent(e: &super::tradeoffs::Economy) -> f64 {
    100.0 * (1.0 - e.without_ms / e.with_ms)
}

/// Rounded to a whole percent, without printing "-0" (round() keeps the sign of −0.3; + 0.0
/// turns −0 into 0).
fn whole_percent(p: f64) -> f64 {
    p.round() + 0.0
}

fn economy(md: &mut String, r: &Results) -> Result<()> {
    writeln!(md, "## Model only what a scene requires\n")?;
    writeln!(
        md,
        "| scene | feature left out | with ms | without ms | saved |\n|---|---|---:|---:|---:|"
    )?;
    let mut economy = r.economy.clone();
    let size = base_size(r);
    for k3 in r
        .rows
        .iter()
        .filter(|x| x.display == PAPER_DISPLAY && x.size == size && x.kind == Kind::SinglePass)
    {
        let k1 = r.rows.iter().find(|o| {
            o.display == "lenticular:8"
                && o.scene == k3.scene
                && o.method == k3.method
                && o.size == size
        });
        if let Some(k1) = k1 {
            economy.push(super::tradeoffs::Economy {
                scene: k3.scene.clone(),
                what: format!("subpixel views (K = 3 → 1), {}", k3.method),
                with_ms: k3.ms,
                without_ms: k1.ms,
            });
        }
    }
    for e in &economy {
        writeln!(
            md,
            "| {} | {} | {:.1} | {:.1} | {:.0} % |",
            e.scene,
            e.what,
            e.with_ms,
            e.without_ms,
            whole_percent(saved_percent(e))
        )?;
    }
    let saved = |filter: &dyn Fn(&super::tradeoffs::Economy) -> bool| {
        let v: Vec<f64> = economy
            .iter()
            .filter(|e| filter(e))
            .map(saved_percent)
            .collect();
        let lo = v.iter().copied().fold(f64::MAX, f64::min);
        let hi = v.iter().copied().fold(f64::MIN, f64::max);
        (!v.is_empty()).then_some((lo, hi))
    };
    let range = |r: Option<(f64, f64)>| {
        r.map_or("not measured".to_string(), |(lo, hi)| {
            let (lo, hi) = (whole_percent(lo), whole_percent(hi));
            if lo == hi {
                format!("{lo:.0} %")
            } else {
                format!("{lo:.0} to {hi:.0} %")
            }
        })
    };
    writeln!(
        md,
        "\nMeasured here: a K = 1 display saves {} of a single pass (the per-fragment work is \
         per view per pixel; the per-primitive work is not); leaving out the volume lighting \
         saves {} (two texture fetches per sample dominate the Blinn-Phong arithmetic on a CPU); \
         skipping the space the transfer function makes transparent saves {} (exact: the same \
         image bit for bit). \
         Differences within ±10 % are noise on a software rasteriser. Not modelled separately: a \
         scene without colour (a vertex colour is 4 of 48 bytes per mesh vertex, 4 of 32 per \
         splat; not specialised: a trial replacing the mesh resolve's colour loads by one colour \
         saved ≈ 1 % at 1920×1080, docs/MESHES.md).\n",
        range(saved(&|e| e.what.starts_with("subpixel"))),
        range(saved(&|e| e.what.starts_with("lighting"))),
        range(saved(&|e| e.what.starts_with("marching"))),
    )?;
    writeln!(
        md,
        "How the pipelines are specialised: `VIEWS_PER_PIXEL` (K) and `VIEW_COUNT` (N) are WGSL \
         override constants set when a pipeline is built for a display (`src/render/specialize.rs`), \
         so a lenticular (K = 1) scene compiles to one ray per fragment and the loops over K fold \
         away; pipelines are cached per (K, N). Volume shading is a uniform switch (`--no-shading`); \
         the pre-integration table and the empty-space distances are rebuilt only when the \
         transfer function (or the step, or the volume) changes; \
         the splat renderer allocates per-subpixel group images only for exact depth on K = 3 \
         displays; the single-pass renderers allocate no per-view buffers at all (N-pass: N layers).\n"
    )?;
    Ok(())
}
