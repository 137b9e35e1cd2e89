//! Display masks (CPU and WGSL), the GL backend, the library as an embedder uses it; bad
//! displays, calibrations, frames and targets refused.
//! One test binary (fewer binaries: less linking, less disk); a module per theme.

#[path = "../common/mod.rs"]
mod common;

mod embedding;
mod gl_backend;
mod mask;
mod quilts;
mod refusals;
