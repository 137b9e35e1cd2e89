//! Issue 31, the viewer's and the display spec's part: a window size no adapter can present is
//! refused by name (not a panic in wgpu or winit), and a display spec's error says what is wrong
//! with its number or its calibration file, naming `--display`.

use crate::common;

use common::xvfb::xvfb_or_clear_error;

#[test]
fn a_window_larger_than_the_adapter_allows_is_refused_by_name() {
    let Some(x) = xvfb_or_clear_error() else {
        return;
    };
    for size in ["20000x20000", "70000x64"] {
        let (ok, _, stderr) = x.cli(&["view", "--size", size, "--quit-after-frames", "1"]);
        assert!(!ok, "--size {size} succeeded");
        assert!(!stderr.contains("panicked"), "--size {size}: {stderr}");
        assert!(
            stderr.contains(&format!(
                "--size {size}: larger than this adapter's largest surface ("
            )) && stderr.contains(" per side on "),
            "--size {size}: {stderr}"
        );
    }
}

#[test]
fn display_spec_errors_name_the_flag_and_what_is_wrong() {
    let out = std::env::temp_dir().join("autostereo_vocabulary_view_mask.png");
    let out = out.to_str().unwrap();
    for (spec, says) in [
        (
            "lenticular:abc",
            "--display lenticular:abc: 'abc' is not a view count (a whole number ≥ 1)",
        ),
        (
            "lkg:nosuch.json",
            "--display lkg:nosuch.json: no such calibration file nosuch.json",
        ),
    ] {
        let (ok, stderr) = common::cli(&["mask", "--display", spec, "--size", "8x8", "--out", out]);
        assert!(!ok, "--display {spec} succeeded");
        assert!(stderr.contains(says), "--display {spec}: {stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
}

/// The viewer's quilt preview showed 45 views on a 7×7 grid while `--output quilt` wrote
/// another (6×8 for tiles of 300×240): both now take the grid from one function, and the
/// window is the quilt that `--output quilt` writes at the window's size (Looking Glass's rule:
/// whole-pixel tiles, views shown at the quilt's aspect).
#[test]
fn the_quilt_preview_uses_the_grid_the_quilt_output_writes() {
    let Some(x) = xvfb_or_clear_error() else {
        return;
    };
    let dir = common::out_dir().join("vocabulary_view");
    std::fs::create_dir_all(&dir).unwrap();
    let quilt = dir.join("q.png");
    let display = ["--display", "lenticular:45"];
    let mut args = vec!["mesh", "--size", "300x240", "--output", "quilt", "--json"];
    args.extend(display);
    args.extend(["--out", quilt.to_str().unwrap()]);
    let (ok, stderr) = common::cli(&args);
    assert!(ok, "{stderr}");
    let written = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .find(|n| n.starts_with("q_qs"))
        .expect("the quilt written");
    let named = autostereo::render::quilt_image::QuiltName::parse(&written).unwrap();
    assert_eq!([named.cols, named.rows], [6, 8], "{written}");
    let shot = dir.join("preview.png");
    let mut args = vec![
        "view",
        "--kind",
        "mesh",
        "--preview",
        "quilt",
        "--size",
        "300x240",
    ];
    args.extend(display);
    args.extend([
        "--quit-after-frames",
        "2",
        "--screenshot",
        shot.to_str().unwrap(),
    ]);
    let (ok, _, err) = x.cli(&args);
    assert!(ok, "{err}");
    let preview = autostereo::image_io::RgbImage::load_png(&shot).unwrap();
    // The window is the quilt `--output quilt --quilt-size 300x240` writes: tiles of
    // 300/6 × 240/8 = 50×30, each view shown at the quilt's aspect (the window's, 1.25).
    let small = dir.join("small.png");
    let mut args = vec!["mesh", "--size", "300x240", "--output", "quilt"];
    args.extend(display);
    args.extend(["--quilt-size", "300x240", "--out", small.to_str().unwrap()]);
    let (ok, err) = common::cli(&args);
    assert!(ok, "{err}");
    let written = autostereo::image_io::RgbImage::load_png(&dir.join("small_qs6x8a1.25.png"))
        .expect("the small quilt, named for its grid and the views' aspect");
    let background = &written.data[..3];
    let drawn = written.data.chunks(3).filter(|p| p != &background).count();
    assert!(drawn > 45 * 150, "the views show the scene: {drawn} pixels");
    let off = common::tile_subpixels_off(&preview, [0, 0], &written);
    assert!(
        off <= 45 * 9,
        "{off} of 216000 subpixels off the quilt file"
    );
}

/// `view --json` says what the window showed and the screenshot it wrote, as every other
/// command's `--json` does (before: the viewer had no `--json`).
#[test]
fn the_viewer_json_names_its_screenshot() {
    let Some(x) = xvfb_or_clear_error() else {
        return;
    };
    let shot = common::out_dir().join("vocabulary_view_json.png");
    let _ = std::fs::remove_file(&shot);
    let (ok, stdout, stderr) = x.cli(&[
        "view",
        "--size",
        "64x48",
        "--screenshot",
        shot.to_str().unwrap(),
        "--json",
    ]);
    assert!(ok, "{stderr}");
    let json: serde_json::Value = serde_json::from_str(stdout.trim()).unwrap();
    assert_eq!(json["written"], serde_json::json!([shot]), "{json}");
    assert_eq!(json["window_size"], serde_json::json!([64, 48]), "{json}");
    assert_eq!(json["frames"], 3, "{json}");
    assert!(shot.is_file());
}

/// A file name that is not UTF-8 reaches the refusal, named, instead of a panic in reading the
/// command line (the viewer names the other primitive's flag from it).
#[test]
fn a_non_utf8_name_does_not_panic_the_viewers_refusal() {
    use std::os::unix::ffi::OsStrExt;
    let mut shot = common::out_dir().into_os_string();
    shot.push(std::ffi::OsStr::from_bytes(b"/view_\xff.png"));
    let mut args: Vec<std::ffi::OsString> =
        ["view", "--kind", "mesh", "--tf", "bone", "--screenshot"]
            .map(Into::into)
            .to_vec();
    args.push(shot);
    let (ok, stderr) = common::xvfb::cli_without_display(&args);
    assert!(!ok && !stderr.contains("panicked"), "{stderr}");
    assert!(
        stderr.contains("--tf is a flag of `autostereo volume`"),
        "{stderr}"
    );
}
