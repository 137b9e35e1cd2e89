//! `--output`: every format puts the right view in the right place. The oracle for each view is
//! the ordinary spatial render of that view alone (`--display view:8,V`, a one-view display),
//! made by a separate run; the arrangement (halves, rows, columns, checkerboard, quilt tiles,
//! anaglyph channels) is checked here on the CPU.

use crate::common;

use autostereo::image_io::RgbImage;
use autostereo::render::quilt::QuiltLayout;

const W: u32 = 96;
const H: u32 = 64;
/// The outermost views: the most different pair, so a swapped pair cannot pass.
const EYES: [u32; 2] = [0, 7];

use crate::common::out;

/// Render the built-in mesh scene with `extra` flags and `--out` `name`.
fn run(name: &str, size: [u32; 2], extra: &[&str]) {
    run_command("mesh", name, size, extra);
}

fn run_command(command: &str, name: &str, size: [u32; 2], extra: &[&str]) {
    let path = out(name);
    let size = format!("{}x{}", size[0], size[1]);
    let mut args = vec![command, "--size", &size, "--out", path.to_str().unwrap()];
    args.extend_from_slice(extra);
    let (ok, err) = common::cli(&args);
    assert!(ok, "{args:?}: {err}");
}

/// [`run`], and the image written to `name`.
fn render(name: &str, size: [u32; 2], extra: &[&str]) -> RgbImage {
    run(name, size, extra);
    RgbImage::load_png(&out(name)).unwrap()
}

/// View `v` of the 8 alone, at `size`.
fn view(v: u32, size: [u32; 2]) -> RgbImage {
    let display = format!("view:8,{v}");
    render(
        &format!("outputs_view{v}_{}x{}.png", size[0], size[1]),
        size,
        &["--display", &display],
    )
}

fn pixel(img: &RgbImage, x: u32, y: u32) -> [u8; 3] {
    let i = ((y * img.width + x) * 3) as usize;
    [img.data[i], img.data[i + 1], img.data[i + 2]]
}

/// Share of `expected`'s channels the output misses by more than 2/255, where `at` maps each
/// output pixel to the expected colour.
fn off_share(output: &RgbImage, at: impl Fn(u32, u32) -> [u8; 3]) -> f64 {
    let mut off = 0usize;
    for y in 0..output.height {
        for x in 0..output.width {
            let (got, want) = (pixel(output, x, y), at(x, y));
            off += (0..3).filter(|&c| got[c].abs_diff(want[c]) > 2).count();
        }
    }
    off as f64 / (3 * output.width * output.height) as f64
}

fn stereo(format: &str) -> RgbImage {
    render(
        &format!("outputs_{format}.png"),
        [W, H],
        &["--output", format, "--eyes", "0,7"],
    )
}

#[test]
fn each_stereo_output_has_the_right_view_in_the_right_place() {
    let [l, r] = EYES.map(|v| view(v, [W, H]));
    assert!(
        off_share(&l, |x, y| pixel(&r, x, y)) > 0.01,
        "the eyes must differ"
    );
    type Place<'a> = Box<dyn Fn(u32, u32) -> [u8; 3] + 'a>;
    let cases: [(&str, [u32; 2], Place); 6] = [
        (
            "side-by-side",
            [2 * W, H],
            Box::new(|x, y| {
                if x < W {
                    pixel(&l, x, y)
                } else {
                    pixel(&r, x - W, y)
                }
            }),
        ),
        (
            "top-bottom",
            [W, 2 * H],
            Box::new(|x, y| {
                if y < H {
                    pixel(&l, x, y)
                } else {
                    pixel(&r, x, y - H)
                }
            }),
        ),
        (
            "rows",
            [W, H],
            Box::new(|x, y| pixel(if y % 2 == 0 { &l } else { &r }, x, y)),
        ),
        (
            "columns",
            [W, H],
            Box::new(|x, y| pixel(if x % 2 == 0 { &l } else { &r }, x, y)),
        ),
        (
            "checkerboard",
            [W, H],
            Box::new(|x, y| pixel(if (x + y) % 2 == 0 { &l } else { &r }, x, y)),
        ),
        (
            "anaglyph",
            [W, H],
            Box::new(|x, y| {
                let (a, b) = (pixel(&l, x, y), pixel(&r, x, y));
                [a[0], b[1], b[2]]
            }),
        ),
    ];
    for (format, size, expected) in cases {
        let img = stereo(format);
        assert_eq!([img.width, img.height], size, "{format}");
        let off = off_share(&img, expected);
        assert!(
            off < 0.001,
            "{format}: {:.3} % of channels off",
            100.0 * off
        );
    }
    // The half formats squeeze each eye into half the width (height) with the full frame's
    // camera, as 3D TVs expect: each half is the eye's full-size view at half resolution. Where
    // the two eyes' views (averaged over pixel pairs) differ, each half is nearer its own eye
    // (measured 82 % of those pixels on lavapipe: half-resolution sampling is not a pair's mean;
    // the wrong eye would give < 30 %).
    for (format, axis) in [("side-by-side-half", 0), ("top-bottom-half", 1)] {
        let img = stereo(format);
        assert_eq!([img.width, img.height], [W, H], "{format}");
        let [sl, sr] = [&l, &r].map(|eye| halve(eye, axis));
        for (which, own, other) in [(0, &sl, &sr), (1, &sr, &sl)] {
            let share = nearer_share(&crop(&img, axis, which), own, other);
            assert!(
                share > 0.7,
                "{format} half {which}: nearer its own eye on only {:.1} % of the pixels where the eyes differ",
                100.0 * share
            );
        }
    }
}

