//! Volume loaders: each format read back from files written here, and every malformed or
//! truncated header a clear error (checked before allocating).

use std::io::Write;
use std::path::PathBuf;

use autostereo::volume::load::{load_any, load_den, load_nrrd, load_raw, RawSpec, SampleType};
use autostereo::Error;

fn write(name: &str, bytes: &[u8]) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target/test-input/volumes");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, bytes).unwrap();
    path
}

pub(crate) fn u16_samples(n: u16) -> Vec<u8> {
    (0..n).flat_map(|v| (v * 100).to_le_bytes()).collect()
}

fn assert_volume_error(result: autostereo::Result<autostereo::volume::Volume>, expect: &str) {
    match result {
        Err(e @ (Error::Volume { .. } | Error::InvalidParameter { .. } | Error::Io { .. })) => {
            assert!(e.to_string().contains(expect), "'{e}' lacks '{expect}'")
        }
        other => panic!("expected an error containing '{expect}', got {other:?}"),
    }
}

#[test]
fn raw_reads_and_rejects_wrong_sizes() {
    let spec = RawSpec {
        dims: [4, 3, 2],
        kind: SampleType::U16,
        big_endian: false,
        spacing: [1.0, 2.0, 3.0],
        header_bytes: 0,
    };
    let path = write("ok.raw", &u16_samples(24));
    let v = load_raw(&path, &spec).unwrap();
    assert_eq!((v.dims, v.spacing), ([4, 3, 2], [1.0, 2.0, 3.0]));
    assert_eq!((v.data[0], v.data[23]), (0.0, 1.0)); // 16-bit: normalised by min..max
    assert_volume_error(
        load_raw(&write("short.raw", &u16_samples(23)), &spec),
        "truncated",
    );
    assert_volume_error(
        load_raw(&write("long.raw", &u16_samples(25)), &spec),
        "need 48",
    );
    let huge = RawSpec {
        dims: [1 << 20, 1 << 20, 1 << 20],
        ..spec
    };
    assert_volume_error(load_raw(&path, &huge), "more than");
    let zero = RawSpec {
        dims: [0, 3, 2],
        ..spec
    };
    assert_volume_error(load_raw(&path, &zero), "at least 1");
}

fn nrrd(header: &str, data: &[u8]) -> Vec<u8> {
    let mut out = header.as_bytes().to_vec();
    out.extend_from_slice(data);
    out
}

#[test]
fn nrrd_raw_gzip_and_detached() {
    let data = u16_samples(24);
    let header = "NRRD0004\ntype: unsigned short\ndimension: 3\nsizes: 4 3 2\nendian: little\nencoding: raw\nspacings: 0.5 0.5 2\n\n";
    let v = load_nrrd(&write("a.nrrd", &nrrd(header, &data))).unwrap();
    assert_eq!((v.dims, v.spacing), ([4, 3, 2], [0.5, 0.5, 2.0]));

    let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
    gz.write_all(&data).unwrap();
    let gz = gz.finish().unwrap();
    let header = "NRRD0004\n# comment\ntype: uint16\ndimension: 3\nsizes: 4 3 2\nendian: little\nencoding: gzip\nspace directions: (0.5,0,0) (0,0.5,0) (0,0,2)\n\n";
    let w = load_nrrd(&write("b.nrrd", &nrrd(header, &gz))).unwrap();
    assert_eq!(v, w);

    write("c.raw", &data);
    let header = "NRRD0004\ntype: ushort\ndimension: 3\nsizes: 4 3 2\nendian: little\nencoding: raw\nspacings: 0.5 0.5 2\ndata file: c.raw\n";
    assert_eq!(load_any(&write("c.nhdr", header.as_bytes())).unwrap(), v);

    let bytes: Vec<u8> = (0..24u8).collect();
    let header = "NRRD0005\ntype: uchar\ndimension: 3\nsizes: 4 3 2\nencoding: raw\n\n";
    let u8v = load_nrrd(&write("d.nrrd", &nrrd(header, &bytes))).unwrap();
    assert!((u8v.data[23] - 23.0 / 255.0).abs() < 1e-6); // 8-bit: normalised by 255
}

