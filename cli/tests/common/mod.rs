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
    let (ok, _, stderr) = cli_out(args);
    (ok, stderr)
}

/// Run the CLI with logging off; return (success, stdout, stderr).
pub fn cli_out(args: &[&str]) -> (bool, String, String) {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_autostereo"))
        .args(args)
        .env("RUST_LOG", "off")
        .output()
        .unwrap();
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// A run that must succeed and print one JSON object (pass `--json` in `args`): that object.
pub fn cli_json(args: &[&str]) -> serde_json::Value {
    let (ok, stdout, stderr) = cli_out(args);
    assert!(ok, "{args:?}: {stderr}");
    serde_json::from_str(stdout.trim()).unwrap_or_else(|e| panic!("{args:?}: {e}: {stdout}"))
}

/// A run that must fail cleanly, naming every one of `words`: its stderr.
pub fn cli_refused(args: &[&str], words: &[&str]) -> String {
    let (ok, _, stderr) = cli_out(args);
    assert!(!ok, "{args:?} succeeded");
    assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    for w in words {
        assert!(stderr.contains(w), "{args:?} does not say {w:?}: {stderr}");
    }
    stderr
}

/// `args` as a run that writes nothing and only reports (`--json`) where a render command has
/// no `--out`: without either, the command refuses to render ("nothing to write") before
/// reaching what a test checks (a load error, a refused flag, the memory budget).
pub fn measuring<'a>(args: &[&'a str]) -> Vec<&'a str> {
    let mut args = args.to_vec();
    let renders = ["mesh", "points", "volume", "gaussians"];
    if args.first().is_some_and(|c| renders.contains(c)) && !args.contains(&"--out") {
        args.push("--json");
    }
    args
}

/// Subpixels of `tile` more than 2/255 off the `tile`-sized region of `image` at `origin`
/// (a quilt's tile, a preview's): how far that region is from the tile rendered alone.
pub fn tile_subpixels_off(
    image: &autostereo::image_io::RgbImage,
    [tx, ty]: [u32; 2],
    tile: &autostereo::image_io::RgbImage,
) -> usize {
    let mut off = 0;
    for y in 0..tile.height {
        for x in 0..tile.width {
            for c in 0..3 {
                off += usize::from(image.get(tx + x, ty + y, c).abs_diff(tile.get(x, y, c)) > 2);
            }
        }
    }
    off
}