/// An image half the size of `img` along `axis` (0 = x), each pixel `f(x, y)`.
fn half_size(img: &RgbImage, axis: usize, f: impl Fn(u32, u32, [u32; 2]) -> [u8; 3]) -> RgbImage {
    let [w, h] = if axis == 0 {
        [img.width / 2, img.height]
    } else {
        [img.width, img.height / 2]
    };
    let mut out = RgbImage::new(w, h);
    for y in 0..h {
        for x in 0..w {
            let i = ((y * w + x) * 3) as usize;
            out.data[i..i + 3].copy_from_slice(&f(x, y, [w, h]));
        }
    }
    out
}

/// Half `which` (0 first) of `img` along `axis`.
fn crop(img: &RgbImage, axis: usize, which: u32) -> RgbImage {
    half_size(img, axis, |x, y, [w, h]| match axis {
        0 => pixel(img, x + which * w, y),
        _ => pixel(img, x, y + which * h),
    })
}

/// `img` at half resolution along `axis`: each pixel the mean of a pair.
fn halve(img: &RgbImage, axis: usize) -> RgbImage {
    half_size(img, axis, |x, y, _| {
        let (a, b) = match axis {
            0 => (pixel(img, 2 * x, y), pixel(img, 2 * x + 1, y)),
            _ => (pixel(img, x, 2 * y), pixel(img, x, 2 * y + 1)),
        };
        [0, 1, 2].map(|c| ((u16::from(a[c]) + u16::from(b[c])) / 2) as u8)
    })
}

/// Of the pixels where `own` and `other` differ clearly, the share where `img` is nearer `own`.
fn nearer_share(img: &RgbImage, own: &RgbImage, other: &RgbImage) -> f64 {
    let dist = |a: [u8; 3], b: [u8; 3]| (0..3).map(|c| u32::from(a[c].abs_diff(b[c]))).sum::<u32>();
    let (mut differ, mut nearer) = (0u32, 0u32);
    for y in 0..img.height {
        for x in 0..img.width {
            let (p, a, b) = (pixel(img, x, y), pixel(own, x, y), pixel(other, x, y));
            if dist(a, b) > 24 {
                differ += 1;
                nearer += u32::from(dist(p, a) < dist(p, b));
            }
        }
    }
    assert!(differ > 20, "the eyes barely differ ({differ} pixels)");
    f64::from(nearer) / f64::from(differ)
}

/// Tile `v` of a quilt of `layout`.
fn quilt_tile(quilt: &RgbImage, layout: &QuiltLayout, v: u32) -> RgbImage {
    let [tx, ty] = layout.tile_origin(v);
    let [w, h] = layout.tile;
    RgbImage {
        width: w,
        height: h,
        data: (0..h)
            .flat_map(|y| {
                let start = (((ty + y) * quilt.width + tx) * 3) as usize;
                quilt.data[start..start + (3 * w) as usize].to_vec()
            })
            .collect(),
    }
}

