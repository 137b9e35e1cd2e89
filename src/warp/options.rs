//! How a warp runs: one options type for both kinds of reference (rendered views of a scene,
//! or one RGB-D image), and the defaults the command line and the bench start from.

use super::WarpPath;
use crate::error::{Error, Result};
use crate::param::Param;

/// References when none are asked for: the two outermost views, every other view interpolated
/// between them.
pub const DEFAULT_REFERENCES: u32 = 2;

/// Two references blend where their nearness differs by at most this share (2 % of the depth):
/// they see the same surface. Beyond it the nearer surface wins.
pub const DEFAULT_SAME_SURFACE: f32 = 0.02;

/// Neighbouring samples warped further apart than this (reference pixels) straddle a
/// disocclusion: the hole between them is filled from the far one. Slopes that stretch the
/// surface less are interpolated.
pub const DEFAULT_HOLE_GAP: f32 = 2.0;

/// Parallax of depthiness 1 (RGB-D): a point at nearness 1 with the focus at 0 shifts by this
/// share of the image width in the outermost views (either way: 6 % between them).
pub const PARALLAX_PER_DEPTHINESS: f32 = 0.03;

/// How a warp runs. The shared settings apply to both warps; the rest to one kind of
/// reference each, as their documentation says.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WarpOptions {
    /// See [`WarpPath`].
    pub path: WarpPath,
    /// See [`DEFAULT_HOLE_GAP`] (pixels of the reference).
    pub hole_gap: f32,
    /// Write the hole mask instead of colour: 255 on every subpixel that was filled (a
    /// disocclusion, or an edge where a view has no source) rather than seen.
    pub hole_mask: bool,
    /// Rendered references: reference views R (1 ≤ R ≤ N), spread evenly over the views' span.
    pub references: u32,
    /// Rendered references: see [`DEFAULT_SAME_SURFACE`].
    pub same_surface: f32,
    /// RGB-D: the nearness that lands on the display plane (zero parallax), 0…1.
    pub focus: f32,
    /// RGB-D: parallax scale; 1 shifts nearness 1 (focus 0) by 3 % of the width in the
    /// outermost views ([`PARALLAX_PER_DEPTHINESS`]); negative reverses depth.
    pub depthiness: f32,
    /// RGB-D: render this one view everywhere instead of the mask's (per-view images, quilts).
    pub view: Option<u32>,
}

impl Default for WarpOptions {
    fn default() -> Self {
        Self {
            path: WarpPath::Direct,
            hole_gap: DEFAULT_HOLE_GAP,
            hole_mask: false,
            references: DEFAULT_REFERENCES,
            same_surface: DEFAULT_SAME_SURFACE,
            focus: 0.5,
            depthiness: 1.0,
            view: None,
        }
    }
}

impl WarpOptions {
    /// Check the values that need no frame (renderer construction).
    pub fn check(&self) -> Result<()> {
        if !(self.hole_gap.is_finite() && self.hole_gap >= 1.0) {
            return Err(Error::invalid(
                Param::HoleGap,
                format!("{}: at least 1 pixel", self.hole_gap),
            ));
        }
        if !(0.0..=1.0).contains(&self.same_surface) {
            return Err(Error::invalid(
                Param::SameSurface,
                format!("{}: a share of the depth in 0…1", self.same_surface),
            ));
        }
        if !(0.0..=1.0).contains(&self.focus) {
            return Err(Error::invalid(
                Param::Focus,
                format!("{}: a nearness in 0…1", self.focus),
            ));
        }
        if !self.depthiness.is_finite() || self.depthiness.abs() > 100.0 {
            return Err(Error::invalid(
                Param::Depthiness,
                format!("{}: a finite scale within ±100", self.depthiness),
            ));
        }
        if self.view.is_some() && self.path == WarpPath::PerView {
            return Err(Error::invalid(
                Param::View,
                "the per-view path warps every view; one view is the direct path's",
            ));
        }
        Ok(())
    }

    /// Check the one view against a display of `views` views.
    pub(crate) fn check_view(&self, views: u32) -> Result<()> {
        if let Some(v) = self.view.filter(|&v| v >= views) {
            return Err(Error::invalid(
                Param::View,
                format!("{v}: the display has views 0…{}", views - 1),
            ));
        }
        Ok(())
    }
}
