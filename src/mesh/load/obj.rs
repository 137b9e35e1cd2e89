//! Wavefront OBJ loading through tobj; materials (`mtllib`) read here, never by tobj.
//!
//! tobj's MTL parser panics on a colour line with fewer than three numbers, and it opens
//! whatever `mtllib` names (a FIFO, `/dev/zero`). So the OBJ text is read by
//! `crate::file::read_text` (a regular file, bounded; BOM, CR and CRLF line ends handled) and
//! handed to tobj from memory, and the material properties used, the diffuse colour `Kd` and
//! texture `map_Kd` (src/mesh/load/map_kd.rs), come from [`load_mtl`].

use std::cell::RefCell;
use std::collections::HashMap;
use std::path::Path;

use glam::{Vec2, Vec3};

use super::map_kd::MapKd;
use crate::error::{Error, Result};
use crate::mesh::{Mesh, DEFAULT_COLOR, NO_TEXTURE};

/// Peak CPU bytes per OBJ file byte: a vertex or face line takes at least 8 bytes; a vertex
/// costs ≈ 140 bytes (tobj's arrays, the mesh's positions, normals, colours and texture
/// coordinates, the uploaded vertex) and a triangle ≈ 24: an upper bound of 21 per byte,
/// checked before parsing.
pub(crate) const MESH_PEAK_PER_OBJ_BYTE: u64 = 21;

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
    let materials_dir = materials;
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
    let mut textures = ObjTextures {
        dir: materials_dir,
        path,
        read: HashMap::new(),
    };
    for model in &models {
        let m = &model.mesh;
        let n = m.positions.len() / 3;
        let base = mesh.positions.len() as u32;
        let texture = m.material_id.and_then(|id| {
            let map = materials.get(id)?.diffuse_texture.as_deref()?;
            textures.texture(id, map, &mut mesh)
        });
        let textured = texture.is_some() && m.texcoords.len() == 2 * n;
        // Kd multiplies the texture (as the MTL format says); a texture without Kd is as it is.
        let material_color = m
            .material_id
            .and_then(|id| materials.get(id))
            .and_then(|mat| mat.diffuse)
            .map(|[r, g, b]| [r, g, b, 1.0])
            .unwrap_or(if textured { [1.0; 4] } else { DEFAULT_COLOR });
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
            mesh.colors.extend(std::iter::repeat_n(material_color, n));
        }
        if let Some(&bad) = m.indices.iter().find(|&&i| i as usize >= n) {
            return Err(fail(format!("face index {} beyond {n} vertices", bad + 1)));
        }
        mesh.indices.extend(m.indices.iter().map(|i| i + base));
        match texture {
            Some((map, id)) if textured => {
                pad_tex_coords(&mut mesh, base as usize);
                mesh.tex_coords.extend(
                    m.texcoords
                        .chunks_exact(2)
                        .map(|uv| map.tex_coord([uv[0], uv[1]])),
                );
                mesh.texture_ids.extend(std::iter::repeat_n(id, n));
            }
            _ => {
                if texture.is_some() {
                    log::warn!(
                        "{}: object {} has a texture but no texture coordinates (vt); drawn in \
                         its colour",
                        path.display(),
                        model.name
                    );
                }
                if !mesh.tex_coords.is_empty() {
                    let count = mesh.positions.len();
                    pad_tex_coords(&mut mesh, count);
                }
            }
        }
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

/// The textures of an OBJ's materials, each read once, from the directory of its MTL.
struct ObjTextures<'a> {
    dir: Option<&'a Path>,
    path: &'a Path,
    /// Material id → its map and texture index, or `None` where it could not be read.
    read: HashMap<usize, Option<(MapKd, u32)>>,
}

impl ObjTextures<'_> {
    /// Material `material`'s `map_Kd` (its arguments `args`) and texture index in `mesh`,
    /// reading the texture on first use; `None` (said once in the log) where it cannot be read.
    fn texture(&mut self, material: usize, args: &str, mesh: &mut Mesh) -> Option<(MapKd, u32)> {
        if let Some(read) = self.read.get(&material) {
            return read.clone();
        }
        let map = MapKd::parse(args).ok()?; // checked by parse_mtl
        let read = match self.dir.map(|dir| map.load(dir)) {
            Some(Ok(texture)) => {
                mesh.textures.push(texture);
                Some((map, mesh.textures.len() as u32 - 1))
            }
            Some(Err(e)) => {
                log::warn!(
                    "{}: texture {} is not shown ({e}); drawn in its Kd colour",
                    self.path.display(),
                    map.file
                );
                None
            }
            None => None,
        };
        self.read.insert(material, read.clone());
        read
    }
}

/// Texture coordinates and ids (none) for `mesh`'s vertices up to `count`.
fn pad_tex_coords(mesh: &mut Mesh, count: usize) {
    let missing = count.saturating_sub(mesh.tex_coords.len());
    mesh.tex_coords
        .extend(std::iter::repeat_n(Vec2::ZERO, missing));
    mesh.texture_ids
        .extend(std::iter::repeat_n(NO_TEXTURE, missing));
}

/// The materials of an MTL file, with only what the renderers use: name, diffuse colour and
/// texture.
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
                let args = words.collect::<Vec<_>>().join(" ");
                if let Err(reason) = MapKd::parse(&args) {
                    return Err(fail(i + 1, reason));
                }
                match materials.last_mut() {
                    Some(material) => material.diffuse_texture = Some(args),
                    None => return Err(fail(i + 1, "map_Kd before any newmtl".into())),
                }
            }
            _ => {}
        }
    }
    Ok((materials, names))
}
