//! Point splats and 3D Gaussians against the N-pass and the CPU reference; duplication.
//! One test binary (fewer binaries: less linking, less disk); a module per theme.

#[path = "../common/mod.rs"]
mod common;

mod duplication;
mod gaussians;
mod gaussians_reference;
mod points;
