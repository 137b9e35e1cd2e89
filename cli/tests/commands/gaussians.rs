//! `autostereo gaussians` (issue 30): a small 3DGS scene written by the test as graphdeco PLY
//! renders with every method the library has for Gaussians and into the other outputs; the
//! single pass and the tiled method equal the N-pass (`--compare`); a 3DGS PLY given to
//! `points` names `gaussians`; methods and cameras the Gaussians have no path for, and flags of
//! another primitive, are refused cleanly. The explicit camera (`--look-from`, `--look-at`,
//! `--up`, every command) parses negative numbers, moves the picture as it says (from −z
//! another picture than from +z; up reversed: the camera rolled half a turn, so every view is
//! the mirror view turned by 180°), and degenerate cameras are refused by name.

use crate::common;

use common::cli_out as cli;
use std::path::{Path, PathBuf};

use autostereo::image_io::{compare, RgbImage};

const SIZE: &str = "64x48";

use crate::common::out;

/// The test scene as `gaussians_{tag}.ply` (each test its own file: they run in parallel).
fn scene(tag: &str) -> PathBuf {
    common::gaussians_ply::write(&common::out_dir(), &format!("gaussians_{tag}.ply"))
}

/// `gaussians FILE --size 64x48 --json ARGS…`: its JSON report.
fn render(file: &Path, args: &[&str]) -> serde_json::Value {
    let mut all = vec![
        "gaussians",
        file.to_str().unwrap(),
        "--size",
        SIZE,
        "--json",
    ];
    all.extend_from_slice(args);
    let (ok, stdout, stderr) = cli(&all);
    assert!(ok, "{args:?}: {stderr}");
    serde_json::from_str(stdout.trim()).unwrap_or_else(|e| panic!("{e}: {stdout}"))
}

/// The error of a run that must fail, checked to be one clean line (no panic).
fn refused(args: &[&str]) -> String {
    let (ok, _, stderr) = cli(&common::measuring(args));
    assert!(!ok, "{args:?} succeeded");
    assert!(
        !stderr.contains("panicked") && !stderr.contains("RUST_BACKTRACE"),
        "{args:?}: {stderr}"
    );
    stderr
}

