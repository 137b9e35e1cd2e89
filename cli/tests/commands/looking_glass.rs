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
fn the_quilt_is_the_familys_own_size_and_grid_its_tiles_stretched_to_the_panel() {
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
    // LKG-J: the family's 5999² quilt of 7×7 tiles of 857², each view shown at the panel's
    // 16:9 (the name's a1.7778), as Looking Glass software writes and reads it.
    assert!(
        stderr.contains("quilt 5999x5999: 7x7 tiles of 857x857"),
        "{stderr}"
    );
    let quilt = out("lkg_16in_qs7x7a1.7778.png");
    let image = autostereo::image_io::RgbImage::load_png(&quilt)
        .unwrap_or_else(|e| panic!("{e}: {stderr}"));
    assert_eq!([image.width, image.height], [5999, 5999]);
    // Every tile holds a view: the middle of each tile is lit (the scene fills it).
    let lit = |tx: u32, ty: u32| {
        let (x, y) = (tx * 857 + 428, ty * 857 + 428);
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
    // The round trip against the direct single pass of the same window: the quilt's views,
    // rendered at 857² and stretched to 16:9, are the direct render's views.
    let (small, direct) = (out("lkg_16in_roundtrip.png"), out("lkg_16in_direct.png"));
    let (ok, _, stderr) = run(&[
        "interleave",
        quilt.to_str().unwrap(),
        "--display",
        &j,
        "--size",
        "256x144",
        "--out",
        small.to_str().unwrap(),
    ]);
    assert!(ok, "{stderr}");
    let (ok, _, stderr) = run(&[
        "mesh",
        "--display",
        &j,
        "--size",
        "256x144",
        "--out",
        direct.to_str().unwrap(),
    ]);
    assert!(ok, "{stderr}");
    let load = |p: &std::path::Path| autostereo::image_io::RgbImage::load_png(p).unwrap();
    let diff = autostereo::image_io::compare(&load(&small), &load(&direct)).unwrap();
    println!(
        "16\" quilt 5999² → interleave 256x144 vs the direct single pass: PSNR {:.2} dB",
        diff.psnr_db
    );
    assert!(diff.psnr_db > 35.0, "PSNR {:.2} dB", diff.psnr_db);
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
        // The viewer gets the scene rendered, not its own default (here the built-in mesh).
        "autostereo view --kind mesh --display slanted",
    ] {
        assert!(stderr.contains(flag), "hint lacks {flag}: {stderr}");
    }
    // A file is repeated as given; a one-view display's image is an ordinary picture.
    let obj = out("lkg_hint_tri.obj");
    std::fs::write(&obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
    let (ok, _, stderr) = run(&[
        "mesh",
        obj.to_str().unwrap(),
        "--display",
        "lenticular:8",
        "--size",
        "32x24",
        "--out",
        spatial.to_str().unwrap(),
    ]);
    assert!(ok, "{stderr}");
    let view = format!("autostereo view {} --display lenticular:8", obj.display());
    assert!(stderr.contains(&view), "{stderr}");
    let (ok, _, stderr) = run(&[
        "mesh",
        "--display",
        "view:8,0",
        "--size",
        "32x24",
        "--out",
        spatial.to_str().unwrap(),
    ]);
    assert!(ok, "{stderr}");
    assert!(stderr.contains("is one view"), "{stderr}");
    assert!(
        !stderr.contains("interleaved") && !stderr.contains("--eyes"),
        "{stderr}"
    );
}

/// Quilts as Looking Glass software writes them: a gen-3 16" 5999² `_qs7x7a1.778` quilt
/// (tiles 857², of aspect 1, shown at 16:9) and a gen-2 4096² `_qs5x9a1.77` one (tiles
/// 819×455, one pixel row and column left over) interleaved for the matching calibration.
/// Tile v is coded 5v + 2 in every channel and the remainder 255: every subpixel of three
/// windows across the panel (its corners and middle) must hold the code of the view the CPU
/// mask gives it (≥ 99.9 %: bilinear filtering may blend two tiles on a tile's edge texel),
/// and none the remainder's.
#[test]
fn looking_glass_quilts_interleave_to_each_subpixels_view() {
    let cases = [
        (
            "lkg_sample_16in_landscape_gen3_visual.json",
            "coded_qs7x7a1.778.png",
            [5999, 5999],
            [7, 7],
        ),
        (
            "lkg_sample_16in_gen2_visual.json",
            "coded_qs5x9a1.77.png",
            [4096, 4096],
            [5, 9],
        ),
    ];
    for (calibration, name, [w, h], [cols, rows]) in cases {
        let spec = format!("lkg:{}", sample(calibration));
        let display = autostereo::display::Display::parse(&spec).unwrap();
        assert_eq!(
            display.views(),
            cols * rows,
            "{calibration}: the family's views"
        );
        let (tw, th) = (w / cols, h / rows);
        let mut quilt = autostereo::image_io::RgbImage::new(w, h);
        quilt.data.fill(255);
        for v in 0..cols * rows {
            let (x0, y0) = ((v % cols) * tw, h - (v / cols + 1) * th);
            for y in y0..y0 + th {
                let row = (y as usize * w as usize + x0 as usize) * 3;
                quilt.data[row..row + tw as usize * 3].fill((5 * v + 2) as u8);
            }
        }
        let path = out(name);
        quilt.save_png(&path).unwrap();
        for origin in [[0, 0], [1792, 1008], [3584, 2016]] {
            let spatial = out(&format!("{name}_{}_{}.png", origin[0], origin[1]));
            let at = format!("{},{}", origin[0], origin[1]);
            let (ok, _, stderr) = run(&[
                "interleave",
                path.to_str().unwrap(),
                "--display",
                &spec,
                "--origin",
                &at,
                "--size",
                "256x144",
                "--out",
                spatial.to_str().unwrap(),
            ]);
            assert!(ok, "{stderr}");
            let image = autostereo::image_io::RgbImage::load_png(&spatial).unwrap();
            let mask = display.clone().with_origin(origin).mask();
            let (mut right, mut remainder) = (0usize, 0usize);
            for y in 0..144 {
                for x in 0..256 {
                    for c in 0..3 {
                        let got = image.get(x, y, c);
                        right += usize::from(got == (5 * mask.view(x, y, c) + 2) as u8);
                        remainder += usize::from(got == 255);
                    }
                }
            }
            let share = right as f64 / (256.0 * 144.0 * 3.0);
            println!(
                "{name} at {at}: {:.4} % of subpixels show their view",
                100.0 * share
            );
            assert!(share >= 0.999, "{name} at {at}: {share}");
            assert_eq!(remainder, 0, "{name} at {at}: the remainder was read");
        }
    }
}
