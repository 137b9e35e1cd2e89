//! `--turntable FRAMES [--axis x|y|z]`: the scene turned once around an axis through the centre
//! of its bounds, as FRAMES numbered files `{stem}_{k:04}.png` in `--output`'s format (spatial
//! images, quilts, anaglyphs…), each rendered by the run's renderer, or as one video
//! (`--out F.mp4` / `F.gif`) of those images. The camera, lights and display stay put, as on a
//! real turntable; a progress bar runs on stderr while it renders and the frame times are
//! summarised at the end.

use std::path::PathBuf;
use std::time::Instant;

use anyhow::Result;
use autostereo::camera::Bounds;
use autostereo::frame::Frame;
use autostereo::gpu::GpuContext;
use autostereo::render::Renderer;
use autostereo::video::VideoWriter;
use glam::{Mat4, Vec3};

use crate::output::flags::Axis;
use crate::plan::RunPlan;

/// What a turntable run wrote and how long its frames took.
pub struct Summary {
    pub frames: u32,
    pub first: PathBuf,
    pub last: PathBuf,
    /// Every file, in order.
    pub written: Vec<PathBuf>,
    /// Per-frame wall time (render, read back, write), ms.
    pub frame_ms: Vec<f64>,
    pub seconds: f64,
}

impl Summary {
    /// The `--json` fields.
    pub fn fields(&self) -> serde_json::Value {
        let (min, median, max) = self.stats();
        serde_json::json!({
            "turntable_frames": self.frames,
            "turntable_first": self.first,
            "turntable_last": self.last,
            "turntable_frame_ms_min": min,
            "turntable_frame_ms_median": median,
            "turntable_frame_ms_max": max,
            "turntable_seconds": self.seconds,
        })
    }

    fn stats(&self) -> (f64, f64, f64) {
        let min = self.frame_ms.iter().copied().fold(f64::INFINITY, f64::min);
        let max = self.frame_ms.iter().copied().fold(0.0, f64::max);
        (min, autostereo::timing::median(&self.frame_ms), max)
    }

    /// One line for stderr.
    pub fn line(&self) -> String {
        let (min, median, max) = self.stats();
        let files = match self.first == self.last {
            true => self.first.display().to_string(),
            false => format!("{} … {}", self.first.display(), self.last.display()),
        };
        format!(
            "turntable: {} frames in {:.1} s, {median:.0} ms/frame median ({min:.0}…{max:.0}; \
             render, read back and write) → {files}",
            self.frames, self.seconds,
        )
    }
}

/// The scene of `frame` turned by `angle` radians around `axis` through `center`: the
/// camera's world → eye transform composed with the turn (still rigid).
pub fn turned(frame: &Frame, axis: Axis, center: Vec3, angle: f32) -> Frame {
    let axis = match axis {
        Axis::X => Vec3::X,
        Axis::Y => Vec3::Y,
        Axis::Z => Vec3::Z,
    };
    let turn = Mat4::from_translation(center)
        * Mat4::from_axis_angle(axis, angle)
        * Mat4::from_translation(-center);
    let mut turned = frame.clone();
    turned.camera.eye_from_world = frame.camera.eye_from_world * turn;
    turned
}

/// Render the turntable `plan` asks for; `None` when it asks for none.
pub fn render<S: ?Sized>(
    ctx: &GpuContext,
    renderer: &mut dyn Renderer<S>,
    scene: &S,
    frame: &Frame,
    bounds: Bounds,
    plan: &mut RunPlan,
) -> Result<Option<Summary>> {
    let (Some((frames, axis)), Some(out)) = (plan.turntable, plan.output.out.clone()) else {
        return Ok(None);
    };
    let quilt = plan.output.format == crate::output::flags::OutputArg::Quilt;
    let start = Instant::now();
    let bar = crate::progress::bar(u64::from(frames), "turntable");
    let mut written = Vec::new();
    let mut frame_ms = Vec::new();
    // A video: one file (a quilt's named for its grid), each frame's image appended.
    let mut video = match crate::output::video::is_video(&out) {
        true => {
            let named = match quilt {
                true => crate::output::frame_quilt(frame, &plan.output)?.file_name(&out),
                false => out.clone(),
            };
            plan.claims.claim(&named, "--out")?;
            let size = crate::output::names::image_size(frame, &plan.output)?;
            written.push(named.clone());
            Some(VideoWriter::create(&named, size, &plan.video)?)
        }
        false => None,
    };
    for k in 0..frames {
        let angle = std::f32::consts::TAU * k as f32 / frames as f32;
        let this = turned(frame, axis, bounds.center(), angle);
        let t = Instant::now();
        match &mut video {
            Some(video) => {
                let image = crate::output::image_of(
                    ctx,
                    renderer,
                    scene,
                    &this,
                    &plan.output,
                    None,
                    false,
                )?;
                video.push(&image)?;
            }
            None => written.extend(crate::output::write(
                ctx,
                renderer,
                scene,
                &this,
                &plan.output,
                &mut plan.claims,
                None,
                &crate::output::names::numbered(&out, k, quilt),
            )?),
        }
        frame_ms.push(t.elapsed().as_secs_f64() * 1e3);
        bar.inc(1);
    }
    if let Some(video) = video {
        bar.set_message("encoding");
        video.finish()?;
    }
    bar.finish_and_clear();
    Ok(Some(Summary {
        frames,
        first: written.first().cloned().unwrap_or_default(),
        last: written.last().cloned().unwrap_or_default(),
        written,
        frame_ms,
        seconds: start.elapsed().as_secs_f64(),
    }))
}