fn load(path: &Path) -> RgbImage {
    RgbImage::load_png(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// Whether the image shows something (the scene is in the picture).
fn lit(image: &RgbImage) -> f64 {
    image
        .data
        .chunks(3)
        .filter(|p| p.iter().any(|&c| c > 8))
        .count() as f64
        / (image.width * image.height) as f64
}

#[test]
fn every_method_and_output_renders() {
    let file = scene("methods");
    for method in ["single-pass", "n-pass", "single-view", "tiled"] {
        let png = out(&format!("gaussians_{method}.png"));
        let mut args = vec![
            "gaussians",
            file.to_str().unwrap(),
            "--size",
            SIZE,
            "--json",
            "--method",
            method,
            "--out",
            png.to_str().unwrap(),
        ];
        let (ok, stdout, stderr) = cli(&args);
        assert!(ok, "{method}: {stderr}");
        let report: serde_json::Value = serde_json::from_str(stdout.trim()).unwrap();
        assert_eq!(report["method"], method, "{report}");
        assert_eq!(
            report["gaussians"],
            common::gaussians_ply::COUNT as u64,
            "{report}"
        );
        assert_eq!(
            report["sh_degree"],
            common::gaussians_ply::DEGREE,
            "{report}"
        );
        assert_eq!(report["sort"], "gpu", "{report}");
        assert!(report["load_ms"].as_f64().unwrap() >= 0.0, "{report}");
        assert!(
            lit(&load(&png)) > 0.2,
            "{method}: the scene is not in the image"
        );
        // And the CPU sort, which renders the same picture.
        args.extend_from_slice(&["--sort", "cpu"]);
        let cpu_png = out(&format!("gaussians_{method}_cpu.png"));
        let last = args.len() - 3;
        args[last] = cpu_png.to_str().unwrap();
        let (ok, stdout, stderr) = cli(&args);
        assert!(ok, "{method} --sort cpu: {stderr}");
        assert!(stdout.contains("\"sort\":\"cpu\""), "{stdout}");
        let diff = compare(&load(&png), &load(&cpu_png)).unwrap();
        assert!(diff.psnr_db >= 40.0, "{method}: gpu vs cpu sort {diff:?}");
    }
    // Every output of views.
    let views = out("gaussians_views.png");
    render(
        &file,
        &["--output", "views", "--out", views.to_str().unwrap()],
    );
    for v in 0..8 {
        let view = load(&out(&format!("gaussians_views_{v:02}.png")));
        assert_eq!([view.width, view.height], [64, 48]);
        assert!(lit(&view) > 0.2, "view {v} is empty");
    }
    let quilt = out("gaussians_quilt.png");
    render(
        &file,
        &["--output", "quilt", "--out", quilt.to_str().unwrap()],
    );
    let layout = autostereo::render::quilt::QuiltLayout::for_views(8, [64, 48]);
    let written =
        load(&autostereo::render::quilt_image::QuiltImage::of_tiles(layout).file_name(&quilt));
    assert_eq!([written.width, written.height], layout.size());
    let anaglyph = out("gaussians_anaglyph.png");
    render(
        &file,
        &["--output", "anaglyph", "--out", anaglyph.to_str().unwrap()],
    );
    assert!(lit(&load(&anaglyph)) > 0.2);
    // A turntable of two frames: the second is the scene half a turn round.
    let spin = out("gaussians_spin.png");
    let report = render(
        &file,
        &["--turntable", "2", "--out", spin.to_str().unwrap()],
    );
    assert_eq!(report["turntable_frames"], 2, "{report}");
    let [a, b] = [0, 1].map(|k| load(&out(&format!("gaussians_spin_{k:04}.png"))));
    assert!(
        compare(&a, &b).unwrap().frac_off_2 > 0.05,
        "the turntable did not turn"
    );
}

#[test]
fn the_built_in_scene_renders_without_a_file() {
    let png = out("gaussians_builtin.png");
    let (ok, stdout, stderr) = cli(&[
        "gaussians",
        "--size",
        SIZE,
        "--json",
        "--out",
        png.to_str().unwrap(),
    ]);
    assert!(ok, "{stderr}");
    let report: serde_json::Value = serde_json::from_str(stdout.trim()).unwrap();
    assert!(report["gaussians"].as_u64().unwrap() > 1000, "{report}");
    // The generated torus and disc seen edge on: a band across the middle.
    assert!(lit(&load(&png)) > 0.05);
}

#[test]
fn the_single_pass_and_the_quilt_match_the_npass() {
    let file = scene("compare");
    for display in ["hubner8", "slanted:45,8,2/3,7/6"] {
        let report = render(&file, &["--display", display, "--compare"]);
        let psnr = report["psnr_db"].as_f64().unwrap();
        assert!(psnr >= 40.0, "{display}: {report}");
    }
    // The tiled method, and its views as a Looking Glass quilt.
    let quilt = out("gaussians_tiled_quilt.png");
    let report = render(&file, &["--method", "tiled", "--compare"]);
    assert!(report["psnr_db"].as_f64().unwrap() >= 40.0, "{report}");
    render(
        &file,
        &[
            "--method",
            "tiled",
            "--output",
            "quilt",
            "--out",
            quilt.to_str().unwrap(),
        ],
    );
    let written = std::fs::read_dir(common::out_dir())
        .unwrap()
        .filter_map(|e| e.ok())
        .any(|e| {
            let name = e.file_name().to_string_lossy().into_owned();
            name.starts_with("gaussians_tiled_quilt_qs") && name.ends_with(".png")
        });
    assert!(written, "no quilt named gaussians_tiled_quilt_qs…png");
}

#[test]
fn a_3dgs_ply_given_to_points_names_gaussians() {
    let file = scene("points");
    let stderr = refused(&["points", file.to_str().unwrap(), "--size", SIZE]);
    assert!(stderr.contains("3D Gaussian splats"), "{stderr}");
    assert!(stderr.contains("autostereo gaussians"), "{stderr}");
}

#[test]
fn methods_cameras_and_flags_without_a_gaussian_path_are_refused() {
    let file = scene("refused");
    let file = file.to_str().unwrap();
    let stderr = refused(&["gaussians", file, "--size", SIZE, "--method", "warp"]);
    assert!(
        stderr.contains("--method") && stderr.contains("warp"),
        "{stderr}"
    );
    // The methods the Gaussians have, named (tiled is joining them).
    assert!(stderr.contains("single-pass, n-pass"), "{stderr}");
    for method in ["single-pass", "n-pass"] {
        let stderr = refused(&[
            "gaussians",
            file,
            "--size",
            SIZE,
            "--method",
            method,
            "--camera",
            "toe-in",
        ]);
        assert!(
            stderr.contains("--camera") && stderr.contains("toe-in"),
            "{stderr}"
        );
        assert!(stderr.contains("skewed or parallel"), "{stderr}");
    }
    // The parallel camera has a Gaussian path.
    render(Path::new(file), &["--camera", "parallel"]);
    // Another primitive's flag: `gaussians` has none of them; the viewer refuses them by name
    // before a window opens, and the Gaussians' own flag for another kind.
    let stderr = refused(&["gaussians", file, "--radius-scale", "2"]);
    assert!(stderr.contains("--radius-scale"), "{stderr}");
    for (args, says) in [
        (
            &["view", file, "--radius-scale", "2"][..],
            "--radius-scale is a flag of `autostereo points`, but",
        ),
        (
            &["view", "--kind", "gaussians", "--tf", "mri"][..],
            "--tf is a flag of `autostereo volume`, but the built-in scene is 3D Gaussian splats",
        ),
        (
            &["view", "--kind", "mesh", "--sort", "cpu"][..],
            "--sort is a flag of `autostereo gaussians`, but the built-in scene is a mesh",
        ),
    ] {
        let (ok, stderr) = common::xvfb::cli_without_display(args);
        assert!(!ok, "{args:?}");
        assert!(stderr.contains(says), "{args:?}: {stderr}");
    }
}

/// `image` turned by half a turn.
fn turned(image: &RgbImage) -> RgbImage {
    let (w, h) = (image.width as usize, image.height as usize);
    let mut data = Vec::with_capacity(image.data.len());
    for y in 0..h {
        for x in 0..w {
            let i = 3 * ((h - 1 - y) * w + (w - 1 - x));
            data.extend_from_slice(&image.data[i..i + 3]);
        }
    }
    RgbImage {
        width: image.width,
        height: image.height,
        data,
    }
}

#[test]
fn the_explicit_camera_parses_negative_numbers_and_moves_the_picture() {
    let file = scene("camera");
    let view = |name: &str, camera: &[&str]| {
        let png = out(&format!("gaussians_camera_{name}.png"));
        let mut args = vec!["--display", "view:1,0", "--out", png.to_str().unwrap()];
        args.extend_from_slice(camera);
        let report = render(&file, &args);
        (load(&png), report)
    };
    let (plain, plain_report) = view("plain", &[]);
    // The framing's own eye, target and up, given: the same picture.
    let bounds = autostereo::gaussians::Gaussians::load(&file)
        .unwrap()
        .bounds()
        .unwrap();
    let c = bounds.center();
    let distance = plain_report["focal_distance"].as_f64().unwrap() as f32;
    let xyz = |v: glam::Vec3| format!("{},{},{}", v.x, v.y, v.z);
    let (same, report) = view(
        "same",
        &[
            "--look-from",
            &xyz(c + glam::Vec3::Z * distance),
            "--look-at",
            &xyz(c),
            "--up",
            "0,1,0",
        ],
    );
    let focal = report["focal_distance"].as_f64().unwrap() as f32;
    assert!((focal - distance).abs() <= 1e-5 * distance, "{report}");
    let diff = compare(&plain, &same).unwrap();
    assert!(diff.psnr_db >= 40.0, "{diff:?}");
    // From behind (a negative number after a space, as written by hand).
    assert!(c.z - distance < 0.0);
    let (behind, _) = view(
        "behind",
        &["--look-from", &xyz(c - glam::Vec3::Z * distance)],
    );
    assert!(lit(&behind) > 0.2);
    let diff = compare(&same, &behind).unwrap();
    assert!(diff.frac_off_2 > 0.1, "from −z as from +z: {diff:?}");
    // Anywhere, with a negative up: runs; --focal still overrides the focal plane.
    let (_, report) = view(
        "anywhere",
        &["--look-from", "-1,2,-3", "--up", "0,-1,0", "--focal", "2.5"],
    );
    assert_eq!(report["focal_distance"], 2.5, "{report}");
    let (_, report) = view("equals", &["--look-from=-1,2,-3", "--look-at=-0.5,0,0"]);
    let expected = (0.5f64 * 0.5 + 4.0 + 9.0).sqrt();
    let focal = report["focal_distance"].as_f64().unwrap();
    assert!((focal - expected).abs() < 1e-4, "{report}");
}

#[test]
fn up_reversed_turns_every_view_half_a_turn() {
    let file = scene("up");
    let views = |name: &str, up: &str| {
        let png = out(&format!("gaussians_up_{name}.png"));
        render(
            &file,
            &[
                "--up",
                up,
                "--output",
                "views",
                "--out",
                png.to_str().unwrap(),
            ],
        );
        (0..8)
            .map(|v| load(&out(&format!("gaussians_up_{name}_{v:02}.png"))))
            .collect::<Vec<_>>()
    };
    let upright = views("upright", "0,1,0");
    let reversed = views("reversed", "0,-1,0");
    for v in 0..8 {
        // The camera rolled by half a turn: its right is world −x, so view v stands where
        // view 7 − v stood, and sees its picture turned.
        let expected = turned(&upright[7 - v]);
        let diff = compare(&reversed[v], &expected).unwrap();
        if diff.psnr_db < 40.0 {
            common::save_diff(&format!("gaussians_up_view{v}"), &reversed[v], &expected);
        }
        assert!(diff.psnr_db >= 40.0, "view {v}: {diff:?}");
        let unturned = compare(&reversed[v], &upright[v]).unwrap();
        assert!(unturned.frac_off_2 > 0.1, "view {v}: up changed nothing");
    }
}

#[test]
fn degenerate_cameras_are_refused_by_name() {
    let file = scene("degenerate");
    let file = file.to_str().unwrap();
    for (camera, says) in [
        (
            &["--look-from", "0,0,1", "--look-at", "0,0,1"][..],
            "--look-at: invalid look-at",
        ),
        (
            &[
                "--look-from",
                "0,0,5",
                "--look-at",
                "0,0,0",
                "--up",
                "0,0,-2",
            ],
            "--up: invalid up",
        ),
        (&["--up", "0,0,0"], "--up: invalid up: the zero vector"),
        (&["--look-from", "nan,0,0"], "--look-from"),
        (&["--look-at", "1,inf,0"], "finite"),
        (&["--up", "1,2"], "three comma-separated numbers"),
        (
            &["--look-from", "0,0,5", "--look-at", "0,0,9"],
            "wholly behind the camera",
        ),
    ] {
        let mut args = vec!["gaussians", file, "--size", SIZE];
        args.extend_from_slice(camera);
        let stderr = refused(&args);
        assert!(stderr.contains(says), "{camera:?}: {stderr}");
    }
    let stderr = refused(&["gaussians", file, "--up", "0,0,1"]);
    assert!(
        stderr.contains("parallel to the view direction"),
        "{stderr}"
    );
    // Every render command has the flags.
    let stderr = refused(&["mesh", "--size", SIZE, "--up", "0,0,1"]);
    assert!(stderr.contains("--up: invalid up"), "{stderr}");
}
