//! Issue 31, errors in the user's terms: each names the flag, the file and the fix in the units
//! the user typed. A frame too wide for a subpixel-resolution mode names `--size` and the
//! widest that works (not the 3× column count); a file's text is quoted escaped and short
//! (never raw bytes on the terminal); no adapter lists the adapters there are and how to pick
//! one; a budget error names `--max-memory` and a figure it takes; the library's names
//! (`Visibility::`, `[2, 2, 2] F32`) never reach the user. Each test fails on the binary before
//! the fix.

use crate::common;

use std::path::PathBuf;
use std::process::Command;

use common::cli;

pub(crate) fn out(name: &str) -> PathBuf {
    common::out_dir().join(name)
}

/// Write `bytes` as `name` in the tests' output folder.
pub(crate) fn write(name: &str, bytes: &[u8]) -> PathBuf {
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
pub(crate) fn error_text(stderr: &str) -> String {
    stderr
        .lines()
        .filter(|l| l.starts_with("error: ") && !l.contains("XDG_RUNTIME_DIR"))
        .collect::<Vec<_>>()
        .join("\n")
}

/// The number after `before` in `text`.
pub(crate) fn number_after(text: &str, before: &str) -> u32 {
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
    // Budget::set_max) and to what, in a figure the flag takes.
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
            !text.contains("set_max") && !text.contains("Budget::"),
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
