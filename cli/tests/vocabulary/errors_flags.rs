//! Issue 31, errors in the user's terms (continued): flags named in the units the user typed
//! (`--spacing`, `--slices`, `--step`, `--groups`, `--look-at`, the slant, `--report`, a raw
//! file's length, `--tf`, `--size` of a mask).

use super::errors::{error_text, number_after, out, write};
use crate::common;
use common::cli;

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
