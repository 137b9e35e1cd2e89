//! Transfer functions (piecewise-linear RGBA over the normalised scalar), their presets and
//! files, as the paper classifies (§3.5.1); their pre-integration table is
//! src/volume/preintegration.rs.

use std::path::Path;

use crate::error::{Error, Result};
use crate::param::Param;
use crate::volume::values::{Units, Values};

/// Piecewise-linear colour and opacity. Opacity is per unit step of one voxel (the smallest
/// voxel spacing); the pre-integration table rescales it to the actual sampling distance.
#[derive(Clone, Debug, PartialEq)]
pub struct TransferFunction {
    /// Control points `(scalar, [r, g, b, a])`, scalars strictly increasing in 0..1.
    pub points: Vec<(f32, [f32; 4])>,
}

/// Preset names accepted by [`TransferFunction::preset`].
pub const PRESETS: &[&str] = &["ct-skin", "ct-bone", "mri", "ml"];

impl TransferFunction {
    /// Check and build from control points.
    pub fn new(mut points: Vec<(f32, [f32; 4])>) -> Result<Self> {
        points.sort_by(|a, b| a.0.total_cmp(&b.0));
        let tf = Self { points };
        tf.validate()?;
        Ok(tf)
    }

    /// Check what [`TransferFunction::new`] checks (at least one point, scalars ascending, all
    /// values in 0..1), for one whose `points` were set directly.
    pub fn validate(&self) -> Result<()> {
        if self.points.is_empty() {
            return Err(Error::invalid(
                Param::TransferFunction,
                "needs at least one control point",
            ));
        }
        for (s, c) in &self.points {
            if !(0.0..=1.0).contains(s) || c.iter().any(|v| !(0.0..=1.0).contains(v)) {
                return Err(Error::invalid(
                    Param::TransferFunction,
                    format!("point {s} {c:?}: scalar and RGBA must be in 0..1"),
                ));
            }
        }
        if self.points.windows(2).any(|w| w[1].0 < w[0].0) {
            return Err(Error::invalid(
                Param::TransferFunction,
                "control point scalars must be in ascending order",
            ));
        }
        Ok(())
    }

    /// A named preset (see [`PRESETS`]).
    pub fn preset(name: &str) -> Result<Self> {
        let p = |s: f32, c: [f32; 4]| (s, c);
        let points = match name {
            // The skin as a thin translucent surface (the band the air-to-tissue edge passes
            // through, so bulk soft tissue stays clear), contrast-filled vessels red, bone
            // opaque (the built-in head's values: soft tissue 0.27–0.33, brain 0.37–0.46,
            // arteries 0.75, bone 0.82–0.95, teeth 1).
            "ct-skin" => vec![
                p(0.0, [0.0; 4]),
                p(0.1, [0.9, 0.6, 0.5, 0.0]),
                p(0.18, [0.95, 0.72, 0.62, 0.2]),
                p(0.26, [0.9, 0.6, 0.5, 0.0]),
                p(0.6, [0.8, 0.3, 0.3, 0.0]),
                p(0.75, [0.9, 0.3, 0.2, 0.5]),
                p(0.85, [1.0, 1.0, 0.95, 0.3]),
                p(1.0, [1.0, 1.0, 0.95, 0.9]),
            ],
            "ct-bone" => vec![
                p(0.0, [0.0; 4]),
                p(0.65, [0.8, 0.7, 0.6, 0.0]),
                p(0.8, [0.95, 0.9, 0.8, 0.6]),
                p(1.0, [1.0, 1.0, 1.0, 0.95]),
            ],
            // MRI: grey matter-ish ramp, bright structures opaque.
            "mri" => vec![
                p(0.0, [0.0; 4]),
                p(0.15, [0.3, 0.3, 0.4, 0.0]),
                p(0.35, [0.7, 0.6, 0.5, 0.08]),
                p(0.6, [0.9, 0.8, 0.7, 0.4]),
                p(1.0, [1.0, 1.0, 1.0, 0.9]),
            ],
            // Marschner–Lobb: a thin shell around the 0.5 isovalue.
            "ml" => vec![
                p(0.0, [0.0; 4]),
                p(0.45, [0.3, 0.5, 0.9, 0.0]),
                p(0.5, [0.4, 0.7, 1.0, 0.7]),
                p(0.55, [0.3, 0.5, 0.9, 0.0]),
                p(1.0, [0.0; 4]),
            ],
            other => {
                return Err(Error::invalid(
                    Param::TransferFunction,
                    format!(
                        "unknown preset {other} (presets: {})",
                        PRESETS.join(", "),
                        other = crate::error::quote(other)
                    ),
                ))
            }
        };
        Self::new(points)
    }

