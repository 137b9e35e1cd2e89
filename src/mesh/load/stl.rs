//! STL meshes, binary and ASCII, through the `stl_io` crate. STL has no colours (the
//! [`DEFAULT_COLOR`]) and its facet normals are per face: vertex normals are computed from
//! the triangles (shared corners merged by `stl_io`), as for an OBJ without normals.

use std::path::Path;

use glam::Vec3;

use crate::error::{Error, Result};
use crate::mesh::{Mesh, DEFAULT_COLOR};

/// Bytes of a binary STL's header and triangle count, and of each triangle.
const BINARY_HEADER: u64 = 84;
const BINARY_TRIANGLE: u64 = 50;
/// Peak CPU bytes per file byte: a binary triangle (50 bytes) costs at most three vertices
/// (≈ 112 bytes each) and its indices; an ASCII triangle takes ≥ 100 bytes.
const MESH_PEAK_PER_STL_BYTE: u64 = 8;

/// Load an STL file.
pub(super) fn load(path: &Path) -> Result<Mesh> {
    let bytes = crate::file::read_bounded(path, crate::file::MAX_TEXT_BYTES, "the STL limit")?;
    let size = bytes.len() as u64;
    crate::budget::check(
        || {
            format!(
                "an STL of {size} bytes ({MESH_PEAK_PER_STL_BYTE} bytes of memory per file byte)"
            )
        },
        size.saturating_mul(MESH_PEAK_PER_STL_BYTE),
    )
    .map_err(|e| fail(path, e.to_string()))?;
    parse(&bytes, path)
}

/// Parse STL `bytes` (`path` names it in errors).
pub(super) fn parse(bytes: &[u8], path: &Path) -> Result<Mesh> {
    check_binary_count(bytes).map_err(|e| fail(path, e))?;
    let stl = stl_io::read_stl(&mut std::io::Cursor::new(as_read_by_stl_io(bytes)))
        .map_err(|e| fail(path, format!("malformed STL: {e}")))?;
    if stl.faces.is_empty() {
        return Err(fail(path, "no triangles"));
    }
    let positions: Vec<Vec3> = stl
        .vertices
        .iter()
        .map(|v| Vec3::new(v[0], v[1], v[2]))
        .collect();
    if let Some(i) = positions.iter().position(|p| !p.is_finite()) {
        return Err(fail(
            path,
            format!("vertex {i} is not finite: {}", positions[i]),
        ));
    }
    let n = positions.len();
    let mut indices = Vec::with_capacity(stl.faces.len() * 3);
    for face in &stl.faces {
        for &v in &face.vertices {
            indices.push(u32::try_from(v).map_err(|_| fail(path, "more than 2^32 vertices"))?);
        }
    }
    let mut mesh = Mesh {
        positions,
        normals: vec![Vec3::Z; n],
        colors: vec![DEFAULT_COLOR; n],
        indices,
        ..Mesh::default()
    };
    mesh.compute_normals();
    for normal in &mut mesh.normals {
        *normal = normal.try_normalize().unwrap_or(Vec3::Z);
    }
    mesh.validate().map_err(|e| fail(path, e.to_string()))?;
    Ok(mesh)
}

/// A binary STL holds the triangles its header counts: a file that does not start as an ASCII
/// one does (`solid`) and is shorter than its count says is refused as truncated, by name,
/// before the reader runs out of bytes half-way. (`stl_io` reserves nothing by that count.)
fn check_binary_count(bytes: &[u8]) -> std::result::Result<(), String> {
    if bytes.starts_with(b"solid") {
        return Ok(()); // ASCII, or binary whose header starts so: the reader tells them apart
    }
    let count = bytes
        .get(80..84)
        .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as u64)
        .ok_or_else(|| format!("{} bytes: shorter than a binary STL header", bytes.len()))?;
    let expected = BINARY_HEADER + count * BINARY_TRIANGLE;
    if (bytes.len() as u64) < expected {
        return Err(format!(
            "truncated: the header says {count} triangles ({expected} bytes) but the file has {}",
            bytes.len()
        ));
    }
    Ok(())
}

