//! What the render commands share: timed frames, the N-pass comparison, the report.

use std::path::{Path, PathBuf};

use anyhow::Result;
use autostereo::frame::Frame;
use autostereo::gpu::GpuContext;
use autostereo::image_io::{compare, ImageDiff, RgbImage};
use autostereo::render::Renderer;
use autostereo::target::SpatialTarget;
use autostereo::timing::{median, FrameTimer, TimingSource};
use autostereo::RendererOptions;

use crate::output::flags::OutputArg;
use crate::output::{say_written, write};
use crate::warp_cmd::hole_share;

/// The last frame's image and the median time over the timed frames.
pub struct Timed {
    pub image: RgbImage,
    pub ms: f64,
    pub timing: TimingSource,
    /// GPU bytes the library held for the frame (scene, renderer, target).
    pub gpu_bytes: u64,
    /// How the renderer made it, where it says (the warp's references; a frame too large for
    /// the adapter in one piece: its bands).
    pub how: Option<String>,
}

/// Render the frames `frames` asks for (`--frames N`: N timed after a warm-up; else one frame
/// without a warm-up, whose time is still reported); keep the last image.
pub fn timed<S: ?Sized>(
    ctx: &GpuContext,
    renderer: &mut dyn Renderer<S>,
    scene: &S,
    frame: &Frame,
    frames: &crate::args::FramesArgs,
) -> Result<Timed> {
    let (warm_up, frames) = (frames.warm_up(), frames.timed());
    let (device, queue) = (&ctx.device, &ctx.queue);
    let target = SpatialTarget::new(device, frame.size)?;
    let timer = FrameTimer::new(device, queue);
    renderer.prepare(device, queue, scene, frame)?;
    let mut times = Vec::new();
    for i in 0..frames + warm_up {
        let ms = timer.time_frame(device, queue, |encoder| {
            renderer.encode(device, encoder, scene, frame, &target)
        })?;
        if i >= warm_up {
            times.push(ms);
        }
    }
    Ok(Timed {
        gpu_bytes: autostereo::budget::Budget::current().gpu_held(),
        how: renderer.describe(),
        image: target.read(device, queue)?,
        ms: median(&times),
        timing: timer.source(),
    })
}

/// One frame of `renderer` (the N-pass oracle for `--compare`, with full-size views whatever
/// the run's `--view-scale`) compared with `image`.
pub fn compare_with<S: ?Sized>(
    ctx: &GpuContext,
    renderer: &mut dyn Renderer<S>,
    scene: &S,
    frame: &Frame,
    image: &RgbImage,
) -> Result<ImageDiff> {
    let full = Frame {
        view_scale: [1.0; 2],
        ..frame.clone()
    };
    let oracle = renderer.render_image(&ctx.device, &ctx.queue, scene, &full)?;
    Ok(compare(image, &oracle)?)
}

/// Print the run: one JSON object on stdout (`json`), else a summary on stderr.
pub fn report(json: bool, mut fields: serde_json::Value, diff: Option<ImageDiff>, summary: &str) {
    if json {
        if let Some(d) = diff {
            fields["psnr_db"] = d.psnr_db.into();
            fields["max_abs_err"] = d.max_abs_err.into();
            fields["frac_off_2"] = d.frac_off_2.into();
        }
        println!("{fields}");
    } else {
        eprintln!("{summary}");
        if let Some(d) = diff {
            eprintln!(
                "vs n-pass: PSNR {:.2} dB, max abs error {}, {:.4} % of subpixels off by > 2/255",
                d.psnr_db,
                d.max_abs_err,
                100.0 * d.frac_off_2
            );
        }
    }
}

