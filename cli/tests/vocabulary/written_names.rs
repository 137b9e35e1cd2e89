//! Issue 31, from the review of the follow-ups: outputs are checked by the names really written
//! (a quilt's `_qs…` suffix, `_NN` views, `_NNNN` turntable frames), never replacing an input or
//! each other; a turntable's quilts are named as one quilt's; a quilt name's aspect is read
//! within 1 %; `--compare` refuses only a run that is the oracle itself; Gaussian splats have no
//! warp flags; `bench --from-json` takes no measuring flags. Each test fails on the binary
//! before its fix.

use std::path::{Path, PathBuf};

use super::outputs::{out, rgbd_pair};
use crate::common;
use common::{cli_json, cli_refused};

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The Looking Glass suffix `args … --output quilt` gives its file (`_qs2x4a1.3333`).
fn quilt_suffix(args: &[&str], tag: &str) -> String {
    let probe = out(&format!("names_probe_{tag}.png"));
    let mut all = args.to_vec();
    all.extend(["--output", "quilt", "--out", s(&probe), "--json"]);
    let written = cli_json(&all)["written"][0].as_str().unwrap().to_string();
    let stem = probe.file_stem().unwrap().to_str().unwrap();
    let name = Path::new(&written).file_stem().unwrap().to_str().unwrap();
    name.strip_prefix(stem).unwrap().to_string()
}

fn digest(path: &Path) -> Vec<u8> {
    std::fs::read(path).unwrap()
}

#[test]
fn outputs_by_their_written_names_never_replace_an_input_or_each_other() {
    // An input named as the quilt --out would become.
    let (colour, _) = rgbd_pair("names_quilt");
    let suffix = quilt_suffix(&["rgbd", s(&colour), "--sbs"], "rgbd");
    let input = out(&format!("names_in{suffix}.png"));
    std::fs::copy(&colour, &input).unwrap();
    let before = digest(&input);
    let stderr = cli_refused(
        &[
            "rgbd",
            s(&input),
            "--sbs",
            "--output",
            "quilt",
            "--out",
            s(&out("names_in.png")),
        ],
        &["is the input file"],
    );
    assert_eq!(digest(&input), before, "the input was replaced: {stderr}");
    // An input named as one of the per-view files.
    let view3 = out("names_views_03.png");
    std::fs::copy(&colour, &view3).unwrap();
    let before = digest(&view3);
    cli_refused(
        &[
            "rgbd",
            s(&view3),
            "--sbs",
            "--output",
            "views",
            "--out",
            s(&out("names_views.png")),
        ],
        &["names_views_03.png is the input file"],
    );
    assert_eq!(digest(&view3), before);
    // A hole mask at the name the quilt got.
    let mesh = ["mesh", "--size", "64x48", "--method", "warp"];
    let suffix = quilt_suffix(&mesh, "mesh");
    let quilt = out("names_q.png");
    let hole_mask = out(&format!("names_q{suffix}.png"));
    let mut args = mesh.to_vec();
    args.extend(["--output", "quilt", "--out", s(&quilt)]);
    args.extend(["--hole-mask", s(&hole_mask)]);
    let _ = std::fs::remove_file(&hole_mask);
    cli_refused(&args, &["--hole-mask", "is also written by --out"]);
    // Refused before rendering: not even the quilt was written.
    assert!(!hole_mask.exists());
}

#[test]
fn a_turntable_of_quilts_is_named_as_one_quilt_is() {
    let mesh = ["mesh", "--size", "64x48"];
    let suffix = quilt_suffix(&mesh, "turntable");
    let named = out(&format!("names_turn{suffix}.png"));
    let mut args = mesh.to_vec();
    args.extend(["--output", "quilt", "--turntable", "2", "--out", s(&named)]);
    args.push("--json");
    let json = cli_json(&args);
    let written: Vec<PathBuf> = json["written"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| PathBuf::from(w.as_str().unwrap()))
        .collect();
    assert_eq!(
        written,
        [0, 1].map(|k| out(&format!("names_turn_{k:04}{suffix}.png"))),
        "{json}"
    );
    let other = out("names_turn_qs5x9a0.75.png");
    let mut args = mesh.to_vec();
    args.extend(["--output", "quilt", "--turntable", "2", "--out", s(&other)]);
    cli_refused(&args, &["the name says a 5x9 quilt"]);
}

#[test]
fn a_quilt_names_aspect_is_read_within_one_percent() {
    let mesh = ["mesh", "--size", "64x48", "--quilt", "2x4"];
    // 1.33 for 1.3333: the same quilt, as `interleave` reads it; the name is kept.
    let near = out("names_aspect_qs2x4a1.33.png");
    let mut args = mesh.to_vec();
    args.extend(["--output", "quilt", "--out", s(&near), "--json"]);
    assert_eq!(cli_json(&args)["written"][0], s(&near));
    // 1.5: another aspect; the fix is the name, not --quilt.
    let far = out("names_aspect_qs2x4a1.5.png");
    let mut args = mesh.to_vec();
    args.extend(["--output", "quilt", "--out", s(&far)]);
    let stderr = cli_refused(&args, &["the name says views of aspect 1.5"]);
    assert!(!stderr.contains("pass --quilt"), "{stderr}");
}

#[test]
fn compare_refuses_only_a_run_that_is_the_oracle_itself() {
    let png = out("names_compare.png");
    for extra in [&["--view-size", "64x48"][..], &["--view-scale", "0.99"][..]] {
        let mut args = vec!["mesh", "--size", "64x48", "--method", "n-pass", "--compare"];
        args.extend_from_slice(extra);
        args.extend(["--out", s(&png)]);
        cli_refused(&args, &["--compare: this run is the N-pass oracle itself"]);
    }
    // A volume N-pass with an approximation is measured against the exact N-pass.
    for extra in [&["--step", "2"][..], &["--empty-stride", "4"][..]] {
        let mut args = vec![
            "volume",
            "--builtin-size",
            "16",
            "--size",
            "32x24",
            "--method",
            "n-pass",
            "--compare",
            "--json",
        ];
        args.extend_from_slice(extra);
        let json = cli_json(&args);
        assert!(json["psnr_db"].as_f64().is_some(), "{extra:?}: {json}");
    }
}

#[test]
fn gaussian_splats_have_no_warp_flags() {
    cli_refused(
        &["gaussians", "--references", "2", "--json"],
        &["--references is not a flag of `autostereo gaussians`; `autostereo mesh`, `autostereo points`, `autostereo volume` take it"],
    );
    let help = common::cli_out(&["gaussians", "--help"]).1;
    assert!(
        !help.contains("--references") && !help.contains("--hole-mask"),
        "{help}"
    );
    // Another command's refusal does not list `gaussians` among those that take it.
    let stderr = cli_refused(&["interleave", "--references", "2"], &["--references"]);
    assert!(!stderr.contains("`autostereo gaussians`"), "{stderr}");
}
