//! Issue 31, refusals by name: a flag the chosen method, path or output would ignore; an
//! output at an input's path or another output's; degenerate settings; another command's flag
//! and a negative count.

use super::outputs::{out, rgbd_pair, with};
use crate::common;
use common::{cli_out as run, cli_refused as refused};

#[test]
fn a_flag_the_method_or_path_would_ignore_is_refused_by_name() {
    let png = out("ignored.png");
    let png = png.to_str().unwrap();
    let cases: [(&str, &[&str], &[&str]); 13] = [
        (
            "mesh",
            &["--visibility", "fast", "--method", "n-pass"],
            &["--visibility", "single"],
        ),
        (
            "mesh",
            &["--bounds", "paper", "--method", "tiled"],
            &["--bounds", "single"],
        ),
        (
            "mesh",
            &["--tile-clip", "discard", "--method", "single-pass"],
            &["--tile-clip", "--method tiled"],
        ),
        (
            "points",
            &["--depth", "paper", "--method", "n-pass"],
            &["--depth", "single"],
        ),
        (
            "volume",
            &["--alpha", "paper"],
            &["--alpha", "--path slices"],
        ),
        (
            "volume",
            &["--path", "slices", "--method", "n-pass"],
            &["--path slices", "single"],
        ),
        (
            "volume",
            &["--path", "slices", "--empty-stride", "4"],
            &["--empty-stride", "compute"],
        ),
        (
            "volume",
            &["--share-samples", "0.5", "--method", "n-pass"],
            &["--share-samples"],
        ),
        (
            "volume",
            &["--thin-alpha", "0.1"],
            &["--thin-alpha", "--empty-stride"],
        ),
        (
            "gaussians",
            &["--sh-per-subpixel", "--method", "n-pass"],
            &["--sh-per-subpixel"],
        ),
        ("mesh", &["--eyes", "1,2"], &["--eyes", "--output"]),
        (
            "mesh",
            &["--clusters", "7", "--method", "tiled"],
            &["--clusters", "single"],
        ),
        (
            "mesh",
            &["--clusters", "7", "--visibility", "exact"],
            &["--clusters", "only compute visibility groups views"],
        ),
    ];
    for (command, flags, words) in cases {
        let mut args = with(command, flags);
        args.extend(["--out", png]);
        refused(&args, words);
    }
    // The same flags with the method that uses them render.
    for (command, flags) in [
        ("mesh", &["--visibility", "fast"][..]),
        ("mesh", &["--tile-clip", "discard", "--method", "tiled"]),
        ("volume", &["--alpha", "paper", "--path", "slices"]),
        ("volume", &["--thin-alpha", "0.1", "--empty-stride", "4"]),
        ("mesh", &["--eyes", "1,2", "--output", "anaglyph"]),
        // Every adapter: `auto` visibility is compute on Vulkan, exact (one cluster) on GL.
        ("mesh", &["--clusters", "1"]),
    ] {
        let mut args = with(command, flags);
        args.extend(["--out", png]);
        let (ok, _, stderr) = run(&args);
        assert!(ok, "{args:?}: {stderr}");
    }
}

#[test]
fn outputs_never_overwrite_an_input_or_each_other() {
    let (c, d) = rgbd_pair("t4");
    let (c, d) = (c.to_str().unwrap(), d.to_str().unwrap());
    // The depth map was silently replaced by the spatial image.
    refused(&["rgbd", c, d, "--out", d], &["input file", "destroy"]);
    refused(&["views", c, "--view", "1", "--out", c], &["input file"]);
    refused(
        &["interleave", c, "--quilt", "4x2", "--out", c],
        &["input file"],
    );
    // Two outputs of one run at one path: the second overwrote the first.
    let x = out("twice.png");
    let x = x.to_str().unwrap();
    refused(
        &["rgbd", c, d, "--out", x, "--hole-mask", x],
        &["two outputs"],
    );
    refused(
        &with("mesh", &["--method", "warp", "--out", x, "--hole-mask", x]),
        &["two outputs"],
    );
}

#[test]
fn degenerate_and_unused_settings_are_refused_by_name() {
    let f = out("degenerate.png");
    let f = f.to_str().unwrap();
    let c = rgbd_pair("t5").0.to_str().unwrap().to_string();
    let cases: [(Vec<&str>, &[&str]); 10] = [
        (
            with(
                "volume",
                &["--output", "anaglyph", "--eyes", "3,3", "--out", f],
            ),
            &["--eyes 3,3", "no depth"],
        ),
        (
            vec!["views", &c, "--eyes", "2,2", "--out", f],
            &["--eyes 2,2"],
        ),
        (
            with(
                "mesh",
                &["--output", "quilt", "--quilt", "100x100", "--out", f],
            ),
            &["--quilt 100x100", "empty", "--quilt 2x4"],
        ),
        (
            with(
                "mesh",
                &["--output", "anaglyph", "--origin", "5,3", "--out", f],
            ),
            &["--origin", "--output anaglyph"],
        ),
        (
            with("mesh", &["--output", "quilt", "--bgr", "--out", f]),
            &["--bgr"],
        ),
        (
            with("volume", &["--raw-header", "5", "--out", f]),
            &["--raw-header", "raw"],
        ),
        (
            with("volume", &["--downsample", "100", "--out", f]),
            &["--downsample: invalid downsample factor: 100", "at most"],
        ),
        (
            vec!["volume", "--builtin-size", "0", "--out", f],
            &["--builtin-size"],
        ),
        (
            with("mesh", &["--clusters", "0", "--out", f]),
            &["--clusters", "at least 1"],
        ),
        (
            vec!["view", "--exercise-switch", "methods"],
            &["--exercise"],
        ),
    ];
    for (args, words) in cases {
        refused(&args, words);
    }
    // A file and the built-in data set's flags: which one was meant?
    let nrrd = out("degenerate.nrrd");
    let header = "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 4 4 4\nencoding: raw\n\n";
    let mut bytes = header.as_bytes().to_vec();
    bytes.extend([9u8; 64]);
    std::fs::write(&nrrd, bytes).unwrap();
    refused(
        &with(
            "volume",
            &[nrrd.to_str().unwrap(), "--builtin", "ml", "--out", f],
        ),
        &["--builtin", "degenerate.nrrd"],
    );
}

#[test]
fn another_commands_flag_and_a_negative_count_are_named() {
    // clap said "unexpected argument '--visibility'" (and for -3 suggested `-- -3`, which makes
    // it a file name).
    let stderr = refused(&["points", "--visibility", "exact"], &["autostereo mesh"]);
    assert!(
        stderr.contains("--visibility is not a flag of `autostereo points`"),
        "{stderr}"
    );
    refused(&["volume", "--sort", "cpu"], &["`autostereo gaussians`"]);
    let stderr = refused(&["points", "--views", "-3"], &["--views -3", "no negative"]);
    assert!(!stderr.contains("-- -3"), "{stderr}");
}
