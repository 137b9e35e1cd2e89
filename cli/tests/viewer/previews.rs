//! The quilt preview, full screen, the monitor check against a calibration's panel, and
//! Gaussian splat files.

use super::*;

/// The quilt preview: tile v (Looking Glass order, view 0 bottom-left) is view v rendered
/// headless on a `view:8,v` display at the tile's size.
#[test]
fn the_quilt_preview_puts_each_view_in_its_tile() {
    let Some(x) = xvfb_or_clear_error() else {
        return;
    };
    let shot = out("viewer_quilt.png");
    let (ok, _, err) = x.cli(&[
        "view",
        "--kind",
        "mesh",
        "--preview",
        "quilt",
        "--size",
        "300x240",
        "--quit-after-frames",
        "2",
        "--screenshot",
        shot.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    assert!(
        err.contains(&format!("wrote {}", shot.display())),
        "the screenshot is said: {err}"
    );
    let quilt = RgbImage::load_png(&shot).unwrap();
    // 8 views on the squarest grid: 3×3 tiles of 100×80.
    for (view, [tx, ty]) in [(0u32, [0u32, 160u32]), (4, [100, 80]), (7, [100, 0])] {
        let path = out(&format!("viewer_quilt_view{view}.png"));
        let display = format!("view:8,{view}");
        let (ok, err) = common::cli(&[
            "mesh",
            "--display",
            &display,
            "--size",
            "100x80",
            "--out",
            path.to_str().unwrap(),
        ]);
        assert!(ok, "{err}");
        let tile = RgbImage::load_png(&path).unwrap();
        let off = common::tile_subpixels_off(&quilt, [tx, ty], &tile);
        assert!(off <= 24, "view {view}: {off} of 24000 subpixels off");
    }
}

#[test]
fn fullscreen_fills_the_monitor_and_a_missing_monitor_is_refused() {
    let Some(x) = xvfb_or_clear_error() else {
        return;
    };
    let shot = out("viewer_fullscreen.png");
    let (ok, _, err) = x.cli(&[
        "view",
        "--kind",
        "mesh",
        "--fullscreen",
        "--quit-after-frames",
        "1",
        "--screenshot",
        shot.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    let image = RgbImage::load_png(&shot).unwrap();
    assert_eq!([image.width, image.height], [1024, 768], "the Xvfb screen");
    let (ok, _, err) = x.cli(&["view", "--fullscreen", "3", "--quit-after-frames", "1"]);
    assert!(!ok);
    assert!(
        err.contains("--fullscreen 3") && err.contains("1 monitor(s) found"),
        "{err}"
    );
}

/// The viewer says when its monitor is not the calibration's panel (the X screen here is
/// 1024×768; the sample calibration's panel 2560×1600).
#[test]
fn the_viewer_checks_its_monitor_against_the_calibrations_panel() {
    let Some(x) = xvfb_or_clear_error() else {
        return;
    };
    let calibration = format!(
        "lkg:{}/../data/lkg_sample_visual.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let (ok, _, err) = x.cli(&[
        "view",
        "--kind",
        "mesh",
        "--display",
        &calibration,
        "--size",
        "160x120",
        "--quit-after-frames",
        "1",
    ]);
    assert!(ok, "{err}");
    assert!(
        err.contains("(1024x768), but the calibration's panel is 2560x1600"),
        "{err}"
    );
}

/// A Gaussian splat file (graphdeco PLY, issue 30) is presented equal to the headless
/// `gaussians` render at the window's position; with an explicit camera (`--look-from`,
/// `--look-at`, `--up`) the viewer starts from that camera, as the command renders it.
#[test]
fn a_gaussian_splat_file_is_presented_as_the_gaussians_command_renders_it() {
    let Some(x) = xvfb_or_clear_error() else {
        return;
    };
    let file = common::gaussians_ply::write(&common::out_dir(), "viewer_gaussians.ply");
    let file = file.to_str().unwrap();
    let camera = [
        "--look-from",
        "-2,1.5,-4",
        "--look-at",
        "0,-0.2,0",
        "--up",
        "0,-1,0",
    ];
    for (name, flags) in [("plain", &[][..]), ("camera", &camera[..])] {
        let shot = out(&format!("viewer_gaussians_{name}.png"));
        let headless_png = out(&format!("viewer_gaussians_{name}_headless.png"));
        let mut args = vec![
            file,
            "--position",
            "37,21",
            "--size",
            "96x64",
            "--quit-after-frames",
            "2",
        ];
        args.extend_from_slice(flags);
        x.screenshot(&args, &shot);
        let mut args = vec![file, "--size", "96x64"];
        args.extend_from_slice(flags);
        headless("gaussians", &args, "37,21", &headless_png);
        assert_same(name, &shot, &headless_png);
    }
    let a = RgbImage::load_png(&out("viewer_gaussians_plain.png")).unwrap();
    let b = RgbImage::load_png(&out("viewer_gaussians_camera.png")).unwrap();
    assert!(
        compare(&a, &b).unwrap().frac_off_2 > 0.05,
        "the camera flags changed nothing"
    );
}