/// The `--json` fields every render command reports (what ran, where, how fast) plus the
/// command's own `extra` object.
pub fn run_fields(
    ctx: &GpuContext,
    plan: &crate::plan::RunPlan,
    frame: &Frame,
    run: &Timed,
    extra: serde_json::Value,
) -> serde_json::Value {
    let mut fields = serde_json::json!({
        "method": plan.method.name(),
        "output": plan.output.format.name(),
        "views": frame.camera.views,
        "views_per_pixel": frame.display.views_per_pixel(),
        "display": plan.display_spec(),
        "size": frame.size,
        "adapter": ctx.adapter_label(),
        "ms": run.ms,
        "view_scale": frame.view_scale,
        "view_size": frame.view_size(),
        "timing": run.timing,
        "focal_distance": frame.camera.focal_distance,
        "separation": frame.camera.separation,
        "gpu_bytes": run.gpu_bytes,
        "rendered": run.how,
    });
    merge(&mut fields, plan.timing.fields());
    if let Some(choice) = &plan.choice {
        fields["auto"] = choice.fields();
    } else if let Some(line) = plan.auto_line() {
        fields["auto"] = serde_json::json!({ "chosen": plan.method.name(), "note": line });
    }
    merge(&mut fields, extra);
    fields
}

/// Tell the user how to look at the spatial image `out` without the panel: it only looks
/// right through the display's optics (stderr, so that `--json` output stays one object). A
/// one-view display's image is that view, nothing to pick views from.
pub fn how_to_look(out: &Path, plan: &crate::plan::RunPlan, frame: &Frame) {
    if plan.output.json {
        return;
    }
    let views = frame.camera.views;
    let display = plan.display_flags(views);
    if let autostereo::display::DisplayKind::OneView { .. } = frame.display.kind {
        eprintln!(
            "{} is one view ({display}): an ordinary image, no display needed.",
            out.display()
        );
        return;
    }
    let [l, r] = autostereo::render::default_eyes(views);
    let stem = out
        .file_stem()
        .map_or("out".into(), |s| s.to_string_lossy());
    let scene = match &plan.input {
        Some(file) => shell_word(&file.display().to_string()),
        None => format!("--kind {}", plan.kind.name()),
    };
    eprintln!(
        "{} is interleaved for {display} (it looks right only through that display). Without \
         one: render the same command with `--output anaglyph --out {stem}_anaglyph.png` (red-cyan \
         glasses; views {l} and {r}, --eyes L,R chooses), or pick them from this image with \
         `autostereo views {} {display} --eyes {l},{r} --out {stem}_anaglyph.png` (streaky: \
         each view has only its own subpixels), or look live in a window: `autostereo view \
         {scene} {display} --preview side-by-side`.",
        out.display(),
        out.display(),
    );
}

/// `word` quoted for a POSIX shell where it needs it.
fn shell_word(word: &str) -> String {
    let plain = word
        .chars()
        .all(|c| c.is_ascii_alphanumeric() || "/._-+,:=@%".contains(c));
    match plain && !word.is_empty() {
        true => word.to_string(),
        false => format!("'{}'", word.replace('\'', "'\\''")),
    }
}

/// Add the fields of `more` to the object `fields`.
pub fn merge(fields: &mut serde_json::Value, more: serde_json::Value) {
    for (k, v) in more.as_object().into_iter().flatten() {
        fields[k] = v.clone();
    }
}

/// The end of every render command's one-line summary: views, size, speed, adapter.
pub fn run_summary(
    ctx: &GpuContext,
    plan: &crate::plan::RunPlan,
    frame: &Frame,
    run: &Timed,
) -> String {
    let bands = run
        .how
        .as_deref()
        .filter(|how| how.contains("bands"))
        .map_or(String::new(), |how| format!(" ({how})"));
    let fitted_here = ctx.info().device_type == wgpu::DeviceType::Cpu;
    let auto = plan
        .auto_line()
        .map_or(String::new(), |line| match fitted_here {
            true => format!("\n{line}"),
            false => {
                format!("\n{line}; the cost model's constants are llvmpipe's, not this adapter's")
            }
        });
    format!(
        "{} views, {}x{}{bands}, GPU memory {:.1} MiB, {:.2} ms/frame ({}, {:?}) on {}{auto}",
        frame.camera.views,
        frame.size[0],
        frame.size[1],
        run.gpu_bytes as f64 / (1u64 << 20) as f64,
        run.ms,
        plan.timing.described(),
        run.timing,
        ctx.adapter_label()
    )
}

