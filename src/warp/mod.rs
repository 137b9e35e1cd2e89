//! View synthesis by depth-image warping (Beck, Schneider & Fröhlich; docs/WARPING.md): render
//! a few reference views with colour and nearness through an ordinary renderer of the scene's
//! primitive, then warp them into every view.
//!
//! - [`references`]: the reference views' camera, their images (colour + nearness layers) and
//!   the [`ReferenceRenderer`] each primitive implements to fill them.
//! - [`passes`]: [`SceneWarp`], the [`crate::render::Renderer`] of [`crate::render::Method::Warp`]:
//!   references, then one warp pass straight into the spatial image (or, Beck's way, into N
//!   view images and the mask compositing).
//!
//! RGB-D pictures are warped by [`crate::rgbd`], with the same row search
//! (`wgsl/shared/row_warp.wgsl`).

pub mod passes;
pub mod references;

pub use passes::{SceneWarp, SceneWarpOptions, DEFAULT_REFERENCES, DEFAULT_SAME_SURFACE};
pub use references::{reference_frame, ReferenceImages, ReferenceRenderer};

/// Where a warp writes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum WarpPath {
    /// Straight into the spatial image: each subpixel warps its own view (no per-view
    /// images).
    #[default]
    Direct,
    /// Beck's way: every view warped into its own image, then the mask compositing (the
    /// N-pass harness). The same values; N full images of work and memory.
    PerView,
}
