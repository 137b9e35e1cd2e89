//! The panel found, not typed: `--list-monitors`, and `--fullscreen` alone picking the monitor
//! of the calibration's size, its mask the headless render's at that monitor's own origin —
//! on one monitor (Xvfb) and on two (Xorg's dummy driver, the panel right of another).

use super::*;

/// A Looking Glass calibration whose panel is `w`×`h`.
fn calibration_of(w: u32, h: u32) -> std::path::PathBuf {
    let path = out(&format!("viewer_monitor_{w}x{h}_visual.json"));
    std::fs::write(
        &path,
        format!(
            r#"{{"serial": "LKG-TEST-screen", "pitch": {{"value": 47.0}}, "slope": {{"value": -5.5}},
               "center": {{"value": 0.2}}, "viewCone": {{"value": 40.0}}, "DPI": {{"value": 300.0}},
               "screenW": {{"value": {w}.0}}, "screenH": {{"value": {h}.0}},
               "invView": {{"value": 1.0}}, "flipImageX": {{"value": 0.0}}}}"#
        ),
    )
    .unwrap();
    path
}

/// Two monitors, the panel right of a 1024-wide one: `--fullscreen` finds it by its size, and
/// what it presents is the headless render at the panel's own origin 0,0 (the mask is the
/// panel's, not the desktop's: before, this needed `--origin -1024,0`).
#[test]
fn on_two_monitors_the_panel_is_found_and_its_mask_is_its_own() {
    let Some(x) = Xvfb::two_monitors() else {
        // No Xorg dummy driver here (CI installs it): what can be checked on one monitor is.
        let x = xvfb_or_clear_error();
        let display = format!("lkg:{}", calibration_of(640, 480).display());
        if let Some(x) = x {
            let (ok, _, err) = x.cli(&[
                "view",
                "--display",
                &display,
                "--fullscreen",
                "--quit-after-frames",
                "1",
            ]);
            assert!(!ok && err.contains("no monitor is 640x480"), "{err}");
        }
        return;
    };
    let (ok, stdout, err) = x.cli(&["view", "--list-monitors"]);
    assert!(ok, "{err}");
    assert!(stdout.contains("1: DUMMY1 640x480 at 1024,0"), "{stdout}");
    let display = format!("lkg:{}", calibration_of(640, 480).display());
    let shot = out("viewer_two_monitors.png");
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
        err.contains("full screen on monitor 1: DUMMY1 640x480 at 1024,0"),
        "{err}"
    );
    let args = [
        "--display",
        display.as_str(),
        "--views",
        "8",
        "--size",
        "640x480",
    ];
    let at_panel = headless("mesh", &args, "0,0", &out("viewer_two_monitors_0.png"));
    assert_same("the panel's origin", &shot, &at_panel);
    // The desktop's origin would be another mask phase: the comparison can tell them apart.
    let at_desktop = headless(
        "mesh",
        &args,
        "1024,0",
        &out("viewer_two_monitors_1024.png"),
    );
    let a = RgbImage::load_png(&at_panel).unwrap();
    let b = RgbImage::load_png(&at_desktop).unwrap();
    assert!(
        compare(&a, &b).unwrap().frac_off_2 > 0.01,
        "origins 0 and 1024 look alike"
    );
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
    let display = format!("lkg:{}", calibration_of(1024, 768).display());
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
