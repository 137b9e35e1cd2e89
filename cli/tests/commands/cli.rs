//! The CLI contract: the main mesh job, `--json` fields, `--compare`, `mask`, `views`.

use crate::common;

use std::process::Command;

use autostereo::mesh::Visibility;

/// Run the CLI: (success, stdout, stderr).
fn run_any(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_autostereo"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.success(),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn run(args: &[&str]) -> String {
    let (ok, stdout, stderr) = run_any(args);
    assert!(ok, "{args:?} failed: {stderr}");
    stdout
}

use crate::common::out as out_path;

#[test]
fn mesh_json_reports_the_contract_fields_and_compares_with_npass() {
    let png = out_path("cli_mesh.png");
    let stdout = run(&[
        "mesh",
        "--size",
        "96x64",
        "--frames",
        "2",
        "--json",
        "--compare",
        "--out",
        png.to_str().unwrap(),
    ]);
    let json: serde_json::Value = serde_json::from_str(stdout.trim()).unwrap();
    // The default, auto, chooses an exact method; --compare measures it (the N-pass: itself).
    assert_eq!(json["auto"]["chosen"], json["method"], "{json}");
    assert_eq!(json["auto"]["accuracy"], "exact", "{json}");
    assert!(["single-pass", "n-pass"].contains(&json["method"].as_str().unwrap()));
    assert_eq!(json["views"], 8);
    assert_eq!(json["size"], serde_json::json!([96, 64]));
    assert!(json["adapter"].as_str().unwrap().len() > 3);
    assert!(json["ms"].as_f64().unwrap() > 0.0);
    assert!(json["frac_off_2"].as_f64().unwrap() <= 0.001, "{json}");
    assert!(json["psnr_db"].as_f64().unwrap() > 40.0, "{json}");
    let image = image::open(&png).unwrap();
    assert_eq!((image.width(), image.height()), (96, 64));
}

/// Every method and visibility mode runs through the CLI, reports what it ran, and (on this
/// K = 1 display, where even the paper's one depth per pixel is exact) matches N-pass; the
/// single view differs from it (parallax), which shows `--compare` compares.
#[test]
fn every_method_and_visibility_runs_and_matches_npass() {
    // The CLI picks the adapter the tests do (same environment).
    let (features, adapter, best) = {
        let ctx = common::gpu();
        let best = Visibility::best_exact(&ctx.device).name();
        (ctx.device.features(), ctx.info().name.clone(), best)
    };
    let atomics = Visibility::Compute.required_features();
    // Not the n-pass: it is the oracle, and --compare refuses comparing it with itself
    // (cli/tests/vocabulary.rs).
    for (args, method, visibility) in [
        (vec!["--visibility", "exact"], "single-pass", Some("exact")),
        (
            vec!["--visibility", "atomic"],
            "single-pass",
            Some("atomic"),
        ),
        (
            vec!["--visibility", "compute"],
            "single-pass",
            Some("compute"),
        ),
        (vec!["--visibility", "fast"], "single-pass", Some("fast")),
        (vec!["--bounds", "paper"], "single-pass", Some(best)),
        (vec!["--method", "single-view"], "single-view", None),
    ] {
        let mut all = vec![
            "mesh",
            "--size",
            "48x40",
            "--json",
            "--compare",
            "--display",
            "lenticular:4",
        ];
        all.extend(&args);
        let needs_atomics = matches!(visibility, Some("atomic" | "compute"));
        if needs_atomics && !features.contains(atomics) {
            let (ok, _, stderr) = run_any(&all);
            assert!(!ok && !stderr.contains("panicked"), "{args:?}: {stderr}");
            for expected in [adapter.as_str(), "64-bit atomic", "--visibility exact"] {
                assert!(stderr.contains(expected), "{args:?}: {stderr}");
            }
            continue;
        }
        let json: serde_json::Value = serde_json::from_str(run(&all).trim()).unwrap();
        assert_eq!(json["method"], method, "{args:?}: {json}");
        assert_eq!(json["visibility"].as_str(), visibility, "{args:?}: {json}");
        let off = json["frac_off_2"].as_f64().unwrap();
        if method == "single-view" {
            assert!(off > 0.001, "{args:?}: single view equals N-pass? {json}");
        } else {
            assert!(off <= 1e-4, "{args:?}: {json}");
        }
    }
}

