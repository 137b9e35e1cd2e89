//! Hostile input: what a hostile user's files did to the loaders before (panics inside tobj,
//! aborts on allocation, reads that never end) and the unclear errors they got. Each case
//! failed on the code before it was fixed.

use crate::common;

use std::path::{Path, PathBuf};
use std::process::Command;

use autostereo::display::Calibration;
use autostereo::mesh::Mesh;
use autostereo::volume::load::{load_nrrd, load_raw, RawSpec, SampleType};

fn dir() -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../target/test-input/hostile");
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn write(name: &str, contents: &[u8]) -> PathBuf {
    let path = dir().join(name);
    std::fs::write(&path, contents).unwrap();
    path
}

const TRIANGLE: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

/// An OBJ naming `mtllib` and using its material.
fn obj_with_mtllib(name: &str, mtllib: &str) -> PathBuf {
    write(
        name,
        format!("mtllib {mtllib}\n{TRIANGLE}usemtl a\nf 1 2 3\n").as_bytes(),
    )
}

#[test]
fn broken_materials_fall_back_to_the_default_colour_without_panicking() {
    // tobj's MTL parser panicked on colour lines with fewer than three numbers.
    for (i, kd) in ["Kd 1 0", "Kd 1 nan", "Kd", "Ka 1\nKd 0.5 0.5", "Ks 1 2"]
        .iter()
        .enumerate()
    {
        let mtl = format!("bad{i}.mtl");
        write(&mtl, format!("newmtl a\n{kd}\n").as_bytes());
        let mesh = Mesh::load_obj(&obj_with_mtllib(&format!("bad{i}.obj"), &mtl)).unwrap();
        assert_eq!(mesh.indices.len(), 3, "{kd}");
    }
    // A good material still colours the mesh.
    write("good.mtl", b"newmtl a\nKd 0.25 0.5 0.75\n");
    let mesh = Mesh::load_obj(&obj_with_mtllib("good.obj", "good.mtl")).unwrap();
    assert_eq!(mesh.colors[0], [0.25, 0.5, 0.75, 1.0]);
}

#[cfg(unix)]
fn fifo(name: &str) -> PathBuf {
    let path = dir().join(name);
    let _ = std::fs::remove_file(&path);
    let status = Command::new("mkfifo").arg(&path).status().unwrap();
    assert!(status.success());
    path
}

/// A FIFO blocked forever and /dev/zero read until memory ran out: both are refused before
/// any byte is read, as materials (non-fatal) and as volume data (an error naming the line).
#[cfg(unix)]
#[test]
fn fifos_and_devices_are_refused_not_read() {
    let fifo = fifo("pipe");
    for target in ["/dev/zero", fifo.to_str().unwrap()] {
        let mesh = Mesh::load_obj(&obj_with_mtllib("special.obj", target)).unwrap();
        assert_eq!(mesh.indices.len(), 3);
        let header = format!(
            "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2 2\nencoding: raw\ndata file: {target}\n"
        );
        let e = load_nrrd(&write("special.nhdr", header.as_bytes()))
            .unwrap_err()
            .to_string();
        assert!(e.contains(&format!("`data file: {target}`")), "{e}");
        assert!(e.contains("not a regular file"), "{e}");
        // The files themselves, too.
        assert!(Mesh::load_obj(Path::new(target)).is_err());
        assert!(load_nrrd(Path::new(target)).is_err());
    }
}

/// A small file that claims a huge volume is refused from its header, before allocating.
#[test]
fn volumes_over_the_memory_budget_are_refused_from_the_header() {
    let header = "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 1024 1024 1024\nencoding: gzip\n\n";
    let mut bytes = header.as_bytes().to_vec();
    bytes.extend_from_slice(&[0x1f, 0x8b, 8, 0, 0, 0, 0, 0, 0, 3]);
    let e = load_nrrd(&write("huge.nrrd", &bytes))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("memory budget") && e.contains("Budget::set_max"),
        "{e}"
    );
    assert!(e.contains("huge.nrrd"), "names the file: {e}");
    // A (sparse) 1 GiB raw file with the dimensions to match.
    let raw = dir().join("huge.raw");
    std::fs::File::create(&raw)
        .unwrap()
        .set_len(1 << 30)
        .unwrap();
    let spec = RawSpec {
        dims: [1024; 3],
        kind: SampleType::U8,
        big_endian: false,
        header_bytes: 0,
        spacing: [1.0; 3],
    };
    let e = load_raw(&raw, &spec).unwrap_err().to_string();
    assert!(e.contains("memory budget"), "{e}");
    std::fs::remove_file(&raw).unwrap();
}

/// CRLF NRRD headers, CR-only and non-UTF-8 OBJ text and a UTF-8 BOM were rejected.
#[test]
fn line_ends_byte_order_marks_and_stray_bytes_are_read() {
    let header = "NRRD0004\r\ntype: uchar\r\ndimension: 3\r\nsizes: 2 2 2\r\nencoding: raw\r\n\r\n";
    let mut bytes = header.as_bytes().to_vec();
    bytes.extend_from_slice(&[0, 50, 100, 150, 200, 250, 255, 0]);
    let v = load_nrrd(&write("crlf.nrrd", &bytes)).unwrap();
    assert_eq!(v.dims, [2, 2, 2]);

    let cr = TRIANGLE.replace('\n', "\r") + "f 1 2 3\r";
    assert_eq!(
        Mesh::load_obj(&write("cr.obj", cr.as_bytes()))
            .unwrap()
            .indices
            .len(),
        3
    );
    let mut latin = b"# caf\xe9\n".to_vec();
    latin.extend_from_slice(format!("{TRIANGLE}f 1 2 3\n").as_bytes());
    assert_eq!(
        Mesh::load_obj(&write("latin1.obj", &latin))
            .unwrap()
            .indices
            .len(),
        3
    );

    let sample = std::fs::read(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../data/lkg_sample_visual.json"
    ))
    .unwrap();
    let mut bom = b"\xef\xbb\xbf".to_vec();
    bom.extend_from_slice(&sample);
    Calibration::load(&write("bom_visual.json", &bom)).unwrap();
}

