//! PLY meshes: the `vertex` element (x y z; nx ny nz and red green blue when present) and the
//! `face` element's polygons as triangle fans, read by the point clouds' PLY reader
//! (src/points/ply), so that ASCII and both binary byte orders, and the size checks before
//! allocating, are the same code for points and meshes.

use std::path::Path;

use glam::Vec3;

use crate::error::{Error, Result};
use crate::mesh::{Mesh, DEFAULT_COLOR};

/// Peak CPU bytes per PLY file byte: at most the OBJ's (a binary vertex takes 12 bytes and
/// costs ≈ 112, a binary triangle 13 and costs ≈ 24; src/mesh/load/obj.rs).
const MESH_PEAK_PER_PLY_BYTE: u64 = super::obj::MESH_PEAK_PER_OBJ_BYTE;

/// Load a PLY mesh; a file without faces is refused as points (`Error::WrongKind`).
pub(super) fn load(path: &Path) -> Result<Mesh> {
    let bytes = crate::file::read_bounded(path, crate::file::MAX_TEXT_BYTES, "the PLY limit")?;
    let size = bytes.len() as u64;
    crate::budget::check(
        || format!("a PLY mesh of {size} bytes ({MESH_PEAK_PER_PLY_BYTE} bytes of memory per file byte)"),
        size.saturating_mul(MESH_PEAK_PER_PLY_BYTE),
    )
    .map_err(|e| fail(path, e.to_string()))?;
    parse(&bytes, path)
}

/// Parse PLY `bytes` as a mesh (`path` names it in errors).
pub(super) fn parse(bytes: &[u8], path: &Path) -> Result<Mesh> {
    let ply = crate::io::ply::parse_mesh(bytes).map_err(|e| fail(path, e))?;
    if ply.triangles.is_empty() {
        return Err(crate::Error::WrongKind {
            path: path.into(),
            holds: crate::formats::DataKind::Points,
            wanted: Some(crate::formats::DataKind::Mesh),
            detail: format!(
                "PLY: no faces with three or more corners, {} vertices",
                ply.vertices.positions.len()
            ),
        });
    }
    let cloud = ply.vertices;
    let n = cloud.positions.len();
    let mut mesh = Mesh {
        normals: match &cloud.normals {
            Some(normals) => normals.clone(),
            None => vec![Vec3::Z; n],
        },
        colors: match &cloud.colors {
            Some(colors) => colors.iter().map(|&[r, g, b]| [r, g, b, 1.0]).collect(),
            None => vec![DEFAULT_COLOR; n],
        },
        positions: cloud.positions,
        indices: ply.triangles,
        ..Mesh::default()
    };
    if cloud.normals.is_none() {
        mesh.compute_normals();
    }
    for normal in &mut mesh.normals {
        *normal = normal.try_normalize().unwrap_or(Vec3::Z);
    }
    mesh.validate().map_err(|e| fail(path, e.to_string()))?;
    Ok(mesh)
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

    #[test]
    fn polygons_become_fans_and_colours_and_normals_are_kept() {
        let text = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n\
                    property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n\
                    element face 2\nproperty list uchar int vertex_indices\nend_header\n\
                    0 0 0 255 0 0\n1 0 0 0 255 0\n1 1 0 0 0 255\n0 1 0 255 255 255\n4 0 1 2 3\n2 0 1\n";
        let mesh = parse(text.as_bytes(), Path::new("quad.ply")).unwrap();
        // The quad is two triangles; the two-corner face is none.
        assert_eq!(mesh.indices, vec![0, 1, 2, 0, 2, 3]);
        assert_eq!(mesh.colors[1], [0.0, 1.0, 0.0, 1.0]);
        assert!(
            mesh.normals.iter().all(|n| n.z.abs() > 0.99),
            "{:?}",
            mesh.normals
        );
    }

    #[test]
    fn a_cloud_without_faces_is_refused_as_points() {
        let text = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n\
                    property float z\nend_header\n0 0 0\n";
        let e = parse(text.as_bytes(), Path::new("cloud.ply"))
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("cloud.ply: this is a point cloud (PLY: no faces with three or more corners, 1 vertices), not a mesh"),
            "{e}"
        );
    }

    #[test]
    fn corners_beyond_the_vertices_are_refused() {
        let text = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
                    property float z\nelement face 1\nproperty list uchar int vertex_indices\n\
                    end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n";
        let e = parse(text.as_bytes(), Path::new("bad.ply"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("corner 3 is not one of the 3 vertices"), "{e}");
    }
}