/// What a render command has made once its renderer has run: the timed run, the `--json`
/// fields (the run's, the command's `extra`, the files written, the warp's holes) and the
/// comparison with the N-pass (`--compare`).
pub struct Rendered {
    pub run: Timed,
    pub fields: serde_json::Value,
    pub diff: Option<ImageDiff>,
}

/// The steps every render command takes after loading, in one place: the timed run of
/// `renderer`, its outputs (`save_all`), with `--compare` the frame `build` makes of `oracle`
/// (the exact N-pass at full view size) beside it, with `--method warp` the hole report
/// (`build` makes the warp again with a hole mask), then the fields. `extra`: the command's own
/// fields. A run that is the oracle itself is refused before anything is rendered.
#[allow(clippy::too_many_arguments)]
pub fn render_and_save<S: ?Sized>(
    ctx: &GpuContext,
    plan: &mut crate::plan::RunPlan,
    options: &autostereo::RendererOptions,
    renderer: &mut dyn Renderer<S>,
    build: impl Fn(&autostereo::RendererOptions) -> autostereo::Result<Box<dyn Renderer<S>>>,
    oracle: autostereo::RendererOptions,
    scene: &S,
    frame: &Frame,
    bounds: autostereo::camera::Bounds,
    mut extra: serde_json::Value,
) -> Result<Rendered> {
    let is_oracle = *options == oracle && frame.view_size() == frame.size;
    if plan.compare && is_oracle && plan.choice.is_none() {
        anyhow::bail!(
            "--compare: this run is the N-pass oracle itself (same settings, full-size views), \
             so it would be compared with itself; smaller views (--view-scale < 1, a smaller \
             --view-size) or an approximation (volume --step, --empty-stride) are measured"
        );
    }
    // (--hole-mask is refused with any method but the warp: RenderArgs::plan.)
    plan.claims.check(&crate::output::planned(
        frame,
        &plan.output,
        plan.turntable.map(|(frames, _)| frames),
        plan.hole_mask.as_deref(),
    )?)?;
    let rendering = format!(
        "rendering {}x{}, {} views",
        frame.size[0], frame.size[1], frame.camera.views
    );
    let run = crate::progress::during(&rendering, || {
        timed(ctx, renderer, scene, frame, &plan.timing)
    })?;
    let mut saved = save_all(ctx, renderer, scene, frame, bounds, plan, &run.image)?;
    let diff = match (plan.compare, is_oracle) {
        // Auto chose the N-pass: the run is the oracle, identical to it without a second render.
        (true, true) => Some(compare(&run.image, &run.image)?),
        (true, false) => Some(compare_with(
            ctx,
            build(&oracle)?.as_mut(),
            scene,
            frame,
            &run.image,
        )?),
        (false, _) => None,
    };
    if plan.method == autostereo::render::Method::Warp {
        let holes = hole_report(ctx, plan, options, &build, scene, frame, &mut saved)?;
        merge(&mut extra, holes);
    }
    merge(&mut extra, saved.fields());
    let fields = run_fields(ctx, plan, frame, &run, extra);
    Ok(Rendered { run, fields, diff })
}

/// What a run wrote: every file, and the turntable's summary where it turned.
pub struct Saved {
    pub written: Vec<PathBuf>,
    pub turntable: Option<crate::turntable::Summary>,
    /// The quilt written (`--output quilt`): its size is the file's, not `--size`.
    pub quilt: Option<autostereo::render::quilt_image::QuiltImage>,
}

impl Saved {
    /// The `--json` fields: `written` (every file, in order) and the turntable's.
    pub fn fields(&self) -> serde_json::Value {
        let mut fields = serde_json::json!({ "written": self.written });
        if let Some(t) = &self.turntable {
            merge(&mut fields, t.fields());
        }
        if let Some(q) = &self.quilt {
            merge(&mut fields, quilt_fields(q));
        }
        fields
    }
}

