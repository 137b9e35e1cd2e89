//! A volume's values in its own units on the command line: the summary and `--json` say the
//! range; `--window WIDTH,LEVEL` is the same window as a `--tf` of normalised points and as a
//! `--tf` file whose points are in the scan's units (a `units` line first).

use super::*;

/// A 24³ NRRD of floats: −3024 outside a sphere's field of view, −1000 air, 40 tissue, 1000
/// bone shell (a CT's values; NRRD carries no units, so they are the file's own). Written once
/// for every test here: they run in parallel, and one rewriting the file while another's CLI
/// reads it gave that CLI an empty file.
fn ct_nrrd() -> PathBuf {
    static FILE: std::sync::OnceLock<PathBuf> = std::sync::OnceLock::new();
    FILE.get_or_init(write_ct_nrrd).clone()
}

fn write_ct_nrrd() -> PathBuf {
    let n = 24usize;
    let mut bytes = format!(
        "NRRD0004\ntype: float\ndimension: 3\nsizes: {n} {n} {n}\nendian: little\nencoding: raw\n\n"
    )
    .into_bytes();
    for i in 0..n * n * n {
        let c = |v: usize| v as f32 + 0.5 - n as f32 / 2.0;
        let (x, y, z) = (c(i % n), c(i / n % n), c(i / (n * n)));
        let r = (x * x + y * y + z * z).sqrt();
        let hu: f32 = match () {
            _ if (x * x + y * y).sqrt() > 11.5 => -3024.0,
            _ if r < 6.0 => 40.0,
            _ if r < 8.0 => 1000.0,
            _ => -1000.0,
        };
        bytes.extend_from_slice(&hu.to_le_bytes());
    }
    write("ct.nrrd", &bytes)
}

fn render(file: &Path, flags: &[&str], name: &str) -> (RgbImage, serde_json::Value) {
    let png = out(name);
    let mut args = vec![
        "volume",
        s(file),
        "--size",
        "64x48",
        "--json",
        "--out",
        s(&png),
    ];
    args.extend_from_slice(flags);
    let (ok, stdout, stderr) = common::cli_out(&args);
    assert!(ok, "{args:?}: {stderr}");
    let json = serde_json::from_str(&stdout).unwrap();
    (RgbImage::load_png(&png).unwrap(), json)
}

#[test]
fn a_window_in_the_scans_units_is_that_window_as_a_transfer_function() {
    let file = ct_nrrd();
    let (windowed, json) = render(&file, &["--window", "400,40"], "window.png");
    assert_eq!(
        json["values"]["range"],
        serde_json::json!([-3024.0, 1000.0]),
        "{json}"
    );
    assert_eq!(json["values"]["units"], "File");
    let norm = |v: f64| (v + 3024.0) / 4024.0;
    let tf = write(
        "window_tf.txt",
        format!("{} 0 0 0 0\n{} 1 1 1 1\n", norm(-160.0), norm(240.0)).as_bytes(),
    );
    let (normalised, _) = render(&file, &["--tf", s(&tf)], "window_tf.png");
    let units = write("window_units.txt", b"units\n-160 0 0 0 0\n240 1 1 1 1\n");
    let (in_units, _) = render(&file, &["--tf", s(&units)], "window_units.png");
    let diff = compare(&windowed, &normalised).unwrap();
    assert!(
        diff.max_abs_err <= 1,
        "--window vs the normalised --tf: {diff:?}"
    );
    assert_eq!(
        windowed.data, in_units.data,
        "--window vs the --tf in units"
    );
    let lit = windowed
        .data
        .chunks(3)
        .filter(|p| p != &&windowed.data[..3])
        .count();
    assert!(lit > 200, "the window shows the sphere ({lit} pixels)");
    // The summary says the range.
    let png = out("window_summary.png");
    let (ok, _, stderr) =
        common::cli_out(&["volume", s(&file), "--size", "32x24", "--out", s(&png)]);
    assert!(ok && stderr.contains("values -3024…1000"), "{stderr}");
    // A file without a window of its own, and a window of no width, are refused by flag.
    let (ok, _, stderr) = common::cli_out(&["volume", s(&file), "--window", "--out", s(&png)]);
    assert!(
        !ok && stderr.contains("--window") && stderr.contains("no window of its own"),
        "{stderr}"
    );
    let (ok, _, stderr) =
        common::cli_out(&["volume", s(&file), "--window", "0,40", "--out", s(&png)]);
    assert!(!ok && stderr.contains("--window"), "{stderr}");
}

