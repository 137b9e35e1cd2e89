//! Issue 31, "the command line as one vocabulary": each finding fixed here has a test that
//! fails on the binary before the fix. Negative numbers parse as values; `--max-memory` takes
//! `MB`, `GiB`…; `--slices` under 3 (an all-background image) is refused by name; `view
//! --screenshot` exits once the file is written; `--fov` is checked in degrees where it is
//! parsed.

use crate::common;

use std::path::PathBuf;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use common::cli;

pub(crate) fn out(name: &str) -> PathBuf {
    common::out_dir().join(name)
}

/// A small, fast volume render of the built-in head into `png` with `extra` flags.
pub(crate) fn volume(png: &std::path::Path, extra: &[&str]) -> (bool, String) {
    let mut args = vec![
        "volume",
        "--builtin-size",
        "16",
        "--size",
        "32x24",
        "--out",
        png.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    cli(&args)
}

#[test]
fn negative_numbers_parse_as_values() {
    // `--rotate -90,0,0` was "unexpected argument '-9'"; it is the same as `--rotate=-90,0,0`.
    let spaced = out("vocabulary_rotate_spaced.png");
    let joined = out("vocabulary_rotate_joined.png");
    let (ok, stderr) = volume(&spaced, &["--rotate", "-90,0,0"]);
    assert!(ok, "--rotate -90,0,0: {stderr}");
    let (ok, stderr) = volume(&joined, &["--rotate=-90,0,0"]);
    assert!(ok, "--rotate=-90,0,0: {stderr}");
    assert_eq!(
        std::fs::read(&spaced).unwrap(),
        std::fs::read(&joined).unwrap(),
        "--rotate -90,0,0 and --rotate=-90,0,0 differ"
    );
    // A negative separation or baseline (the views in reverse order) renders.
    for flags in [["--separation", "-1"], ["--baseline", "-2"]] {
        let png = out(&format!("vocabulary_{}.png", &flags[0][2..]));
        let _ = std::fs::remove_file(&png);
        let (ok, stderr) = volume(&png, &flags);
        assert!(ok, "{flags:?}: {stderr}");
        assert!(png.exists(), "{flags:?} wrote nothing");
    }
    // A negative focal distance parses, and the library refuses it by name (not clap's
    // "unexpected argument").
    for flags in [["--focal", "-1"], ["--focal-scale", "-0.5"]] {
        let (ok, stderr) = volume(&out("vocabulary_focal.png"), &flags);
        assert!(!ok, "{flags:?} succeeded");
        assert!(
            !stderr.contains("unexpected argument"),
            "{flags:?}: {stderr}"
        );
        assert!(stderr.contains("focal distance"), "{flags:?}: {stderr}");
        assert!(stderr.contains("positive"), "{flags:?}: {stderr}");
    }
    // rgbd's signed numbers: a negative depthiness (parallax reversed) parses (the missing
    // input is what is refused).
    let rgbd_out = out("vocabulary_rgbd.png");
    let (ok, stderr) = cli(&[
        "rgbd",
        "nosuch.png",
        "--sbs",
        "--depthiness",
        "-1",
        "--out",
        rgbd_out.to_str().unwrap(),
    ]);
    assert!(!ok);
    assert!(!stderr.contains("unexpected argument"), "{stderr}");
    assert!(stderr.contains("nosuch.png"), "{stderr}");
}

#[test]
fn max_memory_takes_kb_mb_kib_and_mib() {
    // `--max-memory 1MB` was refused ("not a size"); every spelling of the unit is 1024-based,
    // as K, M, G and T always were: the budget error names 1024 bytes for each of these.
    for size in ["1K", "1KB", "1kb", "1KiB", "1 KiB"] {
        let (ok, stderr) = volume(&out("vocabulary_budget.png"), &["--max-memory", size]);
        assert!(!ok, "--max-memory {size}: a 16³ volume fits 1 KiB?");
        assert!(
            !stderr.contains("not a size"),
            "--max-memory {size}: {stderr}"
        );
        assert!(
            stderr.contains("memory budget of 1024 bytes"),
            "--max-memory {size}: {stderr}"
        );
    }
    for size in ["1MB", "1MiB", "1mb", "1GB", "2GiB", "1TB"] {
        let (ok, stderr) = volume(&out("vocabulary_budget_ok.png"), &["--max-memory", size]);
        assert!(ok, "--max-memory {size}: {stderr}");
    }
    let (ok, stderr) = volume(&out("vocabulary_budget.png"), &["--max-memory", "1PB"]);
    assert!(!ok);
    assert!(
        stderr.contains("--max-memory") && stderr.contains("K, M, G or T"),
        "{stderr}"
    );
}

#[test]
fn slices_under_three_are_refused_by_name() {
    // `--slices 0`, `1` and `2` wrote an all-black image with exit 0.
    for n in ["0", "1", "2"] {
        let png = out(&format!("vocabulary_slices_{n}.png"));
        let _ = std::fs::remove_file(&png);
        let (ok, stderr) = volume(&png, &["--slices", n]);
        assert!(!ok, "--slices {n} succeeded");
        assert!(stderr.contains(&format!("--slices {n}")), "{stderr}");
        assert!(stderr.contains("at least 3"), "{stderr}");
        assert!(!png.exists(), "--slices {n} wrote {}", png.display());
    }
    // Three samples across the diagonal do sample the volume: not a background-only image.
    let png = out("vocabulary_slices_3.png");
    let (ok, stderr) = volume(&png, &["--slices", "3"]);
    assert!(ok, "--slices 3: {stderr}");
    let image = image::open(&png).unwrap().to_rgb8();
    let first = *image.get_pixel(0, 0);
    assert!(
        image.pixels().any(|p| *p != first),
        "--slices 3 rendered a uniform image"
    );
}

#[test]
fn fov_errors_are_in_degrees_and_name_the_flag() {
    // `--fov=180` was "invalid field of view: fov 3.1415927 rad, aspect …".
    for fov in ["180", "0", "-10", "400", "nan"] {
        let (ok, stderr) = volume(&out("vocabulary_fov.png"), &["--fov", fov]);
        assert!(!ok, "--fov {fov} succeeded");
        assert!(stderr.contains("--fov"), "--fov {fov}: {stderr}");
        assert!(
            stderr.contains("between 0 and 180 degrees"),
            "--fov {fov}: {stderr}"
        );
        assert!(!stderr.contains("rad"), "--fov {fov}: {stderr}");
    }
    let (ok, stderr) = volume(&out("vocabulary_fov.png"), &["--fov", "wide"]);
    assert!(!ok);
    assert!(
        stderr.contains("--fov") && stderr.contains("degrees"),
        "{stderr}"
    );
    let (ok, stderr) = volume(&out("vocabulary_fov.png"), &["--fov", "179"]);
    assert!(ok, "--fov 179: {stderr}");
}

#[test]
fn a_screenshot_ends_the_viewer_unless_keep_open() {
    // Refused before any window opens: --keep-open is about the screenshot.
    let (ok, stderr) = cli(&["view", "--keep-open"]);
    assert!(!ok);
    assert!(stderr.contains("--screenshot"), "{stderr}");
    let help = Command::new(env!("CARGO_BIN_EXE_autostereo"))
        .args(["view", "--help"])
        .output()
        .unwrap();
    let help = String::from_utf8_lossy(&help.stdout);
    assert!(help.contains("--keep-open"), "{help}");
    assert!(help.contains("then exit"), "{help}");

    // Without Xvfb (CI installs it) the viewer's clear error is asserted instead.
    let Some(x) = common::xvfb::xvfb_or_clear_error() else {
        return;
    };
    // `view --screenshot s.png` saved the file and then ran forever.
    let shot = out("vocabulary_screenshot.png");
    let _ = std::fs::remove_file(&shot);
    let mut child = Command::new(env!("CARGO_BIN_EXE_autostereo"))
        .args([
            "view",
            "--builtin-size",
            "16",
            "--size",
            "64x48",
            "--screenshot",
            shot.to_str().unwrap(),
        ])
        .env("DISPLAY", &x.display)
        .env_remove("WAYLAND_DISPLAY")
        .env("RUST_LOG", "off")
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break Some(status);
        }
        if start.elapsed() > Duration::from_secs(120) {
            break None;
        }
        std::thread::sleep(Duration::from_millis(100));
    };
    let Some(status) = status else {
        let _ = child.kill();
        let _ = child.wait();
        panic!(
            "view --screenshot still running after 120 s (screenshot written: {})",
            shot.exists()
        );
    };
    let mut stderr = String::new();
    use std::io::Read;
    child
        .stderr
        .take()
        .unwrap()
        .read_to_string(&mut stderr)
        .unwrap();
    assert!(status.success(), "view --screenshot: {stderr}");
    let image = image::open(&shot).unwrap();
    assert_eq!([image.width(), image.height()], [64, 48]);
}

