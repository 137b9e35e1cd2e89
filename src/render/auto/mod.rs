//! `Method` auto: the fastest method for a frame that meets an accuracy floor. Each candidate
//! (the single pass, the N-pass, and on a Looking Glass the quilt pipeline: `tiled` at the
//! family's quilt) gets a predicted time from the frame's counts ([`census`]) and a cost model
//! fitted to measurements (`costs`, docs/DESIGN.md §10); the exact ones equal the N-pass, the
//! quilt carries its PSNR measured against it (docs/quilt_pipeline.md). The floor is exact by
//! default: an approximation is chosen only when a caller names the PSNR it accepts.

pub mod census;
mod costs;

use crate::camera::Bounds;
use crate::display::DisplayKind;
use crate::error::{Error, Result};
use crate::frame::Frame;
use crate::param::Param;
use crate::render::quilt_image::QuiltChoice;
use crate::render::Method;
use crate::DataKind;

pub use census::MeshCensus;

#[cfg(test)]
mod tests;
use costs::{Counts, Work};

/// The accuracy a chosen method must reach against the N-pass.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Accuracy {
    /// Exact methods only: equal to the N-pass (the single pass, the N-pass itself).
    #[default]
    Exact,
    /// Also approximations whose measured PSNR against the N-pass is at least this, dB.
    MinPsnr(f32),
}

impl Accuracy {
    /// `Exact` without a floor, else the floor checked: a finite number of decibels > 0.
    pub fn new(min_psnr: Option<f32>) -> Result<Self> {
        match min_psnr {
            None => Ok(Self::Exact),
            Some(db) if db.is_finite() && db > 0.0 => Ok(Self::MinPsnr(db)),
            Some(db) => Err(Error::invalid(
                Param::MinPsnr,
                format!("{db}: a PSNR floor is a finite number of decibels > 0"),
            )),
        }
    }

    /// Whether a candidate of `psnr_db` (`None`: exact) meets the floor.
    fn admits(self, psnr_db: Option<f32>) -> bool {
        match (self, psnr_db) {
            (_, None) => true,
            (Accuracy::Exact, Some(_)) => false,
            (Accuracy::MinPsnr(floor), Some(db)) => db >= floor,
        }
    }

    /// How a summary says it: `exact` or `≥ 40 dB`.
    pub fn describe(self) -> String {
        match self {
            Accuracy::Exact => "exact".into(),
            Accuracy::MinPsnr(db) => format!("≥ {db} dB"),
        }
    }
}

/// What is to be rendered, as the cost model counts it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Workload {
    /// A mesh, counted in the frame ([`MeshCensus::of`]).
    Mesh(MeshCensus),
    /// A point cloud (ray-tested splats).
    Points,
    /// A volume (ray-marched).
    Volume,
    /// 3D Gaussian splats.
    Gaussians,
}

impl Workload {
    /// The kind of data.
    pub fn kind(&self) -> DataKind {
        match self {
            Workload::Mesh(_) => DataKind::Mesh,
            Workload::Points => DataKind::Points,
            Workload::Volume => DataKind::Volume,
            Workload::Gaussians => DataKind::Gaussians,
        }
    }

    fn work(&self) -> Work {
        match self {
            Workload::Mesh(census) => Work::Mesh(*census),
            Workload::Points => Work::Rays(costs::ns::POINTS_RAY),
            Workload::Volume => Work::Rays(costs::ns::VOLUME_RAY),
            Workload::Gaussians => Work::Rays(costs::ns::GAUSSIANS_RAY),
        }
    }

    /// The quilt pipeline's PSNR against the full-resolution N-pass, the lower of the two
    /// panels measured in docs/quilt_pipeline.md (the 16": 44.0, 38.0, 51.0 dB; the Go: 41.8,
    /// 36.0, 47.6), so that a floor holds on both; `None` where it was not measured (it is then
    /// no candidate).
    fn quilt_psnr(&self) -> Option<f32> {
        match self {
            Workload::Mesh(_) => Some(41.8),
            Workload::Points => Some(36.0),
            Workload::Volume => Some(47.6),
            Workload::Gaussians => None,
        }
    }
}

/// One method the choice weighed.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Candidate {
    /// The method.
    pub method: Method,
    /// The size its views are rendered at (the image's, but for the quilt's tiles).
    pub view_size: [u32; 2],
    /// What it is, for a report.
    pub label: String,
    /// PSNR against the N-pass, dB: `None` for an exact method (equal to it).
    pub psnr_db: Option<f32>,
    /// The model's time for one frame, ms.
    pub predicted_ms: f64,
    /// Whether it meets the accuracy floor.
    pub admitted: bool,
}

/// The method chosen for a frame and what it was weighed against.
#[derive(Clone, Debug, PartialEq)]
pub struct Choice {
    /// Every candidate, the chosen one included.
    pub candidates: Vec<Candidate>,
    /// Index of the chosen candidate.
    pub chosen: usize,
    /// The floor it met.
    pub accuracy: Accuracy,
    /// What was counted.
    pub workload: Workload,
    /// The share of the image the scene's bounds cover ([`census::bounds_coverage`]).
    pub coverage: f64,
}

