#![cfg(feature = "las")]
//! LAS and LAZ point clouds (issue 29; the `las` feature, which `cargo test` at the root turns
//! on through the CLI): the points of a LAS or LAZ file are the points of the same cloud as a
//! PLY — positions about the bounds' centre with lidar precision kept, 8- and 16-bit colours —
//! and broken files are refused by name.

use std::path::PathBuf;

use autostereo::points::PointCloud;

fn write(name: &str, bytes: &[u8]) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("points_las");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, bytes).unwrap();
    path
}

/// Points at UTM-like coordinates (half a million metres east, four million north) on the
/// LAS default 1 mm grid, with colours.
fn points() -> Vec<([f64; 3], [u16; 3])> {
    (0..40)
        .map(|i| {
            let t = i as f64;
            let p = [
                500_000.0 + t * 0.25,
                4_000_000.0 + (t * 0.7).sin(),
                120.0 + t * 0.01,
            ];
            (p, [(i * 6) as u16, 255 - (i * 3) as u16, 17])
        })
        .collect()
}

pub(crate) fn las_bytes(compressed: bool, color_scale: u16) -> Vec<u8> {
    let mut builder = las::Builder::from((1, 2));
    builder.point_format = las::point::Format::new(2).unwrap();
    builder.point_format.is_compressed = compressed;
    // Millimetres about an offset near the data, as lidar files store them.
    let transform = |offset| las::Transform {
        scale: 0.001,
        offset,
    };
    builder.transforms = las::Vector {
        x: transform(500_000.0),
        y: transform(4_000_000.0),
        z: transform(0.0),
    };
    let header = builder.into_header().unwrap();
    let mut writer = las::Writer::new(std::io::Cursor::new(Vec::new()), header).unwrap();
    for (p, c) in points() {
        writer
            .write_point(las::Point {
                x: p[0],
                y: p[1],
                z: p[2],
                color: Some(las::Color::new(
                    c[0] * color_scale,
                    c[1] * color_scale,
                    c[2] * color_scale,
                )),
                ..Default::default()
            })
            .unwrap();
    }
    writer.into_inner().unwrap().into_inner()
}

/// The same points as an ASCII PLY, about the same centre (the bounds' centre).
pub(crate) fn ply_text() -> String {
    let pts = points();
    let (lo, hi) = pts
        .iter()
        .fold(([f64::MAX; 3], [f64::MIN; 3]), |(lo, hi), (p, _)| {
            (
                [0, 1, 2].map(|i| lo[i].min(p[i])),
                [0, 1, 2].map(|i| hi[i].max(p[i])),
            )
        });
    let centre = [0, 1, 2].map(|i| 0.5 * (lo[i] + hi[i]));
    let mut text = format!(
        "ply\nformat ascii 1.0\nelement vertex {}\nproperty double x\nproperty double y\n\
         property double z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n",
        pts.len()
    );
    for (p, c) in pts {
        text += &format!(
            "{} {} {} {} {} {}\n",
            p[0] - centre[0],
            p[1] - centre[1],
            p[2] - centre[2],
            c[0],
            c[1],
            c[2]
        );
    }
    text
}

#[test]
fn las_and_laz_hold_the_points_of_the_same_ply() {
    let reference = PointCloud::load(&write("cloud.ply", ply_text().as_bytes())).unwrap();
    for (name, bytes) in [
        ("cloud.las", las_bytes(false, 1)),
        ("cloud_16bit.las", las_bytes(false, 257)),
        ("cloud.laz", las_bytes(true, 1)),
    ] {
        let cloud = PointCloud::load(&write(name, &bytes)).unwrap();
        assert_eq!(cloud.len(), reference.len(), "{name}");
        for (i, (a, b)) in cloud.positions.iter().zip(&reference.positions).enumerate() {
            // Millimetres kept at 4000 km from the origin (an f32 of the raw value keeps 0.25 m).
            assert!(a.distance(*b) < 2e-3, "{name} point {i}: {a} vs {b}");
        }
        let (colors, want) = (cloud.colors.unwrap(), reference.colors.clone().unwrap());
        for (i, (a, b)) in colors.iter().zip(&want).enumerate() {
            let off = (0..3).map(|c| (a[c] - b[c]).abs()).fold(0.0, f32::max);
            assert!(off < 1e-6, "{name} colour {i}: {a:?} vs {b:?}");
        }
    }
}

#[test]
fn broken_las_files_are_refused_by_name() {
    let good = las_bytes(false, 1);
    let mut lying = good.clone();
    // The legacy point count (offset 107) and, in LAS 1.2, the only one: a billion points.
    lying[107..111].copy_from_slice(&1_000_000_000u32.to_le_bytes());
    // One VLR (offset 100) whose 16-bit length (20 bytes into it) runs past the end.
    let mut vlr = good.clone();
    vlr[100..104].copy_from_slice(&1u32.to_le_bytes());
    vlr[227 + 20..227 + 22].copy_from_slice(&u16::MAX.to_le_bytes());
    // A LAZ chunk table whose header (at the offset the point data starts with) claims 2^31
    // chunks: the scan refuses it before laz reserves a table for them.
    let mut chunks = las_bytes(true, 1);
    let data = u32::from_le_bytes(chunks[96..100].try_into().unwrap()) as usize;
    let table = i64::from_le_bytes(chunks[data..data + 8].try_into().unwrap()) as usize;
    chunks[table + 4..table + 8].copy_from_slice(&(1u32 << 31).to_le_bytes());
    let cases: Vec<(&str, Vec<u8>, &str)> = vec![
        ("short.las", good[..50].to_vec(), "malformed LAS header"),
        (
            "lying.las",
            lying,
            "truncated: the header says 1000000000 points",
        ),
        ("cut.las", good[..good.len() - 20].to_vec(), "point"),
        ("vlr.las", vlr, "VLR 0 at byte 227 declares 65535 bytes"),
        ("chunks.laz", chunks, "lists 2147483648 chunks"),
    ];
    for (name, bytes, expected) in cases {
        let e = PointCloud::load(&write(name, &bytes))
            .unwrap_err()
            .to_string();
        assert!(
            e.contains(expected) && e.contains(name),
            "{name}: '{e}' lacks '{expected}'"
        );
    }
}