#[test]
fn nrrd_errors_name_the_problem() {
    let data = u16_samples(24);
    let good =
        "NRRD0004\ntype: short\ndimension: 3\nsizes: 4 3 2\nendian: little\nencoding: raw\n\n";
    let cases = [
        ("P5 not nrrd\n\n", "not a NRRD"),
        ("NRRD0004\ndimension: 3\nsizes: 4 3 2\nencoding: raw\n\n", "missing field 'type'"),
        ("NRRD0004\ntype: quaternion\ndimension: 3\n\n", "unsupported type"),
        ("NRRD0004\ntype: short\ndimension: 2\nsizes: 4 3\nendian: little\nencoding: raw\n\n", "not 3"),
        ("NRRD0004\ntype: short\ndimension: 3\nsizes: 4 3\nendian: little\nencoding: raw\n\n", "sizes has 2"),
        ("NRRD0004\ntype: short\ndimension: 3\nsizes: 4 3 2\nendian: little\nencoding: bzip2\n\n", "unsupported encoding"),
        ("NRRD0004\ntype: short\ndimension: 3\nsizes: 4 3 2\nencoding: raw\n\n", "endian"),
        ("NRRD0004\ntype: short\ndimension: 3\nsizes: 4 x 2\nendian: little\nencoding: raw\n\n", "bad sizes"),
        ("NRRD0004\ntype: short\ndimension: 3\nsizes: 4 3 2\nendian: little\nencoding: raw\nspacings: 1 0 1\n\n", "spacings"),
    ];
    for (i, (header, expect)) in cases.iter().enumerate() {
        assert_volume_error(
            load_nrrd(&write(&format!("bad{i}.nrrd"), &nrrd(header, &data))),
            expect,
        );
    }
    assert_volume_error(
        load_nrrd(&write("trunc.nrrd", &nrrd(good, &data[..40]))),
        "truncated",
    );
    let gz_header = good.replace("encoding: raw", "encoding: gzip");
    assert_volume_error(
        load_nrrd(&write(
            "trunc.gz.nrrd",
            &nrrd(&gz_header, &[0x1f, 0x8b, 8, 0, 0]),
        )),
        "gzip",
    );
    let detached = "NRRD0004\ntype: short\ndimension: 3\nsizes: 4 3 2\nendian: little\nencoding: raw\ndata file: missing.raw\n";
    assert_volume_error(
        load_nrrd(&write("missing.nhdr", detached.as_bytes())),
        "missing.raw",
    );
    let e = load_any(&write("x.vol", b"abc")).unwrap_err().to_string();
    assert!(
        e.contains("unknown format; read here:") && e.contains("volumes .nrrd"),
        "{e}"
    );
}

pub(crate) fn den(dims: [i16; 3], length: i32, big_endian: bool, data: &[u8]) -> Vec<u8> {
    let mut shorts = vec![1i16];
    for _ in 0..9 {
        shorts.extend_from_slice(&dims); // orig/extr/map × min/max/len: only map_len matters
    }
    shorts.push(0); // map_warps
    let mut out: Vec<u8> = shorts
        .iter()
        .flat_map(|s| {
            if big_endian {
                s.to_be_bytes()
            } else {
                s.to_le_bytes()
            }
        })
        .collect();
    out.extend(if big_endian {
        length.to_be_bytes()
    } else {
        length.to_le_bytes()
    });
    out.extend_from_slice(data);
    out
}

#[test]
fn den_reads_both_byte_orders_and_rejects_bad_headers() {
    let data: Vec<u8> = (0..60u8).collect();
    let a = load_den(&write("a.den", &den([5, 4, 3], 60, false, &data))).unwrap();
    let b = load_den(&write("b.den", &den([5, 4, 3], 60, true, &data))).unwrap();
    assert_eq!(a.dims, [5, 4, 3]);
    assert_eq!(a, b);
    assert!((a.data[59] - 59.0 / 255.0).abs() < 1e-6);
    assert_volume_error(load_den(&write("c.den", &[7, 7, 7])), "shorter than");
    let mut bad_magic = den([5, 4, 3], 60, false, &data);
    bad_magic[0] = 9;
    assert_volume_error(load_den(&write("d.den", &bad_magic)), "not a .den");
    assert_volume_error(
        load_den(&write("e.den", &den([5, 4, 3], 61, false, &data))),
        "inconsistent",
    );
    assert_volume_error(
        load_den(&write("f.den", &den([5, 4, 3], 60, false, &data[..50]))),
        "truncated",
    );
    assert_volume_error(
        load_den(&write("g.den", &den([5, -4, 3], -60, false, &data))),
        "invalid dimensions",
    );
}
