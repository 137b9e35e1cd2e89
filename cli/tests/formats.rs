//! The data people have (issue 29): every mesh format renders as the same mesh does from an
//! OBJ, JPEG images are read wherever PNGs are, and a file of another kind or an unknown
//! format is refused naming what reads it. Every file is generated here.

mod common;

use std::path::{Path, PathBuf};

use autostereo::image_io::{compare, RgbImage};
use autostereo::mesh::Mesh;

fn out(name: &str) -> PathBuf {
    common::out_dir().join(format!("formats_{name}"))
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

#[test]
fn every_mesh_format_renders_as_the_same_obj_does() {
    let mesh = torus();
    let reference = render_mesh(&write("torus.obj", obj_text(&mesh, None).as_bytes()), "obj");
    let files = [
        ("ply_le", write("torus_le.ply", &ply_binary(&mesh, false))),
        ("ply_be", write("torus_be.ply", &ply_binary(&mesh, true))),
        ("stl_binary", write("torus.stl", &stl_binary(&mesh))),
        (
            "stl_ascii_crlf",
            write("torus_ascii.stl", &stl_ascii_crlf(&mesh)),
        ),
        ("glb", write("torus.glb", &gltf(&mesh, true, None))),
        (
            "gltf_data_uri",
            write("torus.gltf", &gltf(&mesh, false, None)),
        ),
        // The signature wins over a misleading extension.
        (
            "glb_named_obj",
            write("torus_glb.obj", &gltf(&mesh, true, None)),
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
    let red_obj = write("red.obj", obj_text(&mesh, Some([0.9, 0.2, 0.1])).as_bytes());
    let red_gltf = write("red.glb", &gltf(&mesh, true, Some([0.9, 0.2, 0.1, 1.0])));
    let diff = compare(
        &render_mesh(&red_gltf, "red_glb"),
        &render_mesh(&red_obj, "red_obj"),
    )
    .unwrap();
    assert!(diff.max_abs_err <= 1, "red: {diff:?}");
}

#[test]
fn a_file_of_another_kind_names_the_command_that_reads_it() {
    let nrrd = write(
        "head.nrrd",
        b"NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2 2\nencoding: raw\n\n\0\0\0\0\0\0\0\0",
    );
    let stl = write("part.stl", &stl_binary(&torus()));
    let obj = write("bunny.obj", obj_text(&torus(), None).as_bytes());
    let cloud = write(
        "cloud.ply",
        b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n",
    );
    let jpeg = write(
        "photo.jpg",
        &[0xff, 0xd8, 0xff, 0xe0, 0, 0x10, b'J', b'F', b'I', b'F'],
    );
    let png = write("spatial.png", b"\x89PNG\r\n\x1a\n");
    let laz = write("scan.laz", b"LASF\0\0\0\0");
    let mut dicom = vec![0u8; 132];
    dicom[128..].copy_from_slice(b"DICM");
    let dicom = write("slice.dcm", &dicom);
    let polydata = write(
        "mesh.vtk",
        b"# vtk DataFile Version 3.0\nmesh\nASCII\nDATASET POLYDATA\nPOINTS 0 float\n",
    );
    let notes = write("notes.txt", b"hello");
    let target = s(&out("never.png")).to_string();
    let cases: Vec<(Vec<&str>, String)> = vec![
        (
            vec!["mesh", s(&nrrd)],
            format!(
                "a volume (NRRD), not a mesh: `autostereo volume {}` reads it",
                s(&nrrd)
            ),
        ),
        (
            vec!["points", s(&stl)],
            format!(
                "a mesh (STL), not a point cloud: `autostereo mesh {}` reads it",
                s(&stl)
            ),
        ),
        (
            vec!["volume", s(&obj)],
            format!(
                "a mesh (OBJ), not a volume: `autostereo mesh {}` reads it",
                s(&obj)
            ),
        ),
        (
            vec!["mesh", s(&cloud)],
            format!(
                "a point cloud, which `autostereo points {}` reads",
                s(&cloud)
            ),
        ),
        (
            vec!["volume", s(&jpeg)],
            "an image (JPEG), not a volume".into(),
        ),
        (vec!["mesh", s(&png)], "an image (PNG), not a mesh".into()),
        (
            vec!["interleave", s(&obj), "--out", &target],
            "a mesh (OBJ), not an image".into(),
        ),
        (vec!["points", s(&laz)], "malformed LAS header".into()),
        (vec!["volume", s(&dicom)], "malformed DICOM".into()),
        (
            vec!["volume", s(&polydata)],
            "DATASET POLYDATA: a mesh/polydata, not image data".into(),
        ),
        (
            vec!["volume", s(&notes)],
            "unknown format; read here: meshes .obj .ply .stl .gltf .glb".into(),
        ),
    ];
    for (args, expected) in cases {
        let (ok, err) = common::cli(&common::measuring(&args));
        assert!(!ok, "{args:?} succeeded");
        assert!(
            err.contains(&expected),
            "{args:?}: '{err}' lacks '{expected}'"
        );
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
    assert!(!Path::new(&target).exists());
}

/// JPEG wherever a PNG is read: a JPEG colour image and a JPEG quilt give what the same pixels
/// (the JPEG decoded, saved as PNG) give.
#[test]
fn jpeg_images_are_read_where_pngs_are() {
    let (w, h) = (48u32, 32u32);
    let mut colour = image::RgbImage::new(w, h);
    for (x, y, p) in colour.enumerate_pixels_mut() {
        *p = image::Rgb([(x * 5) as u8, (y * 7) as u8, ((x + y) * 3) as u8]);
    }
    let jpeg = out("colour.jpg");
    colour.save(&jpeg).unwrap();
    let decoded = out("colour_decoded.png");
    image::open(&jpeg)
        .unwrap()
        .to_rgb8()
        .save(&decoded)
        .unwrap();
    let mut depth = image::GrayImage::new(w, h);
    for (x, _, p) in depth.enumerate_pixels_mut() {
        *p = image::Luma([(x * 5) as u8]);
    }
    let depth_path = out("depth.png");
    depth.save(&depth_path).unwrap();
    let spatial = |colour: &Path, name: &str| {
        let image = out(name);
        let (ok, err) = common::cli(&[
            "rgbd",
            s(colour),
            s(&depth_path),
            "--display",
            "lenticular:8",
            "--out",
            s(&image),
        ]);
        assert!(ok, "{name}: {err}");
        RgbImage::load_png(&image).unwrap()
    };
    let from_jpeg = spatial(&jpeg, "rgbd_jpeg.png");
    let from_png = spatial(&decoded, "rgbd_png.png");
    assert_eq!(compare(&from_jpeg, &from_png).unwrap().max_abs_err, 0);
    // A 4×2 quilt of 8 views as JPEG, against the same pixels as PNG.
    let quilt = out("views_qs4x2a1.5.jpg");
    image::RgbImage::from_fn(4 * w, 2 * h, |x, y| {
        image::Rgb([(x % 251) as u8, (y * 3) as u8, 77])
    })
    .save(&quilt)
    .unwrap();
    let quilt_png = out("views_png_qs4x2a1.5.png");
    image::open(&quilt)
        .unwrap()
        .to_rgb8()
        .save(&quilt_png)
        .unwrap();
    let interleaved = |quilt: &Path, name: &str| {
        let image = out(name);
        let (ok, err) = common::cli(&[
            "interleave",
            s(quilt),
            "--display",
            "lenticular:8",
            "--out",
            s(&image),
        ]);
        assert!(ok, "{name}: {err}");
        RgbImage::load_png(&image).unwrap()
    };
    let a = interleaved(&quilt, "interleave_jpeg.png");
    let b = interleaved(&quilt_png, "interleave_png.png");
    assert_eq!(compare(&a, &b).unwrap().max_abs_err, 0);
}

/// `autostereo volume` reads a MetaImage as the same scan in NRRD (LPS geometry as a
/// TransformMatrix against RAS space directions), and a VTK `.vti` whose Direction points the
/// voxel axes where the NRRD's land on screen: the same image; and the geometry is used: the
/// NRRD's axes flipped render another picture.
#[test]
fn a_volume_renders_alike_from_nrrd_and_metaimage() {
    let n = 16usize;
    let voxels: Vec<u8> = (0..n * n * n)
        .map(|i| {
            let (x, y, z) = (i % n, i / n % n, i / (n * n));
            let d = (x as f32 - 5.0).powi(2) + (y as f32 - 8.0).powi(2) + (z as f32 - 10.0).powi(2);
            if d < 20.0 {
                200
            } else if x < 3 {
                120
            } else {
                0
            }
        })
        .collect();
    // Voxel axes in RAS+: i posterior, j right, k superior.
    let nrrd = |directions: &str| {
        let mut b = format!(
            "NRRD0004\ntype: uchar\ndimension: 3\nspace: RAS\nsizes: {n} {n} {n}\n\
             space directions: {directions}\nencoding: raw\n\n"
        )
        .into_bytes();
        b.extend(&voxels);
        b
    };
    let mut mha = format!(
        "ObjectType = Image\nNDims = 3\nTransformMatrix = 0 1 0 -1 0 0 0 0 1\n\
         ElementSpacing = 1 1 1\nDimSize = {n} {n} {n}\nElementType = MET_UCHAR\n\
         ElementDataFile = LOCAL\n"
    )
    .into_bytes();
    mha.extend(&voxels);
    let render = |file: &Path, name: &str| {
        let image = out(&format!("{name}.png"));
        let (ok, err) = common::cli(&[
            "volume",
            s(file),
            "--size",
            "48x48",
            "--tf",
            "ct-bone",
            "--out",
            s(&image),
        ]);
        assert!(ok, "{name}: {err}");
        RgbImage::load_png(&image).unwrap()
    };
    let from_nrrd = render(
        &write("scan.nrrd", &nrrd("(0,-1,0) (1,0,0) (0,0,1)")),
        "nrrd",
    );
    let from_mha = render(&write("scan.mha", &mha), "mha");
    assert_eq!(compare(&from_mha, &from_nrrd).unwrap().max_abs_err, 0);
    // VTK's world is the screen's (x right, y up, z toward the viewer): the NRRD's axes on
    // screen are i → −z, j → −x, k → +y, the columns of this row-major Direction.
    let values: Vec<String> = voxels.iter().map(u8::to_string).collect();
    let vti = format!(
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" byte_order=\"LittleEndian\">\n\
         <ImageData WholeExtent=\"0 {m} 0 {m} 0 {m}\" Spacing=\"1 1 1\" \
         Direction=\"0 -1 0 0 0 1 -1 0 0\">\n<Piece Extent=\"0 {m} 0 {m} 0 {m}\">\n\
         <PointData Scalars=\"ct\"><DataArray type=\"UInt8\" Name=\"ct\" format=\"ascii\">\n\
         {}\n</DataArray></PointData></Piece></ImageData></VTKFile>\n",
        values.join(" "),
        m = n - 1
    );
    let from_vti = render(&write("scan.vti", vti.as_bytes()), "vti");
    assert_eq!(compare(&from_vti, &from_nrrd).unwrap().max_abs_err, 0);
    let flipped = render(
        &write("flipped.nrrd", &nrrd("(0,1,0) (-1,0,0) (0,0,1)")),
        "flipped",
    );
    assert!(compare(&flipped, &from_nrrd).unwrap().frac_off_2 > 0.01);
}