    /// Read a text file: one control point per line, `scalar r g b a` (all in 0..1); blank
    /// lines and `#` comments ignored.
    pub fn load(path: &Path) -> Result<Self> {
        let text = crate::file::read_text(path)?;
        // The file's name before the parse's reason, once ("invalid transfer function: F: line
        // 3: …", not the parameter's name twice).
        Self::parse(&text).map_err(|e| {
            let reason = match e {
                Error::InvalidParameter { reason, .. } => reason,
                other => other.to_string(),
            };
            Error::invalid(
                Param::TransferFunction,
                format!("{}: {reason}", path.display()),
            )
        })
    }

    /// Parse the text format of [`TransferFunction::load`].
    pub fn parse(text: &str) -> Result<Self> {
        let mut points = Vec::new();
        for (n, line) in text.lines().enumerate() {
            let line = line.split('#').next().unwrap_or("").trim();
            if line.is_empty() {
                continue;
            }
            let v: Vec<f32> = line
                .split_whitespace()
                .map(|w| w.parse::<f32>())
                .collect::<std::result::Result<_, _>>()
                .map_err(|_| {
                    Error::invalid(
                        Param::TransferFunction,
                        format!(
                            "line {}: {line} is not 5 numbers",
                            n + 1,
                            line = crate::error::quote(line)
                        ),
                    )
                })?;
            if v.len() != 5 {
                return Err(Error::invalid(
                    Param::TransferFunction,
                    format!(
                        "line {}: {} numbers, expected 5 (scalar r g b a)",
                        n + 1,
                        v.len()
                    ),
                ));
            }
            points.push((v[0], [v[1], v[2], v[3], v[4]]));
        }
        Self::new(points)
    }

    /// The normalised function of control points given in a volume's units (`values`): exact,
    /// as the mapping from values to scalars is linear — the function at the range's ends and
    /// at every point inside it; points outside the range fall away. Values must be finite
    /// and ascending, RGBA in 0..1.
    pub fn in_units(points: &[(f64, [f32; 4])], values: &Values) -> Result<Self> {
        if points.is_empty() {
            return Err(Error::invalid(
                Param::TransferFunction,
                "needs at least one control point",
            ));
        }
        for (u, c) in points {
            if !u.is_finite() || c.iter().any(|v| !(0.0..=1.0).contains(v)) {
                return Err(Error::invalid(
                    Param::TransferFunction,
                    format!("point {u} {c:?}: a finite value and RGBA in 0..1"),
                ));
            }
        }
        if points.windows(2).any(|w| w[1].0 < w[0].0) {
            return Err(Error::invalid(
                Param::TransferFunction,
                "control point values must be in ascending order",
            ));
        }
        let at = |u: f64| -> [f32; 4] {
            let (first, last) = (points[0], points[points.len() - 1]);
            if u <= first.0 {
                return first.1;
            }
            if u >= last.0 {
                return last.1;
            }
            let w = points
                .windows(2)
                .find(|w| u <= w[1].0)
                .expect("u inside the points");
            let ((u0, c0), (u1, c1)) = (w[0], w[1]);
            let t = if u1 > u0 {
                ((u - u0) / (u1 - u0)) as f32
            } else {
                1.0
            };
            [0, 1, 2, 3].map(|i| c0[i] + (c1[i] - c0[i]) * t)
        };
        let [lo, hi] = values.range;
        let mut normalised = vec![(0.0, at(lo))];
        for &(u, c) in points.iter().filter(|(u, _)| *u > lo && *u < hi) {
            normalised.push((values.normalise(u), c));
        }
        normalised.push((1.0, at(hi)));
        Self::new(normalised)
    }

    /// `--window WIDTH,LEVEL` in a volume's units: grey and opacity ramp from 0 at
    /// level − width/2 to 1 at level + width/2, as a radiologist's window maps values to grey.
    pub fn window(width: f64, level: f64, values: &Values) -> Result<Self> {
        if !(width.is_finite() && width > 0.0 && level.is_finite()) {
            return Err(Error::invalid(
                Param::Window,
                format!("width {width}, level {level}: a positive width and a finite level"),
            ));
        }
        let half = width / 2.0;
        Self::in_units(
            &[(level - half, [0.0; 4]), (level + half, [1.0; 4])],
            values,
        )
    }

