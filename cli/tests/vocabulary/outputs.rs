//! Issue 31, "one vocabulary": every output goes through `--output FORMAT --out F` (the special
//! cases `--quilt-out`, `--views-out`, volume's `--anaglyph` retired, naming the replacement),
//! every command's `--json` names each file written, per-view files are zero-padded, no `--out`
//! is refused unless a measurement was asked for, a flag the chosen method or path would
//! ignore is refused by name, one frame is rendered unless timing is asked for, and `--help`
//! is grouped with examples. Each test fails on the binary before these changes.

use crate::common;

use common::{cli_json as json, cli_out as run, cli_refused as refused};
use std::path::PathBuf;

pub(super) fn out(name: &str) -> PathBuf {
    let dir = common::out_dir().join("vocabulary_outputs");
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

const SMALL: [&str; 2] = ["--size", "32x24"];

pub(super) fn with<'a>(command: &'a str, extra: &[&'a str]) -> Vec<&'a str> {
    let mut args = vec![command];
    if command == "volume" {
        args.extend(["--builtin-size", "16"]);
    }
    args.extend(SMALL);
    args.extend_from_slice(extra);
    args
}

#[test]
fn no_out_is_refused_unless_a_measurement_is_asked_for() {
    // Rendered and then written nowhere, with exit 0: now refused before any work.
    for command in ["mesh", "points", "volume", "gaussians"] {
        refused(&with(command, &[]), &["nothing to write", "--out"]);
        // Asking for numbers writes none, and says so in the JSON.
        let report = json(&with(command, &["--json"]));
        assert_eq!(report["written"], serde_json::json!([]), "{command}");
        let (ok, _, stderr) = run(&with(command, &["--frames", "1"]));
        assert!(ok, "{command} --frames 1: {stderr}");
    }
}

#[test]
fn per_view_files_are_zero_padded_and_every_json_names_what_it_wrote() {
    let stem = out("padded.png");
    let report = json(&with(
        "mesh",
        &[
            "--display",
            "lenticular:12",
            "--output",
            "views",
            "--json",
            "--out",
            stem.to_str().unwrap(),
        ],
    ));
    let names: Vec<PathBuf> = (0..12)
        .map(|v| out(&format!("padded_{v:02}.png")))
        .collect();
    assert_eq!(report["written"], serde_json::json!(names));
    let mut sorted = names.clone();
    sorted.sort();
    assert_eq!(sorted, names, "a listing sorts the views in order");
    for name in &names {
        assert!(name.exists(), "{}", name.display());
    }
    // A quilt: the name written carries the Looking Glass suffix, and the JSON says it.
    let quilt = out("q.png");
    let report = json(&with(
        "mesh",
        &[
            "--output",
            "quilt",
            "--json",
            "--out",
            quilt.to_str().unwrap(),
        ],
    ));
    let named = out("q_qs2x4a1.3333.png");
    assert_eq!(report["written"], serde_json::json!([named]));
    assert!(named.exists());
}

/// A 32×24 colour image and a depth ramp for `rgbd`.
pub(super) fn rgbd_pair(tag: &str) -> (PathBuf, PathBuf) {
    // One pair per test: the tests run at once and must not read each other's half-written file.
    let (c, d) = (
        out(&format!("rgbd_color_{tag}.png")),
        out(&format!("rgbd_depth_{tag}.png")),
    );
    image::RgbImage::from_fn(32, 24, |x, y| {
        image::Rgb([(x * 8) as u8, (y * 10) as u8, 90])
    })
    .save(&c)
    .unwrap();
    image::GrayImage::from_fn(32, 24, |x, _| image::Luma([(x * 8) as u8]))
        .save(&d)
        .unwrap();
    (c, d)
}

#[test]
fn rgbd_and_interleave_take_the_same_output_flags_and_json() {
    let (c, d) = rgbd_pair("t1");
    let (c, d) = (c.to_str().unwrap(), d.to_str().unwrap());
    // --output views as in every command (rgbd had --views-out DIR with other names).
    let views = out("rgbd_views.png");
    let report = json(&[
        "rgbd",
        c,
        d,
        "--output",
        "views",
        "--json",
        "--out",
        views.to_str().unwrap(),
    ]);
    let names: Vec<PathBuf> = (0..8)
        .map(|v| out(&format!("rgbd_views_{v:02}.png")))
        .collect();
    assert_eq!(report["written"], serde_json::json!(names));
    assert_eq!(report["warp_path"], "direct");
    // A quilt of the same views: tile v is view v.
    let quilt = out("rgbd_quilt.png");
    let report = json(&[
        "rgbd",
        c,
        d,
        "--output",
        "quilt",
        "--json",
        "--warp-path",
        "per-view",
        "--out",
        quilt.to_str().unwrap(),
    ]);
    assert_eq!(report["warp_path"], "per-view");
    let named = out("rgbd_quilt_qs2x4a1.3333.png");
    assert_eq!(report["written"], serde_json::json!([named]));
    let q = image::open(&named).unwrap().to_rgb8();
    let layout = autostereo::render::quilt::QuiltLayout::for_views(8, [32, 24]);
    for v in [0, 5, 7] {
        let [x0, y0] = layout.tile_origin(v);
        let view = image::open(&names[v as usize]).unwrap().to_rgb8();
        let tile = image::imageops::crop_imm(&q, x0, y0, 32, 24).to_image();
        assert_eq!(tile, view, "quilt tile {v} is view {v}");
    }
    // The stereo formats too.
    let sbs = out("rgbd_sbs.png");
    json(&[
        "rgbd",
        c,
        d,
        "--output",
        "side-by-side",
        "--json",
        "--out",
        sbs.to_str().unwrap(),
    ]);
    assert_eq!(image::open(&sbs).unwrap().width(), 64);
    // interleave's JSON names its file.
    let spatial = out("interleaved.png");
    let report = json(&[
        "interleave",
        named.to_str().unwrap(),
        "--json",
        "--out",
        spatial.to_str().unwrap(),
    ]);
    assert_eq!(report["written"], serde_json::json!([spatial]));
    assert_eq!(report["quilt_views"], 8);
}

#[test]
fn retired_flags_name_their_replacement() {
    let f = out("retired.png");
    let f = f.to_str().unwrap();
    let dir = common::out_dir();
    let dir = dir.to_str().unwrap();
    refused(
        &with("mesh", &["--method", "tiled", "--quilt-out", f]),
        &["--output quilt --out"],
    );
    refused(
        &with("volume", &["--views-out", dir, "--out", f]),
        &["--output views --out"],
    );
    refused(
        &with("volume", &["--anaglyph", f, "--out", f]),
        &["--output anaglyph --out"],
    );
    let (c, d) = rgbd_pair("t2");
    let (c, d) = (c.to_str().unwrap(), d.to_str().unwrap());
    refused(&["rgbd", c, d, "--quilt-out", f], &["--output quilt --out"]);
    refused(
        &["rgbd", c, d, "--views-out", dir],
        &["--output views --out"],
    );
    refused(
        &["rgbd", c, d, "--path", "per-view", "--out", f],
        &["--warp-path per-view"],
    );
}

#[test]
fn one_frame_unless_timing_is_asked_for() {
    // Three frames (two warm-ups) were rendered for every image; now one, and --frames N
    // times N after the warm-ups.
    let report = json(&with("mesh", &["--json"]));
    assert_eq!(
        (report["frames"].as_u64(), report["warm_up_frames"].as_u64()),
        (Some(1), Some(0))
    );
    let report = json(&with("mesh", &["--json", "--frames", "3"]));
    assert_eq!(
        (report["frames"].as_u64(), report["warm_up_frames"].as_u64()),
        (Some(3), Some(2))
    );
    let (c, d) = rgbd_pair("t3");
    let report = json(&["rgbd", c.to_str().unwrap(), d.to_str().unwrap(), "--json"]);
    assert_eq!(report["warm_up_frames"], 0);
}

#[test]
fn help_is_grouped_with_examples_and_commands_come_in_order() {
    let (ok, stdout, _) = run(&["--help"]);
    assert!(ok);
    let at = |name: &str| {
        stdout
            .find(&format!("\n  {name} "))
            .unwrap_or_else(|| panic!("{name}: {stdout}"))
    };
    let order = [
        "mesh",
        "points",
        "volume",
        "gaussians",
        "rgbd",
        "interleave",
        "view",
        "views",
        "mask",
    ];
    for pair in order.windows(2) {
        assert!(at(pair[0]) < at(pair[1]), "{pair:?}: {stdout}");
    }
    for command in ["mesh", "points", "volume", "gaussians"] {
        let (ok, help, _) = run(&[command, "--help"]);
        assert!(ok);
        let mut last = 0;
        for heading in [
            "Input:",
            "Display:",
            "Camera:",
            "Method:",
            "Output:",
            "Examples:",
        ] {
            let at = help
                .find(&format!("\n{heading}\n"))
                .unwrap_or_else(|| panic!("{command}: no {heading}\n{help}"));
            assert!(at > last, "{command}: {heading} out of order");
            last = at;
        }
        assert!(
            help.contains(&format!("autostereo {command} ")),
            "{command}: no example"
        );
    }
    // The flags shared by definition read the same in every command.
    let line = |command: &str| {
        let (_, help, _) = run(&[command, "--help"]);
        help.lines()
            .find(|l| l.trim_start().starts_with("--output <FORMAT>"))
            .map(str::to_string)
            .unwrap_or_else(|| panic!("{command}: no --output"))
    };
    assert_eq!(line("mesh"), line("rgbd"));
}

#[test]
fn mask_and_views_name_what_they_wrote() {
    let mask = out("mask.png");
    let report = json(&[
        "mask",
        "--size",
        "16x8",
        "--json",
        "--out",
        mask.to_str().unwrap(),
    ]);
    assert_eq!(report["written"], serde_json::json!([mask]));
    assert_eq!(report["views"], 8);
    let (ok, _, stderr) = run(&["mask", "--size", "16x8", "--out", mask.to_str().unwrap()]);
    assert!(ok && stderr.contains("wrote"), "{stderr}");
    let anaglyph = out("views_anaglyph.png");
    let report = json(&[
        "views",
        mask.to_str().unwrap(),
        "--eyes",
        "3,4",
        "--json",
        "--out",
        anaglyph.to_str().unwrap(),
    ]);
    assert_eq!(report["written"], serde_json::json!([anaglyph]));
    assert_eq!(report["eyes"], serde_json::json!([3, 4]));
}

#[test]
fn a_looking_glass_quilt_of_fewer_views_has_no_empty_rows() {
    // 4 views on a 16" Looking Glass went into its 7x7 quilt: 45 empty tiles.
    let cal = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../data/lkg_sample_16in_landscape_gen3_visual.json"
    );
    let display = format!("lkg:{cal}");
    let quilt = out("lkg4.png");
    let report = json(&[
        "mesh",
        "--display",
        &display,
        "--views",
        "4",
        "--size",
        "64x36",
        "--output",
        "quilt",
        // The family's 5999² would render four 2999² views: the grid is the point here.
        "--quilt-size",
        "400x400",
        "--json",
        "--out",
        quilt.to_str().unwrap(),
    ]);
    assert_eq!(
        report["quilt_size"],
        serde_json::json!([400, 400]),
        "{report}"
    );
    let written = report["written"][0].as_str().unwrap();
    let name = std::path::Path::new(written)
        .file_name()
        .unwrap()
        .to_string_lossy();
    let n = autostereo::render::quilt_image::QuiltName::parse(&name).unwrap();
    let (cols, rows) = (n.cols, n.rows);
    assert!(cols * rows - 4 < cols, "{name}");
}
