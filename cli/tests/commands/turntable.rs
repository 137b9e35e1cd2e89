//! `--turntable`: numbered frames of one turn, in any output format. The oracle is geometry:
//! a scene of two boxes of different sizes side by side (symmetric in depth about the centre)
//! turned by half a turn around the vertical axis is its mirror image, and a quarter turn puts
//! the boxes one behind the other (the silhouette narrows to the larger box).

use crate::common;

use std::path::PathBuf;

use autostereo::image_io::RgbImage;
use autostereo::render::quilt::QuiltLayout;

const W: u32 = 96;
const H: u32 = 64;

use crate::common::out;

/// An axis-aligned box as OBJ text, its vertices numbered from `first`.
fn cuboid(min: [f32; 3], max: [f32; 3], first: u32) -> String {
    let mut s = String::new();
    for i in 0..8 {
        let c = |axis: usize| {
            if i >> axis & 1 == 1 {
                max[axis]
            } else {
                min[axis]
            }
        };
        s += &format!("v {} {} {}\n", c(0), c(1), c(2));
    }
    // Each face as two triangles, corners by bit pattern (x = bit 0, y = bit 1, z = bit 2).
    for [a, b, c, d] in [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ] {
        let v = |k: u32| k + first;
        s += &format!(
            "f {} {} {}\nf {} {} {}\n",
            v(a),
            v(b),
            v(c),
            v(a),
            v(c),
            v(d)
        );
    }
    s
}

/// A large box left of the centre and a small one right of it, both centred in depth.
fn two_boxes() -> PathBuf {
    let path = out("turntable_boxes.obj");
    let obj = cuboid([-2.0, -1.0, -1.0], [0.0, 1.0, 1.0], 1)
        + &cuboid([1.0, -0.4, -0.4], [2.0, 0.4, 0.4], 9);
    std::fs::write(&path, obj).unwrap();
    path
}

/// Which pixels are not background.
fn silhouette(img: &RgbImage) -> Vec<bool> {
    img.data
        .chunks(3)
        .map(|p| p.iter().any(|&c| c > 8))
        .collect()
}

fn load(path: &std::path::Path) -> RgbImage {
    RgbImage::load_png(path).unwrap_or_else(|e| panic!("{path:?}: {e}"))
}

/// Share of pixels where two silhouettes differ, `b` read mirrored left-right when `mirror`.
fn mismatch(a: &[bool], b: &[bool], mirror: bool) -> f64 {
    let at = |x: u32, y: u32| {
        let x = if mirror { W - 1 - x } else { x };
        b[(y * W + x) as usize]
    };
    let off = (0..H)
        .flat_map(|y| (0..W).map(move |x| (x, y)))
        .filter(|&(x, y)| a[(y * W + x) as usize] != at(x, y))
        .count();
    off as f64 / f64::from(W * H)
}

#[test]
fn a_half_turn_mirrors_the_scene_and_frame_0_is_the_plain_render() {
    let obj = two_boxes();
    let size = format!("{W}x{H}");
    // Separation 0: every view is the centre camera, on the turntable's axis.
    let base = [
        "mesh",
        obj.to_str().unwrap(),
        "--size",
        &size,
        "--display",
        "view:8,3",
        "--separation",
        "0",
    ];
    let run = |name: &str, extra: &[&str]| {
        let path = out(name);
        let mut args = base.to_vec();
        args.extend_from_slice(&["--out", path.to_str().unwrap()]);
        args.extend_from_slice(extra);
        let (ok, err) = common::cli(&args);
        assert!(ok, "{args:?}: {err}");
    };
    run("turntable_plain.png", &[]);
    run("turntable.png", &["--turntable", "4"]);
    let plain = load(&out("turntable_plain.png"));
    let frames: Vec<RgbImage> = (0..4)
        .map(|k| load(&out(&format!("turntable_{k:04}.png"))))
        .collect();
    assert!(
        !out("turntable_0004.png").exists() && !out("turntable.png").exists(),
        "only the numbered frames are written"
    );
    assert_eq!(frames[0].data, plain.data, "frame 0 is the scene unturned");
    let [s0, s1, s2, s3] = [0, 1, 2, 3].map(|k| silhouette(&frames[k]));
    let lit = s0.iter().filter(|&&p| p).count();
    assert!(lit > (W * H / 10) as usize, "the boxes fill the frame");
    // Half a turn: the mirror image (small box now on the left), and not the same image.
    assert!(
        mismatch(&s0, &s2, true) < 0.01,
        "{}",
        mismatch(&s0, &s2, true)
    );
    assert!(
        mismatch(&s0, &s2, false) > 0.05,
        "the half turn changed nothing"
    );
    // A quarter turn (counter-clockwise seen from above, right-handed about +y) brings the
    // large box to the front, the small one hidden behind it: narrower than side by side, and
    // centred (the axis is through the scene's centre). Three quarters put the small box in
    // front of the large one, now farther away: a smaller silhouette.
    let wide = |s: &[bool]| {
        (0..W)
            .filter(|&x| (0..H).any(|y| s[(y * W + x) as usize]))
            .count()
    };
    assert!(
        wide(&s1) * 10 < wide(&s0) * 9,
        "{} vs {}",
        wide(&s1),
        wide(&s0)
    );
    assert!(
        mismatch(&s1, &s1, true) < 0.01,
        "{}",
        mismatch(&s1, &s1, true)
    );
    let area = |s: &[bool]| s.iter().filter(|&&p| p).count();
    assert!(
        area(&s1) * 10 > area(&s3) * 12,
        "{} vs {}",
        area(&s1),
        area(&s3)
    );
}

#[test]
fn turntables_write_any_output_format_and_report_frame_times() {
    let path = out("turntable_quilt.png");
    let args = [
        "points",
        "--size",
        "48x32",
        "--turntable",
        "3",
        "--axis",
        "x",
        "--output",
        "quilt",
        "--json",
        "--out",
        path.to_str().unwrap(),
    ];
    let output = std::process::Command::new(env!("CARGO_BIN_EXE_autostereo"))
        .args(args)
        .output()
        .unwrap();
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let report: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(report["turntable_frames"], 3, "{report}");
    for key in ["min", "median", "max"] {
        let ms = report[format!("turntable_frame_ms_{key}")]
            .as_f64()
            .unwrap();
        assert!(ms > 0.0, "{key}: {report}");
    }
    let layout = QuiltLayout::for_views(8, [48, 32]);
    for k in 0..3 {
        let quilt = autostereo::render::quilt_image::QuiltImage::of_tiles(layout)
            .file_name(&out(&format!("turntable_quilt_{k:04}.png")));
        let image = load(&quilt);
        assert_eq!([image.width, image.height], layout.size(), "{quilt:?}");
    }
}

#[test]
fn turntable_flags_out_of_range_are_refused() {
    for (args, expect) in [
        (&["mesh", "--turntable", "4"][..], "--out"),
        (
            &["mesh", "--turntable", "0", "--out", "x.png"][..],
            "--turntable",
        ),
        (
            &["mesh", "--axis", "y", "--out", "x.png"][..],
            "--turntable",
        ),
        (
            &["mesh", "--turntable", "4", "--axis", "w", "--out", "x.png"][..],
            "w",
        ),
    ] {
        let (ok, err) = common::cli(args);
        assert!(!ok && err.contains(expect), "{args:?}: {err}");
    }
}
