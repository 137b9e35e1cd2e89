//! KHR_draco_mesh_compression: a mesh encoded here with draco-core's encoder, wrapped in a GLB
//! as the extension says (accessors without buffer views, the stream in one view), loads with
//! its triangles and renders as the uncompressed mesh does (Draco quantises positions: close,
//! not equal).
#![cfg(feature = "gltf")]

use crate::common;
use crate::mesh_formats::glb_container;

use autostereo::camera::MultiViewCamera;
use autostereo::display::Display;
use autostereo::frame::Frame;
use autostereo::image_io::{compare, RgbImage};
use autostereo::mesh::{Mesh, MeshBuffers};
use autostereo::RendererOptions;
use draco_core::{DataType, EncoderBuffer, EncoderOptions, GeometryAttributeType, MeshEncoder};
use draco_core::{FaceIndex, PointAttribute, PointIndex};

/// `mesh`'s positions and normals as a Draco stream; their unique ids.
fn draco_stream(mesh: &Mesh) -> (Vec<u8>, u32, u32) {
    let mut out = draco_core::Mesh::new();
    let n = mesh.positions.len();
    let mut ids = Vec::new();
    for (kind, values) in [
        (GeometryAttributeType::Position, &mesh.positions),
        (GeometryAttributeType::Normal, &mesh.normals),
    ] {
        let mut attribute = PointAttribute::new();
        attribute.init(kind, 3, DataType::Float32, false, n);
        for (i, v) in values.iter().enumerate() {
            let bytes: Vec<u8> = v.to_array().iter().flat_map(|c| c.to_le_bytes()).collect();
            attribute.buffer_mut().write(i * 12, &bytes);
        }
        let id = out.add_attribute(attribute);
        ids.push(out.attribute(id).unique_id());
    }
    out.set_num_faces(mesh.triangle_count());
    for (f, t) in mesh.indices.chunks_exact(3).enumerate() {
        out.set_face(FaceIndex(f as u32), [t[0], t[1], t[2]].map(PointIndex));
    }
    let mut encoder = MeshEncoder::new();
    encoder.set_mesh(out);
    let mut bytes = EncoderBuffer::new();
    encoder.encode(&EncoderOptions::new(), &mut bytes).unwrap();
    (bytes.data().to_vec(), ids[0], ids[1])
}

/// A GLB of `mesh` compressed with Draco, as exporters write it; its buffer view holds the
/// stream's first `share` of bytes (1: all of it).
fn draco_glb(mesh: &Mesh, share: f64) -> Vec<u8> {
    let (stream, position, normal) = draco_stream(mesh);
    let view = (stream.len() as f64 * share) as usize;
    let bounds = mesh.bounds().unwrap();
    let (lo, hi) = (bounds.min, bounds.max);
    let json = format!(
        r#"{{"asset":{{"version":"2.0"}},"extensionsUsed":["KHR_draco_mesh_compression"],
"extensionsRequired":["KHR_draco_mesh_compression"],"scene":0,"scenes":[{{"nodes":[0]}}],"nodes":[{{"mesh":0}}],
"meshes":[{{"primitives":[{{"attributes":{{"POSITION":0,"NORMAL":1}},"indices":2,"mode":4,
"extensions":{{"KHR_draco_mesh_compression":{{"bufferView":0,"attributes":{{"POSITION":{position},"NORMAL":{normal}}}}}}}}}]}}],
"buffers":[{{"byteLength":{len}}}],"bufferViews":[{{"buffer":0,"byteOffset":0,"byteLength":{view}}}],
"accessors":[{{"componentType":5126,"count":{n},"type":"VEC3","min":[{},{},{}],"max":[{},{},{}]}},
{{"componentType":5126,"count":{n},"type":"VEC3"}},{{"componentType":5125,"count":{i},"type":"SCALAR"}}]}}"#,
        lo.x,
        lo.y,
        lo.z,
        hi.x,
        hi.y,
        hi.z,
        len = stream.len(),
        n = mesh.positions.len(),
        i = mesh.indices.len(),
    );
    glb_container(json.into_bytes(), stream)
}

fn render(mesh: &Mesh) -> RgbImage {
    let display = Display::parse("hubner8").unwrap();
    let camera = MultiViewCamera::framing(
        mesh.bounds().unwrap(),
        8,
        None,
        30f32.to_radians(),
        4.0 / 3.0,
    )
    .unwrap();
    let frame = Frame::new(camera, display, [96, 72]).unwrap();
    let device = common::gpu().device.clone();
    let buffers = MeshBuffers::new(&device, mesh).unwrap();
    let mut renderer = RendererOptions::default().mesh_renderer(&device).unwrap();
    common::render(renderer.as_mut(), &buffers, &frame)
}

#[test]
fn a_draco_compressed_gltf_renders_as_the_uncompressed_mesh() {
    let mut mesh = Mesh::torus_scene();
    mesh.colors.fill(autostereo::mesh::DEFAULT_COLOR); // the stream holds no colours
    let file = common::input_file("torus_draco.glb", draco_glb(&mesh, 1.0));
    let loaded = Mesh::load(&file).unwrap();
    assert_eq!(loaded.triangle_count(), mesh.triangle_count());
    let (a, b) = (mesh.bounds().unwrap(), loaded.bounds().unwrap());
    let tolerance = 1e-2 * a.radius();
    assert!(
        a.min.distance(b.min) < tolerance && a.max.distance(b.max) < tolerance,
        "bounds {a:?} became {b:?}"
    );
    let diff = compare(&render(&loaded), &render(&mesh)).unwrap();
    assert!(diff.psnr_db > 30.0, "{diff:?}");
    // A stream cut short is an error that names the file and the stream, not a panic.
    let file = common::input_file("torus_draco_cut.glb", draco_glb(&mesh, 0.5));
    let error = match Mesh::load(&file) {
        Ok(cut) => panic!("a cut stream loaded: {} triangles", cut.triangle_count()),
        Err(e) => e.to_string(),
    };
    assert!(
        error.contains("torus_draco_cut.glb") && error.contains("Draco stream"),
        "{error}"
    );
}
