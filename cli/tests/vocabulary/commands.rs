//! Issue 31's follow-ups: each render command offers its primitive's methods; the summary
//! says "one frame"; `--compare` of the N-pass with itself is refused; a quilt's name is kept
//! or refused, never doubled; `mask` takes a calibration's panel size; `bench --json` names
//! the report's files.

use super::numbers::{out, volume};
use crate::common;

/// Each render command offers its primitive's methods: `--help` lists only those, and another
/// primitive's method is refused by the parser naming what this one takes (before: every
/// command listed all seven and refused `mrt` for points only after loading the data).
#[test]
fn each_command_offers_its_primitives_methods() {
    for (command, refused, says) in [
        ("points", "mrt", "--method mrt: points do not render by mrt"),
        (
            "volume",
            "mrt",
            "--method mrt: volumes do not render by mrt",
        ),
        (
            "gaussians",
            "warp",
            "--method warp: Gaussian splats do not render by warp",
        ),
        (
            "gaussians",
            "layered",
            "--method layered: Gaussian splats do not render by layered",
        ),
    ] {
        common::cli_refused(
            &[command, "--method", refused, "--json"],
            &[says, "single-pass"],
        );
    }
    let help = |command: &str| common::cli_out(&[command, "--help"]).1;
    let values = |command: &str| {
        let text = help(command);
        let method = text
            .find("--method <METHOD>")
            .expect("--method in the help");
        let at = method + text[method..].find("[possible values:").unwrap();
        let end = text[at..].find(']').unwrap();
        text[at..at + end].to_string()
    };
    assert!(values("mesh").contains("mrt"), "{}", values("mesh"));
    for command in ["points", "volume", "gaussians"] {
        let method = values(command);
        assert!(!method.contains("mrt"), "{command}: {method}");
    }
    let gaussians = values("gaussians");
    assert!(
        !gaussians.contains("warp")
            && !gaussians.contains("layered")
            && gaussians.contains("tiled"),
        "{gaussians}"
    );
    // The mesh's file is a FILE (OBJ, PLY, STL, glTF), not an [OBJ].
    assert!(help("mesh").contains("[FILE]"), "{}", help("mesh"));
}

/// A single image says "one frame", a timed run "median of N frames" (before: "median of 1").
#[test]
fn the_summary_says_one_frame_or_the_median_of_n() {
    let png = out("vocabulary_one_frame.png");
    let (ok, stderr) = volume(&png, &[]);
    assert!(ok && stderr.contains("(one frame, "), "{stderr}");
    assert!(!stderr.contains("1 frames"), "{stderr}");
    let (ok, stderr) = volume(&png, &["--frames", "2"]);
    assert!(ok && stderr.contains("(median of 2 frames, "), "{stderr}");
}

/// `--compare` renders the N-pass as its oracle: with `--method n-pass` at full view size that
/// compared the N-pass with itself (PSNR ∞, exit 0). Refused; with smaller views it measures.
#[test]
fn compare_of_the_npass_with_itself_is_refused() {
    let png = out("vocabulary_compare_npass.png");
    let (ok, stderr) = volume(&png, &["--method", "n-pass", "--compare"]);
    assert!(!ok, "compared the N-pass with itself");
    assert!(
        stderr.contains("--compare: this run is the N-pass oracle itself"),
        "{stderr}"
    );
    let (ok, stderr) = volume(
        &png,
        &["--method", "n-pass", "--compare", "--view-scale", "0.5"],
    );
    assert!(ok && stderr.contains("vs n-pass: PSNR"), "{stderr}");
}

/// `--out` already named as a quilt: the name is kept when it is this quilt's, refused when it
/// says another grid or aspect (before: `z_qs2x4a1_qs2x4a1.3333.png`).
#[test]
fn a_quilt_name_is_kept_or_refused_never_doubled() {
    // A small quilt of the built-in head into `out`, with `extra` flags.
    let args = |out: &str, extra: &[&'static str]| -> Vec<String> {
        let mut args = [
            "volume",
            "--builtin-size",
            "16",
            "--size",
            "32x24",
            "--output",
            "quilt",
            "--out",
        ]
        .map(String::from)
        .to_vec();
        args.push(out.to_string());
        args.extend(extra.iter().map(|e| e.to_string()));
        args
    };
    let quilt = |out: &str| {
        let args = args(out, &["--json"]);
        let json = common::cli_json(&args.iter().map(String::as_str).collect::<Vec<_>>());
        json["written"][0].as_str().unwrap().to_string()
    };
    let named = quilt(out("vocabulary_named.png").to_str().unwrap());
    let file = std::path::Path::new(&named)
        .file_name()
        .unwrap()
        .to_str()
        .unwrap();
    assert!(
        file.starts_with("vocabulary_named_qs") && file.ends_with("a1.3333.png"),
        "{named}"
    );
    assert_eq!(file.matches("_qs").count(), 1, "{named}");
    assert_eq!(quilt(&named), named);
    let other = args(
        out("vocabulary_named_qs5x9a0.75.png").to_str().unwrap(),
        &[],
    );
    common::cli_refused(
        &other.iter().map(String::as_str).collect::<Vec<_>>(),
        &[
            "vocabulary_named_qs5x9a0.75.png: the name says a 5x9 quilt",
            "vocabulary_named.png (the suffix is added)",
        ],
    );
}

/// `mask` takes its size from a Looking Glass calibration like every other command (before:
/// `--size` was required even with `lkg:`); other displays default to 512x512.
#[test]
fn mask_takes_the_calibrations_panel_size() {
    let calibration = format!(
        "lkg:{}/../data/lkg_sample_go_gen3_visual.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let png = out("vocabulary_mask.png");
    let png = png.to_str().unwrap();
    let json = common::cli_json(&["mask", "--display", &calibration, "--out", png, "--json"]);
    assert_eq!(json["size"], serde_json::json!([1440, 2560]), "{json}");
    let json = common::cli_json(&["mask", "--display", "hubner8", "--out", png, "--json"]);
    assert_eq!(json["size"], serde_json::json!([512, 512]), "{json}");
    // Its --size sits with the display flags, as in the render commands; interleave's --quilt
    // with its input.
    let help = common::cli_out(&["interleave", "--help"]).1;
    let input = help.find("Input:").expect("an Input heading");
    let options = help.find("Options:").unwrap_or(usize::MAX);
    let grid = help.find("--quilt <COLSxROWS>").unwrap();
    assert!(
        input < grid && (options < input || grid < options),
        "{help}"
    );
}
