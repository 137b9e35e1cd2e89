//! The PLY reader (Stanford polygon format) every primitive reads PLY with: ASCII and binary
//! little/big endian. The `vertex` element gives the points (x y z; optional nx ny nz, red green blue, radius); other elements
//! (faces…) are skipped. Every count is checked against the bytes present before allocating.

mod body;
pub(crate) mod header;

use std::path::Path;

use glam::Vec3;

use self::body::{read_faces, read_vertices, skip_element, AsciiReader, BinaryReader, ValueReader};
use self::header::{parse_header, Format};
use crate::error::{Error, Result};

/// A PLY file's `vertex` element: positions, and whichever attributes it has (what
/// [`crate::points::PointCloud`] holds).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Vertices {
    /// Positions.
    pub positions: Vec<Vec3>,
    /// Normals, if given.
    pub normals: Option<Vec<Vec3>>,
    /// Linear RGB colours in [0, 1], if given.
    pub colors: Option<Vec<[f32; 3]>>,
    /// Radii, if given.
    pub radii: Option<Vec<f32>>,
}

/// Load the `vertex` element of a PLY file.
pub fn load(path: &Path) -> Result<Vertices> {
    let bytes = crate::file::read_bounded(path, crate::file::MAX_TEXT_BYTES, "the PLY limit")?;
    parse(&bytes).map_err(|reason| Error::Points {
        path: path.into(),
        reason,
    })
}

/// Parse PLY `bytes` (errors are plain reasons; [`load`] adds the path).
pub fn parse(bytes: &[u8]) -> std::result::Result<Vertices, String> {
    Ok(parse_elements(bytes, false)?.vertices)
}

/// A PLY file's `vertex` element and, when asked for, its `face` element's polygons as
/// triangles (fans, three vertex indices each).
pub(crate) struct PlyMesh {
    pub vertices: Vertices,
    pub triangles: Vec<u32>,
}

/// Parse PLY `bytes` with its faces (errors are plain reasons).
pub(crate) fn parse_mesh(bytes: &[u8]) -> std::result::Result<PlyMesh, String> {
    parse_elements(bytes, true)
}

/// How many faces the header of PLY `bytes` declares (a mesh's vertices read as points say so).
pub(crate) fn face_count(bytes: &[u8]) -> std::result::Result<usize, String> {
    let header = parse_header(bytes)?;
    Ok(header
        .elements
        .iter()
        .filter(|e| e.name == "face")
        .map(|e| e.count)
        .fold(0, usize::saturating_add))
}

/// The vertices and, with `faces`, the triangles; elements are read in the file's order (the
/// vertex count from the header, so faces may come first) and the others skipped.
fn parse_elements(bytes: &[u8], faces: bool) -> std::result::Result<PlyMesh, String> {
    let header = parse_header(bytes)?;
    let vertex = header
        .elements
        .iter()
        .find(|e| e.name == "vertex")
        .ok_or("no 'vertex' element")?;
    let body = &bytes[header.body_start..];
    let mut reader: Box<dyn ValueReader> = match header.format {
        Format::Ascii => Box::new(AsciiReader::new(body)?),
        f => Box::new(BinaryReader {
            bytes: body,
            at: 0,
            format: f,
        }),
    };
    let (mut vertices, mut triangles) = (None, Vec::new());
    for element in &header.elements {
        match element.name.as_str() {
            "vertex" if vertices.is_none() => {
                vertices = Some(read_vertices(reader.as_mut(), element)?);
                if !faces {
                    break;
                }
            }
            "face" if faces && triangles.is_empty() => {
                triangles = read_faces(reader.as_mut(), element, vertex.count)?;
            }
            "face" if faces => {
                triangles.extend(read_faces(reader.as_mut(), element, vertex.count)?);
            }
            _ => skip_element(reader.as_mut(), element)?,
        }
    }
    Ok(PlyMesh {
        vertices: vertices.ok_or("no 'vertex' element")?,
        triangles,
    })
}

/// The vertex properties that tell a 3DGS PLY from a point cloud's.
pub(crate) const GAUSSIAN_PROPERTIES: [&str; 4] = ["f_dc_0", "scale_0", "rot_0", "opacity"];

