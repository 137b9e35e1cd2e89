//! What a volume's normalised scalars stand for: the values at 0 and 1 in the scan's units
//! (Hounsfield units for CT, the file's own otherwise), the modality where the file says it,
//! and the display window it suggests. Transfer functions given in those units
//! ([`crate::volume::TransferFunction::in_units`]), `--window WIDTH,LEVEL` and the CT presets
//! (defined in HU) are turned into the normalised function the renderers sample, whatever
//! range a file's padding stretches the normalisation to (docs/VOLUMES.md "Windows and
//! presets").

/// The units of a volume's values.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub enum Units {
    /// No units: the scalars were given normalised (the built-in data, `Volume::new`).
    Normalised,
    /// Hounsfield units (a CT after its rescale slope and intercept).
    Hounsfield,
    /// The file's own units (an MRI's intensities, a NRRD's samples).
    File,
}

impl Units {
    /// How the summary writes them after a value ("HU"; "" for the file's own).
    pub fn suffix(self) -> &'static str {
        match self {
            Units::Hounsfield => " HU",
            Units::Normalised | Units::File => "",
        }
    }
}

/// What made the scan, where the file says.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub enum Modality {
    /// Computed tomography.
    Ct,
    /// Magnetic resonance.
    Mr,
    /// Anything else a file names (PET, ultrasound, microscopy…).
    Other,
}

/// The values a volume's normalised scalars 0 and 1 stand for, and what they are.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Values {
    /// The values at scalar 0 and at scalar 1 (lo < hi, or equal for a constant volume).
    pub range: [f64; 2],
    /// What the values are.
    pub units: Units,
    /// What made the scan, where its file says.
    pub modality: Option<Modality>,
    /// The file's own display window, `[width, level]` in `units` (DICOM's WindowWidth and
    /// WindowCenter), where it has one.
    pub window: Option<[f64; 2]>,
    /// The 1st and 99th percentiles of the voxels' values, in `units`, where the loader
    /// measured them ([`super::Volume::with_robust_range`]): the range the MR presets span
    /// (a few bright voxels or a scanner's padding then move nothing).
    pub robust: Option<[f64; 2]>,
}

impl Default for Values {
    fn default() -> Self {
        Self::NORMALISED
    }
}

impl Values {
    /// Scalars that stand for themselves.
    pub const NORMALISED: Self = Self {
        range: [0.0, 1.0],
        units: Units::Normalised,
        modality: None,
        window: None,
        robust: None,
    };

    /// The normalised scalar of `value` (in this volume's units), clamped to 0..1.
    pub fn normalise(&self, value: f64) -> f32 {
        let [lo, hi] = self.range;
        match hi > lo {
            true => ((value - lo) / (hi - lo)).clamp(0.0, 1.0) as f32,
            false => 0.0,
        }
    }

    /// The value (in this volume's units) of the normalised scalar `s`.
    pub fn value(&self, s: f32) -> f64 {
        let [lo, hi] = self.range;
        lo + f64::from(s) * (hi - lo)
    }

    /// "−3024…3071 HU" (the summary's words), with the robust range where it was measured:
    /// "0…255 (1–99 %: 0…97)".
    pub fn described(&self) -> String {
        let [lo, hi] = self.range;
        let robust = self.robust.map_or_else(String::new, |[a, b]| {
            format!(" (1–99 %: {}…{})", short(a.round()), short(b.round()))
        });
        format!("{}…{}{}{robust}", short(lo), short(hi), self.units.suffix())
    }
}

/// A value as a person writes it: whole where it is whole, else 4 significant digits.
fn short(v: f64) -> String {
    if v.fract() == 0.0 && v.abs() < 1e9 {
        format!("{v:.0}")
    } else {
        format!("{v:.4}")
            .trim_end_matches('0')
            .trim_end_matches('.')
            .to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_map_to_scalars_and_back() {
        let v = Values {
            range: [-1024.0, 3071.0],
            units: Units::Hounsfield,
            modality: Some(Modality::Ct),
            window: None,
            robust: None,
        };
        assert_eq!(v.normalise(-1024.0), 0.0);
        assert_eq!(v.normalise(3071.0), 1.0);
        assert_eq!(v.normalise(-5000.0), 0.0);
        assert!((v.value(v.normalise(40.0)) - 40.0).abs() < 1e-3);
        assert_eq!(v.described(), "-1024…3071 HU");
        assert_eq!(Values::NORMALISED.described(), "0…1");
    }
}
