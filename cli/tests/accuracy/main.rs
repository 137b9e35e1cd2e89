//! Approximations and baselines measured against the N-pass through the CLI: cameras, duplication, steps, view scale.
//! One test binary (fewer binaries: less linking, less disk); a module per theme.

#[path = "../common/mod.rs"]
mod common;

mod camera_models;
mod duplication;
mod empty_stride;
mod sampling_step;
mod view_scale;
