//! How point splats render where there is a choice: the settings [`crate::RendererOptions`]
//! holds for them.

use super::{SplatDepth, SplatOptions, SplatScene, DEFAULT_EPSILON_FRACTION};

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

impl PointOptions {
    /// The splatter's options for `scene` (ε in its units).
    pub fn for_scene(&self, scene: &SplatScene) -> SplatOptions {
        SplatOptions {
            depth: self.depth,
            epsilon: SplatOptions::epsilon_for(scene, self.epsilon_fraction),
        }
    }
}
