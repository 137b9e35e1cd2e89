//! Volume renderers against the N-pass; duplication; sample sharing.
//! One test binary (fewer binaries: less linking, less disk); a module per theme.

#[path = "../common/mod.rs"]
mod common;

mod clipping;
mod duplication;
mod projections;
mod share_samples;
mod volume;
