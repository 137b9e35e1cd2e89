//! Bad input reported by the command line: a clear error naming the file or flag, never a
//! panic. (The library's errors for the same input: tests/formats/bad_input.rs,
//! tests/display/refusals.rs.)

use crate::common;

use std::path::PathBuf;

use common::cli;

#[test]
fn cli_reports_bad_input_without_panicking() {
    let bad_obj = common::input_file("cli_bad.obj", "v 1 2 x\nf 1 2 3\n");
    let bad_ply = common::input_file(
        "cli_bad.ply",
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n1 1\n",
    );
    let calibration = common::input_file("cli_calibration.json", r#"{"pitch": {"value": 50}}"#);
    let tiny_raw = common::input_file("cli_tiny.raw", "ab");
    let xyz = common::input_file("cli_cloud.xyz", "1 2 3\n");
    let out = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../target/test-input/cli_out.png");
    let out = out.to_str().unwrap();
    let lkg = format!("lkg:{}", calibration.display());
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            vec!["mesh", bad_obj.to_str().unwrap(), "--out", out],
            "malformed OBJ",
        ),
        (
            vec!["mesh", "--display", "hologram", "--out", out],
            "unknown display",
        ),
        (
            vec!["mesh", "--display", "lenticular:0", "--out", out],
            "views",
        ),
        (vec!["mesh", "--size", "0x0", "--out", out], "at least 1"),
        (
            vec!["mask", "--display", &lkg, "--size", "8x8", "--out", out],
            "missing field",
        ),
        (
            vec![
                "mask",
                "--display",
                "hubner8",
                "--size",
                "8x8",
                "--views",
                "0",
                "--out",
                out,
            ],
            "views",
        ),
        (vec!["mesh", "--frames", "0"], "1..=100000"),
        (vec!["volume", "--frames", "4294967295"], "1..=100000"),
        (
            vec!["mask", "--size", "100000x100000", "--out", out],
            "more than 268435456",
        ),
        (vec!["volume", "--builtin-size", "2000"], "4..=1024"),
        (
            vec![
                "volume",
                tiny_raw.to_str().unwrap(),
                "--raw-dims",
                "2,1,1",
                "--raw-type",
                "u8",
                "--raw-header",
                "18446744073709551615",
            ],
            "overflow",
        ),
        (vec!["volume", "missing.nrrd"], "missing.nrrd"),
        (vec!["points", "missing.ply"], "missing.ply"),
        (vec!["points", bad_ply.to_str().unwrap()], "truncated"),
        (
            vec!["points", xyz.to_str().unwrap()],
            "unknown format; read here: meshes .obj .ply",
        ),
        (
            vec!["points", "--groups", "0", "--size", "8x8"],
            "group count",
        ),
        (vec!["points", "--epsilon=-1", "--size", "8x8"], "--epsilon"),
        (
            vec!["points", "--radius-scale", "NaN", "--size", "8x8"],
            "radius scale",
        ),
        (
            vec!["volume", "--tf", "nope", "--size", "8x8"],
            "unknown preset",
        ),
        (
            vec!["volume", "--step", "0", "--size", "8x8"],
            "sampling step",
        ),
        (vec!["volume", "x.raw", "--raw-dims", "4,4,4"], "--raw-type"),
        (vec!["volume", "--rotate", "1,2"], "three comma-separated"),
        (
            vec![
                "volume",
                "--builtin-size",
                "8",
                "--path",
                "slices",
                "--method",
                "n-pass",
            ],
            "single-pass",
        ),
        (vec!["mesh", "--visibility", "bogus"], "invalid value"),
        (
            vec!["views", "nonexistent.png", "--view", "0", "--out", out],
            "nonexistent.png",
        ),
        (
            vec!["mesh", "--out", "/no/such/dir/x.png"],
            "does not exist",
        ),
    ];
    for (args, expect) in cases {
        let (ok, stderr) = cli(&common::measuring(&args));
        assert!(!ok, "{args:?} should fail");
        assert!(!stderr.contains("panicked"), "{args:?} panicked: {stderr}");
        assert!(
            stderr.contains(expect),
            "{args:?}: stderr lacks '{expect}': {stderr}"
        );
    }
}
