//! The panel found, not typed: `--list-monitors`, and `--fullscreen` alone picking the monitor
//! of the calibration's size, its mask the headless render's at that monitor's origin.

use super::*;

/// A Looking Glass calibration whose panel is the tests' Xvfb screen (1024×768).
fn screen_sized_calibration() -> std::path::PathBuf {
    let path = out("viewer_monitor_visual.json");
    std::fs::write(
        &path,
        r#"{"serial": "LKG-TEST-screen", "pitch": {"value": 47.0}, "slope": {"value": -5.5},
           "center": {"value": 0.2}, "viewCone": {"value": 40.0}, "DPI": {"value": 300.0},
           "screenW": {"value": 1024.0}, "screenH": {"value": 768.0},
           "invView": {"value": 1.0}, "flipImageX": {"value": 0.0}}"#,
    )
    .unwrap();
    path
}

#[test]
fn the_panel_is_found_by_its_size_and_its_mask_starts_at_the_monitor() {
    let Some(x) = xvfb_or_clear_error() else {
        return;
    };
    let (ok, stdout, err) = x.cli(&["view", "--list-monitors"]);
    assert!(ok, "{err}");
    assert!(
        stdout.contains("0: ") && stdout.contains("1024x768 at 0,0"),
        "{stdout}"
    );
    let (ok, stdout, err) = x.cli(&["view", "--list-monitors", "--json"]);
    assert!(ok, "{err}");
    let listed: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(
        listed["monitors"][0]["size"],
        serde_json::json!([1024, 768])
    );
    // --fullscreen alone: the monitor of the calibration's size, said; the window there has
    // the mask of the headless render at origin 0,0.
    let display = format!("lkg:{}", screen_sized_calibration().display());
    let shot = out("viewer_panel_fullscreen.png");
    let (ok, _, err) = x.cli(&[
        "view",
        "--kind",
        "mesh",
        "--display",
        &display,
        "--views",
        "8",
        "--fullscreen",
        "--quit-after-frames",
        "2",
        "--screenshot",
        shot.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    assert!(
        err.contains("full screen on monitor 0:") && err.contains("the calibration's panel size"),
        "{err}"
    );
    let alone = out("viewer_panel_headless.png");
    headless(
        "mesh",
        &["--display", &display, "--views", "8", "--size", "1024x768"],
        "0,0",
        &alone,
    );
    assert_same("panel", &shot, &alone);
    // No monitor of the panel's size: refused, the monitors listed.
    let sample = format!(
        "lkg:{}/../data/lkg_sample_visual.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let (ok, _, err) = x.cli(&[
        "view",
        "--display",
        &sample,
        "--fullscreen",
        "--quit-after-frames",
        "1",
    ]);
    assert!(!ok);
    assert!(
        err.contains("no monitor is 2560x1600") && err.contains("1024x768 at 0,0"),
        "{err}"
    );
}
