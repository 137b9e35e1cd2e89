//! Malformed files refused by name; a 3DGS PLY given to the point-cloud or mesh loaders
//! names `autostereo gaussians`.

use super::*;

fn refused(result: autostereo::Result<Gaussians>, name: &str, expected: &str) {
    let e = result.expect_err(expected).to_string();
    assert!(e.contains(name), "names the file: {e}");
    assert!(e.contains(expected), "'{e}' lacks '{expected}'");
}

#[test]
fn malformed_files_are_refused_by_name() {
    let raw = scene();
    let ply = write_ply(&raw, 45);
    let p = Path::new("bad.ply");
    refused(parse_ply(&ply[..ply.len() - 5], p), "bad.ply", "truncated");
    let text = |from: &str, to: &str| {
        let end = ply.windows(10).position(|w| w == b"end_header").unwrap();
        let head = String::from_utf8_lossy(&ply[..end]).replace(from, to);
        [head.as_bytes(), &ply[end..]].concat()
    };
    refused(
        parse_ply(&text("vertex 50", "vertex 5000000"), p),
        "bad.ply",
        "truncated: the header declares 5000000 Gaussians",
    );
    refused(
        parse_ply(&text("property float f_rest_44\n", ""), p),
        "bad.ply",
        "44 f_rest properties: SH degree 0, 1, 2 or 3 has 0, 9, 24 or 45",
    );
    refused(
        parse_ply(&text("f_rest_44", "f_rest_45"), p),
        "bad.ply",
        "f_rest_44 is missing",
    );
    refused(
        parse_ply(&text("float opacity", "float alpha"), p),
        "bad.ply",
        "lacks opacity",
    );
    refused(
        parse_ply(&text("float opacity", "double opacity"), p),
        "bad.ply",
        "'opacity' is not float",
    );
    refused(
        parse_ply(&text("binary_little_endian", "binary_big_endian"), p),
        "bad.ply",
        "binary_little_endian",
    );
    let mut zero = raw;
    zero[3].rotation = [0.0; 4];
    refused(
        parse_ply(&write_ply(&zero, 45), p),
        "bad.ply",
        "Gaussian 3 has a zero or non-finite rotation",
    );
    zero[3].rotation = [1.0, 0.0, 0.0, 0.0];
    zero[7].log_scale[1] = 100.0;
    refused(
        parse_ply(&write_ply(&zero, 45), p),
        "bad.ply",
        "Gaussian 7 has a negative or non-finite scale",
    );

    let raw = scene();
    let splat = write_splat(&raw);
    let s = Path::new("bad.splat");
    refused(
        parse_splat(&splat[..splat.len() - 1], s),
        "bad.splat",
        "not a whole number of 32-byte splats",
    );
    let mut zero = splat.clone();
    zero[32 * 2 + 28..32 * 3].copy_from_slice(&[128; 4]);
    refused(parse_splat(&zero, s), "bad.splat", "Gaussian 2 has a zero");
    refused(parse_splat(&[], s), "bad.splat", "no Gaussians");

    let z = Path::new("bad.spz");
    let spz = write_spz(&raw, 3, 3);
    refused(parse_spz(&splat, z), "bad.spz", "not gzip");
    refused(
        parse_spz(b"NGSP\x04\0\0\0", z),
        "bad.spz",
        "version 4 (ZSTD",
    );
    let mut plain = Vec::new();
    flate2::read::GzDecoder::new(&spz[..])
        .read_to_end(&mut plain)
        .unwrap();
    let patched = |at: usize, bytes: &[u8]| {
        let mut p = plain.clone();
        p[at..at + bytes.len()].copy_from_slice(bytes);
        gzip(&p)
    };
    refused(
        parse_spz(&patched(0, b"NGSQ"), z),
        "bad.spz",
        "wrong magic 0x5153474e",
    );
    refused(parse_spz(&patched(4, &[1]), z), "bad.spz", "version 1");
    refused(parse_spz(&patched(12, &[4]), z), "bad.spz", "SH degree 4");
    refused(
        parse_spz(&patched(8, &1_000_000_000u32.to_le_bytes()), z),
        "bad.spz",
        "compressed bytes can hold",
    );
    refused(
        parse_spz(&patched(8, &60u32.to_le_bytes()), z),
        "bad.spz",
        "truncated",
    );
    refused(
        parse_spz(&gzip(&plain[..plain.len() - 1]), z),
        "bad.spz",
        "truncated",
    );
    refused(
        parse_spz(&gzip(&plain[..10]), z),
        "bad.spz",
        "16-byte header",
    );
    refused(parse_spz(&spz[..spz.len() / 2], z), "bad.spz", "gzip");
}

#[test]
fn a_3dgs_ply_given_to_points_or_meshes_names_gaussians() {
    let raw = scene();
    let path = file("splats.ply", &write_ply(&raw[..2], 45));
    for e in [
        autostereo::points::PointCloud::load(&path).unwrap_err(),
        autostereo::mesh::Mesh::load(&path).unwrap_err(),
    ] {
        let e = e.to_string();
        assert!(e.contains("3D Gaussian splats"), "{e}");
        assert!(e.ends_with("read it as 3D Gaussian splats"), "{e}");
    }
    // And a point cloud's PLY, or another kind's file, given to the Gaussians loader.
    let cloud = file(
        "cloud.ply",
        b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n",
    );
    let e = Gaussians::load(&cloud).unwrap_err().to_string();
    assert!(
        e.contains("this is a point cloud (PLY, vertices only"),
        "{e}"
    );
    assert!(e.ends_with("read it as a point cloud"), "{e}");
    let e = autostereo::points::PointCloud::load(&file("scene.spz", &write_spz(&raw, 3, 0)))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("this is 3D Gaussian splats (SPZ), not a point cloud"),
        "{e}"
    );
    assert_eq!(
        formats::kind(&dir().join("scene.spz")).unwrap(),
        (Format::Spz, DataKind::Gaussians)
    );
    assert!(formats::supported().contains("Gaussian splats .ply .splat .spz"));
}