    /// The preset `name` for a volume whose scalars stand for `values`: the CT presets in
    /// Hounsfield units where the volume is in them (so a scanner's padding outside the field
    /// of view changes nothing), else every preset on the normalised scalar as
    /// [`TransferFunction::preset`] defines it.
    ///
    /// The MR preset (`mri`) spans the volume's robust range where it was measured
    /// ([`Values::robust`], the 1st to 99th percentile): its normalised points stretched from
    /// there, so the few brightest voxels (vessels, fat, artefacts) no longer squeeze the
    /// brain into the bottom of the ramp.
    pub fn preset_for(name: &str, values: &Values) -> Result<Self> {
        match (hounsfield_preset(name), values.units, values.robust) {
            (Some(points), Units::Hounsfield, _) => Self::in_units(&points, values),
            (None, _, Some([lo, hi])) if name == "mri" && hi > lo => {
                let points: Vec<(f64, [f32; 4])> = Self::preset(name)?
                    .points
                    .iter()
                    .map(|&(s, c)| (lo + f64::from(s) * (hi - lo), c))
                    .collect();
                Self::in_units(&points, values)
            }
            _ => Self::preset(name),
        }
    }

    /// RGBA at scalar `s` (clamped at the ends; transparent black without control points).
    pub fn eval(&self, s: f32) -> [f32; 4] {
        let pts = &self.points;
        let Some(&(first, colour)) = pts.first() else {
            return [0.0; 4];
        };
        if s <= first {
            return colour;
        }
        for w in pts.windows(2) {
            let ((s0, c0), (s1, c1)) = (w[0], w[1]);
            if s <= s1 {
                let t = if s1 > s0 { (s - s0) / (s1 - s0) } else { 1.0 };
                return [0, 1, 2, 3].map(|i| c0[i] + (c1[i] - c0[i]) * t);
            }
        }
        pts[pts.len() - 1].1
    }
}

/// How a volume is classified: what a user gives, resolved against the loaded volume's values
/// ([`Transfer::resolve`]) since control points in the scan's units, a window and the CT
/// presets need its range.
#[derive(Clone, Debug, PartialEq)]
pub enum Transfer {
    /// Control points on the normalised scalar.
    Normalised(TransferFunction),
    /// Control points in the scan's units ([`TransferFunction::in_units`]).
    InUnits(Vec<(f64, [f32; 4])>),
    /// A preset by name ([`PRESETS`], [`TransferFunction::preset_for`]).
    Preset(String),
    /// A window `[width, level]` in the scan's units; `None`: the file's own (DICOM's
    /// WindowWidth and WindowCenter).
    Window(Option<[f64; 2]>),
}

impl Transfer {
    /// The normalised function for a volume of `values`, and the preset it is, if one.
    pub fn resolve(&self, values: &Values) -> Result<(TransferFunction, Option<&'static str>)> {
        Ok(match self {
            Transfer::Normalised(tf) => (tf.clone(), None),
            Transfer::InUnits(points) => (TransferFunction::in_units(points, values)?, None),
            Transfer::Preset(name) => {
                let known = PRESETS.iter().find(|p| **p == name.as_str()).copied();
                (TransferFunction::preset_for(name, values)?, known)
            }
            Transfer::Window(Some([width, level])) => {
                (TransferFunction::window(*width, *level, values)?, None)
            }
            Transfer::Window(None) => {
                let [width, level] = values.window.ok_or_else(|| {
                    Error::invalid(
                        Param::Window,
                        "the file has no window of its own (DICOM's WindowWidth and \
                         WindowCenter): give one, WIDTH,LEVEL in the scan's units",
                    )
                })?;
                (TransferFunction::window(width, level, values)?, None)
            }
        })
    }

    /// A transfer-function file: `s r g b a` lines on the normalised scalar, or — after a line
    /// `units` — `value r g b a` lines in the scan's units (HU for a CT).
    pub fn load(path: &Path) -> Result<Self> {
        let text = crate::file::read_text(path)?;
        let in_units = text
            .lines()
            .map(|l| l.split('#').next().unwrap_or("").trim())
            .find(|l| !l.is_empty())
            == Some("units");
        if !in_units {
            return Ok(Transfer::Normalised(TransferFunction::load(path)?));
        }
        let mut points = Vec::new();
        let mut header = true;
        for (n, line) in text.lines().enumerate() {
            let line = line.split('#').next().unwrap_or("").trim();
            if line.is_empty() || std::mem::take(&mut header) && line == "units" {
                continue;
            }
            let v: Vec<f64> = line
                .split_whitespace()
                .map(str::parse)
                .collect::<std::result::Result<_, _>>()
                .ok()
                .filter(|v: &Vec<f64>| v.len() == 5)
                .ok_or_else(|| {
                    Error::invalid(
                        Param::TransferFunction,
                        format!(
                            "{}: line {}: {} is not 5 numbers (value r g b a)",
                            path.display(),
                            n + 1,
                            crate::error::quote(line)
                        ),
                    )
                })?;
            points.push((v[0], [v[1], v[2], v[3], v[4]].map(|x| x as f32)));
        }
        points.sort_by(|a, b| a.0.total_cmp(&b.0));
        Ok(Transfer::InUnits(points))
    }
}

