//! Passes that turn scene data into images.
//!
//! - [`mask_image`]: the display mask as a view-index image (GPU side of the mask oracle).
//! - [`composite`]: N per-view layers → spatial image (shared by every N-pass baseline).
//! - [`mesh_npass`]: the N-pass and single-view mesh baselines.
//! - [`mesh_single_pass`]: single-pass meshes (covering quads + ray-triangle tests).
//! - [`splat`]: point splats (single pass, N-pass, single view; ε-z deferred compositing).
//! - [`volume_raycast`]: volumes by ray marching (single pass, N-pass, single view).

pub mod composite;
pub mod mask_image;
pub mod mesh_npass;
pub mod mesh_single_pass;
mod pass_params;
mod pipeline;
mod renderer;
mod specialize;
pub mod splat;
pub(crate) mod texture;
mod view_layers;
pub mod volume_raycast;
mod volume_resources;
pub mod volume_slices;

pub use composite::Compositor;
pub use mask_image::MaskImageRenderer;
pub use mesh_npass::{MeshBaseline, MeshBaselineMethod};
pub use mesh_single_pass::{CoverBounds, MeshSinglePass, MeshSinglePassOptions, Visibility};
pub use renderer::Renderer;
pub use splat::{PointSplatter, SplatDepth, SplatMethod, SplatOptions};
pub use view_layers::ViewLayers;
pub use volume_raycast::{VolumeMethod, VolumeRaycaster, VolumeScene};
pub use volume_resources::VolumeParams;
pub use volume_slices::{AlphaMode, VolumeSlicer};
