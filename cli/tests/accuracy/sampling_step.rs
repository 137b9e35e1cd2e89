//! A coarser sampling distance (`VolumeSettings::step`, `--step S` in voxels; the exact image is
//! sampled every half voxel): pre-integration keeps the image close to the exact one, with an
//! error within what was measured here and in the benchmark (docs/volumes/BENCHMARKS.md) that
//! grows with the step, alone and with the probes; the single pass equals the N-pass at every
//! step, as the views share the sample planes; the command line's `--step` counts voxels of the
//! smallest spacing and `--compare` measures a coarser step against the default one.

use crate::common;

use autostereo::image_io::compare;
use autostereo::render::Method;
use autostereo::volume::generate;
use autostereo::volume::VolumeSettings;

const SIZE: [u32; 2] = [96, 80];
const DISPLAYS: [&str; 2] = ["hubner8", "slanted:45,7.5,1/6,0.2"];

/// Sampling every `step` voxels, probing `stride` planes ahead through air.
fn at(step: f32, stride: u32) -> VolumeSettings {
    VolumeSettings {
        step: Some(step),
        empty_stride: stride,
        ..VolumeSettings::default()
    }
}

#[test]
fn single_pass_equals_the_npass_at_every_step() {
    let head = generate::ct_head(32).unwrap();
    let scene = common::turned_volume(&head, "ct-skin");
    for spec in DISPLAYS {
        let frame = common::frame(head.bounds(), spec, 0.06, 1.0, SIZE);
        for (step, stride) in [(0.75, 1), (1.0, 1), (1.5, 1), (1.0, 3), (1.5, 4)] {
            let settings = at(step, stride);
            let single = common::render_volume(&scene, &frame, Method::SinglePass, settings);
            let npass = common::render_volume(&scene, &frame, Method::NPass, settings);
            assert!(single == npass, "{spec} step {step} P = {stride}");
        }
    }
}

/// A setting and the error it may have against the exact image.
#[derive(Clone, Copy)]
struct Bound {
    step: f32,
    stride: u32,
    /// Least PSNR, dB.
    min_db: f64,
    /// Largest share of subpixels off by more than 2/255.
    max_off: f64,
}

/// The error against the exact single pass (half-voxel steps) on these small phantoms stays
/// within the bound measured here (lavapipe, 96×80, rotated, worst of the two displays; PSNR /
/// share of subpixels off by > 2/255), with a margin of about 1.5 dB and a sixth:
///
/// | setting | head 48³ | Marschner–Lobb 40³ |
/// |---|---|---|
/// | step 1 | 38.2 dB / 6.9 % | 37.7 dB / 9.0 % |
/// | step 1, P = 3 | 33.8 dB / 7.2 % | 35.9 dB / 9.6 % |
/// | step 1.5 | 34.9 dB / 9.1 % | 32.9 dB / 14.4 % |
/// | step 1.5, P = 4 | 31.6 dB / 9.4 % | 32.6 dB / 14.6 % |
///
/// The probed settings are the fastest ≥ 40 dB of the benchmark on the 96×96×77 head (41.9 dB)
/// and brainsmall (42.5 dB) at 512²; these phantoms' shells are one or two voxels thin and
/// their features a few voxels wide, so a coarse step costs them more: the bound says what it
/// costs on small features, not on typical data. The error grows with the step.
#[test]
fn the_error_of_a_coarser_step_stays_within_its_measured_bound() {
    let head = generate::ct_head(48).unwrap();
    let ml = generate::marschner_lobb(40).unwrap();
    let bound = |step, stride, min_db, max_off| Bound {
        step,
        stride,
        min_db,
        max_off,
    };
    let head_bounds = [
        bound(1.0, 1, 36.5, 0.08),
        bound(1.0, 3, 32.0, 0.085),
        bound(1.5, 1, 33.0, 0.11),
        bound(1.5, 4, 30.0, 0.11),
    ];
    let ml_bounds = [
        bound(1.0, 1, 36.0, 0.105),
        bound(1.0, 3, 34.0, 0.115),
        bound(1.5, 1, 31.0, 0.17),
        bound(1.5, 4, 31.0, 0.17),
    ];
    let volumes = [
        ("head", &head, "ct-skin", head_bounds),
        ("ml", &ml, "ml", ml_bounds),
    ];
    for (name, volume, tf, bounds) in volumes {
        let scene = common::turned_volume(volume, tf);
        for spec in DISPLAYS {
            let frame = common::frame(volume.bounds(), spec, 0.06, 1.0, SIZE);
            let exact = common::render_volume(&scene, &frame, Method::SinglePass, at(0.5, 1));
            let mut psnr_at_step = Vec::new();
            for Bound {
                step,
                stride,
                min_db,
                max_off,
            } in bounds
            {
                let settings = at(step, stride);
                let d = compare(
                    &common::render_volume(&scene, &frame, Method::SinglePass, settings),
                    &exact,
                )
                .unwrap();
                eprintln!("{name} {spec} step {step} P {stride}: {d:?}");
                assert!(
                    d.max_abs_err > 0,
                    "{name} {spec}: step {step} changed nothing"
                );
                assert!(
                    d.psnr_db >= min_db && d.frac_off_2 <= max_off,
                    "{name} {spec} step {step} P {stride}: {d:?}"
                );
                if stride == 1 {
                    psnr_at_step.push(d.psnr_db);
                }
            }
            assert!(
                psnr_at_step.is_sorted_by(|a, b| a > b),
                "{name} {spec}: PSNR at steps 1 and 1.5 {psnr_at_step:?}"
            );
        }
    }
}

/// `autostereo volume ARGS --json` on a 32³ head with voxels 2 × 2 × 3 units: the JSON.
fn volume_json(args: &[&str]) -> serde_json::Value {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_autostereo"))
        .arg("volume")
        .args(["--builtin-size", "32", "--spacing", "2,2,3"])
        .args(["--size", "64x48", "--frames", "1", "--json"])
        .args(args)
        .env("RUST_LOG", "off")
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{args:?}: {stderr}");
    serde_json::from_str(String::from_utf8_lossy(&out.stdout).trim()).unwrap()
}

/// `--step 1` is one voxel of the smallest spacing (2 units here), and `--compare` measures it
/// against the exact N-pass at the default half voxel (1 unit), not at its own step, where the
/// single pass and the N-pass agree exactly.
#[test]
fn the_command_line_step_counts_voxels_and_compare_measures_it_against_the_default() {
    let exact = volume_json(&["--compare"]);
    assert_eq!(exact["step"], 1.0, "{exact}");
    assert!(exact["psnr_db"].as_f64().unwrap() >= 999.0, "{exact}");
    let coarse = volume_json(&["--step", "1", "--compare"]);
    assert_eq!(coarse["step"], 2.0, "{coarse}");
    assert_eq!(coarse["compare_step"], 1.0, "{coarse}");
    let psnr = coarse["psnr_db"].as_f64().unwrap();
    assert!((20.0..999.0).contains(&psnr), "{coarse}");
    // A finer step than the default is its own reference.
    let fine = volume_json(&["--step", "0.25", "--compare"]);
    assert_eq!(fine["compare_step"], 0.5, "{fine}");
    assert!(fine["psnr_db"].as_f64().unwrap() >= 999.0, "{fine}");
}