/// The CT presets in Hounsfield units: air (−1000) and a scanner's padding below clear; skin
/// as a thin translucent surface where air meets tissue (−600…−100, the partial-volume band the
/// skin's edge passes through) so that bulk soft tissue (0…100) stays clear; contrast-filled
/// vessels (150…300) red; bone (from 300, cortical 1000 and more) opaque.
fn hounsfield_preset(name: &str) -> Option<Vec<(f64, [f32; 4])>> {
    let p = |u: f64, c: [f32; 4]| (u, c);
    Some(match name {
        "ct-skin" => vec![
            p(-1000.0, [0.0; 4]),
            p(-600.0, [0.9, 0.6, 0.5, 0.0]),
            p(-350.0, [0.95, 0.72, 0.62, 0.2]),
            p(-100.0, [0.9, 0.6, 0.5, 0.0]),
            p(150.0, [0.8, 0.3, 0.3, 0.0]),
            p(250.0, [0.9, 0.3, 0.2, 0.5]),
            p(400.0, [1.0, 1.0, 0.95, 0.3]),
            p(1200.0, [1.0, 1.0, 0.95, 0.9]),
        ],
        "ct-bone" => vec![
            p(-1000.0, [0.0; 4]),
            p(150.0, [0.8, 0.7, 0.6, 0.0]),
            p(400.0, [0.95, 0.9, 0.8, 0.6]),
            p(1500.0, [1.0, 1.0, 1.0, 0.95]),
        ],
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An MR of values 0 … 1000 whose voxels lie within 0 … 400 but for 0.5 % at 1000: the
    /// `mri` preset spans the robust 1–99 % range, so a value of 300 gets the colour the
    /// normalised preset gives 0.75 of its ramp, where min–max would give it 0.3.
    #[test]
    fn the_mr_preset_spans_the_robust_range() {
        let n = 1000;
        let data: Vec<f32> = (0..n)
            .map(|i| {
                if i < 5 {
                    1.0
                } else {
                    (i % 401) as f32 / 1000.0
                }
            })
            .collect();
        let volume = crate::volume::Volume::new([n as u32, 1, 1], [1.0; 3], data)
            .unwrap()
            .with_values(Values {
                range: [0.0, 1000.0],
                units: Units::File,
                ..Values::NORMALISED
            })
            .with_robust_range();
        let [lo, hi] = volume.values.robust.unwrap();
        assert!(lo <= 5.0 && (395.0..=401.0).contains(&hi), "{lo} {hi}");
        let robust = TransferFunction::preset_for("mri", &volume.values).unwrap();
        let plain = TransferFunction::preset("mri").unwrap();
        let at = |v: f64| robust.eval(volume.values.normalise(v));
        let want = plain.eval(((300.0 - lo) / (hi - lo)) as f32);
        for c in 0..4 {
            assert!(
                (at(300.0)[c] - want[c]).abs() < 1e-4,
                "{:?} {want:?}",
                at(300.0)
            );
        }
        assert!(at(300.0)[3] > plain.eval(0.3)[3] * 2.0);
        // Without a measured range (data given normalised) the preset is as defined.
        let normalised = TransferFunction::preset_for("mri", &Values::NORMALISED).unwrap();
        assert_eq!(normalised, plain);
    }

    #[test]
    fn parse_eval_and_errors() {
        let tf = TransferFunction::parse("# ramp\n0 0 0 0 0\n1 1 0.5 0 1\n").unwrap();
        assert_eq!(tf.eval(0.5), [0.5, 0.25, 0.0, 0.5]);
        assert!(TransferFunction::parse("0 0 0\n").is_err());
        assert!(TransferFunction::parse("0 0 0 0 x\n").is_err());
        assert!(TransferFunction::parse("2 0 0 0 0\n").is_err());
        assert!(TransferFunction::parse("").is_err());
        assert!(TransferFunction::preset("nope").is_err());
        for p in PRESETS {
            TransferFunction::preset(p).unwrap();
        }
    }
}
