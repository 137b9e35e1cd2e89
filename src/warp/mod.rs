//! View synthesis by depth-image warping (docs/WARPING.md): every view made from a few
//! reference images with their nearness, by a horizontal row search (Beck, Schneider &
//! Fröhlich). The references are either rendered or given:
//!
//! - [`SceneWarp`] (`scene.rs`), the renderer of [`crate::render::Method::Warp`] for meshes,
//!   points and volumes: R reference views rendered through the primitive's own
//!   [`ReferenceRenderer`] (`references.rs`: their cameras, their colour + nearness images),
//!   the nearness range of each row (`wgsl/warp/row_bounds.wgsl`), then one warp pass
//!   (`wgsl/warp/references.wgsl`).
//! - [`RgbdWarp`] (`rgbd.rs`): a caller's RGB-D image ([`crate::rgbd`] holds the data and its
//!   loading) warped in one pass (`wgsl/warp/rgbd.wgsl`).
//!
//! Both take one [`WarpOptions`] (`options.rs`), fill one set of constants (`uniform.rs`,
//! `struct Warp` in `wgsl/warp/shared/warp.wgsl`) and search rows with one function
//! (`wgsl/warp/shared/row_warp.wgsl`), straight into the spatial image or, Beck's way, through
//! N view images ([`WarpPath`]).

mod options;
pub(crate) mod references;
mod rgbd;
mod scene;
pub(crate) mod uniform;

pub use options::{
    WarpOptions, DEFAULT_HOLE_GAP, DEFAULT_REFERENCES, DEFAULT_SAME_SURFACE,
    PARALLAX_PER_DEPTHINESS,
};
pub use references::{
    reference_frame, ReferenceImages, ReferenceRenderer, REFERENCE_NEARNESS_FORMAT,
};
pub use rgbd::{predicted_shift, RgbdWarp};
pub use scene::SceneWarp;

/// Where a warp writes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum WarpPath {
    /// Straight into the spatial image: each subpixel warps its own view (no per-view
    /// images).
    #[default]
    Direct,
    /// Beck's way: every view warped into its own image, then the mask compositing (the
    /// N-pass harness). The same values; N full images of work and memory.
    PerView,
}

impl WarpPath {
    /// Its name as a command line writes it (`direct`, `per-view`) and reports give it.
    pub fn name(self) -> &'static str {
        match self {
            Self::Direct => "direct",
            Self::PerView => "per-view",
        }
    }
}
