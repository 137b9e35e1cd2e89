//! glTF 2.0 meshes (`.gltf` JSON with its buffers, `.glb` binary), through the `gltf` crate:
//! every triangle primitive of the default scene (else the first), placed by its nodes'
//! transforms, coloured by its vertex colours (`COLOR_0`) times its material's base colour
//! factor. Textures are not shown (the renderers have no texture coordinates): a file with
//! base-colour textures says so in the log. Buffers come from the GLB's binary chunk, `data:`
//! URIs, or files beside the `.gltf` (relative paths without `..`, read bounded like every
//! input); their declared lengths are checked, and the vertices every node instance adds up
//! to are checked against the memory budget before anything is built.

use std::path::Path;

use base64::Engine as _;
use glam::{Mat3, Mat4, Vec3};

use super::{Mesh, DEFAULT_COLOR};
use crate::error::{Error, Result};

/// Deepest node nesting followed (a cycle or a pathological tree is refused, not recursed).
const MAX_NODE_DEPTH: usize = 64;
/// Peak CPU bytes per vertex instance and per index: the mesh's position, normal and colour
/// and the uploaded vertex (≈ 112, as for OBJ: src/mesh/obj.rs), and one u32 index.
const BYTES_PER_VERTEX: u64 = 112;
const BYTES_PER_INDEX: u64 = 4;

/// Load a `.gltf` or `.glb` file.
pub(super) fn load(path: &Path) -> Result<Mesh> {
    let bytes = crate::file::read_bounded(path, crate::file::MAX_TEXT_BYTES, "the glTF limit")?;
    parse(&bytes, path, Some(path.parent().unwrap_or(Path::new("."))))
}

/// Parse glTF `bytes` (`path` names it in errors); external buffer files are read from
/// `dir`, or refused when it is `None` (bytes from memory: the fuzz target).
pub(super) fn parse(bytes: &[u8], path: &Path, dir: Option<&Path>) -> Result<Mesh> {
    let fail = |reason: String| Error::Mesh {
        path: path.to_path_buf(),
        reason,
    };
    let gltf = gltf::Gltf::from_slice(bytes).map_err(|e| fail(format!("malformed glTF: {e}")))?;
    let buffers = buffer_data(&gltf, dir).map_err(&fail)?;
    let scene = gltf
        .document
        .default_scene()
        .or_else(|| gltf.document.scenes().next())
        .ok_or_else(|| fail("no scene".into()))?;
    let mut instances = Vec::new();
    for node in scene.nodes() {
        collect(node, Mat4::IDENTITY, 0, &mut instances).map_err(&fail)?;
    }
    check_budget(&instances).map_err(|e| fail(e.to_string()))?;
    let mut mesh = Mesh::default();
    let mut textured = false;
    let mut skipped = 0usize;
    for (node_mesh, transform) in &instances {
        for primitive in node_mesh.primitives() {
            let pbr = primitive.material().pbr_metallic_roughness();
            textured |= pbr.base_color_texture().is_some();
            // Without a material glTF's default is white; the project's grey is kept then.
            let factor = match primitive.material().index() {
                Some(_) => pbr.base_color_factor(),
                None => DEFAULT_COLOR,
            };
            match triangles(&primitive, &buffers).map_err(&fail)? {
                Some(part) => append(&mut mesh, part, *transform, factor),
                None => skipped += 1,
            }
        }
    }
    if mesh.indices.is_empty() {
        return Err(fail(
            "no triangles in the scene (points and lines are not drawn as meshes)".into(),
        ));
    }
    if textured {
        log::warn!(
            "{}: base-colour textures are not shown (the renderers draw vertex and material \
             colours only)",
            path.display()
        );
    }
    if skipped > 0 {
        log::warn!(
            "{}: {skipped} primitives of points or lines skipped",
            path.display()
        );
    }
    mesh.validate().map_err(|e| fail(e.to_string()))?;
    Ok(mesh)
}

