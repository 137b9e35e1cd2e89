//! How 3D Gaussian splats render where there is a choice: the settings
//! [`crate::RendererOptions`] holds for them.

use super::SortOn;

/// How the Gaussian renderers work where there is a choice (each choice renders the same
/// image; they differ in speed and memory).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GaussianOptions {
    /// Where the depth sort runs.
    pub sort: SortOn,
    /// The single pass evaluates each Gaussian's SH once per view into a table (8 bytes per
    /// Gaussian and view) and its subpixels read it; `false`, or where the table would exceed
    /// a storage binding, every subpixel evaluates the SH itself.
    pub color_table: bool,
}

impl Default for GaussianOptions {
    fn default() -> Self {
        Self {
            sort: SortOn::Gpu,
            color_table: true,
        }
    }
}
