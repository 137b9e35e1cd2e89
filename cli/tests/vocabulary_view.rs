//! Issue 31, the viewer's and the display spec's part: a window size no adapter can present is
//! refused by name (not a panic in wgpu or winit), and a display spec's error says what is wrong
//! with its number or its calibration file, naming `--display`.

mod common;

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
