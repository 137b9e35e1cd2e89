//! A Looking Glass calibration sets what its owner expects (docs/USAGE.md "Looking Glass"): the
//! panel's size, the family's view count and quilt, the views spread over the calibration's
//! viewCone; `--display lkg` alone looks for the attached display; the stereo checks have real
//! disparity and the hint after a render repeats every display flag.

use crate::common;

use common::cli_out as run;

fn sample(name: &str) -> String {
    format!("{}/../data/{name}", env!("CARGO_MANIFEST_DIR"))
}

use crate::common::out;

/// The run's JSON line.
fn json(args: &[&str]) -> serde_json::Value {
    let mut all = args.to_vec();
    all.push("--json");
    let (ok, stdout, stderr) = run(&all);
    assert!(ok, "{args:?}: {stderr}");
    serde_json::from_str(&stdout).unwrap_or_else(|e| panic!("{e}: {stdout}"))
}

#[test]
fn a_calibration_sets_the_panel_size_the_family_views_and_the_view_cone() {
    let go = format!("lkg:{}", sample("lkg_sample_go_gen3_visual.json"));
    let image = out("lkg_go.png");
    let run = json(&["mesh", "--display", &go, "--out", image.to_str().unwrap()]);
    // The Go's panel, and its family's 66 views (an 11×6 quilt).
    assert_eq!(run["size"], serde_json::json!([1440, 2560]));
    assert_eq!(run["views"], 66);
    let written = autostereo::image_io::RgbImage::load_png(&image).unwrap();
    assert_eq!([written.width, written.height], [1440, 2560]);
    // viewCone 54°: the outermost views ±27° from the focal point.
    let fd = run["focal_distance"].as_f64().unwrap();
    let baseline = run["separation"].as_f64().unwrap() * 65.0;
    let expected = 2.0 * fd * 27f64.to_radians().tan();
    assert!(
        (baseline - expected).abs() < 1e-3 * expected,
        "{baseline} vs {expected}"
    );
    // The flags still decide where given.
    let run = json(&[
        "mesh",
        "--display",
        &go,
        "--size",
        "64x96",
        "--views",
        "45",
        "--separation",
        "0.01",
        "--out",
        image.to_str().unwrap(),
    ]);
    assert_eq!(run["size"], serde_json::json!([64, 96]));
    assert_eq!(run["views"], 45);
    assert!((run["separation"].as_f64().unwrap() - 0.01).abs() < 1e-6);
    // A serial of no known family: 45 views, as before.
    let unknown = format!("lkg:{}", sample("lkg_sample_visual.json"));
    let run = json(&[
        "points",
        "--display",
        &unknown,
        "--size",
        "64x40",
        "--out",
        image.to_str().unwrap(),
    ]);
    assert_eq!(run["views"], 45);
}

#[test]
fn the_quilt_is_the_familys_grid_with_tiles_of_the_panels_aspect() {
    let j = format!(
        "lkg:{}",
        sample("lkg_sample_16in_landscape_gen3_visual.json")
    );
    let base = out("lkg_16in.png");
    // --size sets the spatial image only (small here, to keep the test fast; the panel's own
    // size renders in bands: docs/panel_sizes.md).
    let (ok, _, stderr) = run(&[
        "mesh",
        "--display",
        &j,
        "--size",
        "64x36",
        "--output",
        "quilt",
        "--out",
        base.to_str().unwrap(),
    ]);
    assert!(ok, "{stderr}");
    // LKG-J: 49 views in 7×7 within 5999², tiles 857 wide at the panel's 16:9.
    let quilt = out("lkg_16in_qs7x7a1.778.png");
    let image = autostereo::image_io::RgbImage::load_png(&quilt)
        .unwrap_or_else(|e| panic!("{e}: {stderr}"));
    assert_eq!([image.width, image.height], [7 * 857, 7 * 482]);
    // Every tile holds a view: the middle of each tile is lit (the scene fills it).
    let lit = |tx: u32, ty: u32| {
        let (x, y) = (tx * 857 + 428, ty * 482 + 241);
        (0..3).any(|c| image.get(x, y, c) > 0)
    };
    assert!((0..7).all(|tx| (0..7).all(|ty| lit(tx, ty))));
    // Interleaved again for the display: the panel's size by default.
    let spatial = out("lkg_16in_interleaved.png");
    let (ok, _, stderr) = run(&[
        "interleave",
        quilt.to_str().unwrap(),
        "--display",
        &j,
        "--out",
        spatial.to_str().unwrap(),
    ]);
    assert!(ok, "{stderr}");
    let image = autostereo::image_io::RgbImage::load_png(&spatial).unwrap();
    assert_eq!([image.width, image.height], [3840, 2160]);
}

#[test]
fn lkg_without_a_path_looks_for_the_attached_display_and_says_where() {
    let (ok, _, stderr) = run(&[
        "mesh",
        "--display",
        "lkg",
        "--out",
        out("x.png").to_str().unwrap(),
    ]);
    // No Looking Glass is attached to a test machine.
    assert!(!ok);
    assert!(
        stderr.contains("LKG_calibration/visual.json") && stderr.contains("/media"),
        "{stderr}"
    );
}

#[test]
fn stereo_defaults_have_disparity_and_the_hint_repeats_every_display_flag() {
    // 45 views: the default pair used to be view 22 twice (a flat picture).
    let sbs = out("lkg_default_eyes.png");
    let (ok, _, stderr) = run(&[
        "mesh",
        "--display",
        "slanted:45,7.5,-1,0",
        "--size",
        "96x64",
        "--output",
        "side-by-side",
        "--out",
        sbs.to_str().unwrap(),
    ]);
    assert!(ok, "{stderr}");
    let image = autostereo::image_io::RgbImage::load_png(&sbs).unwrap();
    let differ = (0..64)
        .flat_map(|y| (0..96).map(move |x| (x, y)))
        .filter(|&(x, y)| (0..3).any(|c| image.get(x, y, c) != image.get(x + 96, y, c)))
        .count();
    assert!(
        differ > 50,
        "the default eyes barely differ ({differ} pixels)"
    );
    let spatial = out("lkg_hint.png");
    let (ok, _, stderr) = run(&[
        "mesh",
        "--display",
        "slanted:45,7.5,-1,0",
        "--size",
        "64x48",
        "--origin",
        "3,4",
        "--flip-views",
        "--bgr",
        "--out",
        spatial.to_str().unwrap(),
    ]);
    assert!(ok, "{stderr}");
    for flag in [
        "--display slanted:45,7.5,-1,0 --views 45 --origin 3,4 --flip-views --bgr",
        "--output anaglyph",
        "--eyes 16,27",
    ] {
        assert!(stderr.contains(flag), "hint lacks {flag}: {stderr}");
    }
}
