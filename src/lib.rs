//! # autostereo
//!
//! Rendering for multi-view autostereoscopic displays (lenticular sheets, slanted lenses,
//! wavelength-selective filters), after Hübner, Zhang & Pajarola, *Single-pass multi-view
//! rendering*. Data flows one way:
//!
//! scene data ([`mesh`]) → GPU resources ([`mesh::MeshBuffers`]) → passes ([`render`]) →
//! spatial image ([`target::SpatialTarget`]) → CPU ([`image_io`], [`views`]).
//!
//! Geometry and conventions: [`display`] (masks, docs/DESIGN.md §1), [`camera`] (docs/DESIGN.md §2),
//! [`frame`] (everything a renderer needs besides the scene). The library borrows the device;
//! [`gpu::GpuContext`] is a convenience for headless tools and tests.

#![warn(missing_docs)]

pub mod advice;
mod any;
pub mod budget;
pub mod camera;
mod data_kind;
pub mod display;
mod error;
pub mod file;
pub mod formats;
pub mod frame;
pub mod gaussians;
pub mod gpu;
pub mod image_io;
pub mod io;
mod load;
pub mod mesh;
mod options;
mod param;
pub mod points;
pub mod readback;
pub mod render;
pub mod rgbd;
pub mod shader;
pub mod target;
pub mod timing;
#[cfg(feature = "video")]
pub mod video;
pub mod views;
pub mod volume;
pub mod warp;

pub use any::{AnyRenderer, AnyScene};
pub use data_kind::DataKind;
pub use error::{Error, Result};
pub use gaussians::GaussianOptions;
pub use load::{
    complete, default_preset, default_preset_for, load, resampled, AnyData, GaussianLoad,
    LoadOptions, MeshLoad, PointData, PointLoad, VolumeData, VolumeLoad,
};
pub use mesh::MeshOptions;
pub use options::RendererOptions;
pub use param::Param;
pub use points::PointOptions;
pub use render::Renderer;
pub use volume::{VolumeOptions, VolumePath};
