//! glTF 2.0 meshes (`.gltf` JSON with its buffers, `.glb` binary), through the `gltf` crate:
//! every triangle primitive of the default scene (else the first), placed by its nodes'
//! transforms, coloured by its vertex colours (`COLOR_0`) times its material's base colour
//! factor times its base-colour texture (textures.rs). Buffers come from the GLB's binary chunk, `data:`
//! URIs, or files beside the `.gltf` (relative paths without `..`, read bounded like every
//! input); their declared lengths are checked, and the vertices every node instance adds up
//! to are checked against the memory budget before anything is built.

mod draco;
mod extensions;
mod textures;
mod uri;
use std::path::Path;

use glam::{Mat3, Mat4, Vec2, Vec3};

use crate::error::{Error, Result};
use crate::mesh::{Mesh, DEFAULT_COLOR, NO_TEXTURE};
use textures::Sampling;

/// Deepest node nesting followed (a cycle or a pathological tree is refused, not recursed).
const MAX_NODE_DEPTH: usize = 64;
/// Most node visits of a scene (a tree whose nodes share children grows exponentially).
const MAX_NODE_VISITS: usize = 1 << 20;
/// Peak CPU bytes per vertex instance and per index: the mesh's position, normal, colour,
/// texture coordinate and id, and the uploaded vertex (≈ 140, as for OBJ:
/// src/mesh/load/obj.rs), and one u32 index.
const BYTES_PER_VERTEX: u64 = 140;
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
    // The crate's own validation indexes accessors before it has checked that they exist (a
    // panic); so the document is read unvalidated and every index and accessor this reader
    // follows is checked here first.
    extensions::check_version_and_extensions(bytes).map_err(&fail)?;
    let gltf = gltf::Gltf::from_slice_without_validation(bytes)
        .map_err(|e| fail(format!("malformed glTF: {e}")))?;
    check_document(gltf.document.as_json()).map_err(&fail)?;
    let buffers = buffer_data(&gltf, dir).map_err(&fail)?;
    let scene = gltf
        .document
        .default_scene()
        .or_else(|| gltf.document.scenes().next())
        .ok_or_else(|| fail("no scene".into()))?;
    let mut instances = Vec::new();
    let mut visits = 0;
    for node in scene.nodes() {
        collect(node, Mat4::IDENTITY, 0, &mut visits, &mut instances).map_err(&fail)?;
    }
    check_budget(&instances).map_err(|e| fail(e.to_string()))?;
    let mut mesh = Mesh::default();
    let root = gltf.document.as_json();
    let mut textures = textures::Textures::new(root, &buffers, dir, path);
    let (mut skipped, mut without_coords) = (0usize, 0usize);
    for (node_mesh, transform) in &instances {
        for primitive in node_mesh.primitives() {
            let pbr = primitive.material().pbr_metallic_roughness();
            // Without a material glTF's default is white; the project's grey is kept then.
            let factor = match primitive.material().index() {
                Some(_) => pbr.base_color_factor(),
                None => DEFAULT_COLOR,
            };
            let sampling = textures.sampling(primitive.material().index());
            match triangles(&primitive, root, &buffers, sampling.map(|s| s.set)).map_err(&fail)? {
                Some(part) => {
                    without_coords += (sampling.is_some() && part.tex_coords.is_none()) as usize;
                    append(&mut mesh, part, *transform, factor, sampling)
                }
                None => skipped += 1,
            }
        }
    }
    mesh.textures = textures.list;
    if mesh.indices.is_empty() {
        return Err(fail(
            "no triangles in the scene (points and lines are not drawn as meshes)".into(),
        ));
    }
    if without_coords > 0 {
        log::warn!(
            "{}: {without_coords} textured primitives have no readable texture coordinates; \
             they are drawn in their colours",
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

/// Every index the reader follows names an object that exists; modes, component types and
/// accessor types are ones glTF defines; no sparse accessors.
fn check_document(root: &gltf::json::Root) -> std::result::Result<(), String> {
    use gltf::json::validation::Checked;
    let exists = |i: usize, len: usize, what: &str| match i < len {
        true => Ok(()),
        false => Err(format!("{what} {i} does not exist (there are {len})")),
    };
    if let Some(scene) = root.scene {
        exists(scene.value(), root.scenes.len(), "scene")?;
    }
    for scene in &root.scenes {
        for node in &scene.nodes {
            exists(node.value(), root.nodes.len(), "node")?;
        }
    }
    for node in &root.nodes {
        for child in node.children.iter().flatten() {
            exists(child.value(), root.nodes.len(), "node")?;
        }
        if let Some(mesh) = node.mesh {
            exists(mesh.value(), root.meshes.len(), "mesh")?;
        }
    }
    for mesh in &root.meshes {
        for p in &mesh.primitives {
            if matches!(p.mode, Checked::Invalid) {
                return Err("a primitive of an unknown mode".into());
            }
            for accessor in p.attributes.values().chain(&p.indices) {
                exists(accessor.value(), root.accessors.len(), "accessor")?;
            }
            if let Some(material) = p.material {
                exists(material.value(), root.materials.len(), "material")?;
            }
        }
    }
    for (i, a) in root.accessors.iter().enumerate() {
        // An accessor without a view is zeros, or (KHR_draco_mesh_compression) decoded from
        // the primitive's Draco stream; one read as plain data is checked when read.
        if a.sparse.is_some() {
            return Err(format!("accessor {i}: sparse accessors are not read"));
        }
        if matches!(a.component_type, Checked::Invalid) || matches!(a.type_, Checked::Invalid) {
            return Err(format!(
                "accessor {i}: an unknown component or element type"
            ));
        }
        if let Some(view) = a.buffer_view {
            exists(view.value(), root.buffer_views.len(), "buffer view")?;
        }
    }
    for view in &root.buffer_views {
        exists(view.buffer.value(), root.buffers.len(), "buffer")?;
    }
    textures::check_indices(root)
}

/// An accessor the reader may read: one of `types` (component type and dimensions), at least
/// one element (`count` of them when given), its elements within its view and the view within
/// its buffer, strides no shorter than an element.
fn check_accessor(
    a: &gltf::Accessor,
    buffers: &[std::borrow::Cow<'_, [u8]>],
    what: &str,
    types: &[(gltf::accessor::DataType, gltf::accessor::Dimensions)],
    count: Option<usize>,
) -> std::result::Result<(), String> {
    let fail = |reason: String| Err(format!("{what} (accessor {}): {reason}", a.index()));
    if !types.contains(&(a.data_type(), a.dimensions())) {
        return fail(format!(
            "{:?} {:?} is not read",
            a.data_type(),
            a.dimensions()
        ));
    }
    if a.count() == 0 || count.is_some_and(|n| n != a.count()) {
        return fail(format!(
            "{} elements ({} wanted)",
            a.count(),
            count.unwrap_or(1)
        ));
    }
    let Some(view) = a.view() else {
        return fail("no buffer view".into());
    };
    let element = a.size() as u64;
    let stride = view.stride().map_or(element, |s| s as u64);
    if stride < element {
        return fail(format!(
            "a stride of {stride} bytes for elements of {element}"
        ));
    }
    let buffer = buffers
        .get(view.buffer().index())
        .map_or(0, |b| b.len() as u64);
    let view_end = (view.offset() as u64).checked_add(view.length() as u64);
    let last = (a.count() as u64 - 1)
        .checked_mul(stride)
        .and_then(|v| v.checked_add(a.offset() as u64))
        .and_then(|v| v.checked_add(element));
    match (view_end, last) {
        (Some(end), Some(last)) if end <= buffer && last <= view.length() as u64 => Ok(()),
        _ => fail("its elements run past its view or its view past its buffer".into()),
    }
}

/// The bytes of every buffer, each at least its declared length (the GLB's binary chunk
/// borrowed, however many buffers name it).
fn buffer_data<'a>(
    gltf: &'a gltf::Gltf,
    dir: Option<&Path>,
) -> std::result::Result<Vec<std::borrow::Cow<'a, [u8]>>, String> {
    gltf.document
        .buffers()
        .map(|buffer| {
            let data: std::borrow::Cow<'a, [u8]> = match buffer.source() {
                gltf::buffer::Source::Bin => gltf
                    .blob
                    .as_deref()
                    .ok_or("buffer 0 is the GLB binary chunk, which is missing")?
                    .into(),
                gltf::buffer::Source::Uri(uri) => uri::uri_data(uri, dir)?.into(),
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

/// Every (mesh, world transform) under `node`.
fn collect<'a>(
    node: gltf::Node<'a>,
    parent: Mat4,
    depth: usize,
    visits: &mut usize,
    out: &mut Vec<(gltf::Mesh<'a>, Mat4)>,
) -> std::result::Result<(), String> {
    *visits += 1;
    if *visits > MAX_NODE_VISITS {
        return Err(format!(
            "more than {MAX_NODE_VISITS} node visits in the scene"
        ));
    }
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
        collect(child, transform, depth + 1, visits, out)?;
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

/// One primitive's positions, normals, colours, texture coordinates and triangle indices;
/// `None` for points and lines.
struct Part {
    positions: Vec<Vec3>,
    normals: Option<Vec<Vec3>>,
    colors: Option<Vec<[f32; 4]>>,
    tex_coords: Option<Vec<[f32; 2]>>,
    indices: Vec<u32>,
}

/// The triangles of `primitive`, with texture coordinate set `set` where given.
fn triangles(
    primitive: &gltf::Primitive,
    root: &gltf::json::Root,
    buffers: &[std::borrow::Cow<'_, [u8]>],
    set: Option<u32>,
) -> std::result::Result<Option<Part>, String> {
    use gltf::accessor::{DataType as T, Dimensions as D};
    use gltf::mesh::Mode;
    use gltf::Semantic;
    let mode = primitive.mode();
    if !matches!(
        mode,
        Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan
    ) {
        return Ok(None);
    }
    let i = primitive.index();
    if let Some(compressed) = draco::Compressed::of(primitive) {
        return compressed
            .decode(root, buffers, set)
            .map(Some)
            .map_err(|e| format!("primitive {i}: {e}"));
    }
    let positions = primitive
        .get(&Semantic::Positions)
        .ok_or_else(|| format!("primitive {i} has no POSITION"))?;
    check_accessor(&positions, buffers, "POSITION", &[(T::F32, D::Vec3)], None)?;
    let n = positions.count();
    // Normals and colours of another count or type are left out (computed, default colour).
    let usable = |semantic: Semantic, types: &[(T, D)]| {
        primitive
            .get(&semantic)
            .is_some_and(|a| check_accessor(&a, buffers, "attribute", types, Some(n)).is_ok())
    };
    let normals_ok = usable(Semantic::Normals, &[(T::F32, D::Vec3)]);
    let colour_types = [T::U8, T::U16, T::F32].map(|t| [(t, D::Vec3), (t, D::Vec4)]);
    let colors_ok = usable(Semantic::Colors(0), colour_types.as_flattened());
    let coord_types = [(T::F32, D::Vec2), (T::U8, D::Vec2), (T::U16, D::Vec2)];
    let coords_ok = set.is_some_and(|set| usable(Semantic::TexCoords(set), &coord_types));
    if let Some(indices) = primitive.indices() {
        let types = [(T::U8, D::Scalar), (T::U16, D::Scalar), (T::U32, D::Scalar)];
        check_accessor(&indices, buffers, "indices", &types, None)?;
    }
    let reader = primitive.reader(|buffer| buffers.get(buffer.index()).map(|b| &b[..]));
    let positions: Vec<Vec3> = reader
        .read_positions()
        .ok_or_else(|| format!("primitive {} has no POSITION", primitive.index()))?
        .map(Vec3::from)
        .collect();
    let n = positions.len();
    let normals = reader
        .read_normals()
        .filter(|_| normals_ok)
        .map(|it| it.map(Vec3::from).collect::<Vec<_>>())
        .filter(|v| v.len() == n);
    let colors = reader
        .read_colors(0)
        .filter(|_| colors_ok)
        .map(|it| it.into_rgba_f32().collect::<Vec<_>>())
        .filter(|v| v.len() == n);
    let tex_coords = set
        .filter(|_| coords_ok)
        .and_then(|set| reader.read_tex_coords(set))
        .map(|it| it.into_f32().collect::<Vec<_>>())
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
        tex_coords,
        indices,
    }))
}

/// Add `part` placed by `transform`, its colours times `factor`, textured as `sampling` says
/// where it has the coordinates.
fn append(
    mesh: &mut Mesh,
    part: Part,
    transform: Mat4,
    factor: [f32; 4],
    sampling: Option<Sampling>,
) {
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
        ..Mesh::default()
    };
    if part.normals.is_none() {
        part_mesh.compute_normals();
    }
    let n = part_mesh.positions.len();
    match (sampling, &part.tex_coords) {
        (Some(sampling), Some(coords)) => {
            if mesh.tex_coords.is_empty() {
                mesh.tex_coords = vec![Vec2::ZERO; mesh.positions.len()];
                mesh.texture_ids = vec![NO_TEXTURE; mesh.positions.len()];
            }
            mesh.tex_coords
                .extend(coords.iter().map(|&uv| sampling.apply(uv)));
            mesh.texture_ids
                .extend(std::iter::repeat_n(sampling.texture, n));
        }
        _ if !mesh.tex_coords.is_empty() => {
            mesh.tex_coords.extend(std::iter::repeat_n(Vec2::ZERO, n));
            mesh.texture_ids.extend(std::iter::repeat_n(NO_TEXTURE, n));
        }
        _ => {}
    }
    mesh.positions.extend(part_mesh.positions);
    mesh.normals.extend(part_mesh.normals);
    mesh.colors.extend(part_mesh.colors);
    mesh.indices
        .extend(part_mesh.indices.iter().map(|i| i + base));
}

#[cfg(test)]
mod tests;
