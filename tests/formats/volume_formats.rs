#![cfg(feature = "nifti")]
//! One acquisition in every volume format (issue 29): the same voxels and the same patient
//! geometry written as NRRD (`space` RAS), NIfTI-1 (sform; qform; gzip; big-endian; scaled),
//! MetaImage (`.mha`, zlib, MSB; `.mhd` + raw) load to the same volume — data, spacing and the
//! voxel axes on screen (src/volume/orientation.rs) — so they render alike; broken headers are
//! refused by name. (NIfTI needs the `nifti` feature: `cargo test` at the root turns it on
//! through the CLI.)

use crate::common;

use std::io::Write;
use std::path::PathBuf;

use autostereo::volume::load::load_any;
use autostereo::volume::orientation::RAS_TO_SCREEN;
use autostereo::volume::Volume;
use glam::{Mat3, Vec3};

fn write(name: &str, bytes: &[u8]) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("volume_formats");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, bytes).unwrap();
    path
}

const SPACING: [f32; 3] = [0.5, 0.75, 2.0];

/// Voxel values (i16, signed and past 8 bits: a CT's range).
pub(crate) fn voxels() -> Vec<i16> {
    (0..60).map(|i| (i * 37 % 61) as i16 * 20 - 400).collect()
}

pub(crate) fn le(v: &[i16]) -> Vec<u8> {
    v.iter().flat_map(|x| x.to_le_bytes()).collect()
}

fn be(v: &[i16]) -> Vec<u8> {
    v.iter().flat_map(|x| x.to_be_bytes()).collect()
}

/// The geometry: voxel axis i toward the patient's posterior, j toward the right, k superior
/// (RAS+ directions; a turn of −90° about superior).
fn ras_directions() -> [Vec3; 3] {
    [Vec3::new(0.0, -1.0, 0.0), Vec3::X, Vec3::Z]
}

fn gzip(bytes: &[u8]) -> Vec<u8> {
    let mut e = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
    e.write_all(bytes).unwrap();
    e.finish().unwrap()
}

fn zlib(bytes: &[u8]) -> Vec<u8> {
    let mut e = flate2::write::ZlibEncoder::new(Vec::new(), flate2::Compression::fast());
    e.write_all(bytes).unwrap();
    e.finish().unwrap()
}

pub(crate) fn nrrd() -> Vec<u8> {
    let d = ras_directions();
    let dir = |a: usize| {
        let v = d[a] * SPACING[a];
        format!("({},{},{})", v.x, v.y, v.z)
    };
    let mut b = format!(
        "NRRD0004\ntype: short\ndimension: 3\nspace: right-anterior-superior\nsizes: 5 4 3\n\
         space directions: {} {} {}\nendian: little\nencoding: raw\n\n",
        dir(0),
        dir(1),
        dir(2)
    )
    .into_bytes();
    b.extend(le(&voxels()));
    b
}

/// How a NIfTI file says where it is.
#[derive(Clone, Copy)]
pub(crate) enum Geometry {
    Sform,
    Qform,
}

/// A NIfTI-1 `.nii` of `data` (datatype `code`) with `geometry`, in either byte order.
pub(crate) fn nifti(
    data: &[u8],
    code: i16,
    bits: i16,
    geometry: Geometry,
    big: bool,
    scale: [f32; 2],
) -> Vec<u8> {
    let mut h = vec![0u8; 352];
    let put =
        |h: &mut Vec<u8>, at: usize, bytes: &[u8]| h[at..at + bytes.len()].copy_from_slice(bytes);
    let i32b = |v: i32| {
        if big {
            v.to_be_bytes()
        } else {
            v.to_le_bytes()
        }
    };
    let i16b = |v: i16| {
        if big {
            v.to_be_bytes()
        } else {
            v.to_le_bytes()
        }
    };
    let f32b = |v: f32| {
        if big {
            v.to_be_bytes()
        } else {
            v.to_le_bytes()
        }
    };
    put(&mut h, 0, &i32b(348));
    for (i, d) in [3i16, 5, 4, 3, 1, 1, 1, 1].iter().enumerate() {
        put(&mut h, 40 + 2 * i, &i16b(*d));
    }
    put(&mut h, 70, &i16b(code));
    put(&mut h, 72, &i16b(bits));
    for (i, p) in [
        1.0f32, SPACING[0], SPACING[1], SPACING[2], 1.0, 1.0, 1.0, 1.0,
    ]
    .iter()
    .enumerate()
    {
        put(&mut h, 76 + 4 * i, &f32b(*p));
    }
    put(&mut h, 108, &f32b(352.0));
    put(&mut h, 112, &f32b(scale[0]));
    put(&mut h, 116, &f32b(scale[1]));
    let d = ras_directions();
    match geometry {
        Geometry::Sform => {
            put(&mut h, 254, &i16b(1));
            // Row r of the affine: component r of each axis's direction × spacing.
            for r in 0..3 {
                for (a, (direction, spacing)) in d.iter().zip(SPACING).enumerate() {
                    put(&mut h, 280 + 16 * r + 4 * a, &f32b(direction[r] * spacing));
                }
            }
        }
        Geometry::Qform => {
            put(&mut h, 252, &i16b(1));
            // −90° about z: (b, c, d) = (0, 0, −sin 45°).
            put(&mut h, 264, &f32b(-std::f32::consts::FRAC_1_SQRT_2));
        }
    }
    put(&mut h, 344, b"n+1\0");
    h.extend_from_slice(data);
    h
}

