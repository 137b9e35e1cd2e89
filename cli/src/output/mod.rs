//! `--output`: what a render command writes to `--out`. The spatial image is the run's own
//! frame; every other format is made of views, each rendered by the run's renderer (any
//! method) with the run's camera on a one-view display (`view:N,V`), then tiled into a quilt,
//! written one PNG per view, or composited as a stereo pair (`StereoCompositor`).

use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};
use autostereo::frame::Frame;
use autostereo::gpu::GpuContext;
use autostereo::image_io::RgbImage;
use autostereo::render::Renderer;

pub mod flags;
pub(crate) mod names;
pub mod video;
pub use names::{frame_quilt, planned, view_file};

use flags::{OutputArg, OutputArgs};

/// The two views of the stereo formats: `eyes`, or the library's `default_eyes`.
pub fn eye_views(eyes: Option<[u32; 2]>, views: u32) -> Result<[u32; 2]> {
    let [l, r] = eyes.unwrap_or(autostereo::render::default_eyes(views));
    for v in [l, r] {
        if v >= views {
            bail!(
                "--eyes {l},{r}: view {v} does not exist (the display has views 0..{})",
                views - 1
            );
        }
    }
    Ok([l, r])
}

/// Say on stderr what was written (unless `json`: then the JSON's `written` says it): every
/// file, or for many the count, the first and the last.
pub fn say_written(json: bool, written: &[PathBuf]) {
    if json {
        return;
    }
    match written {
        [] => {}
        [one] => eprintln!("wrote {}", one.display()),
        [first, .., last] if written.len() > 4 => eprintln!(
            "wrote {} files: {} … {}",
            written.len(),
            first.display(),
            last.display()
        ),
        many => {
            let names: Vec<String> = many.iter().map(|p| p.display().to_string()).collect();
            eprintln!("wrote {}", names.join(", "));
        }
    }
}

/// The end of a command that writes files and renders nothing to time (`mask`, `views`): with
/// `json`, one object of `fields` plus `written`; else the files on stderr.
pub fn report_written(json: bool, mut fields: serde_json::Value, written: &[PathBuf]) {
    if json {
        fields["written"] = serde_json::json!(written);
        println!("{fields}");
    } else {
        say_written(false, written);
    }
}

/// Write `--out` in `--output`'s format; `spatial` is the frame's image if already rendered
/// (else the spatial format renders it). Returns what was written.
#[allow(clippy::too_many_arguments)]
pub fn write<S: ?Sized>(
    ctx: &GpuContext,
    renderer: &mut dyn Renderer<S>,
    scene: &S,
    frame: &Frame,
    output: &OutputArgs,
    claims: &mut crate::claims::Claims,
    spatial: Option<&RgbImage>,
    out: &Path,
) -> Result<Vec<PathBuf>> {
    let views = frame.camera.views;
    let (device, queue) = (&ctx.device, &ctx.queue);
    if output.format == OutputArg::Views {
        let what = || format!("--output {}", output.format.name());
        let written: Vec<PathBuf> = (0..views).map(|v| view_file(out, v, views)).collect();
        for path in &written {
            claims.claim(path, "--out")?;
        }
        for (v, path) in (0..views).zip(&written) {
            let size = frame.size;
            autostereo::render::render_view(device, queue, renderer, scene, frame, v, size, None)
                .with_context(what)?
                .read(device, queue)?
                .save_png(path)?;
        }
        return Ok(written);
    }
    let named = match output.format {
        OutputArg::Quilt => frame_quilt(frame, output)?.file_name(out),
        _ => out.to_path_buf(),
    };
    claims.claim(&named, "--out")?;
    // A run's own output (its spatial image given) counts its quilt views; a turntable's
    // frames (none given) are counted on the turntable's bar.
    let counted = spatial.is_some();
    image_of(ctx, renderer, scene, frame, output, spatial, counted)?.save_png(&named)?;
    Ok(vec![named])
}

/// The one image `--output`'s format makes of `frame` (every format but `views`): the spatial
/// image (`spatial` where already rendered), the quilt (its views counted on a bar where
/// `counted`: not inside a turntable's own), or the stereo pair composed.
pub fn image_of<S: ?Sized>(
    ctx: &GpuContext,
    renderer: &mut dyn Renderer<S>,
    scene: &S,
    frame: &Frame,
    output: &OutputArgs,
    spatial: Option<&RgbImage>,
    counted: bool,
) -> Result<RgbImage> {
    let (device, queue) = (&ctx.device, &ctx.queue);
    let what = || format!("--output {}", output.format.name());
    if let Some((format, eye)) = output.format.stereo(frame.size) {
        let eyes = eye_views(output.eyes, frame.camera.views)?;
        return autostereo::render::render_stereo(
            device, queue, renderer, scene, frame, format, eye, eyes,
        )
        .with_context(what);
    }
    match output.format {
        OutputArg::Quilt => {
            let quilt = frame_quilt(frame, output)?;
            let views = frame.camera.views.min(quilt.layout.views);
            let bar = match counted {
                true => crate::progress::bar(u64::from(views), "quilt views"),
                false => indicatif::ProgressBar::hidden(),
            };
            let image = autostereo::render::render_quilt_counted(
                device,
                queue,
                renderer,
                scene,
                frame,
                &quilt,
                &mut |_| bar.inc(1),
            );
            bar.finish_and_clear();
            image.with_context(what)
        }
        OutputArg::Views => bail!("--output views is a file per view, not one image"),
        _ => match spatial {
            Some(image) => Ok(image.clone()),
            None => Ok(renderer.render_image(device, queue, scene, frame)?),
        },
    }
}