impl Choice {
    /// The chosen candidate.
    pub fn chosen(&self) -> &Candidate {
        &self.candidates[self.chosen]
    }

    /// One line: `auto → n-pass (exact; predicted 1.3 s; single pass 1.6 s, …)`.
    pub fn summary(&self) -> String {
        let c = self.chosen();
        let others: Vec<String> = self
            .candidates
            .iter()
            .enumerate()
            .filter(|(i, _)| *i != self.chosen)
            .map(|(_, o)| {
                let accuracy = match (o.psnr_db, o.admitted) {
                    (None, _) => String::new(),
                    (Some(db), true) => format!(" at {db} dB"),
                    (Some(db), false) => format!(" at {db} dB, below the floor"),
                };
                format!("{} {}{accuracy}", o.label, seconds(o.predicted_ms))
            })
            .collect();
        let accuracy = match c.psnr_db {
            None => "exact".to_string(),
            Some(db) => format!("{db} dB measured, floor {}", self.accuracy.describe()),
        };
        let mut line = format!(
            "auto → {} ({accuracy}; predicted {}",
            c.label,
            seconds(c.predicted_ms)
        );
        if !others.is_empty() {
            line += &format!("; {}", others.join(", "));
        }
        line + ")"
    }

    /// The choice as `--json` reports it.
    pub fn fields(&self) -> serde_json::Value {
        serde_json::json!({
            "chosen": self.chosen().method.name(),
            "label": self.chosen().label,
            "accuracy": self.accuracy.describe(),
            "candidates": self.candidates,
            "coverage": self.coverage,
            "census": match &self.workload {
                Workload::Mesh(m) => serde_json::to_value(m).unwrap_or_default(),
                other => other.kind().name().into(),
            },
        })
    }
}

/// The model's time for `method` rendering its views at `view_size` in an image of `size`.
fn predict(
    workload: &Workload,
    counts: &Counts,
    method: Method,
    view_size: [u32; 2],
    size: [u32; 2],
) -> f64 {
    let work = workload.work();
    match method {
        Method::SinglePass => costs::single_pass(&work, counts),
        _ => {
            let pixels = view_size[0] as f64 * view_size[1] as f64;
            costs::per_view(&work, counts, pixels, view_size != size)
        }
    }
}

fn seconds(ms: f64) -> String {
    match ms >= 1000.0 {
        true => format!("{:.1} s", ms / 1000.0),
        false => format!("{ms:.0} ms"),
    }
}

/// The fastest of the `offered` methods that meets `accuracy` for `workload` in `frame`
/// (its scene within `bounds`). `offered` is what the caller's other settings allow (a
/// single-pass-only option leaves only the single pass); of them, the single pass, the N-pass
/// and on a Looking Glass the quilt pipeline are weighed. Fails where none of them is offered
/// or none meets the floor, naming what was.
pub fn choose(
    frame: &Frame,
    bounds: Bounds,
    workload: Workload,
    accuracy: Accuracy,
    offered: &[Method],
) -> Result<Choice> {
    let counts = Counts {
        pixels: frame.size[0] as f64 * frame.size[1] as f64,
        per_pixel: frame.display.views_per_pixel() as f64,
        views: frame.camera.views as f64,
        coverage: census::bounds_coverage(frame, bounds),
    };
    let mut candidates = Vec::new();
    let mut add = |method, view_size: [u32; 2], label: String, psnr_db| {
        if offered.contains(&method) {
            let predicted_ms = predict(&workload, &counts, method, view_size, frame.size);
            candidates.push(Candidate {
                method,
                view_size,
                label,
                psnr_db,
                predicted_ms,
                admitted: accuracy.admits(psnr_db),
            });
        }
    };
    add(Method::SinglePass, frame.size, "single pass".into(), None);
    add(Method::NPass, frame.size, "n-pass".into(), None);
    if let (DisplayKind::LookingGlass { .. }, Some(psnr)) =
        (&frame.display.kind, workload.quilt_psnr())
    {
        let quilt = frame
            .display
            .quilt(frame.camera.views, frame.size, &QuiltChoice::default())?;
        let l = quilt.layout;
        // Views are never rendered larger than the image (an image smaller than the tiles
        // gets tiles of its own size: sharper than the family's, so the PSNR still holds).
        let tile = [0, 1].map(|k| l.tile[k].min(frame.size[k]));
        let label = format!(
            "the family's quilt ({}x{} tiles of {}x{}, tiled)",
            l.cols, l.rows, tile[0], tile[1]
        );
        add(Method::Tiled, tile, label, Some(psnr));
    }
    let chosen = candidates
        .iter()
        .enumerate()
        .filter(|(_, c)| c.admitted)
        .min_by(|a, b| a.1.predicted_ms.total_cmp(&b.1.predicted_ms))
        .map(|(i, _)| i);
    let Some(chosen) = chosen else {
        let names: Vec<&str> = offered.iter().map(|m| m.name()).collect();
        return Err(Error::invalid(
            Param::Method,
            format!(
                "auto: no method the other settings allow ({}) is {} for {}; name one",
                names.join(", "),
                accuracy.describe(),
                workload.kind().name()
            ),
        ));
    };
    Ok(Choice {
        candidates,
        chosen,
        accuracy,
        workload,
        coverage: counts.coverage,
    })
}