pub(crate) fn metaimage(
    local: Option<&[u8]>,
    data_file: &str,
    msb: bool,
    compressed: bool,
) -> Vec<u8> {
    // Row a: voxel axis a's direction in LPS+ (x and y of RAS+ flipped).
    let lps: Vec<String> = ras_directions()
        .iter()
        .map(|v| format!("{} {} {}", -v.x + 0.0, -v.y + 0.0, v.z))
        .collect();
    let mut b = format!(
        "ObjectType = Image\r\nNDims = 3\r\nBinaryData = True\r\nBinaryDataByteOrderMSB = {}\r\n\
         CompressedData = {}\r\nTransformMatrix = {}\r\nOffset = 0 0 0\r\n\
         AnatomicalOrientation = PRS\r\nElementSpacing = 0.5 0.75 2\r\nDimSize = 5 4 3\r\n\
         ElementType = MET_SHORT\r\nElementDataFile = {data_file}\r\n",
        if msb { "True" } else { "False" },
        if compressed { "True" } else { "False" },
        lps.join(" ")
    )
    .into_bytes();
    if let Some(data) = local {
        b.extend_from_slice(data);
    }
    b
}

#[test]
fn one_acquisition_loads_alike_from_every_format() {
    let reference = load_any(&write("scan.nrrd", &nrrd())).unwrap();
    // The geometry reached the screen: i (posterior) points away from the viewer, j (the
    // patient's right) to the screen's left, k (superior) up.
    let d = ras_directions();
    let expected = RAS_TO_SCREEN * Mat3::from_cols(d[0], d[1], d[2]);
    assert!(
        reference.axes.abs_diff_eq(expected, 1e-6),
        "{}",
        reference.axes
    );
    assert_eq!(reference.axes.x_axis, Vec3::new(0.0, 0.0, -1.0));
    assert_eq!(reference.axes.y_axis, Vec3::new(-1.0, 0.0, 0.0));
    // Its box on screen: k's 3 × 2 = 6 high, j's 4 × 0.75 = 3 wide, i's 2.5 deep.
    let bounds = reference.bounds();
    assert!(
        (bounds.max - Vec3::new(1.5, 3.0, 1.25)).abs().max_element() < 1e-6,
        "{bounds:?}"
    );

    let v = voxels();
    let files = [
        (
            "nii sform",
            write(
                "scan_sform.nii",
                &nifti(&le(&v), 4, 16, Geometry::Sform, false, [0.0, 0.0]),
            ),
        ),
        (
            "nii qform",
            write(
                "scan_qform.nii",
                &nifti(&le(&v), 4, 16, Geometry::Qform, false, [1.0, 0.0]),
            ),
        ),
        (
            "nii big-endian",
            write(
                "scan_be.nii",
                &nifti(&be(&v), 4, 16, Geometry::Sform, true, [0.0, 0.0]),
            ),
        ),
        (
            "nii.gz",
            write(
                "scan.nii.gz",
                &gzip(&nifti(&le(&v), 4, 16, Geometry::Qform, false, [0.0, 0.0])),
            ),
        ),
        (
            "mha",
            write("scan.mha", &metaimage(Some(&le(&v)), "LOCAL", false, false)),
        ),
        (
            "mha msb",
            write(
                "scan_msb.mha",
                &metaimage(Some(&be(&v)), "LOCAL", true, false),
            ),
        ),
        (
            "mha zlib",
            write(
                "scan_zlib.mha",
                &metaimage(Some(&zlib(&le(&v))), "LOCAL", false, true),
            ),
        ),
        ("mhd + raw", {
            write("scan_data.raw", &le(&v));
            write("scan.mhd", &metaimage(None, "scan_data.raw", false, false))
        }),
    ];
    for (name, file) in &files {
        common::assert_same_volume(name, &load_any(file).unwrap(), &reference);
    }
}

/// `scl_slope`/`scl_inter` reach the values (CT's Hounsfield units from stored counts); values
/// are then normalised by their range, so the presets see the same 0…1 whatever the scaling.
#[test]
fn nifti_rescaling_is_applied() {
    let stored: Vec<u8> = (0..60u8).map(|i| i * 4).collect();
    let scaled = nifti(&stored, 2, 8, Geometry::Sform, false, [2.0, -1024.0]);
    let volume = load_any(&write("scaled.nii", &scaled)).unwrap();
    // u8 stored, scaled: normalised by the scaled range, 0 … 236·2 − 1024.
    let (lo, hi) = (-1024.0f32, 236.0 * 2.0 - 1024.0);
    for (i, &v) in volume.data.iter().enumerate() {
        let want = (stored[i] as f32 * 2.0 - 1024.0 - lo) / (hi - lo);
        assert!((v - want).abs() < 1e-6, "voxel {i}: {v} vs {want}");
    }
    // Unscaled u8 keeps the 0…255 range (as every 8-bit format does).
    let plain = load_any(&write(
        "plain.nii",
        &nifti(&stored, 2, 8, Geometry::Sform, false, [0.0, 0.0]),
    ))
    .unwrap();
    assert!((plain.data[59] - 236.0 / 255.0).abs() < 1e-6);
}

