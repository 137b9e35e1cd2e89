#![cfg(all(feature = "stl", feature = "gltf"))]
//! The data people have (issue 29): every mesh format (PLY both byte orders, STL binary and
//! ASCII, glTF and GLB) loads as the same mesh in OBJ and renders as it does, as
//! `autostereo mesh FILE` loads and renders it. Every file is generated here.

use std::path::Path;

use autostereo::camera::MultiViewCamera;
use autostereo::display::Display;
use autostereo::frame::Frame;
use autostereo::image_io::{compare, RgbImage};
use autostereo::mesh::{Mesh, MeshBuffers};
use autostereo::RendererOptions;

use crate::common;

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
    glb_container(json.into_bytes(), bin)
}

/// A binary glTF (`.glb`) of a `json` chunk and a `bin` chunk, each padded to 4 bytes.
pub fn glb_container(mut json: Vec<u8>, mut bin: Vec<u8>) -> Vec<u8> {
    while !json.len().is_multiple_of(4) {
        json.push(b' ');
    }
    while !bin.len().is_multiple_of(4) {
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

/// `file` loaded as `autostereo mesh FILE` loads it ([`Mesh::load`]) and rendered as that
/// command renders it on a small lenticular display (its framing, 30° field of view, method
/// and options by default); saved as `name`.
fn render_mesh(file: &Path, name: &str) -> RgbImage {
    let mesh = Mesh::load(file).unwrap_or_else(|e| panic!("{name}: {e}"));
    let display = Display::parse("lenticular:8").unwrap();
    let size = [64, 48];
    let aspect = size[0] as f32 / size[1] as f32;
    let bounds = mesh.bounds().unwrap();
    let camera =
        MultiViewCamera::framing(bounds, display.views(), None, 30f32.to_radians(), aspect)
            .unwrap();
    let frame = Frame::new(camera, display, size).unwrap();
    let device = common::gpu().device.clone();
    let buffers = MeshBuffers::new(&device, &mesh).unwrap();
    let mut renderer = RendererOptions::default().mesh_renderer(&device).unwrap();
    let image = common::render(renderer.as_mut(), &buffers, &frame);
    image
        .save_png(&common::out(&format!("formats_{name}.png")))
        .unwrap();
    image
}

#[test]
fn every_mesh_format_renders_as_the_same_obj_does() {
    let mesh = torus();
    let reference = render_mesh(
        &common::input_file("torus.obj", obj_text(&mesh, None).as_bytes()),
        "obj",
    );
    let files = [
        (
            "ply_le",
            common::input_file("torus_le.ply", ply_binary(&mesh, false)),
        ),
        (
            "ply_be",
            common::input_file("torus_be.ply", ply_binary(&mesh, true)),
        ),
        (
            "stl_binary",
            common::input_file("torus.stl", stl_binary(&mesh)),
        ),
        (
            "stl_ascii_crlf",
            common::input_file("torus_ascii.stl", stl_ascii_crlf(&mesh)),
        ),
        (
            "glb",
            common::input_file("torus.glb", gltf(&mesh, true, None)),
        ),
        (
            "gltf_data_uri",
            common::input_file("torus.gltf", gltf(&mesh, false, None)),
        ),
        // The signature wins over a misleading extension.
        (
            "glb_named_obj",
            common::input_file("torus_glb.obj", gltf(&mesh, true, None)),
        ),
    ];
    for (name, file) in &files {
        let loaded = Mesh::load(file).unwrap();
        assert_eq!(loaded.triangle_count(), mesh.triangle_count(), "{name}");
        // Every triangle's corners where the OBJ's are (STL merges and renumbers vertices).
        for (t, corners) in loaded.indices.chunks(3).enumerate() {
            for (k, &i) in corners.iter().enumerate() {
                let want = mesh.positions[mesh.indices[3 * t + k] as usize];
                let got = loaded.positions[i as usize];
                assert!(
                    got.distance(want) < 1e-5,
                    "{name} triangle {t}: {got} vs {want}"
                );
            }
        }
        let image = render_mesh(file, name);
        let diff = compare(&image, &reference).unwrap();
        assert!(diff.max_abs_err <= 1, "{name}: {diff:?}");
    }
    // Colour: a glTF material's base colour factor is an OBJ's vertex colour.
    let red_obj = common::input_file("red.obj", obj_text(&mesh, Some([0.9, 0.2, 0.1])).as_bytes());
    let red_gltf = common::input_file("red.glb", gltf(&mesh, true, Some([0.9, 0.2, 0.1, 1.0])));
    let diff = compare(
        &render_mesh(&red_gltf, "red_glb"),
        &render_mesh(&red_obj, "red_obj"),
    )
    .unwrap();
    assert!(diff.max_abs_err <= 1, "red: {diff:?}");
}