/// The bytes of every buffer, each at least its declared length.
fn buffer_data(gltf: &gltf::Gltf, dir: Option<&Path>) -> std::result::Result<Vec<Vec<u8>>, String> {
    gltf.document
        .buffers()
        .map(|buffer| {
            let data = match buffer.source() {
                gltf::buffer::Source::Bin => gltf
                    .blob
                    .clone()
                    .ok_or("buffer 0 is the GLB binary chunk, which is missing")?,
                gltf::buffer::Source::Uri(uri) => uri_data(uri, dir)?,
            };
            if data.len() < buffer.length() {
                return Err(format!(
                    "buffer {} declares {} bytes but holds {}",
                    buffer.index(),
                    buffer.length(),
                    data.len()
                ));
            }
            Ok(data)
        })
        .collect()
}

/// A buffer's bytes from a `data:` URI or a file beside the glTF.
fn uri_data(uri: &str, dir: Option<&Path>) -> std::result::Result<Vec<u8>, String> {
    if let Some(data) = uri.strip_prefix("data:") {
        let (_, encoded) = data
            .split_once(";base64,")
            .ok_or("a data: URI that is not base64")?;
        return base64::engine::general_purpose::STANDARD
            .decode(encoded)
            .map_err(|e| format!("a data: URI's base64: {e}"));
    }
    let name = percent_decode(uri)?;
    let relative = Path::new(&name);
    if uri.contains("://")
        || relative.is_absolute()
        || relative
            .components()
            .any(|c| !matches!(c, std::path::Component::Normal(_)))
    {
        return Err(format!(
            "buffer '{uri}': only files beside the glTF are read (no absolute paths, '..' or URLs)"
        ));
    }
    let dir = dir.ok_or_else(|| format!("buffer '{uri}' is an external file (not read here)"))?;
    crate::file::read_bounded(
        &dir.join(relative),
        crate::file::MAX_TEXT_BYTES,
        "the glTF limit",
    )
    .map_err(|e| format!("buffer '{uri}': {e}"))
}

/// `%20` and the like in a URI's path.
fn percent_decode(uri: &str) -> std::result::Result<String, String> {
    let bytes = uri.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b'%' {
            let hex = uri
                .get(i + 1..i + 3)
                .and_then(|h| u8::from_str_radix(h, 16).ok())
                .ok_or_else(|| format!("buffer '{uri}': a bad %-escape"))?;
            out.push(hex);
            i += 3;
        } else {
            out.push(bytes[i]);
            i += 1;
        }
    }
    String::from_utf8(out).map_err(|_| format!("buffer '{uri}' is not UTF-8"))
}

/// Every (mesh, world transform) under `node`.
fn collect<'a>(
    node: gltf::Node<'a>,
    parent: Mat4,
    depth: usize,
    out: &mut Vec<(gltf::Mesh<'a>, Mat4)>,
) -> std::result::Result<(), String> {
    if depth > MAX_NODE_DEPTH {
        return Err(format!(
            "nodes nested deeper than {MAX_NODE_DEPTH} (a cycle?) at node {}",
            node.index()
        ));
    }
    let transform = parent * Mat4::from_cols_array_2d(&node.transform().matrix());
    if let Some(mesh) = node.mesh() {
        out.push((mesh, transform));
    }
    for child in node.children() {
        collect(child, transform, depth + 1, out)?;
    }
    Ok(())
}

/// The vertices and indices every instance adds, against the memory budget.
fn check_budget(instances: &[(gltf::Mesh, Mat4)]) -> Result<()> {
    let (mut vertices, mut indices) = (0u64, 0u64);
    for (mesh, _) in instances {
        for primitive in mesh.primitives() {
            let count = primitive
                .get(&gltf::Semantic::Positions)
                .map_or(0, |a| a.count() as u64);
            vertices = vertices.saturating_add(count);
            let index_count = primitive.indices().map_or(count, |a| a.count() as u64);
            indices = indices.saturating_add(index_count.saturating_mul(3));
        }
    }
    crate::budget::check(
        || format!("a glTF scene of {vertices} vertices and up to {indices} indices"),
        vertices
            .saturating_mul(BYTES_PER_VERTEX)
            .saturating_add(indices.saturating_mul(BYTES_PER_INDEX)),
    )
}