#[test]
fn mask_cpu_and_gpu_images_agree_and_views_extracts() {
    let cpu = out_path("cli_mask_cpu.png");
    let gpu = out_path("cli_mask_gpu.png");
    for (path, extra) in [(&cpu, None), (&gpu, Some("--gpu"))] {
        let mut args = vec![
            "mask",
            "--display",
            "slanted:5,4.5,-1/3,0.7",
            "--size",
            "64x48",
            "--origin",
            "3,4",
        ];
        args.extend(extra);
        args.extend(["--out", path.to_str().unwrap()]);
        run(&args);
    }
    let (a, b) = (
        image::open(&cpu).unwrap().to_rgb8(),
        image::open(&gpu).unwrap().to_rgb8(),
    );
    assert_eq!(a, b);
    assert!(a.pixels().all(|p| p.0.iter().all(|&v| v < 5)));
    let spatial = out_path("cli_spatial.png");
    run(&[
        "mesh",
        "--size",
        "64x48",
        "--out",
        spatial.to_str().unwrap(),
    ]);
    // --eyes names a pair as in every command; --anaglyph is its old name, still accepted.
    for extra in [["--view", "3"], ["--eyes", "2,5"], ["--anaglyph", "2,5"]] {
        let out = out_path("cli_view.png");
        let mut args = vec!["views", spatial.to_str().unwrap(), "--display", "hubner8"];
        args.extend(extra);
        args.extend(["--out", out.to_str().unwrap()]);
        run(&args);
        assert_eq!(image::open(&out).unwrap().width(), 64);
    }
}

#[test]
fn volume_main_job_writes_spatial_views_and_anaglyph() {
    let spatial = out_path("cli_volume.png");
    let anaglyph = out_path("cli_volume_anaglyph.png");
    let views = out_path("cli_volume_views");
    std::fs::create_dir_all(&views).unwrap();
    let volume = |output: &str, out: &std::path::Path| {
        let stdout = run(&[
            "volume",
            "--builtin-size",
            "24",
            "--size",
            "64x48",
            "--rotate",
            "20,30,0",
            "--json",
            "--compare",
            "--output",
            output,
            "--out",
            out.to_str().unwrap(),
        ]);
        serde_json::from_str::<serde_json::Value>(stdout.trim()).unwrap()
    };
    let json = volume("spatial", &spatial);
    assert_eq!(json["method"], "single-pass");
    assert_eq!(json["volume_dims"], serde_json::json!([24, 24, 19]));
    assert!(json["psnr_db"].as_f64().unwrap() >= 45.0, "{json}");
    assert_eq!(json["written"], serde_json::json!([spatial]));
    let json = volume("anaglyph", &anaglyph);
    assert_eq!(json["written"], serde_json::json!([anaglyph]));
    let json = volume("views", &views.join("view.png"));
    // Every view, named in view order with two digits (what --views-out DIR wrote).
    let names: Vec<std::path::PathBuf> = (0..8)
        .map(|v| views.join(format!("view_{v:02}.png")))
        .collect();
    assert_eq!(json["written"], serde_json::json!(names));
    for path in [&spatial, &anaglyph, &names[0], &names[7]] {
        assert_eq!(image::open(path).unwrap().width(), 64, "{}", path.display());
    }
    let slices = run(&[
        "volume",
        "--builtin",
        "ml",
        "--builtin-size",
        "16",
        "--size",
        "48x40",
        "--path",
        "slices",
        "--alpha",
        "paper",
        "--json",
    ]);
    let json: serde_json::Value = serde_json::from_str(slices.trim()).unwrap();
    assert_eq!(
        (json["path"].as_str(), json["alpha"].as_str()),
        (Some("slices"), Some("paper"))
    );
}

#[test]
fn points_json_reports_preprocessing_memory_and_compares_with_npass() {
    let ply = out_path("cli_points.ply");
    // A binary little-endian PLY of a sphere without normals or radii: both get estimated.
    let n = 3000;
    let mut bytes = format!("ply\nformat binary_little_endian 1.0\nelement vertex {n}\nproperty float x\nproperty float y\nproperty float z\nend_header\n").into_bytes();
    let cloud = autostereo::points::PointCloud::sphere(n, glam::Vec3::ZERO, 1.0, None);
    for p in &cloud.positions {
        for v in p.to_array() {
            bytes.extend(v.to_le_bytes());
        }
    }
    std::fs::write(&ply, bytes).unwrap();
    for depth in ["exact", "paper"] {
        let stdout = run(&[
            "points",
            ply.to_str().unwrap(),
            "--size",
            "96x64",
            "--frames",
            "1",
            "--depth",
            depth,
            "--json",
            "--compare",
        ]);
        let json: serde_json::Value = serde_json::from_str(stdout.trim()).unwrap();
        assert_eq!(json["points"], n);
        assert_eq!(json["normals_estimated"], true);
        assert_eq!(json["radii_estimated"], true);
        assert_eq!(json["depth"], depth);
        assert!(json["groups"].as_u64().unwrap() >= 2, "{json}");
        assert!(json["gpu_bytes"].as_u64().unwrap() > 0);
        let psnr = json["psnr_db"].as_f64().unwrap();
        assert!(
            if depth == "exact" {
                psnr >= 45.0
            } else {
                psnr >= 20.0
            },
            "{json}"
        );
    }
    for method in ["n-pass", "single-view"] {
        run(&[
            "points", "--size", "64x48", "--frames", "1", "--method", method, "--groups", "3",
        ]);
    }
}