/// A quilt written with `extra` flags, named by `layout`, of `layout`'s size.
fn quilt(name: &str, layout: &QuiltLayout, extra: &[&str]) -> RgbImage {
    let path = autostereo::render::quilt_image::QuiltImage::of_tiles(*layout).file_name(&out(name));
    let mut args = vec!["--output", "quilt"];
    args.extend_from_slice(extra);
    run(name, layout.tile, &args);
    let quilt = RgbImage::load_png(&path).unwrap();
    assert_eq!([quilt.width, quilt.height], layout.size(), "{path:?}");
    quilt
}

#[test]
fn views_and_quilt_outputs_hold_every_view() {
    let views = out("outputs_all.png");
    run("outputs_all.png", [W, H], &["--output", "views"]);
    let chosen = QuiltLayout::for_views(8, [W, H]);
    let default = quilt("outputs_quilt.png", &chosen, &[]);
    // A grid the user picks (one tile left empty), as Looking Glass quilts often have.
    let picked = QuiltLayout::with_grid(3, 3, [W, H], 8).unwrap();
    let three = quilt("outputs_quilt3.png", &picked, &["--quilt", "3x3"]);
    for v in 0..8 {
        let alone = view(v, [W, H]);
        let file = views.with_file_name(format!("outputs_all_{v:02}.png"));
        let written = RgbImage::load_png(&file).unwrap();
        assert!(
            off_share(&written, |x, y| pixel(&alone, x, y)) < 0.001,
            "view {v}"
        );
        for (quilt, layout) in [(&default, &chosen), (&three, &picked)] {
            let tile = quilt_tile(quilt, layout, v);
            assert!(
                off_share(&tile, |x, y| pixel(&alone, x, y)) < 0.001,
                "quilt {}x{} tile {v}",
                layout.cols,
                layout.rows
            );
        }
    }
    let empty = quilt_tile(&three, &picked, 8);
    assert!(empty.data.iter().all(|&c| c == 0), "the 9th tile is empty");
}

/// Every render command, with methods other than the single pass: the stereo output's eyes are
/// what that command and method render for each view alone.
#[test]
fn every_command_and_method_writes_stereo_outputs() {
    for (command, method, extra) in [
        ("mesh", "n-pass", &[][..]),
        ("mesh", "tiled", &[]),
        ("mesh", "warp", &[]),
        ("points", "single-pass", &[]),
        ("points", "n-pass", &[]),
        ("volume", "single-pass", &["--builtin-size", "32"]),
        ("volume", "n-pass", &["--builtin-size", "32"]),
    ] {
        let load = |name: &str, more: &[&str]| {
            let mut args = vec!["--method", method];
            args.extend_from_slice(extra);
            args.extend_from_slice(more);
            run_command(command, name, [W, H], &args);
            RgbImage::load_png(&out(name)).unwrap()
        };
        let tag = format!("outputs_{command}_{method}");
        let [l, r] = EYES.map(|v| {
            let display = format!("view:8,{v}");
            load(&format!("{tag}_view{v}.png"), &["--display", &display])
        });
        let columns = load(
            &format!("{tag}_columns.png"),
            &["--output", "columns", "--eyes", "0,7"],
        );
        let off = off_share(&columns, |x, y| {
            pixel(if x % 2 == 0 { &l } else { &r }, x, y)
        });
        assert!(off < 0.001, "{command} {method}: {:.3} % off", 100.0 * off);
        assert!(
            off_share(&l, |x, y| pixel(&r, x, y)) > 0.005,
            "{command}: eyes equal"
        );
    }
}

#[test]
fn output_flags_out_of_range_are_refused() {
    for (args, expect) in [
        (&["mesh", "--output", "rows"][..], "--out"),
        (
            &[
                "mesh", "--output", "rows", "--eyes", "3,8", "--out", "x.png",
            ][..],
            "view 8 does not exist",
        ),
        (
            &[
                "mesh", "--output", "quilt", "--quilt", "2x2", "--out", "x.png",
            ][..],
            "a 2x2 grid cannot hold 8 views",
        ),
        (
            &[
                "mesh", "--output", "rows", "--quilt", "3x3", "--out", "x.png",
            ][..],
            "--quilt sets the grid of --output quilt",
        ),
    ] {
        let (ok, err) = common::cli(args);
        assert!(!ok && err.contains(expect), "{args:?}: {err}");
    }
}