/// One primitive's positions, normals, colours and triangle indices; `None` for points and
/// lines.
struct Part {
    positions: Vec<Vec3>,
    normals: Option<Vec<Vec3>>,
    colors: Option<Vec<[f32; 4]>>,
    indices: Vec<u32>,
}

fn triangles(
    primitive: &gltf::Primitive,
    buffers: &[Vec<u8>],
) -> std::result::Result<Option<Part>, String> {
    use gltf::mesh::Mode;
    let mode = primitive.mode();
    if !matches!(
        mode,
        Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan
    ) {
        return Ok(None);
    }
    let reader = primitive.reader(|buffer| buffers.get(buffer.index()).map(Vec::as_slice));
    let positions: Vec<Vec3> = reader
        .read_positions()
        .ok_or_else(|| format!("primitive {} has no POSITION", primitive.index()))?
        .map(Vec3::from)
        .collect();
    let n = positions.len();
    let normals = reader
        .read_normals()
        .map(|it| it.map(Vec3::from).collect::<Vec<_>>())
        .filter(|v| v.len() == n);
    let colors = reader
        .read_colors(0)
        .map(|it| it.into_rgba_f32().collect::<Vec<_>>())
        .filter(|v| v.len() == n);
    let order: Vec<u32> = match reader.read_indices() {
        Some(indices) => indices.into_u32().collect(),
        None => (0..n as u32).collect(),
    };
    if let Some(&bad) = order.iter().find(|&&i| i as usize >= n) {
        return Err(format!(
            "primitive {}: index {bad} beyond its {n} vertices",
            primitive.index()
        ));
    }
    let indices = match mode {
        Mode::TriangleStrip => (2..order.len())
            .flat_map(|k| match k % 2 {
                0 => [order[k - 2], order[k - 1], order[k]],
                _ => [order[k - 1], order[k - 2], order[k]],
            })
            .collect(),
        Mode::TriangleFan => (2..order.len())
            .flat_map(|k| [order[0], order[k - 1], order[k]])
            .collect(),
        _ => order[..order.len() / 3 * 3].to_vec(),
    };
    Ok(Some(Part {
        positions,
        normals,
        colors,
        indices,
    }))
}

/// Add `part` placed by `transform`, its colours times `factor`.
fn append(mesh: &mut Mesh, part: Part, transform: Mat4, factor: [f32; 4]) {
    let base = mesh.positions.len() as u32;
    let normal_matrix = Mat3::from_mat4(transform).inverse().transpose();
    let mut part_mesh = Mesh {
        positions: part
            .positions
            .iter()
            .map(|&p| transform.transform_point3(p))
            .collect(),
        normals: match &part.normals {
            Some(normals) => normals
                .iter()
                .map(|&n| (normal_matrix * n).try_normalize().unwrap_or(Vec3::Z))
                .collect(),
            None => vec![Vec3::Z; part.positions.len()],
        },
        colors: match &part.colors {
            Some(colors) => colors
                .iter()
                .map(|c| [0, 1, 2, 3].map(|i| c[i] * factor[i]))
                .collect(),
            None => vec![factor; part.positions.len()],
        },
        indices: part.indices,
    };
    if part.normals.is_none() {
        part_mesh.compute_normals();
    }
    mesh.positions.extend(part_mesh.positions);
    mesh.normals.extend(part_mesh.normals);
    mesh.colors.extend(part_mesh.colors);
    mesh.indices
        .extend(part_mesh.indices.iter().map(|i| i + base));
}
