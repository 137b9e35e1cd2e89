//! What the window presents equals the headless render at the window's position, with the
//! render commands' own flags; another primitive's flags are refused; moving the window moves
//! the mask phase.

use super::*;

#[test]
fn presented_frames_equal_the_headless_render_at_the_window_position() {
    let Some(x) = xvfb_or_clear_error() else {
        return;
    };
    for (kind, command, extra) in [
        ("mesh", "mesh", &[][..]),
        ("points", "points", &[][..]),
        ("volume", "volume", &["--builtin-size", "96"][..]),
    ] {
        let shot = out(&format!("viewer_{kind}.png"));
        let headless_png = out(&format!("viewer_{kind}_headless.png"));
        x.screenshot(
            &[
                "--kind",
                kind,
                "--position",
                "37,21",
                "--size",
                "160x120",
                "--quit-after-frames",
                "3",
            ],
            &shot,
        );
        let mut args = vec!["--size", "160x120"];
        args.extend_from_slice(extra);
        headless(command, &args, "37,21", &headless_png);
        assert_same(kind, &shot, &headless_png);
    }
}

/// The viewer takes the render commands' own flags (one definition, issue 29): with each
/// primitive's non-default flags the presented frame equals the command's image with the same
/// flags — and differs from the frame without them, so the flags were not ignored.
#[test]
fn the_viewer_takes_the_render_commands_flags() {
    let Some(x) = xvfb_or_clear_error() else {
        return;
    };
    let cases: [(&str, &[&str]); 3] = [
        (
            "volume",
            &[
                "--builtin",
                "ml",
                "--builtin-size",
                "32",
                "--tf",
                "mri",
                "--rotate=-90,0,30",
                "--step",
                "1",
            ],
        ),
        ("points", &["--radius-scale", "2", "--depth", "paper"]),
        ("mesh", &["--visibility", "fast", "--sort-triangles"]),
    ];
    for (kind, flags) in cases {
        let shot = out(&format!("viewer_flags_{kind}.png"));
        let plain = out(&format!("viewer_flags_{kind}_plain.png"));
        let headless = out(&format!("viewer_flags_{kind}_headless.png"));
        let window = [
            "view",
            "--kind",
            kind,
            "--position",
            "0,0",
            "--size",
            "96x64",
        ];
        let shoot = |to: &Path, flags: &[&str]| {
            let mut args = window.to_vec();
            args.extend_from_slice(&["--quit-after-frames", "2", "--screenshot"]);
            args.push(to.to_str().unwrap());
            args.extend_from_slice(flags);
            let (ok, _, err) = x.cli(&args);
            assert!(ok, "{kind} {flags:?}: {err}");
        };
        shoot(&shot, flags);
        shoot(&plain, &[]);
        let mut args = vec![kind, "--size", "96x64", "--out", headless.to_str().unwrap()];
        args.extend_from_slice(flags);
        let (ok, err) = common::cli(&args);
        assert!(ok, "{kind} headless: {err}");
        assert_same(kind, &shot, &headless);
        let a = RgbImage::load_png(&shot).unwrap();
        let b = RgbImage::load_png(&plain).unwrap();
        let diff = compare(&a, &b).unwrap();
        if kind != "mesh" {
            // The mesh's flags change how, not what (fast visibility differs at a few edges).
            assert!(
                diff.frac_off_2 > 0.01,
                "{kind}: the flags changed nothing: {diff:?}"
            );
        }
    }
}

/// Flags of another primitive are refused by name before a window opens (they would be
/// ignored).
#[test]
fn the_viewer_refuses_another_primitives_flags() {
    for (args, says) in [
        (
            &["view", "--kind", "mesh", "--tf", "mri"][..],
            "--tf is a flag of `autostereo volume`, but the built-in scene is a mesh",
        ),
        (
            &["view", "--radius-scale", "2"][..],
            "--radius-scale is a flag of `autostereo points`, but the built-in scene is a volume",
        ),
        (
            &["view", "--kind", "points", "--visibility", "fast"][..],
            "--visibility is a flag of `autostereo mesh`, but the built-in scene is a point cloud",
        ),
    ] {
        let (ok, stderr) = common::xvfb::cli_without_display(args);
        assert!(!ok, "{args:?}");
        assert!(stderr.contains(says), "{args:?}: {stderr}");
    }
}

#[test]
fn moving_the_window_moves_the_mask_phase() {
    let Some(x) = xvfb_or_clear_error() else {
        return;
    };
    let shot = x.screenshot(
        &[
            "--kind",
            "mesh",
            "--position",
            "10,10",
            "--size",
            "160x120",
            "--move-after",
            "2:51,33",
            "--quit-after-frames",
            "8",
        ],
        &out("viewer_moved.png"),
    );
    let render =
        |origin: &str, name: &str| headless("mesh", &["--size", "160x120"], origin, &out(name));
    let moved = render("51,33", "viewer_moved_headless.png");
    assert_same("after the move", &shot, &moved);
    // And the phase really changed: the image at the old position differs.
    let before = render("10,10", "viewer_before_headless.png");
    let a = RgbImage::load_png(&shot).unwrap();
    let b = RgbImage::load_png(&before).unwrap();
    assert!(
        compare(&a, &b).unwrap().frac_off_2 > 0.01,
        "the mask did not move"
    );
}
