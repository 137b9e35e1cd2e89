#![cfg(feature = "vti")]
//! VTK image data (feature `vti`): the voxels of tests/formats/volume_formats.rs written as XML `.vti`
//! — ascii, inline base64 (header and data encoded apart, as VTK writes them, or together),
//! zlib blocks with UInt64 headers, appended raw and base64, big-endian — and as legacy `.vtk`
//! (ASCII, BINARY) load to what a NRRD without `space` of them loads to; a `Direction` places
//! the voxel axes (VTK's world shown x right, y up, z toward the viewer); broken files are
//! refused by name.

use crate::common;

use std::io::Write;
use std::path::PathBuf;

use autostereo::volume::load::load_any;
use glam::{Mat3, Vec3};

fn write(name: &str, bytes: &[u8]) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("volume_vtk");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, bytes).unwrap();
    path
}

/// The voxels of tests/formats/volume_formats.rs: 5 × 4 × 3 i16 values past 8 bits.
fn voxels() -> Vec<i16> {
    (0..60).map(|i| (i * 37 % 61) as i16 * 20 - 400).collect()
}

fn bytes(big: bool) -> Vec<u8> {
    voxels()
        .iter()
        .flat_map(|x| {
            if big {
                x.to_be_bytes()
            } else {
                x.to_le_bytes()
            }
        })
        .collect()
}

fn nrrd() -> Vec<u8> {
    let mut b = b"NRRD0004\ntype: short\ndimension: 3\nsizes: 5 4 3\nspacings: 0.5 0.75 2\n\
        endian: little\nencoding: raw\n\n"
        .to_vec();
    b.extend(bytes(false));
    b
}

/// Standard base64 with padding (written here, so that the reader is not its own oracle).
fn base64(data: &[u8]) -> String {
    const A: &[u8] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut s = String::new();
    for c in data.chunks(3) {
        let n = c.len();
        let byte = |i: usize| u32::from(c.get(i).copied().unwrap_or(0));
        let v = (byte(0) << 16) | (byte(1) << 8) | byte(2);
        for i in 0..4 {
            s.push(if i <= n {
                A[((v >> (18 - 6 * i)) & 63) as usize] as char
            } else {
                '='
            });
        }
    }
    s
}

fn zlib(bytes: &[u8]) -> Vec<u8> {
    let mut e = flate2::write::ZlibEncoder::new(Vec::new(), flate2::Compression::fast());
    e.write_all(bytes).unwrap();
    e.finish().unwrap()
}

/// How a `.vti` stores its array.
#[derive(Clone, Copy)]
pub(crate) struct Vti {
    /// `ascii`, `binary` or `appended`.
    format: &'static str,
    /// Appended data as base64 (else raw).
    base64: bool,
    /// Binary header and data base64-encoded together (else apart, as VTK does).
    together: bool,
    header64: bool,
    zlib: bool,
    big: bool,
}

pub(crate) const ASCII: Vti = Vti {
    format: "ascii",
    base64: false,
    together: false,
    header64: false,
    zlib: false,
    big: false,
};

impl Vti {
    fn word(&self, x: u64) -> Vec<u8> {
        match (self.header64, self.big) {
            (true, false) => x.to_le_bytes().to_vec(),
            (true, true) => x.to_be_bytes().to_vec(),
            (false, false) => (x as u32).to_le_bytes().to_vec(),
            (false, true) => (x as u32).to_be_bytes().to_vec(),
        }
    }

    /// An array's binary header and data: a byte count, or zlib blocks of 32 bytes.
    fn blob(&self, data: &[u8]) -> (Vec<u8>, Vec<u8>) {
        if !self.zlib {
            return (self.word(data.len() as u64), data.to_vec());
        }
        let blocks: Vec<Vec<u8>> = data.chunks(32).map(zlib).collect();
        let last = data.len() % 32;
        let mut header = [blocks.len() as u64, 32, last as u64]
            .iter()
            .flat_map(|&w| self.word(w))
            .collect::<Vec<u8>>();
        for b in &blocks {
            header.extend(self.word(b.len() as u64));
        }
        (header, blocks.concat())
    }

    fn encoded(&self, data: &[u8]) -> String {
        let (header, data) = self.blob(data);
        if self.together {
            base64(&[header, data].concat())
        } else {
            base64(&header) + &base64(&data)
        }
    }