/// `--projection iso --iso VALUE` takes the value in the scan's units, checked against its range.
#[test]
fn an_isosurface_value_is_in_the_scans_units() {
    let file = ct_nrrd();
    let png = out("iso.png");
    let run = |flags: &[&str]| {
        let mut args = vec!["volume", s(&file), "--size", "48x32", "--out", s(&png)];
        args.extend_from_slice(flags);
        common::cli_out(&args)
    };
    let (ok, _, stderr) = run(&["--projection", "iso", "--iso", "300"]);
    assert!(ok, "{stderr}");
    let image = RgbImage::load_png(&png).unwrap();
    let lit = image
        .data
        .chunks(3)
        .filter(|p| p != &&image.data[..3])
        .count();
    assert!(
        lit > 100,
        "the bone shell at 300 HU is drawn ({lit} pixels)"
    );
    let (ok, _, stderr) = run(&["--projection", "iso"]);
    assert!(
        !ok && stderr.contains("needs --iso VALUE") && stderr.contains("-3024…1000"),
        "{stderr}"
    );
    let (ok, _, stderr) = run(&["--projection", "iso", "--iso", "5000"]);
    assert!(
        !ok && stderr.contains("--iso 5000: outside the scan's values"),
        "{stderr}"
    );
    let (ok, _, stderr) = run(&["--iso", "40"]);
    assert!(
        !ok && stderr.contains("--iso sets the surface of --projection iso"),
        "{stderr}"
    );
}

/// `--crop` keeps a box of voxels (or of millimetres): the volume rendered is that box.
#[test]
fn a_crop_box_keeps_its_voxels() {
    let file = ct_nrrd();
    let (_, json) = render(&file, &["--crop", "0,0,12,23,23,23"], "crop.png");
    assert_eq!(
        json["volume_dims"],
        serde_json::json!([24, 24, 12]),
        "{json}"
    );
    let (_, json) = render(&file, &["--crop", "2,2,2,10,10,10mm"], "crop_mm.png");
    assert_eq!(json["volume_dims"], serde_json::json!([8, 8, 8]), "{json}");
    let png = out("crop_bad.png");
    let (ok, _, stderr) = common::cli_out(&[
        "volume",
        s(&file),
        "--crop",
        "0,0,0,30,5,5",
        "--out",
        s(&png),
    ]);
    assert!(
        !ok && stderr.contains("--crop") && stderr.contains("[24, 24, 24]"),
        "{stderr}"
    );
}

/// `--fit visible` (the default) frames the voxels the classification shows: the CT's sphere of
/// tissue and bone inside its padded box fills more of the image than `--fit box` frames it,
/// and `--json` says the box framed; a `--clip` half moves that box.
#[test]
fn a_volume_is_framed_on_what_its_classification_shows() {
    let file = ct_nrrd();
    let lit_width = |image: &RgbImage| {
        let cols: Vec<u32> = (0..image.width)
            .filter(|&x| (0..image.height).any(|y| (0..3).any(|c| image.get(x, y, c) > 20)))
            .collect();
        cols.last().unwrap() - cols.first().unwrap() + 1
    };
    let (visible, json) = render(&file, &["--window", "400,40"], "fit_visible.png");
    let (whole, box_json) = render(
        &file,
        &["--window", "400,40", "--fit", "box"],
        "fit_box.png",
    );
    assert_eq!(json["framed"]["fit"], "visible", "{json}");
    assert_eq!(
        box_json["framed"]["max"],
        serde_json::json!([12.0, 12.0, 12.0])
    );
    // The sphere of radius 8 voxels, grown by one voxel: about ±9 of the box's ±12.
    let max = json["framed"]["max"][0].as_f64().unwrap();
    assert!((8.0..=10.0).contains(&max), "{json}");
    let (a, b) = (lit_width(&visible), lit_width(&whole));
    assert!(
        a as f64 >= 1.2 * b as f64,
        "visible {a} px wide against the box's {b}"
    );
    let (_, half) = render(
        &file,
        &["--window", "400,40", "--clip", "x<12"],
        "fit_clip.png",
    );
    let framed_max = half["framed"]["max"][0].as_f64().unwrap();
    assert!(
        framed_max <= 1.0,
        "the kept half x < 12 voxels ends at the centre: {half}"
    );
    assert_eq!(half["framed"]["clip_planes"], 1);
}
