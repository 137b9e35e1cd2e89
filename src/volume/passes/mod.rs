//! The volume methods: ray marching in a compute pass ([`raycast`]: single pass, N-pass,
//! single view) and the paper's proxy slices ([`slices`]), over the bindings they share
//! ([`resources`]).

pub mod raycast;
pub(crate) mod resources;
pub mod slices;

pub use raycast::VolumeRaycaster;
#[cfg(test)]
pub(crate) use resources::VolumeParams;
pub use slices::VolumeSlicer;