    /// The file, with `image` as extra `ImageData` attributes (`Direction`).
    pub(crate) fn file(&self, image: &str) -> Vec<u8> {
        let data = bytes(self.big);
        // Another array before the scalars (the one `Scalars` names is read).
        let other = vec![7u8; 12];
        let (array, appended) = match self.format {
            "ascii" => {
                let text: Vec<String> = voxels().iter().map(|v| v.to_string()).collect();
                (format!("format=\"ascii\">\n{}\n", text.join(" ")), None)
            }
            "binary" => (
                format!("format=\"binary\">\n  {}\n", self.encoded(&data)),
                None,
            ),
            _ => {
                let (first, ours) = if self.base64 {
                    let (a, b) = (self.encoded(&other), self.encoded(&data));
                    (a.clone().into_bytes(), [a, b].concat().into_bytes())
                } else {
                    let (h, d) = self.blob(&other);
                    let (a, b) = ([h, d].concat(), self.blob(&data));
                    (a.clone(), [a, b.0, b.1].concat())
                };
                (
                    format!("format=\"appended\" offset=\"{}\"/>", first.len()),
                    Some(ours),
                )
            }
        };
        let array = if array.ends_with("/>") {
            array
        } else {
            array + "</DataArray>"
        };
        let other_array = if appended.is_some() {
            "<DataArray type=\"UInt8\" Name=\"other\" format=\"appended\" offset=\"0\"/>"
        } else {
            "<DataArray type=\"UInt8\" Name=\"other\" format=\"ascii\">7 7 7 7 7 7 7 7 7 7 7 7\
             </DataArray>"
        };
        let mut b = format!(
            "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"1.0\" \
             byte_order=\"{}\" header_type=\"{}\"{}>\n  <ImageData WholeExtent=\"0 4 0 3 0 2\" \
             Origin=\"-1 2 3\" Spacing=\"0.5 0.75 2\"{image}>\n    <Piece Extent=\"0 4 0 3 0 2\">\n\
             <PointData Scalars=\"density\">\n{other_array}\n\
             <DataArray type=\"Int16\" Name=\"density\" NumberOfComponents=\"1\" {array}\n\
             </PointData>\n<CellData/>\n</Piece>\n</ImageData>\n",
            if self.big {
                "BigEndian"
            } else {
                "LittleEndian"
            },
            if self.header64 { "UInt64" } else { "UInt32" },
            if self.zlib {
                " compressor=\"vtkZLibDataCompressor\""
            } else {
                ""
            },
        )
        .into_bytes();
        if let Some(data) = appended {
            let encoding = if self.base64 { "base64" } else { "raw" };
            b.extend(format!("<AppendedData encoding=\"{encoding}\">\n   _").bytes());
            b.extend(data);
            b.extend(b"\n</AppendedData>\n");
        }
        b.extend(b"</VTKFile>\n");
        b
    }
}

pub(crate) fn legacy(binary: bool) -> Vec<u8> {
    let mut b = format!(
        "# vtk DataFile Version 3.0\nscan\n{}\nDATASET STRUCTURED_POINTS\nDIMENSIONS 5 4 3\n\
         SPACING 0.5 0.75 2\nORIGIN 0 0 0\nPOINT_DATA 60\nSCALARS density short 1\n\
         LOOKUP_TABLE default\n",
        if binary { "BINARY" } else { "ASCII" }
    )
    .into_bytes();
    if binary {
        b.extend(bytes(true));
    } else {
        for row in voxels().chunks(9) {
            let text: Vec<String> = row.iter().map(|v| v.to_string()).collect();
            b.extend(format!("{}\n", text.join(" ")).bytes());
        }
    }
    b
}

#[test]
fn vtk_image_data_loads_like_the_nrrd_of_the_same_voxels() {
    let reference = load_any(&write("scan.nrrd", &nrrd())).unwrap();
    assert_eq!(reference.axes, Mat3::IDENTITY);
    let binary = Vti {
        format: "binary",
        ..ASCII
    };
    let appended = Vti {
        format: "appended",
        ..ASCII
    };
    let files = [
        ("ascii.vti", ASCII.file("")),
        ("binary.vti", binary.file("")),
        (
            "binary_together.vti",
            Vti {
                together: true,
                ..binary
            }
            .file(""),
        ),
        (
            "binary_zlib64.vti",
            Vti {
                zlib: true,
                header64: true,
                ..binary
            }
            .file(""),
        ),
        ("appended_raw.vti", appended.file("")),
        (
            "appended_base64.vti",
            Vti {
                base64: true,
                ..appended
            }
            .file(""),
        ),
        (
            "appended_zlib_be.vti",
            Vti {
                zlib: true,
                big: true,
                ..appended
            }
            .file(""),
        ),
        (
            "binary_be.vti",
            Vti {
                big: true,
                ..binary
            }
            .file(""),
        ),
        (
            "identity.vti",
            ASCII.file(" Direction=\"1 0 0 0 1 0 0 0 1\""),
        ),
        ("ascii.vtk", legacy(false)),
        ("binary.vtk", legacy(true)),
    ];
    for (name, bytes) in &files {
        let volume = load_any(&write(name, bytes)).unwrap_or_else(|e| panic!("{name}: {e}"));
        common::assert_same_volume(name, &volume, &reference);
    }
    // A legacy file named .vti, and an XML one named .vtk: told by their first bytes.
    for (name, bytes) in [("legacy.vti", legacy(true)), ("xml.vtk", binary.file(""))] {
        common::assert_same_volume(name, &load_any(&write(name, &bytes)).unwrap(), &reference);
    }
}

