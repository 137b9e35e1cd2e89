//! How point splats render where there is a choice: the settings [`crate::RendererOptions`]
//! holds for them (plain values: no GPU, no errors, so that an error's advice can name them,
//! `src/advice.rs`; `PointOptions::for_scene` is the splatter's, src/points/passes/mod.rs).

/// Point-splat settings (every method splats the same way, so the baselines compare).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointOptions {
    /// Single-pass depth per group image (K = 3 displays).
    pub depth: SplatDepth,
    /// ε of the ε-z compositing as a share of the scene's bounding diameter.
    pub epsilon_fraction: f32,
}

impl Default for PointOptions {
    fn default() -> Self {
        Self {
            depth: SplatDepth::Exact,
            epsilon_fraction: DEFAULT_EPSILON_FRACTION,
        }
    }
}

/// Depth kept per group image by the single pass on subpixel (K = 3) displays.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum SplatDepth {
    /// The paper's: one depth per pixel, the mean of its subpixels' hit depths.
    Paper,
    /// One depth per subpixel (subpixel-resolution geometry pass).
    Exact,
}

impl SplatDepth {
    /// Lower-case name (CLI, reports).
    pub fn name(self) -> &'static str {
        match self {
            Self::Paper => "paper",
            Self::Exact => "exact",
        }
    }
}

/// Default ε as a fraction of the scene's depth extent (its bounding-sphere diameter).
pub const DEFAULT_EPSILON_FRACTION: f32 = 0.01;