use common::cli;

#[test]
fn cli_flags_are_refused_not_clamped_and_failures_leave_no_file() {
    // --out o.jpg failed after rendering and left an empty file.
    let jpg = dir().join("o.jpg");
    let _ = std::fs::remove_file(&jpg);
    let (ok, stderr) = cli(&["mesh", "--size", "16x16", "--out", jpg.to_str().unwrap()]);
    assert!(
        !ok && stderr.contains("PNG, MP4 or GIF is written"),
        "{stderr}"
    );
    assert!(!jpg.exists(), "no file is left behind");
    // --downsample 0 was silently 1.
    let (ok, stderr) = cli(&["volume", "--downsample", "0", "--size", "16x16", "--json"]);
    assert!(!ok && stderr.contains("--downsample"), "{stderr}");
    // A missing --tf file said "unknown preset".
    let (ok, stderr) = cli(&[
        "volume",
        "--tf",
        "missing_tf.txt",
        "--size",
        "16x16",
        "--json",
    ]);
    assert!(
        !ok && stderr.contains("missing_tf.txt") && !stderr.contains("unknown preset"),
        "{stderr}"
    );
    assert!(stderr.contains("No such file"), "{stderr}");
    // The budget is a flag.
    let (ok, stderr) = cli(&["volume", "--max-memory", "1K", "--size", "16x16", "--json"]);
    assert!(
        !ok && stderr.contains("memory budget of 1024 bytes"),
        "{stderr}"
    );
    assert!(stderr.contains("raise it with --max-memory"), "{stderr}");
    let (ok, stderr) = cli(&["volume", "--max-memory", "lots"]);
    assert!(!ok && stderr.contains("not a size"), "{stderr}");
}

/// f32 samples near ±f32::MAX made every voxel NaN ("voxel 0 is NaN", no file named).
#[test]
fn extreme_float_samples_normalise() {
    let samples: Vec<f32> = vec![3.4e38, -3.4e38, 0.0, 1.0, -1.0, 3.4e38, 2.0, 5.0];
    let bytes: Vec<u8> = samples.iter().flat_map(|v| v.to_le_bytes()).collect();
    let spec = RawSpec {
        dims: [2, 2, 2],
        kind: SampleType::F32,
        big_endian: false,
        header_bytes: 0,
        spacing: [1.0; 3],
    };
    let v = load_raw(&write("extreme.raw", &bytes), &spec).unwrap();
    assert!(v
        .data
        .iter()
        .all(|s| s.is_finite() && (0.0..=1.0).contains(s)));
    assert_eq!((v.data[0], v.data[1]), (1.0, 0.0));
}

/// A 16384×1×1 volume failed on a `--step` the user never set; now the default step fits and
/// the error is the adapter's 3D texture limit, with what to do.
#[test]
fn a_very_long_volume_gets_the_texture_limit_error() {
    let raw = write("long.raw", &[0u8; 16384]);
    let (ok, stderr) = cli(&[
        "volume",
        raw.to_str().unwrap(),
        "--raw-dims",
        "16384,1,1",
        "--raw-type",
        "u8",
        "--size",
        "16x16",
        "--json",
    ]);
    assert!(!ok && !stderr.contains("sampling step"), "{stderr}");
    assert!(stderr.contains("--downsample"), "{stderr}");
}

/// Meshes and point clouds are under the budget too (checked from the file size or the PLY
/// header's count, before parsing or allocating).
#[test]
fn meshes_and_point_clouds_are_under_the_budget() {
    let obj = write("budget.obj", format!("{TRIANGLE}f 1 2 3\n").as_bytes());
    let ply = write(
        "budget.ply",
        b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n",
    );
    for (command, file) in [("mesh", &obj), ("points", &ply)] {
        let file = file.to_str().unwrap();
        let (ok, stderr) = cli(&[
            command,
            file,
            "--max-memory",
            "64",
            "--size",
            "8x8",
            "--json",
        ]);
        assert!(
            !ok && stderr.contains("memory budget of 64 bytes"),
            "{command}: {stderr}"
        );
        assert!(stderr.contains(file), "{command} names the file: {stderr}");
        let (ok, stderr) = cli(&[command, file, "--size", "8x8", "--json"]);
        assert!(ok, "{command} within the default budget: {stderr}");
    }
}

/// The GPU side of the budget is a running total: every texture and buffer a render holds at
/// once counts. The 8-view N-pass at 256² holds 2.36 MB of view layers and depth on top of
/// 0.43 MB of target, scratch and mesh: a 2.5 MB budget passes each allocation on its own
/// (what the per-resource check allowed) but not their sum, and 3 MB passes.
#[test]
fn the_gpu_budget_counts_everything_held_at_once() {
    let run = |budget: &str| {
        cli(&[
            "mesh",
            "--method",
            "n-pass",
            "--size",
            "256x256",
            "--max-memory",
            budget,
            "--json",
        ])
    };
    let (ok, stderr) = run("2500K");
    assert!(!ok, "over the budget in total: {stderr}");
    assert!(
        stderr.contains("view layers") && stderr.contains("already held"),
        "names what and what is held: {stderr}"
    );
    let (ok, stderr) = run("3M");
    assert!(ok, "within the budget: {stderr}");
}
