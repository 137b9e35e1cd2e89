//! Issue 31, the origins' part: a window or monitor left of or above the primary has negative
//! coordinates on a virtual desktop (X11, Wayland, Windows), so `--origin X,Y` (the window's
//! origin on the panel) and `view --position X,Y` take negative numbers as they are written
//! (`--origin -5,-3`, no `=` needed), and the mask at a negative origin is the origin-0 mask
//! moved.

use crate::common;

use std::process::Command;

use autostereo::image_io::{compare, RgbImage};
use common::xvfb::{headless, xvfb_or_clear_error};

use crate::common::out;

/// `autostereo mask` of `size` with `extra` flags, read back with the `image` crate.
fn mask(name: &str, size: &str, extra: &[&str]) -> image::RgbImage {
    let path = out(name);
    let mut args = vec!["mask", "--size", size, "--out", path.to_str().unwrap()];
    args.extend(extra);
    let (ok, stderr) = common::cli(&args);
    assert!(ok, "{args:?}: {stderr}");
    image::open(&path).unwrap().to_rgb8()
}

/// `--origin -5,-3` parses as it is written and writes the origin-0 mask moved: window pixel
/// (x + 5, y + 3) shows panel pixel (x, y), for the paper's display and a Looking Glass with
/// subpixel cells (their parities at negative columns and rows), from the Rust mask and the
/// GPU's (`--gpu`).
#[test]
fn a_negative_origin_writes_the_origin_0_mask_moved() {
    let gen3 = concat!(
        "lkg:",
        env!("CARGO_MANIFEST_DIR"),
        "/../data/lkg_sample_go_gen3_visual.json"
    );
    for (name, display) in [("hubner8", "hubner8"), ("gen3", gen3)] {
        for gpu in [false, true] {
            let mut flags = vec!["--display", display];
            if gpu {
                flags.push("--gpu");
            }
            let tag = format!("{name}{}", if gpu { "_gpu" } else { "" });
            let at_0 = mask(&format!("origin_0_{tag}.png"), "64x48", &flags);
            flags.extend(["--origin", "-5,-3"]);
            let moved = mask(&format!("origin_minus_5_3_{tag}.png"), "69x51", &flags);
            assert_eq!(moved.dimensions(), (69, 51));
            let mut differ = 0;
            for y in 0..48 {
                for x in 0..64 {
                    assert_eq!(
                        moved.get_pixel(x + 5, y + 3),
                        at_0.get_pixel(x, y),
                        "{tag}: window pixel ({}, {}) at --origin -5,-3",
                        x + 5,
                        y + 3
                    );
                    differ += u32::from(moved.get_pixel(x, y) != at_0.get_pixel(x, y));
                }
            }
            // And the origin moved the phase: the same window pixels differ.
            assert!(differ > 64 * 48 / 2, "{tag}: only {differ} pixels moved");
        }
    }
    // `=` and spaces still work; a non-number names what it wants.
    let eq = mask("origin_eq.png", "69x51", &["--origin=-5,-3"]);
    let spaced = mask("origin_spaced.png", "69x51", &["--origin", " -5, -3"]);
    let plain = mask(
        "origin_minus_5_3_hubner8.png",
        "69x51",
        &["--origin", "-5,-3"],
    );
    assert_eq!(eq, plain);
    assert_eq!(spaced, plain);
    let path = out("origin_bad.png");
    let (ok, stderr) = common::cli(&[
        "mask",
        "--size",
        "8x8",
        "--origin",
        "-5,x",
        "--out",
        path.to_str().unwrap(),
    ]);
    assert!(!ok);
    assert!(
        stderr.contains("'-5,x' is not two whole numbers X,Y (negative allowed)"),
        "{stderr}"
    );
}

/// `view --position -100,0` parses (without a window system the viewer's own error comes, not
/// one about --position); under Xvfb the window sits there, partly off the screen, and what it
/// presents is the headless render at `--origin -100,0` (the mask followed the negative
/// position instead of clamping it to 0).
#[test]
fn view_takes_a_negative_position_and_the_mask_follows_it() {
    let no_display = Command::new(env!("CARGO_BIN_EXE_autostereo"))
        .args(["view", "--position", "-100,0", "--quit-after-frames", "1"])
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .env("RUST_LOG", "off")
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&no_display.stderr);
    assert!(
        !no_display.status.success(),
        "a window opened without a display"
    );
    assert!(
        stderr.contains("window system") && !stderr.contains("--position"),
        "{stderr}"
    );
    let (ok, stderr) = common::cli(&["view", "--position", "-100,y"]);
    assert!(!ok);
    assert!(
        stderr.contains("'-100,y' is not two whole numbers X,Y (negative allowed)"),
        "{stderr}"
    );

    let Some(x) = xvfb_or_clear_error() else {
        return;
    };
    let shot = x.screenshot(
        &[
            "--kind",
            "mesh",
            "--position",
            "-100,0",
            "--size",
            "160x120",
            "--quit-after-frames",
            "3",
        ],
        &out("viewer_negative_position.png"),
    );
    let rendered_at = |origin: &str, name: &str| {
        let path = headless("mesh", &["--size", "160x120"], origin, &out(name));
        RgbImage::load_png(&path).unwrap()
    };
    let presented = RgbImage::load_png(&shot).unwrap();
    let diff = compare(
        &presented,
        &rendered_at("-100,0", "negative_position_headless.png"),
    )
    .unwrap();
    assert!(diff.frac_off_2 <= 0.001, "at --origin -100,0: {diff:?}");
    // Clamped to 0 (the window's position read as 0,0) it would be another image.
    let diff = compare(
        &presented,
        &rendered_at("0,0", "negative_position_at_0.png"),
    )
    .unwrap();
    assert!(diff.frac_off_2 > 0.01, "the mask did not follow: {diff:?}");
}
