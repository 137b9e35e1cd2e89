//! Mesh renderers against the N-pass and each other; camera models, duplication, bands, stereo,
//! stability.
//! One test binary (fewer binaries: less linking, less disk); a module per theme.

#[path = "../common/mod.rs"]
mod common;

mod bands;
mod camera_models;
mod duplication;
mod npass_mesh;
mod single_pass_mesh;
mod stability;
mod stereo;
mod view_clusters;
mod whole_views;
