//! Depth-image warping and RGB-D input.
//! One test binary (fewer binaries: less linking, less disk); a module per theme.

#[path = "../common/mod.rs"]
mod common;

mod rgbd;
mod warp;