/// A 45-view quilt on an 8-view display: the display's views spread across the quilt's cone
/// (view i ← quilt view round(i·44/7)), said on stderr, not quilt views 0–7 (one edge of it).
#[test]
fn a_larger_quilt_is_spread_over_the_display_views() {
    use autostereo::image_io::RgbImage;
    use autostereo::render::quilt::QuiltLayout;
    let tile = [8, 6];
    let layout = QuiltLayout::with_grid(9, 5, tile, 45).unwrap();
    let size = layout.size();
    let mut quilt = RgbImage::new(size[0], size[1]);
    // Tile t is solid (t + 1)·5 in every channel (none black: black tiles count as empty).
    let colour = |t: u32| ((t + 1) * 5) as u8;
    for t in 0..45 {
        let [x0, y0] = layout.tile_origin(t);
        for y in 0..tile[1] {
            for x in 0..tile[0] {
                for c in 0..3 {
                    quilt.set(x0 + x, y0 + y, c, colour(t));
                }
            }
        }
    }
    let path = autostereo::render::quilt_image::QuiltImage::of_tiles(layout)
        .file_name(&out("vocabulary_quilt45.png"));
    quilt.save_png(&path).unwrap();
    let spatial = out("vocabulary_quilt45_on_8.png");
    let (ok, stderr) = cli(&[
        "interleave",
        path.to_str().unwrap(),
        "--display",
        "lenticular:8",
        "--size",
        "48x24",
        "--out",
        spatial.to_str().unwrap(),
    ]);
    assert!(ok, "{stderr}");
    assert!(
        stderr.contains(
            "the quilt has 45 views, the display 8: using quilt views 0, 6, 13, 19, 25, 31, 38, 44"
        ),
        "{stderr}"
    );
    let image = RgbImage::load_png(&spatial).unwrap();
    let seen: std::collections::BTreeSet<u8> = image.data.iter().copied().collect();
    let picked: std::collections::BTreeSet<u8> = [0, 6, 13, 19, 25, 31, 38, 44].map(colour).into();
    assert_eq!(seen, picked);
}
