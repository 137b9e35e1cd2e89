//! The data people have (issue 29): every mesh format renders as the same mesh does from an
//! OBJ, JPEG images are read wherever PNGs are, and a file of another kind or an unknown
//! format is refused naming what reads it. Every file is generated here.

use crate::common;

mod images;
mod kinds;
mod meshes;

use std::path::{Path, PathBuf};

use autostereo::image_io::{compare, RgbImage};
use autostereo::mesh::Mesh;

fn out(name: &str) -> PathBuf {
    common::out(&format!("formats_{name}"))
}

fn write(name: &str, bytes: &[u8]) -> PathBuf {
    let path = out(name);
    std::fs::write(&path, bytes).unwrap();
    path
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// A small torus: shared vertices, so that every format (STL merges equal corners) has the
/// same topology and the computed normals agree.
fn torus() -> Mesh {
    Mesh::torus(1.0, 0.35, 12, 8, [0.8, 0.8, 0.8, 1.0])
}

fn obj_text(mesh: &Mesh, color: Option<[f32; 3]>) -> String {
    let mut text = String::new();
    for p in &mesh.positions {
        match color {
            Some([r, g, b]) => text += &format!("v {} {} {} {r} {g} {b}\n", p.x, p.y, p.z),
            None => text += &format!("v {} {} {}\n", p.x, p.y, p.z),
        }
    }
    for t in mesh.indices.chunks(3) {
        text += &format!("f {} {} {}\n", t[0] + 1, t[1] + 1, t[2] + 1);
    }
    text
}

fn ply_binary(mesh: &Mesh, big_endian: bool) -> Vec<u8> {
    let order = if big_endian { "big" } else { "little" };
    let mut b = format!(
        "ply\nformat binary_{order}_endian 1.0\ncomment faces first: the reader follows the \
         header's order\nelement face {}\nproperty list uchar int vertex_indices\nelement \
         vertex {}\nproperty float x\nproperty float y\nproperty float z\nend_header\n",
        mesh.triangle_count(),
        mesh.positions.len()
    )
    .into_bytes();
    let f32s = |v: f32| {
        if big_endian {
            v.to_be_bytes()
        } else {
            v.to_le_bytes()
        }
    };
    let i32s = |v: i32| {
        if big_endian {
            v.to_be_bytes()
        } else {
            v.to_le_bytes()
        }
    };
    for t in mesh.indices.chunks(3) {
        b.push(3);
        for &i in t {
            b.extend(i32s(i as i32));
        }
    }
    for p in &mesh.positions {
        for c in p.to_array() {
            b.extend(f32s(c));
        }
    }
    b
}

fn stl_binary(mesh: &Mesh) -> Vec<u8> {
    let mut b = vec![b' '; 80];
    b.extend((mesh.triangle_count() as u32).to_le_bytes());
    for t in mesh.indices.chunks(3) {
        b.extend([0u8; 12]);
        for &i in t {
            for c in mesh.positions[i as usize].to_array() {
                b.extend(c.to_le_bytes());
            }
        }
        b.extend([0u8; 2]);
    }
    b
}

fn stl_ascii_crlf(mesh: &Mesh) -> Vec<u8> {
    let mut text = String::from("solid torus\r\n");
    for t in mesh.indices.chunks(3) {
        text += "facet normal 0 0 0\r\nouter loop\r\n";
        for &i in t {
            let p = mesh.positions[i as usize];
            text += &format!("vertex {} {} {}\r\n", p.x, p.y, p.z);
        }
        text += "endloop\r\nendfacet\r\n";
    }
    text += "endsolid torus\r\n";
    text.into_bytes()
}

/// A glTF of `positions` (already divided by the nodes' transforms: a parent scaling by 2 and
/// a child moving by +0.5 in x after turning 90° about z) and `mesh`'s indices, as GLB or as JSON with a data: URI; the
/// material's base colour factor when given.
fn gltf(mesh: &Mesh, glb: bool, factor: Option<[f32; 4]>) -> Vec<u8> {
    let local: Vec<[f32; 3]> = mesh
        .positions
        .iter()
        .map(|p| [p.y / 2.0, 0.5 - p.x / 2.0, p.z / 2.0])
        .collect();
    let mut bin = Vec::new();
    for p in &local {
        for c in p {
            bin.extend(c.to_le_bytes());
        }
    }
    let positions_len = bin.len();
    for &i in &mesh.indices {
        bin.extend(i.to_le_bytes());
    }
    let (min, max) = local
        .iter()
        .fold(([f32::MAX; 3], [f32::MIN; 3]), |(lo, hi), p| {
            (
                [0, 1, 2].map(|i| lo[i].min(p[i])),
                [0, 1, 2].map(|i| hi[i].max(p[i])),
            )
        });
    let uri = if glb {
        String::new()
    } else {
        use std::fmt::Write;
        // Base64 by hand: the test checks the reader, not an encoder it shares.
        const ABC: &[u8] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
        let mut enc = String::new();
        for chunk in bin.chunks(3) {
            let n = chunk
                .iter()
                .enumerate()
                .fold(0u32, |n, (i, &b)| n | (b as u32) << (16 - 8 * i));
            for k in 0..4 {
                if k <= chunk.len() {
                    enc.push(ABC[(n >> (18 - 6 * k) & 63) as usize] as char);
                } else {
                    enc.push('=');
                }
            }
        }
        let mut uri = String::new();
        write!(
            uri,
            r#","uri":"data:application/octet-stream;base64,{enc}""#
        )
        .unwrap();
        uri
    };
    let (material, materials) = match factor {
        Some(f) => (
            r#","material":0"#.to_string(),
            format!(
                r#","materials":[{{"pbrMetallicRoughness":{{"baseColorFactor":[{},{},{},{}]}}}}]"#,
                f[0], f[1], f[2], f[3]
            ),
        ),
        None => (String::new(), String::new()),
    };
    let json = format!(
        r#"{{"asset":{{"version":"2.0"}},"scene":0,"scenes":[{{"nodes":[0]}}],
"nodes":[{{"scale":[2,2,2],"children":[1]}},{{"translation":[0.5,0,0],"rotation":[0,0,0.70710678,0.70710678],"mesh":0}}],
"meshes":[{{"primitives":[{{"attributes":{{"POSITION":0}},"indices":1{material}}}]}}]{materials},
"buffers":[{{"byteLength":{}{uri}}}],
"bufferViews":[{{"buffer":0,"byteOffset":0,"byteLength":{positions_len}}},
{{"buffer":0,"byteOffset":{positions_len},"byteLength":{}}}],
"accessors":[{{"bufferView":0,"componentType":5126,"count":{},"type":"VEC3","min":[{},{},{}],"max":[{},{},{}]}},
{{"bufferView":1,"componentType":5125,"count":{},"type":"SCALAR"}}]}}"#,
        bin.len(),
        bin.len() - positions_len,
        local.len(),
        min[0],
        min[1],
        min[2],
        max[0],
        max[1],
        max[2],
        mesh.indices.len()
    );
    if !glb {
        return json.into_bytes();
    }
    let mut json = json.into_bytes();
    while json.len() % 4 != 0 {
        json.push(b' ');
    }
    while bin.len() % 4 != 0 {
        bin.push(0);
    }
    let total = 12 + 8 + json.len() + 8 + bin.len();
    let mut b = b"glTF".to_vec();
    b.extend(2u32.to_le_bytes());
    b.extend((total as u32).to_le_bytes());
    b.extend((json.len() as u32).to_le_bytes());
    b.extend(b"JSON");
    b.extend(json);
    b.extend((bin.len() as u32).to_le_bytes());
    b.extend(b"BIN\0");
    b.extend(bin);
    b
}

/// `autostereo mesh FILE` on a small lenticular display; the image it wrote.
fn render_mesh(file: &Path, name: &str) -> RgbImage {
    let image = out(&format!("{name}.png"));
    let (ok, err) = common::cli(&[
        "mesh",
        s(file),
        "--display",
        "lenticular:8",
        "--size",
        "64x48",
        "--out",
        s(&image),
    ]);
    assert!(ok, "{name}: {err}");
    RgbImage::load_png(&image).unwrap()
}
