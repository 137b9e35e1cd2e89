//! The renderer kit every primitive's passes share, and the one interface they implement.
//!
//! - [`Renderer`]: one frame of a scene into a spatial target ([`crate::AnyRenderer`] /
//!   [`crate::AnyScene`] hide the primitive; [`crate::RendererOptions`] builds them).
//! - [`MaskImageRenderer`]: the display mask as a view-index image (GPU side of the mask
//!   oracle).
//! - [`Compositor`]: N per-view layers → spatial image (every N-pass method).
//! - [`OutputBlit`]: the spatial image into a caller's texture or surface (BGRA8, sRGB…).
//! - [`StereoCompositor`]: two eyes' views into anaglyph, side-by-side, top-bottom or
//!   interlaced images.
//! - [`quilt`], [`atlas`]: the Looking Glass quilt layout, the atlas the tiled methods render
//!   into (and quilt files are read into), and its compositing.
//! - [`ViewLayers`]: the per-view (or per-group) layers those passes render into.
//! - [`render_view`], [`render_quilt`], [`render_stereo`]: images of whole views (one view, a
//!   quilt, a stereo pair) by any renderer.
//! - crate-internal: the pipeline cache and specialisation constants the passes build with
//!   (the low-level GPU helpers below them are [`crate::gpu`]'s).
//!
//! The renderers themselves live with their primitive ([`crate::mesh`], [`crate::points`],
//! [`crate::volume`], [`crate::rgbd`], [`crate::warp`]); [`crate::RendererOptions`] builds any
//! of them.

pub(crate) mod accumulation;
pub mod atlas;
pub mod auto;
mod bands;
pub mod batches;
pub(crate) mod camera_crop;
pub(crate) mod composite;
pub(crate) mod depth_readback;
pub(crate) mod mask_image;
mod method;
pub(crate) mod npass;
pub(crate) mod output;
pub(crate) mod pipeline_cache;
pub mod quilt;
pub mod quilt_image;
pub mod quilt_views;
mod renderer;
pub(crate) mod specialize;
pub(crate) mod stereo;
pub(crate) mod view_layers;
mod whole_views;

pub use bands::Banded;
pub use composite::Compositor;
pub use mask_image::MaskImageRenderer;
pub use method::Method;
pub use output::{OutputBlit, OUTPUT_FORMATS};
pub use renderer::Renderer;
pub(crate) use renderer::{
    begin_prepare, check_prepared, check_target, prepared_state, Made, Prepared, PreparedState,
};
pub use stereo::{default_eyes, StereoCompositor, StereoFormat};
pub use view_layers::ViewLayers;
pub use whole_views::{render_quilt, render_quilt_counted, render_stereo, render_view};
