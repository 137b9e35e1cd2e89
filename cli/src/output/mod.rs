//! `--output`: what a render command writes to `--out`. The spatial image is the run's own
//! frame; every other format is made of views, each rendered by the run's renderer (any
//! method) with the run's camera on a one-view display (`view:N,V`), then tiled into a quilt,
//! written one PNG per view, or composited as a stereo pair (`StereoCompositor`).

use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};
use autostereo::frame::Frame;
use autostereo::gpu::GpuContext;
use autostereo::image_io::RgbImage;
use autostereo::render::{Renderer, StereoFormat};

mod names;
pub use names::{frame_quilt, planned, view_file};

/// The formats of `--output`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum OutputArg {
    /// The display's interleaved image.
    Spatial,
    /// A Looking Glass quilt of every view (view 0 bottom-left), named `…_qs{c}x{r}a{aspect}`.
    Quilt,
    /// One PNG per view: `{stem}_{V}.png`, V zero-padded to the digits of the last view (at
    /// least two), so that the files sort in view order.
    Views,
    /// Red-cyan anaglyph of the --eyes pair, full colour.
    Anaglyph,
    /// Red-cyan anaglyph, half colour (the left eye's luminance in red).
    AnaglyphHalf,
    /// Red-cyan anaglyph, Dubois' least-squares matrices.
    AnaglyphDubois,
    /// Left and right eye side by side, each the full --size (output twice as wide).
    SideBySide,
    /// Side by side in the --size: each eye half as wide (what 3D TVs expect).
    SideBySideHalf,
    /// Left eye above the right, each the full --size (output twice as tall).
    TopBottom,
    /// Top and bottom in the --size: each eye half as tall.
    TopBottomHalf,
    /// Row-interlaced (left eye on even rows), for line-polarised monitors.
    Rows,
    /// Column-interlaced (left eye on even columns).
    Columns,
    /// Checkerboard (left eye where x + y is even), for DLP 3D projectors.
    Checkerboard,
}

impl OutputArg {
    /// The flag value, as the user wrote it.
    pub fn name(self) -> String {
        clap::ValueEnum::to_possible_value(&self)
            .map_or_else(|| format!("{self:?}"), |v| v.get_name().to_string())
    }

    /// The compositor's format and each eye's size for an output of `size`, for the stereo
    /// formats; `None` for the others.
    fn stereo(self, size: [u32; 2]) -> Option<(StereoFormat, [u32; 2])> {
        let half_w = [(size[0] / 2).max(1), size[1]];
        let half_h = [size[0], (size[1] / 2).max(1)];
        Some(match self {
            Self::Spatial | Self::Quilt | Self::Views => return None,
            Self::Anaglyph => (StereoFormat::AnaglyphColor, size),
            Self::AnaglyphHalf => (StereoFormat::AnaglyphHalfColor, size),
            Self::AnaglyphDubois => (StereoFormat::AnaglyphDubois, size),
            Self::SideBySide => (StereoFormat::SideBySide, size),
            Self::SideBySideHalf => (StereoFormat::SideBySide, half_w),
            Self::TopBottom => (StereoFormat::TopBottom, size),
            Self::TopBottomHalf => (StereoFormat::TopBottom, half_h),
            Self::Rows => (StereoFormat::Rows, size),
            Self::Columns => (StereoFormat::Columns, size),
            Self::Checkerboard => (StereoFormat::Checkerboard, size),
        })
    }
}

/// What a command writes and where: the flags every command that renders views shares
/// (`mesh`, `points`, `volume`, `gaussians`, `rgbd`), one definition.
#[derive(clap::Args, Clone, Debug)]
#[command(next_help_heading = "Output")]
pub struct OutputArgs {
    /// Output PNG (of the spatial image, or of --output's format). Without it nothing is
    /// written, which only --json, --compare or --frames (a measurement) may ask for.
    #[arg(long, value_name = "F.png")]
    pub out: Option<PathBuf>,
    /// What --out holds: spatial | quilt (named `{stem}_qs{c}x{r}a{aspect}.png`) | views
    /// (`{stem}_00.png`…, zero-padded) | anaglyph | anaglyph-half | anaglyph-dubois |
    /// side-by-side | side-by-side-half | top-bottom | top-bottom-half | rows | columns |
    /// checkerboard (every format but spatial renders each view it needs with the --method).
    #[arg(
        long = "output",
        value_name = "FORMAT",
        value_enum,
        default_value = "spatial"
    )]
    pub format: OutputArg,
    /// With --output quilt: the quilt's grid COLSxROWS (default: a Looking Glass's own grid,
    /// else one chosen for the view count; Looking Glass software also reads e.g. 8x6 for 48
    /// views, the last tiles empty).
    #[arg(long = "quilt", value_name = "COLSxROWS", value_parser = crate::args::parse_size)]
    pub quilt_grid: Option<[u32; 2]>,
    /// With the stereo formats of --output (anaglyph…, side-by-side…, top-bottom…, rows,
    /// columns, checkerboard): the left and right views L,R (default: two views a quarter of
    /// the views apart, about the middle).
    #[arg(long, value_name = "L,R", value_parser = crate::args::parse_eyes)]
    pub eyes: Option<[u32; 2]>,
    /// Print one JSON object with the run's parameters, timing and the files written
    /// (`written`) on stdout.
    #[arg(long)]
    pub json: bool,
    /// Retired: `--output quilt --out F.png` writes the quilt.
    #[arg(long, hide = true)]
    pub quilt_out: Option<PathBuf>,
    /// Retired: `--output views --out DIR/view.png` writes every view.
    #[arg(long, hide = true)]
    pub views_out: Option<PathBuf>,
}