/// `bytes` as `stl_io` will read them right: it takes a file starting with `solid ` for ASCII
/// and anything else for binary, but binary files whose 80-byte header starts with `solid`
/// exist (several CAD exporters write them), and ASCII files may have `solid` alone on its
/// line. A file whose size is exactly a binary STL's for its count is binary; one that starts
/// with `solid` otherwise is ASCII.
fn as_read_by_stl_io(bytes: &[u8]) -> std::borrow::Cow<'_, [u8]> {
    let binary_size = bytes.get(80..84).map(|c| {
        BINARY_HEADER + u64::from(u32::from_le_bytes([c[0], c[1], c[2], c[3]])) * BINARY_TRIANGLE
    });
    let solid = bytes.starts_with(b"solid");
    if solid && binary_size == Some(bytes.len() as u64) {
        let mut copy = bytes.to_vec();
        copy[0] = b'S'; // no longer `solid `: read as binary (the header is not used)
        return copy.into();
    }
    if solid && bytes.get(5) != Some(&b' ') {
        let mut copy = b"solid ".to_vec();
        copy.extend_from_slice(&bytes[5..]);
        return copy.into();
    }
    bytes.into()
}

fn fail(path: &Path, reason: impl Into<String>) -> Error {
    Error::Mesh {
        path: path.to_path_buf(),
        reason: reason.into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A binary STL of `triangles` (normal zero; stl_io recomputes nothing).
    pub(crate) fn binary(triangles: &[[[f32; 3]; 3]]) -> Vec<u8> {
        let mut b = vec![0u8; 80];
        b.extend((triangles.len() as u32).to_le_bytes());
        for t in triangles {
            b.extend([0u8; 12]);
            for v in t {
                for c in v {
                    b.extend(c.to_le_bytes());
                }
            }
            b.extend([0u8; 2]);
        }
        b
    }

    #[test]
    fn binary_and_ascii_give_the_same_mesh() {
        let quad = [
            [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0]],
            [[0.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]],
        ];
        let from_binary = parse(&binary(&quad), Path::new("quad.stl")).unwrap();
        let ascii =
            "solid quad\r\nfacet normal 0 0 1\r\nouter loop\r\nvertex 0 0 0\r\nvertex 1 0 0\r\n\
                     vertex 1 1 0\r\nendloop\r\nendfacet\r\nfacet normal 0 0 1\r\nouter loop\r\n\
                     vertex 0 0 0\r\nvertex 1 1 0\r\nvertex 0 1 0\r\nendloop\r\nendfacet\r\n\
                     endsolid quad\r\n";
        let from_ascii = parse(ascii.as_bytes(), Path::new("quad.stl")).unwrap();
        assert_eq!(from_binary, from_ascii);
        // Shared corners are merged: 4 vertices, 2 triangles.
        assert_eq!(from_binary.positions.len(), 4);
        assert_eq!(from_binary.triangle_count(), 2);
    }

    #[test]
    fn a_binary_header_starting_with_solid_and_a_bare_solid_line_are_read() {
        let triangle = [[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]];
        let mut cad = binary(&triangle);
        cad[..11].copy_from_slice(b"solid part ");
        assert_eq!(
            parse(&cad, Path::new("cad.stl")).unwrap().triangle_count(),
            1
        );
        let bare = "solid\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n\
                    vertex 0 1 0\nendloop\nendfacet\nendsolid\n";
        assert_eq!(
            parse(bare.as_bytes(), Path::new("bare.stl"))
                .unwrap()
                .triangle_count(),
            1
        );
    }

    #[test]
    fn a_count_beyond_the_data_is_refused_before_reading() {
        let mut b = binary(&[[[0.0; 3]; 3]]);
        b[80..84].copy_from_slice(&u32::MAX.to_le_bytes());
        let e = parse(&b, Path::new("big.stl")).unwrap_err().to_string();
        assert!(
            e.contains("truncated") && e.contains("4294967295 triangles"),
            "{e}"
        );
        let e = parse(b"abc", Path::new("tiny.stl"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("shorter than a binary STL header"), "{e}");
    }
}