/// Which of [`GAUSSIAN_PROPERTIES`] the `vertex` element of the PLY header at the start of
/// `head` declares (`Err`: not a PLY header).
pub(crate) fn gaussian_properties(head: &[u8]) -> std::result::Result<Vec<&'static str>, String> {
    let header = parse_header(head)?;
    let Some(vertex) = header.elements.iter().find(|e| e.name == "vertex") else {
        return Ok(Vec::new());
    };
    Ok(GAUSSIAN_PROPERTIES
        .into_iter()
        .filter(|p| vertex.properties.iter().any(|q| q.name == *p))
        .collect())
}

#[cfg(test)]
mod tests {
    use glam::Vec3;

    use super::*;

    const ASCII: &str = "ply\nformat ascii 1.0\ncomment test\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0 255 0 0\n1 2 3 0 255 0\n3 0 1 1\n";

    #[test]
    fn ascii_with_colours() {
        let c = parse(ASCII.as_bytes()).unwrap();
        assert_eq!(c.positions, vec![Vec3::ZERO, Vec3::new(1.0, 2.0, 3.0)]);
        assert_eq!(c.colors.unwrap()[1], [0.0, 1.0, 0.0]);
        assert!(c.normals.is_none() && c.radii.is_none());
    }

    fn binary(big: bool) -> Vec<u8> {
        let format = if big { "big" } else { "little" };
        let mut b = format!("ply\nformat binary_{format}_endian 1.0\nelement face 1\nproperty list uchar int vertex_indices\nelement vertex 1\nproperty double x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\nproperty float nz\nproperty float radius\nend_header\n").into_bytes();
        let f = |v: f32| {
            if big {
                v.to_be_bytes()
            } else {
                v.to_le_bytes()
            }
        };
        b.push(2);
        for i in [7i32, 8] {
            b.extend(if big {
                i.to_be_bytes()
            } else {
                i.to_le_bytes()
            });
        }
        b.extend(if big {
            1.5f64.to_be_bytes()
        } else {
            1.5f64.to_le_bytes()
        });
        for v in [2.0, 3.0, 0.0, 0.0, 1.0, 0.25] {
            b.extend(f(v));
        }
        b
    }

    #[test]
    fn binary_both_endians_after_a_list_element() {
        for big in [false, true] {
            let c = parse(&binary(big)).unwrap();
            assert_eq!(c.positions, vec![Vec3::new(1.5, 2.0, 3.0)]);
            assert_eq!(c.normals.unwrap(), vec![Vec3::Z]);
            assert_eq!(c.radii.unwrap(), vec![0.25]);
        }
    }

    #[test]
    fn malformed_inputs_are_errors() {
        let mut truncated = binary(false);
        truncated.truncate(truncated.len() - 3);
        let huge = ASCII.replace("vertex 2", "vertex 999999999999");
        let no_z = ASCII.replace("property float z\n", "");
        let nan = ASCII.replace("1 2 3", "1 nan 3");
        let cases: Vec<(Vec<u8>, &str)> = vec![
            (b"hello".to_vec(), "not a PLY"),
            (truncated, "truncated"),
            (huge.into_bytes(), "truncated"),
            (no_z.into_bytes(), "x, y and z"),
            (nan.into_bytes(), "non-finite"),
            (
                ASCII.replace("ascii", "utf9").into_bytes(),
                "unknown format",
            ),
            (
                ASCII.replace("uchar red", "quad red").into_bytes(),
                "unknown property type",
            ),
            (
                ASCII.replace("255 0 0", "255 x 0").into_bytes(),
                "not a number",
            ),
            (
                ASCII.replace("end_header", "end_headr").into_bytes(),
                "end_header",
            ),
            (
                ASCII
                    .replace("comment test", "comment no end_header here")
                    .replace("end_header\n0", "end_headr\n0")
                    .into_bytes(),
                "end_header",
            ),
            (
                ASCII
                    .replace("property float z", "property float x")
                    .into_bytes(),
                "twice",
            ),
        ];
        for (bytes, expected) in cases {
            let err = parse(&bytes).unwrap_err();
            assert!(err.contains(expected), "{err} lacks '{expected}'");
        }
    }
}
