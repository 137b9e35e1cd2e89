//! `autostereo interleave`: a quilt of views made elsewhere → any display's spatial image.
//! Oracles: the CPU mask (each subpixel = its view's tile) and the N-pass's own spatial image
//! from the same views; bad quilts refused by name.

use std::path::Path;
use std::process::Command;

use autostereo::display::Display;
use autostereo::image_io::RgbImage;
use autostereo::render::quilt::QuiltLayout;
use autostereo::render::quilt_image::QuiltImage;

fn run(args: &[&str]) -> (bool, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_autostereo"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

use crate::common::out;

/// `views` as a quilt of `layout`.
fn quilt_of(views: &[RgbImage], layout: &QuiltLayout) -> RgbImage {
    let size = layout.size();
    let mut quilt = RgbImage::new(size[0], size[1]);
    for (v, view) in views.iter().enumerate() {
        let [x0, y0] = layout.tile_origin(v as u32);
        for y in 0..view.height {
            for x in 0..view.width {
                for c in 0..3 {
                    quilt.set(x0 + x, y0 + y, c, view.get(x, y, c));
                }
            }
        }
    }
    quilt
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// Tile v is a pattern that encodes v in every channel: every subpixel of the interleaved
/// image must hold its own view's tile, on every kind of display (a Looking Glass calibration
/// included).
#[test]
fn every_subpixel_shows_the_tile_of_its_view() {
    let lkg = format!(
        "lkg:{}/../data/lkg_sample_visual.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let cases: &[(&str, &[&str], [u32; 2])] = &[
        ("lenticular:8", &[], [40, 30]),
        ("hubner8", &[], [48, 32]),
        ("slanted:45,7.5,1/6,0.2", &[], [60, 40]),
        // The panel is the default size of a calibration's output: this checks the tiles' size.
        (&lkg, &["--views", "48", "--size", "64x48"], [64, 48]),
    ];
    for (i, &(spec, extra, size)) in cases.iter().enumerate() {
        let mut display = Display::parse(spec).unwrap();
        if let Some(n) = extra.get(1) {
            display = display.with_views(n.parse().unwrap()).unwrap();
        }
        let n = display.views();
        let views: Vec<RgbImage> = (0..n)
            .map(|v| {
                let mut image = RgbImage::new(size[0], size[1]);
                for y in 0..size[1] {
                    for x in 0..size[0] {
                        image.set(x, y, 0, (v * 5) as u8);
                        image.set(x, y, 1, (x * 3 + v) as u8);
                        image.set(x, y, 2, (y * 3 + 2 * v) as u8);
                    }
                }
                image
            })
            .collect();
        let layout = QuiltLayout::for_views(n, size);
        let path =
            QuiltImage::of_tiles(layout).file_name(&out(&format!("interleave_views_{i}.png")));
        quilt_of(&views, &layout).save_png(&path).unwrap();
        let spatial = out(&format!("interleave_spatial_{i}.png"));
        let mut args = vec![
            "interleave",
            s(&path),
            "--display",
            spec,
            "--out",
            s(&spatial),
        ];
        args.extend_from_slice(extra);
        let (ok, err) = run(&args);
        assert!(ok, "{spec}: {err}");
        let image = RgbImage::load_png(&spatial).unwrap();
        let mask = display.mask();
        for y in 0..size[1] {
            for x in 0..size[0] {
                for c in 0..3 {
                    let v = mask.view(x, y, c) as usize;
                    assert_eq!(
                        image.get(x, y, c),
                        views[v].get(x, y, c),
                        "{spec} ({x},{y},{c})"
                    );
                }
            }
        }
    }
}

/// The N-pass's per-view images as a quilt, interleaved, are the N-pass's spatial image.
#[test]
fn a_quilt_of_the_npass_views_interleaves_to_the_npass_image() {
    for (i, spec) in ["hubner8", "lenticular:8", "slanted:5,4.5,1/4,0.3"]
        .iter()
        .enumerate()
    {
        let dir = out(&format!("interleave_npass_views_{i}"));
        std::fs::create_dir_all(&dir).unwrap();
        let spatial = out(&format!("interleave_npass_{i}.png"));
        let volume = |more: &[&str]| {
            let mut args = vec![
                "volume",
                "--builtin-size",
                "32",
                "--size",
                "48x40",
                "--method",
                "n-pass",
                "--display",
                spec,
            ];
            args.extend_from_slice(more);
            let (ok, err) = run(&args);
            assert!(ok, "{err}");
        };
        volume(&["--out", s(&spatial)]);
        volume(&["--output", "views", "--out", s(&dir.join("view.png"))]);
        let mut views = Vec::new();
        for entry in std::fs::read_dir(&dir).unwrap() {
            views.push(entry.unwrap().path());
        }
        views.sort();
        let views: Vec<RgbImage> = views
            .iter()
            .map(|p| RgbImage::load_png(p).unwrap())
            .collect();
        let n = Display::parse(spec).unwrap().views();
        assert_eq!(views.len() as u32, n, "{spec}");
        let layout = QuiltLayout::for_views(n, [48, 40]);
        let quilt = QuiltImage::of_tiles(layout)
            .file_name(&out(&format!("interleave_npass_quilt_{i}.png")));
        quilt_of(&views, &layout).save_png(&quilt).unwrap();
        let again = out(&format!("interleave_npass_again_{i}.png"));
        let (ok, err) = run(&[
            "interleave",
            s(&quilt),
            "--display",
            spec,
            "--out",
            s(&again),
        ]);
        assert!(ok, "{err}");
        assert_eq!(
            RgbImage::load_png(&again).unwrap(),
            RgbImage::load_png(&spatial).unwrap(),
            "{spec}"
        );
    }
}

#[test]
fn quilts_that_do_not_fit_are_refused_by_name() {
    let spatial = out("interleave_refused.png");
    let o = s(&spatial);
    let write = |name: &str, w: u32, h: u32| {
        let path = out(name);
        RgbImage::new(w, h).save_png(&path).unwrap();
        path
    };
    let plain = write("interleave_plain.png", 64, 32);
    let (ok, err) = run(&["interleave", s(&plain), "--out", o]);
    assert!(
        !ok && err.contains("no grid") && err.contains("--quilt"),
        "{err}"
    );
    // The grid from a flag: 4x2 tiles of 16x16 hold hubner8's 8 views.
    let (ok, err) = run(&["interleave", s(&plain), "--quilt", "4x2", "--out", o]);
    assert!(ok, "{err}");
    // Looking Glass's rule: whole-pixel tiles of floor(64/3) x floor(32/3), the remainder
    // ignored; a grid of more tiles than pixels is refused.
    let (ok, err) = run(&["interleave", s(&plain), "--quilt", "3x3", "--out", o]);
    assert!(ok, "{err}");
    let (ok, err) = run(&["interleave", s(&plain), "--quilt", "100x2", "--out", o]);
    assert!(!ok && err.contains("too small for a 100x2 grid"), "{err}");
    let few = write("interleave_few_qs2x2a2.png", 64, 32);
    let (ok, err) = run(&["interleave", s(&few), "--out", o]);
    assert!(!ok && err.contains("cannot hold 8 views"), "{err}");
    // A name's aspect is the views' as shown, whatever the tiles' own (16x16 here).
    let skew = write("interleave_skew_qs4x2a0.75.png", 64, 32);
    let (ok, err) = run(&["interleave", s(&skew), "--json", "--out", o]);
    assert!(ok, "{err}");
    let (ok, err) = run(&["interleave", "/nonexistent_qs4x2a1.png", "--out", o]);
    assert!(!ok && err.contains("/nonexistent_qs4x2a1.png"), "{err}");
}
