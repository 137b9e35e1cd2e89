//! Wavefront OBJ loading through tobj.

use std::path::Path;

use glam::Vec3;

use super::{Mesh, DEFAULT_COLOR};
use crate::error::{Error, Result};

pub(super) fn load(path: &Path) -> Result<Mesh> {
    let fail = |reason: String| Error::Mesh {
        path: path.to_path_buf(),
        reason,
    };
    if !path.is_file() {
        return Err(fail("no such file".into()));
    }
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ignore_points: true,
        ignore_lines: true,
    };
    let (models, materials) =
        tobj::load_obj(path, &options).map_err(|e| fail(format!("malformed OBJ: {e}")))?;
    let materials = materials.unwrap_or_else(|e| {
        log::warn!(
            "{}: materials not loaded ({e}); using the default colour",
            path.display()
        );
        Vec::new()
    });
    let mut mesh = Mesh::default();
    let mut has_normals = true;
    for model in &models {
        let m = &model.mesh;
        let n = m.positions.len() / 3;
        let base = mesh.positions.len() as u32;
        let material_color = m
            .material_id
            .and_then(|id| materials.get(id))
            .and_then(|mat| mat.diffuse)
            .map(|[r, g, b]| [r, g, b, 1.0]);
        mesh.positions.extend(
            m.positions
                .chunks_exact(3)
                .map(|p| Vec3::new(p[0], p[1], p[2])),
        );
        if m.normals.len() == m.positions.len() {
            mesh.normals.extend(
                m.normals
                    .chunks_exact(3)
                    .map(|p| Vec3::new(p[0], p[1], p[2])),
            );
        } else {
            has_normals = false;
            mesh.normals.extend(std::iter::repeat_n(Vec3::Z, n));
        }
        if m.vertex_color.len() == m.positions.len() {
            mesh.colors.extend(
                m.vertex_color
                    .chunks_exact(3)
                    .map(|c| [c[0], c[1], c[2], 1.0]),
            );
        } else {
            mesh.colors.extend(std::iter::repeat_n(
                material_color.unwrap_or(DEFAULT_COLOR),
                n,
            ));
        }
        if let Some(&bad) = m.indices.iter().find(|&&i| i as usize >= n) {
            return Err(fail(format!("face index {} beyond {n} vertices", bad + 1)));
        }
        mesh.indices.extend(m.indices.iter().map(|i| i + base));
    }
    if mesh.indices.is_empty() {
        return Err(fail("no triangles".into()));
    }
    if !has_normals {
        mesh.compute_normals();
    }
    for n in &mut mesh.normals {
        *n = n.try_normalize().unwrap_or(Vec3::Z);
    }
    mesh.validate().map_err(|e| fail(e.to_string()))?;
    Ok(mesh)
}
