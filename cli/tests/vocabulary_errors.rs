//! Issue 31, errors in the user's terms: each names the flag, the file and the fix in the units
//! the user typed. A frame too wide for a subpixel-resolution mode names `--size` and the
//! widest that works (not the 3× column count); a file's text is quoted escaped and short
//! (never raw bytes on the terminal); no adapter lists the adapters there are and how to pick
//! one; a budget error names `--max-memory` and a figure it takes; the library's names
//! (`Visibility::`, `[2, 2, 2] F32`) never reach the user. Each test fails on the binary before
//! the fix.

mod common;

use std::path::PathBuf;
use std::process::Command;

use common::cli;

fn out(name: &str) -> PathBuf {
    common::out_dir().join(name)
}

/// Write `bytes` as `name` in the tests' output folder.
fn write(name: &str, bytes: &[u8]) -> PathBuf {
    let path = out(name);
    std::fs::write(&path, bytes).unwrap();
    path
}

/// Run the CLI with `env` set (and logging off); (success, stderr).
fn cli_env(args: &[&str], env: &[(&str, &str)]) -> (bool, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_autostereo"))
        .args(args)
        .env("RUST_LOG", "off")
        .envs(env.iter().copied())
        .output()
        .unwrap();
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// The `error: …` lines of `stderr` (wgpu's loaders may print their own lines).
fn error_text(stderr: &str) -> String {
    stderr
        .lines()
        .filter(|l| l.starts_with("error: ") && !l.contains("XDG_RUNTIME_DIR"))
        .collect::<Vec<_>>()
        .join("\n")
}

/// The number after `before` in `text`.
fn number_after(text: &str, before: &str) -> u32 {
    let at = text
        .find(before)
        .unwrap_or_else(|| panic!("no '{before}': {text}"))
        + before.len();
    let digits: String = text[at..]
        .chars()
        .take_while(char::is_ascii_digit)
        .collect();
    digits
        .parse()
        .unwrap_or_else(|_| panic!("no number after '{before}': {text}"))
}

#[test]
fn a_frame_too_wide_for_subpixel_resolution_names_size_and_the_widest_that_works() {
    // Said "image width = 49152 exceeds the adapter limit 16384": the 3× subpixel columns, a
    // width nobody typed. The parallel camera renders the frame whole (no bands).
    let png = out("vocabulary_errors_wide.png");
    let png = png.to_str().unwrap();
    for (command, mode, flags) in [
        ("mesh", "--visibility exact", &["--visibility", "exact"][..]),
        ("points", "--depth exact", &["--depth", "exact"][..]),
    ] {
        let mut args = vec![command, "--size", "16384x16", "--camera", "parallel"];
        args.extend_from_slice(flags);
        args.extend_from_slice(&["--out", png]);
        let (ok, stderr) = cli(&args);
        assert!(
            !ok,
            "{command} 16384 pixels wide at subpixel resolution succeeded"
        );
        let text = error_text(&stderr);
        assert!(
            text.starts_with("error: --size 16384x16: a frame 16384 pixels wide"),
            "{text}"
        );
        assert!(
            text.contains(&format!("too wide for {mode}"))
                && text.contains("subpixel resolution: 3 columns per pixel"),
            "says why: {text}"
        );
        assert!(!text.contains("::"), "library names: {text}");
        assert!(!text.contains("image width ="), "{text}");
        // The fix: the widest --size that renders, and the mode that has no such limit.
        let widest = number_after(&text, &format!("{mode} renders at most "));
        assert!(text.contains("else use --"), "{text}");
        let size = format!("{widest}x16");
        let mut args = vec![command, "--size", &size, "--camera", "parallel"];
        args.extend_from_slice(flags);
        args.extend_from_slice(&["--out", png]);
        let (ok, stderr) = cli(&args);
        assert!(ok, "{command} --size {size}, the advised widest: {stderr}");
    }
}

/// 200 bytes of a binary file: terminal escape sequences, a bell, a carriage return and
/// bytes that are not UTF-8.
fn garbage() -> Vec<u8> {
    let mut bytes = b"\x1b[2J\x1b]0;pwned\x07\r\x01\x02\x7f".to_vec();
    let mut x = 0x2545_f491_u32;
    while bytes.len() < 200 {
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        bytes.push((x >> 24) as u8);
    }
    bytes
}

/// Whether `text` holds a control character other than a line break.
fn has_control(text: &str) -> bool {
    text.chars().any(|c| c.is_control() && c != '\n')
}

#[test]
fn file_text_in_errors_is_escaped_and_short() {
    // A binary file named .nrrd printed its first line raw: the escapes cleared the screen and
    // retitled the terminal.
    let png = out("vocabulary_errors_garbage.png");
    let png = png.to_str().unwrap();
    let g = garbage();
    let line = |head: &str| [head.as_bytes(), &g, b"\n"].concat();
    let long = "x".repeat(5000);
    let cases: Vec<(&str, &str, Vec<u8>, &str)> = vec![
        ("volume", "garbage.nrrd", g.clone(), "not a NRRD file"),
        (
            "volume",
            "type.nrrd",
            line("NRRD0004\ntype: "),
            "unsupported type",
        ),
        ("volume", "object.mhd", line("ObjectType = "), "ObjectType"),
        (
            "volume",
            "third.vtk",
            line("# vtk DataFile Version 3.0\ntitle\n"),
            "third line",
        ),
        ("volume", "garbage.vtk", g.clone(), "not a legacy VTK file"),
        (
            "points",
            "format.ply",
            b"ply\nformat \x1b]0;pwned\x07\x1b[2J 1.0\nend_header\n".to_vec(),
            "unknown format",
        ),
        ("points", "vertex.obj", line("v 1 2 "), "is not a number"),
        (
            "volume",
            "long.nrrd",
            format!("NRRD0004\ntype: {long}\n").into_bytes(),
            "unsupported type",
        ),
    ];
    for (command, name, bytes, says) in cases {
        let path = write(&format!("vocabulary_errors_{name}"), &bytes);
        let (ok, stderr) = cli(&[command, path.to_str().unwrap(), "--out", png]);
        assert!(!ok, "{name} was read");
        assert!(
            !has_control(&stderr),
            "{name}: raw control characters: {stderr:?}"
        );
        let text = error_text(&stderr);
        assert!(text.contains(says) && text.contains(name), "{name}: {text}");
        // The quote is short: the 5000-character line is not echoed whole.
        assert!(
            text.len() < 400,
            "{name}: {} characters: {text}",
            text.len()
        );
        if bytes.starts_with(b"\x1b") || bytes.windows(2).any(|w| w == b" \x1b") {
            assert!(text.contains("\\u{1b}"), "{name}: the escape shown: {text}");
        }
    }
    // A transfer-function file: escaped, and "invalid transfer function" said once.
    let tf = write("vocabulary_errors_tf.txt", &line(""));
    let (ok, stderr) = cli(&[
        "volume",
        "--builtin-size",
        "16",
        "--size",
        "16x16",
        "--tf",
        tf.to_str().unwrap(),
        "--out",
        png,
    ]);
    assert!(!ok);
    assert!(!has_control(&stderr), "{stderr:?}");
    assert_eq!(
        stderr.matches("invalid transfer function").count(),
        1,
        "{stderr}"
    );
}

#[test]
fn no_adapter_lists_the_adapters_there_are_and_how_to_pick_one() {
    // Said "no GPU adapter found (backends: Backends(NOOP | VULKAN | GL | …), name contains
    // 'nvidia')" and advised installing lavapipe, on a machine that has adapters.
    let png = out("vocabulary_errors_adapter.png");
    let png = png.to_str().unwrap();
    let (ok, stderr) = cli_env(
        &["mesh", "--size", "8x8", "--out", png],
        &[("WGPU_ADAPTER_NAME", "no-such-adapter-anywhere")],
    );
    assert!(!ok, "an adapter matched");
    let text = error_text(&stderr);
    assert!(text.contains("no GPU adapter found"), "{text}");
    assert!(
        text.contains("name contains 'no-such-adapter-anywhere'"),
        "{text}"
    );
    assert!(!text.contains("Backends("), "wgpu's debug names: {text}");
    if text.contains("the adapters here: ") {
        // Each adapter by name and backend, and how to pick one.
        assert!(
            text.contains("' (vulkan)") || text.contains("' (gl)"),
            "no adapter listed with its backend: {text}"
        );
        assert!(
            text.contains("WGPU_ADAPTER_NAME=") && text.contains("WGPU_BACKEND="),
            "how to pick one: {text}"
        );
    } else {
        // A machine without any adapter: how to get one.
        assert!(text.contains("no adapter on any backend") && text.contains("apt-get"));
    }
    // A backend name wgpu does not know selected none, silently: "Backends(0x0)".
    let (ok, stderr) = cli_env(
        &["mesh", "--size", "8x8", "--out", png],
        &[("WGPU_BACKEND", "vulcan")],
    );
    assert!(!ok);
    let text = error_text(&stderr);
    assert!(
        text.contains("WGPU_BACKEND='vulcan' names no backend (vulkan, gl"),
        "{text}"
    );
}

/// A PNG of `w`×`h` grey pixels.
fn png(name: &str, w: u32, h: u32) -> PathBuf {
    let path = out(name);
    image::RgbImage::from_pixel(w, h, image::Rgb([128, 128, 128]))
        .save(&path)
        .unwrap();
    path
}

#[test]
fn budget_errors_name_max_memory_and_a_figure_it_takes() {
    // Every command with --max-memory says raise it with --max-memory (never the library's
    // budget::set_max_memory) and to what, in a figure the flag takes.
    let target = out("vocabulary_errors_budget.png");
    let target = target.to_str().unwrap();
    let colour = png("vocabulary_errors_rgbd_colour.png", 16, 16);
    let depth = png("vocabulary_errors_rgbd_depth.png", 16, 16);
    let small = ["--size", "16x16", "--max-memory", "1K", "--out", target];
    let rgbd = [colour.to_str().unwrap(), depth.to_str().unwrap()];
    for command in [
        vec!["mesh"],
        vec!["points"],
        vec!["volume", "--builtin-size", "16"],
        vec!["gaussians"],
        vec!["rgbd", rgbd[0], rgbd[1]],
    ] {
        let mut args = command.clone();
        args.extend_from_slice(&small);
        let (ok, stderr) = cli(&args);
        assert!(!ok, "{command:?} fits 1 KiB?");
        let text = error_text(&stderr);
        assert!(text.contains("memory budget of 1024 bytes"), "{text}");
        assert!(
            !text.contains("set_max_memory") && !text.contains("budget::"),
            "{command:?}: library names: {text}"
        );
        let at = text
            .find("raise it with --max-memory, to at least ")
            .unwrap_or_else(|| panic!("{command:?}: no figure: {text}"));
        let figure: String = text[at..]
            .split("at least ")
            .nth(1)
            .unwrap()
            .chars()
            .take_while(char::is_ascii_alphanumeric)
            .collect();
        let bytes = autostereo::budget::parse_bytes(&figure)
            .unwrap_or_else(|e| panic!("{command:?}: '{figure}' is no --max-memory: {e}"));
        assert!(bytes > 1024, "{command:?}: {figure}");
    }
    // The commands that read an image take the budget too (they had no --max-memory), and the
    // viewer (it loads any file).
    let image = png("vocabulary_errors_budget_in.png", 32, 32);
    let image = image.to_str().unwrap();
    for args in [
        vec![
            "interleave",
            image,
            "--quilt",
            "8x1",
            "--max-memory",
            "1K",
            "--out",
            target,
        ],
        vec![
            "views",
            image,
            "--view",
            "0",
            "--max-memory",
            "1K",
            "--out",
            target,
        ],
    ] {
        let (ok, stderr) = cli(&args);
        let text = error_text(&stderr);
        assert!(
            !ok && text.contains("memory budget of 1024 bytes"),
            "{args:?}: {text}"
        );
        assert!(text.contains("--max-memory"), "{args:?}: {text}");
    }
    let (ok, stderr) = cli(&["view", "--max-memory", "1K", "--quit-after-frames", "1"]);
    let text = error_text(&stderr);
    assert!(
        !ok && !text.contains("unexpected argument"),
        "view --max-memory: {text}"
    );
}

#[test]
fn negative_point_flags_reach_their_own_check() {
    // `--radius-scale -1` was clap's "unexpected argument '-1'".
    for (flag, says) in [
        ("--radius-scale", "radius scale"),
        ("--epsilon", "--epsilon"),
    ] {
        let (ok, stderr) = cli(&["points", flag, "-1", "--json"]);
        let text = error_text(&stderr);
        assert!(
            !ok && text.contains(says) && !text.contains("unexpected"),
            "{text}"
        );
    }
}

#[test]
fn a_lens_number_the_display_cannot_use_names_display() {
    let (ok, stderr) = cli(&[
        "mask",
        "--display",
        "slanted:8,0,0.2,0",
        "--size",
        "8x8",
        "--out",
        out("vocabulary_errors_pitch.png").to_str().unwrap(),
    ]);
    let text = error_text(&stderr);
    assert!(!ok, "pitch 0 accepted");
    assert!(
        text.contains("--display slanted:8,0,0.2,0: invalid pitch: 0: the lens pitch must be"),
        "{text}"
    );
    assert!(!text.contains("0.0000000002"), "{text}");
}

#[test]
fn raw_volume_errors_speak_the_flags_units() {
    // `--raw-type float32` was refused though uint8 … int32 are taken; the size mismatch said
    // "[2, 2, 2] F32 samples" (the library's debug forms), not 2x2x2 f32.
    let raw = write("vocabulary_errors.raw", &[0u8; 32]);
    let raw = raw.to_str().unwrap();
    let png = out("vocabulary_errors_raw.png");
    let png = png.to_str().unwrap();
    let render = |kind: &str, dims: &str| {
        cli(&[
            "volume",
            raw,
            "--raw-type",
            kind,
            "--raw-dims",
            dims,
            "--size",
            "16x16",
            "--out",
            png,
        ])
    };
    let (ok, stderr) = render("float32", "2,2,2");
    assert!(ok, "--raw-type float32: {stderr}");
    let (ok, stderr) = render("f32", "4,4,4");
    assert!(!ok);
    let text = error_text(&stderr);
    assert!(
        text.contains("32 bytes, but 4x4x4 f32 samples") && text.contains("need 256"),
        "{text}"
    );
    let (ok, stderr) = render("float128", "2,2,2");
    assert!(!ok);
    assert!(
        error_text(&stderr).contains("u8, i8, u16, i16, u32, i32, f32, f64"),
        "the valid types: {stderr}"
    );
}

#[test]
fn sizes_counts_and_separations_name_their_flags() {
    let png = out("vocabulary_errors_flags.png");
    let png = png.to_str().unwrap();
    // "invalid views: 0: …" named no flag.
    let (ok, stderr) = cli(&["mesh", "--views", "0", "--out", png]);
    assert!(!ok);
    assert!(
        error_text(&stderr).starts_with("error: --views:"),
        "{stderr}"
    );
    // "image width = 100000 exceeds the adapter limit 16384" named no flag.
    let (ok, stderr) = cli(&["mesh", "--size", "100000x8", "--out", png]);
    assert!(!ok);
    let text = error_text(&stderr);
    assert!(
        text.contains("100000") && text.contains("(--size: at most "),
        "{text}"
    );
    // "invalid camera framing: the scene's bounds Vec3(…) .. Vec3(…) give no usable camera
    // (invalid separation: must be finite); centre or scale the data": the flag was at fault.
    let (ok, stderr) = cli(&["mesh", "--separation", "nan", "--out", png]);
    assert!(!ok);
    let text = error_text(&stderr);
    assert!(text.starts_with("error: --separation:"), "{text}");
    assert!(
        !text.contains("Vec3") && !text.contains("scale the data"),
        "{text}"
    );
}

#[test]
fn an_empty_nifti_file_is_too_short_for_a_header() {
    // Said "not a NIfTI-1 header: Io(Error { kind: UnexpectedEof, message: \"failed to fill
    // whole buffer\" })": the library's debug form, and no size.
    let nii = write("vocabulary_errors_empty.nii", b"");
    let png = out("vocabulary_errors_nii.png");
    let (ok, stderr) = cli(&[
        "volume",
        nii.to_str().unwrap(),
        "--out",
        png.to_str().unwrap(),
    ]);
    assert!(!ok);
    let text = error_text(&stderr);
    assert!(
        text.contains("vocabulary_errors_empty.nii")
            && text.contains("too short for a NIfTI-1 header (348 bytes)"),
        "{text}"
    );
    assert!(
        !text.contains("UnexpectedEof") && !text.contains("Io("),
        "{text}"
    );
}

#[test]
fn a_spacing_out_of_range_names_spacing_and_the_range() {
    // 1e30 said "the scene's bounds Vec3(-8e30, …) … give no usable camera" and 0 "invalid
    // voxel spacing", neither naming --spacing.
    let png = out("vocabulary_errors_spacing.png");
    let png = png.to_str().unwrap();
    for spacing in ["1e30,1,1", "0,1,1", "1,-1,1"] {
        let (ok, stderr) = cli(&["volume", "--spacing", spacing, "--out", png]);
        assert!(!ok, "{spacing}");
        let text = error_text(&stderr);
        assert!(
            text.contains("--spacing") && text.contains("from 1e-6 to 1e6 world units"),
            "{spacing}: {text}"
        );
        assert!(!text.contains("Vec3"), "{spacing}: {text}");
    }
}

#[test]
fn slices_and_step_name_their_flag_in_its_units_and_the_limit() {
    let png = out("vocabulary_errors_step.png");
    let png = png.to_str().unwrap();
    // Said "--step: invalid sampling step: 0.000000278579 world units": the wrong flag, in
    // world units.
    let (ok, stderr) = cli(&["volume", "--slices", "100000000", "--out", png]);
    assert!(!ok);
    let text = error_text(&stderr);
    assert!(
        text.contains("--slices") && text.contains("at most 16384") && !text.contains("--step"),
        "{text}"
    );
    // --step is in voxels of the smallest spacing; the error said world units and "(the box
    // diagonal / 16384)".
    let (ok, stderr) = cli(&["volume", "--step", "0.000001", "--out", png]);
    assert!(!ok);
    let text = error_text(&stderr);
    assert!(
        text.starts_with("error: --step:") && text.contains("voxels: must be at least 0.0"),
        "{text}"
    );
    assert!(
        !text.contains("world units: must") && !text.contains("box diagonal /"),
        "{text}"
    );
}

#[test]
fn too_many_groups_name_groups_and_the_most_allowed() {
    // Said "splat groups (1000000: texture array layers, a spare included) = 1000000 exceeds
    // the adapter limit 2048".
    let png = out("vocabulary_errors_groups.png");
    let (ok, stderr) = cli(&[
        "points",
        "--groups",
        "1000000",
        "--out",
        png.to_str().unwrap(),
    ]);
    assert!(!ok);
    let text = error_text(&stderr);
    assert!(text.starts_with("error: --groups:"), "{text}");
    let most = number_after(&text, "at most --groups ");
    assert!((1..1000000).contains(&most), "{text}");
    assert!(!text.contains("texture array layers, a spare"), "{text}");
}

#[test]
fn a_look_at_or_look_from_too_far_names_its_flag() {
    // Said "--up: … view direction [0, 0, -0]": the distance overflowed, --up was blameless.
    let png = out("vocabulary_errors_look.png");
    let png = png.to_str().unwrap();
    for flag in ["--look-at", "--look-from"] {
        let (ok, stderr) = cli(&["mesh", flag, "1e30,0,0", "--out", png]);
        assert!(!ok, "{flag}");
        let text = error_text(&stderr);
        assert!(
            text.starts_with(&format!("error: {flag}:")) && text.contains("too far"),
            "{flag}: {text}"
        );
        assert!(!text.contains("--up"), "{flag}: {text}");
    }
}

#[test]
fn a_slant_too_large_is_said_plainly() {
    // Said "at most 4294967296 lens pitches (7.5 subpixels)".
    let png = out("vocabulary_errors_slant.png");
    let (ok, stderr) = cli(&[
        "mesh",
        "--display",
        "slanted:8,7.5,1e30,0.2",
        "--out",
        png.to_str().unwrap(),
    ]);
    assert!(!ok);
    let text = error_text(&stderr);
    assert!(
        text.starts_with("error: --display slanted:8,7.5,1e30,0.2:")
            && text.contains("the slant must be finite and within ±2^32 lens pitches"),
        "{text}"
    );
    assert!(!text.contains("4294967296"), "{text}");
}

#[test]
fn a_report_path_that_is_a_file_names_report_and_the_path() {
    // Said "Not a directory (os error 20)", no flag, no path.
    let dir = out("vocabulary_errors_report");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("BENCHMARKS.md");
    std::fs::write(&file, "# Benchmarks\n").unwrap();
    let (ok, stderr) = cli(&["bench", "--report", file.to_str().unwrap()]);
    assert!(!ok);
    let text = error_text(&stderr);
    assert!(
        text.starts_with("error: --report ") && text.contains(file.to_str().unwrap()),
        "{text}"
    );
    assert!(text.contains("takes a folder"), "{text}");
}

#[test]
fn a_raw_file_longer_than_described_suggests_raw_header() {
    // Said "126 bytes, but 4x4x4 u8 samples after a 0-byte header need 64": no fix.
    let raw = write("vocabulary_errors_long.raw", &[0u8; 126]);
    let png = out("vocabulary_errors_long.png");
    let (ok, stderr) = cli(&[
        "volume",
        raw.to_str().unwrap(),
        "--raw-dims",
        "4,4,4",
        "--raw-type",
        "u8",
        "--out",
        png.to_str().unwrap(),
    ]);
    assert!(!ok);
    let text = error_text(&stderr);
    assert!(
        text.contains("need 64") && text.contains("--raw-header 62 if the samples are at the end"),
        "{text}"
    );
    assert!(!text.contains("RawSpec"), "{text}");
}

#[test]
fn an_unknown_tf_names_tf_and_an_empty_cloud_names_its_file() {
    let png = out("vocabulary_errors_tf.png");
    let png = png.to_str().unwrap();
    // Said "invalid transfer function: unknown preset 'nope' (…)", no flag.
    let (ok, stderr) = cli(&["volume", "--tf", "nope", "--out", png]);
    assert!(!ok);
    let text = error_text(&stderr);
    assert!(
        text.starts_with("error: --tf nope:") && text.contains("ct-skin, ct-bone, mri, ml"),
        "{text}"
    );
    // Said "invalid point cloud: no points", no file.
    let ply = write(
        "vocabulary_errors_empty.ply",
        b"ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n\
          property float z\nend_header\n",
    );
    let (ok, stderr) = cli(&["points", ply.to_str().unwrap(), "--out", png]);
    assert!(!ok);
    let text = error_text(&stderr);
    assert!(
        text.contains("vocabulary_errors_empty.ply") && text.contains("no points"),
        "{text}"
    );
}

#[test]
fn a_mask_too_large_names_size_and_the_limit() {
    // Said "invalid image size: 20000x20000: 400000000 pixels, more than 268435456", no flag.
    let png = out("vocabulary_errors_mask.png");
    let png = png.to_str().unwrap();
    for gpu in [false, true] {
        let mut args = vec!["mask", "--size", "20000x20000", "--out", png];
        if gpu {
            args.push("--gpu");
        }
        let (ok, stderr) = cli(&args);
        assert!(!ok, "gpu {gpu}");
        let text = error_text(&stderr);
        assert!(
            text.starts_with("error: --size 20000x20000:")
                && text.contains("more than 268435456, the most")
                && text.contains("--size 16384x16384"),
            "gpu {gpu}: {text}"
        );
    }
}