#[test]
fn broken_headers_are_refused_by_name() {
    let v = le(&voxels());
    let good = nifti(&v, 4, 16, Geometry::Sform, false, [0.0, 0.0]);
    let cases: Vec<(&str, Vec<u8>, &str)> = vec![
        (
            "truncated.nii",
            good[..good.len() - 10].to_vec(),
            "truncated",
        ),
        (
            "complex.nii",
            {
                let mut b = good.clone();
                b[70] = 32;
                b
            },
            "datatype 32 is not a scalar type",
        ),
        (
            "pair.nii",
            {
                let mut b = good.clone();
                b[344..348].copy_from_slice(b"ni1\0");
                b
            },
            ".hdr/.img pair",
        ),
        (
            "short.nii.gz",
            gzip(&good[..200]),
            "200 bytes after inflating: too short for a NIfTI-1 header",
        ),
        (
            "sheared.nii",
            {
                let mut b = good.clone();
                b[280..284].copy_from_slice(&0.3f32.to_le_bytes());
                b
            },
            "right angles",
        ),
        (
            "trunc.mha",
            metaimage(Some(&v[..20]), "LOCAL", false, false),
            "truncated",
        ),
        (
            "rgb.mha",
            String::from_utf8(metaimage(None, "LOCAL", false, false))
                .unwrap()
                .replace("NDims = 3", "NDims = 3\r\nElementNumberOfChannels = 3")
                .into_bytes(),
            "channels",
        ),
        (
            "escape.mhd",
            metaimage(None, "../secret.raw", false, false),
            "only a file beside the header",
        ),
        (
            "type.mha",
            {
                let header = String::from_utf8(metaimage(None, "LOCAL", false, false)).unwrap();
                let mut b = header.replace("MET_SHORT", "MET_LONG_LONG").into_bytes();
                b.extend_from_slice(&v);
                b
            },
            "ElementType 'MET_LONG_LONG' is not read",
        ),
    ];
    for (name, bytes, expected) in cases {
        let e = load_any(&write(name, &bytes)).unwrap_err().to_string();
        assert!(
            e.contains(expected) && e.contains(name),
            "{name}: '{e}' lacks '{expected}'"
        );
    }
}

/// The renderers place the voxel axes by `Volume::axes`: the head's voxels with x and y
/// swapped, placed by axes that swap them back (a mirror), render as the head itself — the
/// single pass and the N-pass alike.
#[test]
fn the_renderers_place_the_voxel_axes() {
    use autostereo::render::Method;
    use autostereo::volume::{TransferFunction, VolumeScene, VolumeSettings};
    let head = autostereo::volume::generate::ct_head(24).unwrap();
    let [nx, ny, nz] = head.dims;
    // Voxel (i, j, k) of `moved` is voxel (j, i, k) of the head: moved's axis 0 is the head's
    // axis 1 and the other way round.
    let mut data = Vec::with_capacity(head.data.len());
    for k in 0..nz {
        for j in 0..nx {
            for i in 0..ny {
                // moved's voxel (i, j, k), x fastest.
                data.push(head.at(j as i64, i as i64, k as i64));
            }
        }
    }
    let [sx, sy, sz] = head.spacing;
    let moved = Volume::new([ny, nx, nz], [sy, sx, sz], data).unwrap();
    // The head's axes swapped: the head (identity) shows what `swapped` shows.
    let swap = Mat3::from_cols(Vec3::Y, Vec3::X, Vec3::Z);
    let swapped = moved.clone().with_axes(swap).unwrap();
    let ctx = common::gpu();
    let tf = || TransferFunction::preset("ct-skin").unwrap();
    let scene = |v: &Volume| {
        VolumeScene::new(&ctx.device, &ctx.queue, v, tf(), glam::Mat4::IDENTITY).unwrap()
    };
    let (original, placed, unplaced) = (scene(&head), scene(&swapped), scene(&moved));
    drop(ctx);
    assert_eq!(head.bounds(), swapped.bounds());
    let frame = common::frame(head.bounds(), "hubner8", 0.1, 1.0, [48, 48]);
    for method in [Method::SinglePass, Method::NPass] {
        let render =
            |s: &VolumeScene| common::render_volume(s, &frame, method, VolumeSettings::default());
        let want = render(&original);
        let diff = autostereo::image_io::compare(&render(&placed), &want).unwrap();
        assert!(diff.max_abs_err <= 1, "{method}: {diff:?}");
        // Without its axes the moved head is another picture: the axes did the work.
        let diff = autostereo::image_io::compare(&render(&unplaced), &want).unwrap();
        assert!(diff.frac_off_2 > 0.05, "{method}: {diff:?}");
    }
}