/// `Direction` (row-major: column a is voxel axis a's direction) places the voxel axes on
/// screen as ParaView shows VTK's world: x right, y up, z toward the viewer.
#[test]
fn a_direction_places_the_voxel_axes() {
    let reference = load_any(&write("plain.nrrd", &nrrd())).unwrap();
    // i along z (toward the viewer), j along x (right), k along y (up).
    let file = ASCII.file(" Direction=\"0 1 0  0 0 1  1 0 0\"");
    let volume = load_any(&write("permuted.vti", &file)).unwrap();
    assert_eq!(volume.axes, Mat3::from_cols(Vec3::Z, Vec3::X, Vec3::Y));
    assert_eq!(volume.dims, reference.dims);
    assert_eq!(volume.spacing, reference.spacing);
    assert_eq!(volume.data, reference.data);
    // On screen: k's 3 × 2 = 6 high, j's 4 × 0.75 = 3 wide, i's 5 × 0.5 = 2.5 deep.
    let bounds = volume.bounds();
    assert!(
        (bounds.max - Vec3::new(1.5, 3.0, 1.25)).abs().max_element() < 1e-6,
        "{bounds:?}"
    );
    // A negative spacing turns its axis around, with or without a Direction.
    let flipped = String::from_utf8(ASCII.file(""))
        .unwrap()
        .replace("Spacing=\"0.5 0.75 2\"", "Spacing=\"0.5 -0.75 2\"");
    let volume = load_any(&write("flipped.vti", flipped.as_bytes())).unwrap();
    assert_eq!(volume.axes, Mat3::from_cols(Vec3::X, -Vec3::Y, Vec3::Z));
    assert_eq!(volume.spacing, reference.spacing);
}

#[test]
fn broken_vtk_files_are_refused_by_name() {
    let text = |v: Vti| String::from_utf8(v.file("")).unwrap();
    let ascii = text(ASCII);
    let zlib = text(Vti {
        format: "binary",
        zlib: true,
        ..ASCII
    });
    let cases: Vec<(&str, Vec<u8>, &str)> = vec![
        (
            "no_extent.vti",
            ascii
                .replace("WholeExtent=\"0 4 0 3 0 2\"", "")
                .into_bytes(),
            "missing WholeExtent",
        ),
        (
            "few.vti",
            ascii.replace("\n-400 ", "\n").into_bytes(),
            "too few values: 59 of 60",
        ),
        (
            "type.vti",
            ascii.replace("\"Int16\"", "\"Int128\"").into_bytes(),
            "type 'Int128' is not read",
        ),
        (
            "int64.vti",
            ascii.replace("\"Int16\"", "\"Int64\"").into_bytes(),
            "Int64: 64-bit integers are not read",
        ),
        (
            "vectors.vti",
            ascii
                .replace("NumberOfComponents=\"1\"", "NumberOfComponents=\"3\"")
                .into_bytes(),
            "'density' has 3 components",
        ),
        (
            "sheared.vti",
            text(ASCII)
                .replace("Spacing", "Direction=\"1 0.3 0 0 1 0 0 0 1\" Spacing")
                .into_bytes(),
            "right angles",
        ),
        (
            "cut_block.vti",
            {
                // Cut 6 bytes (8 base64 characters) off the last zlib block.
                let end = zlib.find("\n</DataArray>").unwrap();
                format!("{}{}", &zlib[..end - 8], &zlib[end..]).into_bytes()
            },
            "truncated",
        ),
        (
            "cells.vti",
            ascii
                .replace("<PointData Scalars=\"density\">", "<CellData>")
                .replace("</PointData>\n<CellData/>", "</CellData>")
                .into_bytes(),
            "CellData only",
        ),
        (
            "mesh.vtk",
            String::from_utf8(legacy(false))
                .unwrap()
                .replace("STRUCTURED_POINTS", "POLYDATA")
                .into_bytes(),
            "DATASET POLYDATA: a mesh/polydata, not image data",
        ),
        ("short.vtk", legacy(true)[..250].to_vec(), "truncated"),
    ];
    for (name, bytes, expected) in cases {
        let e = load_any(&write(name, &bytes)).unwrap_err().to_string();
        assert!(
            e.contains(expected) && e.contains(name),
            "{name}: '{e}' lacks '{expected}'"
        );
    }
}
