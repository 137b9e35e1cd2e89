//! The library's shared test helpers (tests/common/mod.rs at the repository root) and running
//! the `autostereo` binary this crate builds.
#![allow(dead_code, unused_imports)]

#[path = "../../../tests/common/mod.rs"]
mod shared;
pub use shared::*;

/// A small 3DGS scene as graphdeco PLY.
pub mod gaussians_ply;

/// Xvfb for the viewer's tests.
pub mod xvfb;

/// Run the CLI with logging off; return (success, stderr).
pub fn cli(args: &[&str]) -> (bool, String) {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_autostereo"))
        .args(args)
        .env("RUST_LOG", "off")
        .output()
        .unwrap();
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}