/// What a render command writes after its timed run: `--out` in `--output`'s format, or with
/// `--turntable` its numbered frames (scene turned around the centre of `bounds`).
#[allow(clippy::too_many_arguments)]
pub fn save_all<S: ?Sized>(
    ctx: &GpuContext,
    renderer: &mut dyn Renderer<S>,
    scene: &S,
    frame: &Frame,
    bounds: autostereo::camera::Bounds,
    plan: &mut crate::plan::RunPlan,
    spatial: &RgbImage,
) -> Result<Saved> {
    let turntable = crate::turntable::render(ctx, renderer, scene, frame, bounds, plan)?;
    let output = &plan.output;
    let quilt = match (output.format, &output.out) {
        (OutputArg::Quilt, Some(_)) => Some(crate::output::frame_quilt(frame, output)?),
        _ => None,
    };
    if let (Some(q), false) = (&quilt, output.json) {
        eprintln!("{}", quilt_line(q));
    }
    let written = if let Some(summary) = &turntable {
        if !output.json {
            eprintln!("{}", summary.line());
        }
        summary.written.clone()
    } else if let Some(out) = &output.out {
        let what = format!("writing --output {}", output.format.name());
        let claims = &mut plan.claims;
        let written = crate::progress::during(&what, || {
            write(
                ctx,
                renderer,
                scene,
                frame,
                output,
                claims,
                Some(spatial),
                out,
            )
        })?;
        say_written(output.json, &written);
        if output.format == OutputArg::Spatial {
            crate::run::how_to_look(out, plan, frame);
        }
        written
    } else {
        Vec::new()
    };
    Ok(Saved {
        written,
        turntable,
        quilt,
    })
}

/// The `--json` fields of a quilt written: its size, grid, tile and the aspect its views are
/// shown at.
pub fn quilt_fields(q: &autostereo::render::quilt_image::QuiltImage) -> serde_json::Value {
    serde_json::json!({
        "quilt_size": q.size,
        "quilt_grid": [q.layout.cols, q.layout.rows],
        "quilt_tile": q.layout.tile,
        "quilt_aspect": q.aspect,
    })
}

/// The summary's line for a quilt written.
pub fn quilt_line(q: &autostereo::render::quilt_image::QuiltImage) -> String {
    let l = &q.layout;
    format!(
        "quilt {}x{}: {}x{} tiles of {}x{} (views shown at aspect {:.4}, the tiles stretched to \
         it as Looking Glass software shows them)",
        q.size[0], q.size[1], l.cols, l.rows, l.tile[0], l.tile[1], q.aspect
    )
}

/// The report fields of a warp: R, the path, what depth the references carry, and the share
/// of subpixels filled rather than seen (from a hole-mask render of the renderer `build` makes
/// from `options`, written where asked).
#[allow(clippy::too_many_arguments)]
pub fn hole_report<S: ?Sized>(
    ctx: &GpuContext,
    plan: &mut crate::plan::RunPlan,
    options: &RendererOptions,
    build: impl FnOnce(&RendererOptions) -> autostereo::Result<Box<dyn Renderer<S>>>,
    scene: &S,
    frame: &Frame,
    saved: &mut Saved,
) -> Result<serde_json::Value> {
    let json = plan.output.json;
    let mut options = *options;
    options.warp.hole_mask = true;
    let mut warp = build(&options)?;
    let mask = warp.render_image(&ctx.device, &ctx.queue, scene, frame)?;
    if let Some(path) = &plan.hole_mask {
        plan.claims.save_png(&mask, path, "--hole-mask")?;
        crate::output::say_written(json, std::slice::from_ref(path));
        saved.written.push(path.clone());
    }

    Ok(serde_json::json!({
        "references": options.warp.references,
        "warp_path": options.warp.path.name(),
        "warp": warp.describe(),
        "hole_share": hole_share(&mask),
    }))
}
