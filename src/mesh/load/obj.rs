//! Wavefront OBJ loading through tobj; materials (`mtllib`) read here, never by tobj.
//!
//! tobj's MTL parser panics on a colour line with fewer than three numbers, and it opens
//! whatever `mtllib` names (a FIFO, `/dev/zero`). So the OBJ text is read by
//! `crate::file::read_text` (a regular file, bounded; BOM, CR and CRLF line ends handled) and
//! handed to tobj from memory, and the one material property used, the diffuse colour `Kd`,
//! comes from [`load_mtl`].

use std::cell::RefCell;
use std::collections::HashMap;
use std::path::Path;

use glam::Vec3;

use crate::error::{Error, Result};
use crate::mesh::{Mesh, DEFAULT_COLOR};

/// Peak CPU bytes per OBJ file byte: a vertex or face line takes at least 8 bytes; a vertex
/// costs ≈ 112 bytes (tobj's arrays, the mesh's positions, normals and colours, the uploaded
/// vertex) and a triangle ≈ 24: an upper bound of 17 per byte, checked before parsing.
pub(crate) const MESH_PEAK_PER_OBJ_BYTE: u64 = 17;

pub(super) fn load(path: &Path) -> Result<Mesh> {
    let fail = |reason: String| Error::Mesh {
        path: path.to_path_buf(),
        reason,
    };
    if !path.exists() {
        return Err(fail("no such file".into()));
    }
    let text = crate::file::read_text(path)?;
    let bytes = text.len() as u64;
    crate::budget::check(
        || {
            format!(
                "an OBJ of {bytes} bytes (up to {} vertices and triangles, {MESH_PEAK_PER_OBJ_BYTE} \
                 bytes of memory per file byte)",
                bytes / 8
            )
        },
        bytes.saturating_mul(MESH_PEAK_PER_OBJ_BYTE),
    )
    .map_err(|e| fail(e.to_string()))?;
    parse(&text, path, Some(path.parent().unwrap_or(Path::new("."))))
}

/// Parse OBJ `text` (`path` names it in errors); `mtllib` files are read from `materials`,
/// or ignored when it is `None` (text from memory, e.g. the fuzz targets).
pub(super) fn parse(text: &str, path: &Path, materials: Option<&Path>) -> Result<Mesh> {
    let fail = |reason: String| Error::Mesh {
        path: path.to_path_buf(),
        reason,
    };
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ignore_points: true,
        ignore_lines: true,
    };
    let material_problems = RefCell::new(Vec::new());
    let (models, materials) = tobj::load_obj_buf(&mut text.as_bytes(), &options, |mtl| {
        let Some(dir) = materials else {
            return Err(tobj::LoadError::OpenFileFailed);
        };
        match load_mtl(&dir.join(mtl)) {
            Ok((materials, names)) => Ok((materials, names.into_iter().collect())),
            Err(e) => {
                material_problems.borrow_mut().push(e.to_string());
                Err(tobj::LoadError::MaterialParseError)
            }
        }
    })
    .map_err(|e| fail(format!("malformed OBJ: {e}")))?;
    let materials = materials.unwrap_or_else(|_| {
        if material_problems.borrow().is_empty() {
            return Vec::new(); // none named, or not read (text from memory)
        }
        log::warn!(
            "{}: materials not loaded ({}); using the default colour",
            path.display(),
            material_problems.borrow().join("; ")
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

/// The materials of an MTL file, with only what the renderers use: name and diffuse colour.
fn load_mtl(path: &Path) -> Result<(Vec<tobj::Material>, HashMap<String, usize>)> {
    parse_mtl(&crate::file::read_text(path)?, path)
}

/// Parse MTL `text` (`path` names it in errors).
pub(super) fn parse_mtl(
    text: &str,
    path: &Path,
) -> Result<(Vec<tobj::Material>, HashMap<String, usize>)> {
    let fail = |line: usize, reason: String| Error::Mesh {
        path: path.to_path_buf(),
        reason: format!("MTL line {line}: {reason}"),
    };
    let mut materials: Vec<tobj::Material> = Vec::new();
    let mut names = HashMap::new();
    for (i, line) in text.lines().enumerate() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("newmtl") => {
                let name = words.collect::<Vec<_>>().join(" ");
                if name.is_empty() {
                    return Err(fail(i + 1, "newmtl without a name".into()));
                }
                names.insert(name.clone(), materials.len());
                materials.push(tobj::Material {
                    name,
                    ..Default::default()
                });
            }
            Some("Kd") => {
                let values: Vec<f32> = words.filter_map(|w| w.parse().ok()).collect();
                let rgb = match values[..] {
                    [r, g, b] if values.iter().all(|v| v.is_finite()) => [r, g, b],
                    _ => {
                        return Err(fail(
                            i + 1,
                            format!(
                                "Kd needs three finite numbers: {}",
                                crate::error::quote(line)
                            ),
                        ))
                    }
                };
                match materials.last_mut() {
                    Some(material) => material.diffuse = Some(rgb),
                    None => return Err(fail(i + 1, "Kd before any newmtl".into())),
                }
            }
            Some("map_Kd") => {
                let material = materials.last().map_or("(none)", |m| m.name.as_str());
                log::warn!(
                    "{}: material {material}'s texture {} is not shown (the renderers draw \
                     vertex and material colours only; its Kd colour is used)",
                    path.display(),
                    words.collect::<Vec<_>>().join(" ")
                );
            }
            _ => {}
        }
    }
    Ok((materials, names))
}