/// `rgbd`: a colour + 16-bit depth pair and the same as one side-by-side file give the same
/// spatial image; the quilt holds every view under the Looking Glass name; a flat picture at
/// the focus is the picture; mismatched or malformed inputs are refused by name.
#[test]
fn rgbd_pairs_side_by_side_quilts_and_bad_maps() {
    let (w, h) = (48u32, 32u32);
    let mut color = image::RgbImage::new(w, h);
    let mut depth = image::ImageBuffer::<image::Luma<u16>, Vec<u16>>::new(w, h);
    let mut sbs = image::RgbImage::new(2 * w, h);
    for y in 0..h {
        for x in 0..w {
            let rgb = image::Rgb([(x * 5) as u8, (y * 7) as u8, 90]);
            let near = if (16..32).contains(&x) {
                60000u16
            } else {
                8000
            };
            color.put_pixel(x, y, rgb);
            depth.put_pixel(x, y, image::Luma([near]));
            sbs.put_pixel(x, y, rgb);
            let grey = (near >> 8) as u8;
            sbs.put_pixel(w + x, y, image::Rgb([grey; 3]));
        }
    }
    let (c, d, s) = (
        out_path("rgbd_color.png"),
        out_path("rgbd_depth.png"),
        out_path("rgbd_sbs.png"),
    );
    color.save(&c).unwrap();
    depth.save(&d).unwrap();
    sbs.save(&s).unwrap();
    let (pair_out, sbs_out) = (out_path("rgbd_pair_out.png"), out_path("rgbd_sbs_out.png"));
    let quilt = out_path("rgbd_quilt.png");
    let (c_s, d_s, s_s) = (
        c.to_str().unwrap(),
        d.to_str().unwrap(),
        s.to_str().unwrap(),
    );
    run(&["rgbd", c_s, d_s, "--out", pair_out.to_str().unwrap()]);
    run(&[
        "rgbd",
        c_s,
        d_s,
        "--output",
        "quilt",
        "--out",
        quilt.to_str().unwrap(),
    ]);
    run(&["rgbd", s_s, "--sbs", "--out", sbs_out.to_str().unwrap()]);
    let a = autostereo::image_io::RgbImage::load_png(&pair_out).unwrap();
    let b = autostereo::image_io::RgbImage::load_png(&sbs_out).unwrap();
    // 8-bit (side by side) and 16-bit depth differ by < 1/256 in nearness: a fraction of a
    // pixel of parallax here.
    let diff = autostereo::image_io::compare(&a, &b).unwrap();
    assert!(diff.frac_off_2 < 0.02, "{diff:?}");
    let named = out_path("rgbd_quilt_qs2x4a1.5.png");
    let q = autostereo::image_io::RgbImage::load_png(&named).unwrap();
    assert_eq!([q.width, q.height], [2 * w, 4 * h]);
    // Flat at the focus: the picture itself.
    let flat = out_path("rgbd_flat_depth.png");
    image::GrayImage::from_pixel(w, h, image::Luma([128]))
        .save(&flat)
        .unwrap();
    let flat_out = out_path("rgbd_flat_out.png");
    run(&[
        "rgbd",
        c_s,
        flat.to_str().unwrap(),
        "--focus",
        &(128.0 / 255.0).to_string(),
        "--display",
        "slanted:45,7.5,1/6,0.2",
        "--out",
        flat_out.to_str().unwrap(),
    ]);
    let picture = autostereo::image_io::RgbImage::load_png(&c).unwrap();
    assert_eq!(
        autostereo::image_io::RgbImage::load_png(&flat_out).unwrap(),
        picture
    );
    // Refusals, each naming what is wrong.
    let small = out_path("rgbd_small_depth.png");
    image::GrayImage::new(w / 2, h).save(&small).unwrap();
    let small_s = small.to_str().unwrap();
    let o = pair_out.to_str().unwrap();
    let (ok, _, err) = run_any(&["rgbd", c_s, small_s, "--out", o]);
    assert!(
        !ok && err.contains("24x32") && err.contains("--depth-resample"),
        "{err}"
    );
    run(&["rgbd", c_s, small_s, "--depth-resample", "--out", o]);
    let (ok, _, err) = run_any(&["rgbd", c_s, "--sbs", d_s, "--out", o]);
    assert!(!ok, "{err}");
    let odd = out_path("rgbd_odd.png");
    image::RgbImage::new(5, 4).save(&odd).unwrap();
    let (ok, _, err) = run_any(&["rgbd", odd.to_str().unwrap(), "--sbs", "--out", o]);
    assert!(!ok && err.contains("even width"), "{err}");
    let holes = out_path("rgbd_holes.png");
    let (ok, _, err) = run_any(&["rgbd", c_s, d_s, "--hole-mask", holes.to_str().unwrap()]);
    assert!(ok && err.contains("% of subpixels filled"), "{err}");
    let (ok, _, err) = run_any(&["rgbd", c_s, d_s]);
    assert!(!ok && err.contains("nothing to write"), "{err}");
    let (ok, _, err) = run_any(&["rgbd", c_s, d_s, "--focus", "2", "--out", o]);
    assert!(!ok && err.contains("focus"), "{err}");
    let (ok, _, err) = run_any(&["rgbd", "/nonexistent.png", d_s, "--out", o]);
    assert!(!ok && err.contains("/nonexistent.png"), "{err}");
}
