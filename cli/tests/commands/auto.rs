//! `--method auto`, the default: what it chose said in the summary and `--json`, the floor
//! `--min-psnr`, flags that leave it one method, and what it refuses.

use crate::common::{cli_json, cli_out, cli_refused};

fn lkg16() -> String {
    format!(
        "lkg:{}/../data/lkg_sample_16in_landscape_gen3_visual.json",
        env!("CARGO_MANIFEST_DIR")
    )
}

#[test]
fn auto_weighs_exact_methods_and_admits_the_quilt_only_above_a_floor() {
    let display = lkg16();
    let json = |extra: &[&str]| {
        let mut args = vec!["mesh", "--display", &display, "--size", "256x144", "--json"];
        args.extend_from_slice(extra);
        cli_json(&args)
    };
    let exact = json(&[]);
    let auto = &exact["auto"];
    assert_eq!(auto["accuracy"], "exact", "{exact}");
    assert_eq!(auto["chosen"], exact["method"]);
    let candidates = auto["candidates"].as_array().unwrap();
    let names: Vec<&str> = candidates
        .iter()
        .map(|c| c["method"].as_str().unwrap())
        .collect();
    assert_eq!(names, ["single-pass", "n-pass", "tiled"], "{exact}");
    let quilt = &candidates[2];
    assert!(
        (quilt["psnr_db"].as_f64().unwrap() - 41.8).abs() < 1e-4,
        "{exact}"
    );
    assert_eq!(quilt["admitted"], false, "exact by default: {exact}");
    assert_ne!(exact["method"], "tiled");
    // The family's 7x7 quilt, its 857x857 tiles no larger than the image.
    assert_eq!(quilt["view_size"], serde_json::json!([256, 144]));
    assert!(
        quilt["label"].as_str().unwrap().contains("7x7 tiles"),
        "{exact}"
    );
    assert!(
        auto["census"]["triangles"].as_u64().unwrap() > 100,
        "{exact}"
    );

    // A floor the quilt meets: it is admitted, and chosen where the model has it fastest.
    let floor = json(&["--min-psnr", "40"]);
    let quilt = &floor["auto"]["candidates"][2];
    assert_eq!(quilt["admitted"], true, "{floor}");
    let fastest = floor["auto"]["candidates"]
        .as_array()
        .unwrap()
        .iter()
        .min_by(|a, b| {
            a["predicted_ms"]
                .as_f64()
                .partial_cmp(&b["predicted_ms"].as_f64())
                .unwrap()
        })
        .unwrap()["method"]
        .clone();
    assert_eq!(floor["method"], fastest, "{floor}");
    if floor["method"] == "tiled" {
        assert_eq!(floor["view_size"], serde_json::json!([256, 144]), "{floor}");
    }
    assert_eq!(
        json(&["--min-psnr", "50"])["auto"]["candidates"][2]["admitted"],
        false
    );

    // The summary says it in one line.
    let (ok, _, stderr) = cli_out(&[
        "mesh",
        "--display",
        &display,
        "--size",
        "256x144",
        "--frames",
        "1",
    ]);
    assert!(ok, "{stderr}");
    assert!(
        stderr.contains("auto → ") && stderr.contains("predicted"),
        "{stderr}"
    );
}

#[test]
fn flags_of_one_method_leave_auto_that_method() {
    for (flags, method) in [
        (&["--bounds", "paper"][..], "single-pass"),
        (&["--visibility", "exact"], "single-pass"),
        (&["--tile-clip", "discard"], "tiled"),
        (&["--references", "2"], "warp"),
    ] {
        let mut args = vec!["mesh", "--size", "64x48", "--json"];
        args.extend_from_slice(flags);
        let json = cli_json(&args);
        assert_eq!(json["method"], method, "{flags:?}: {json}");
        assert!(
            json["auto"]["note"]
                .as_str()
                .unwrap()
                .contains("the only method"),
            "{flags:?}: {json}"
        );
    }
}

#[test]
fn auto_refuses_what_it_cannot_honour() {
    cli_refused(
        &[
            "mesh",
            "--method",
            "single-pass",
            "--min-psnr",
            "40",
            "--json",
        ],
        &["--min-psnr 40", "only --method auto"],
    );
    for bad in [
        "--min-psnr=0",
        "--min-psnr=-1",
        "--min-psnr=nan",
        "--min-psnr=inf",
    ] {
        cli_refused(&["mesh", bad, "--json"], &["--min-psnr"]);
    }
    cli_refused(
        &["mesh", "--view-size", "32x24", "--json"],
        &[
            "--view-size 32x24",
            "--method auto chooses the method and its view size",
        ],
    );
    cli_refused(
        &["mesh", "--view-scale", "0.5", "--json"],
        &["--view-scale 0.5", "name the method"],
    );
    // Flags no method of the primitive takes together: the single pass's refusal.
    cli_refused(
        &[
            "mesh",
            "--clusters",
            "2",
            "--tile-clip",
            "discard",
            "--json",
        ],
        &["--tile-clip"],
    );
}
