//! The render commands end to end: outputs, quilts, turntables, videos, interleave, Looking
//! Glass, Gaussians.
//! One test binary (fewer binaries: less linking, less disk); a module per theme.

#[path = "../common/mod.rs"]
mod common;

mod auto;
mod cli;
mod gaussians;
mod interleave;
mod looking_glass;
mod outputs;
mod turntable;
mod video;