impl OutputArgs {
    /// Fail early on what can be checked before loading anything; `measuring`: the run was
    /// asked for something besides --out (numbers: --compare, --frames; or another file), so
    /// writing no --out is what was asked.
    pub fn check(&self, measuring: bool) -> Result<()> {
        if let Some(f) = &self.quilt_out {
            bail!(
                "--quilt-out was retired: write the quilt with --output quilt --out {} (one \
                 output per run; the name gets the _qs{{cols}}x{{rows}}a{{aspect}} suffix)",
                f.display()
            );
        }
        if let Some(dir) = &self.views_out {
            bail!(
                "--views-out was retired: write every view with --output views --out {} \
                 (writes view_00.png, view_01.png, … there, as --views-out did)",
                dir.join("view.png").display()
            );
        }
        match &self.out {
            Some(out) => crate::args::check_output(out)?,
            None if self.format != OutputArg::Spatial => bail!(
                "--output {} writes to --out, which is missing",
                self.format.name()
            ),
            None if !(measuring || self.json) => bail!(
                "nothing to write: give --out F.png (or --json, --compare or --frames N to \
                 measure without writing an image)"
            ),
            None => {}
        }
        if self.quilt_grid.is_some() && self.format != OutputArg::Quilt {
            bail!(
                "--quilt sets the grid of --output quilt, not of --output {}",
                self.format.name()
            );
        }
        if let Some([l, r]) = self.eyes {
            if l == r {
                bail!("--eyes {l},{r}: one view for both eyes has no depth; give two views L,R");
            }
            if self.format.stereo([1, 1]).is_none() {
                bail!(
                    "--eyes {l},{r} chooses the views of a stereo --output (anaglyph, \
                     side-by-side, top-bottom, rows, columns, checkerboard), not of --output {}",
                    self.format.name()
                );
            }
        }
        Ok(())
    }
}

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

/// What a run wrote: every file, and the turntable's summary where it turned.
pub struct Saved {
    pub written: Vec<PathBuf>,
    pub turntable: Option<crate::turntable::Summary>,
}

impl Saved {
    /// The `--json` fields: `written` (every file, in order) and the turntable's.
    pub fn fields(&self) -> serde_json::Value {
        let mut fields = serde_json::json!({ "written": self.written });
        if let Some(t) = &self.turntable {
            crate::run::merge(&mut fields, t.fields());
        }
        fields
    }
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
    let written = if let Some(summary) = &turntable {
        if !output.json {
            eprintln!("{}", summary.line());
        }
        summary.written.clone()
    } else if let Some(out) = &output.out {
        let written = write(
            ctx,
            renderer,
            scene,
            frame,
            output,
            &mut plan.claims,
            Some(spatial),
            out,
        )?;
        say_written(output.json, &written);
        if output.format == OutputArg::Spatial {
            crate::run::how_to_look(out, plan, frame);
        }
        written
    } else {
        Vec::new()
    };
    Ok(Saved { written, turntable })
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
    let what = || format!("--output {}", output.format.name());
    if let Some((format, eye)) = output.format.stereo(frame.size) {
        claims.claim(out, "--out")?;
        let eyes = eye_views(output.eyes, views)?;
        autostereo::render::render_stereo(device, queue, renderer, scene, frame, format, eye, eyes)
            .with_context(what)?
            .save_png(out)?;
        return Ok(vec![out.to_path_buf()]);
    }
    match output.format {
        OutputArg::Views => {
            let written: Vec<PathBuf> = (0..views).map(|v| view_file(out, v, views)).collect();
            for path in &written {
                claims.claim(path, "--out")?;
            }
            for (v, path) in (0..views).zip(&written) {
                let size = frame.size;
                autostereo::render::render_view(
                    device, queue, renderer, scene, frame, v, size, false,
                )
                .with_context(what)?
                .read(device, queue)?
                .save_png(path)?;
            }
            Ok(written)
        }
        OutputArg::Quilt => {
            let layout = frame_quilt(frame, output)?;
            let named = layout.file_name(out);
            claims.claim(&named, "--out")?;
            autostereo::render::render_quilt(device, queue, renderer, scene, frame, &layout)
                .with_context(what)?
                .save_png(&named)?;
            Ok(vec![named])
        }
        _ => {
            claims.claim(out, "--out")?;
            match spatial {
                Some(image) => image.save_png(out)?,
                None => renderer
                    .render_image(&ctx.device, &ctx.queue, scene, frame)?
                    .save_png(out)?,
            }
            Ok(vec![out.to_path_buf()])
        }
    }
}
