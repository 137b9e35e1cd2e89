//! Base-colour textures (issue 39's must-show): a textured glTF and an OBJ with `map_Kd`,
//! generated here with a checker texture, render the texture's colours in the single pass,
//! equal to the N-pass (≤ 0.1 % of subpixels off by 2/255), and so do the duplication
//! methods; the texture lands the right way up (glTF's v down, OBJ's v up); the sampler's
//! wrapping and KHR_texture_transform are applied.
#![cfg(feature = "gltf")]

use crate::common;
use crate::mesh_formats::glb_container;

use autostereo::camera::MultiViewCamera;
use autostereo::display::Display;
use autostereo::frame::Frame;
use autostereo::image_io::RgbImage;
use autostereo::mesh::{Filter, Mesh, MeshBuffers, MeshNPass, Wrap};
use autostereo::mesh::{MeshLayered, MeshSinglePassOptions, MeshTiled, TileClip, Visibility};
use autostereo::render::Method;

const RED: [u8; 3] = [220, 30, 30];
const BLUE: [u8; 3] = [30, 40, 220];

/// A PNG of `w × h` texels coloured by `color(x, y)`.
fn png(w: u32, h: u32, color: impl Fn(u32, u32) -> [u8; 3]) -> Vec<u8> {
    let image = image::RgbImage::from_fn(w, h, |x, y| image::Rgb(color(x, y)));
    let mut bytes = Vec::new();
    image
        .write_to(
            &mut std::io::Cursor::new(&mut bytes),
            image::ImageFormat::Png,
        )
        .unwrap();
    bytes
}

/// An 8 × 8 checker of red and blue texels.
fn checker_png() -> Vec<u8> {
    png(8, 8, |x, y| if (x + y) % 2 == 0 { RED } else { BLUE })
}

/// 16 × 16 texels in quadrants: red top-left, green top-right, blue bottom-left, yellow
/// bottom-right (large enough that bilinear filtering blends only near their edges).
fn quadrants_png() -> Vec<u8> {
    png(16, 16, |x, y| match (x < 8, y < 8) {
        (true, true) => [230, 20, 20],
        (false, true) => [20, 230, 20],
        (true, false) => [20, 20, 230],
        _ => [230, 230, 20],
    })
}

/// A unit quad facing +z (the camera) turned `yaw` about y, texture coordinates (0, 0) at its
/// top-left to `uv_max` at its bottom-right (glTF's convention).
fn quad(yaw: f32, uv_max: f32) -> ([[f32; 3]; 4], [[f32; 2]; 4]) {
    let (s, c) = yaw.sin_cos();
    let corner = |x: f32, y: f32| [x * c, y, -x * s];
    (
        [
            corner(-1.0, 1.0),
            corner(1.0, 1.0),
            corner(1.0, -1.0),
            corner(-1.0, -1.0),
        ],
        [[0.0, 0.0], [uv_max, 0.0], [uv_max, uv_max], [0.0, uv_max]],
    )
}

/// A GLB of `quad` with its image `png` in a buffer view, the texture's `sampler` JSON and the
/// texture info's `extensions` JSON (empty for none).
fn textured_glb(
    quad: ([[f32; 3]; 4], [[f32; 2]; 4]),
    png: &[u8],
    sampler: &str,
    ext: &str,
) -> Vec<u8> {
    let mut bin = Vec::new();
    quad.0
        .iter()
        .flatten()
        .for_each(|v| bin.extend(v.to_le_bytes()));
    quad.1
        .iter()
        .flatten()
        .for_each(|v| bin.extend(v.to_le_bytes()));
    [0u16, 3, 1, 1, 3, 2]
        .iter()
        .for_each(|i| bin.extend(i.to_le_bytes()));
    bin.extend([0, 0]); // the image's view starts 4-aligned
    let image_at = bin.len();
    bin.extend(png);
    let json = format!(
        r#"{{"asset":{{"version":"2.0"}},"scene":0,"scenes":[{{"nodes":[0]}}],"nodes":[{{"mesh":0}}],
"meshes":[{{"primitives":[{{"attributes":{{"POSITION":0,"TEXCOORD_0":1}},"indices":2,"material":0}}]}}],
"materials":[{{"pbrMetallicRoughness":{{"baseColorTexture":{{"index":0{ext}}}}}}}],
"textures":[{{"source":0,"sampler":0}}],"samplers":[{sampler}],
"images":[{{"bufferView":3,"mimeType":"image/png"}}],
"buffers":[{{"byteLength":{total}}}],
"bufferViews":[{{"buffer":0,"byteOffset":0,"byteLength":48}},{{"buffer":0,"byteOffset":48,"byteLength":32}},
{{"buffer":0,"byteOffset":80,"byteLength":12}},{{"buffer":0,"byteOffset":{image_at},"byteLength":{image_len}}}],
"accessors":[{{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[-1,-1,-1],"max":[1,1,1]}},
{{"bufferView":1,"componentType":5126,"count":4,"type":"VEC2"}},
{{"bufferView":2,"componentType":5123,"count":6,"type":"SCALAR"}}]}}"#,
        total = bin.len(),
        image_len = png.len(),
    );
    glb_container(json.into_bytes(), bin)
}

/// An OBJ of `quad` (OBJ's v up: v = 1 − glTF's v), its MTL with `map_Kd map`, and the PNG,
/// written side by side; the OBJ's path.
fn textured_obj(
    name: &str,
    quad: ([[f32; 3]; 4], [[f32; 2]; 4]),
    png: &[u8],
    map: &str,
) -> std::path::PathBuf {
    let mut obj = format!("mtllib {name}.mtl\nusemtl checker\n");
    for p in quad.0 {
        obj += &format!("v {} {} {}\n", p[0], p[1], p[2]);
    }
    for t in quad.1 {
        obj += &format!("vt {} {}\n", t[0], 1.0 - t[1]);
    }
    obj += "f 1/1 4/4 2/2\nf 2/2 4/4 3/3\n";
    common::input_file(&format!("{name}.png"), png);
    common::input_file(
        &format!("{name}.mtl"),
        format!("newmtl checker\nKd 1 1 1\nmap_Kd {map}\n"),
    );
    common::input_file(&format!("{name}.obj"), obj)
}

fn frame(mesh: &Mesh, spec: &str, size: [u32; 2]) -> Frame {
    let display = Display::parse(spec).unwrap();
    let aspect = size[0] as f32 / size[1] as f32;
    let camera = MultiViewCamera::framing(
        mesh.bounds().unwrap(),
        display.views(),
        Some(0.2 * mesh.bounds().unwrap().radius()),
        0.6,
        aspect,
    )
    .unwrap();
    Frame::new(camera, display, size).unwrap()
}

/// `mesh` rendered by the N-pass and compared with every exact single-pass mode the adapter
/// runs, the paper's fast mode, tiled and layered, on a subpixel Looking-Glass-like display
/// and on hubner8; the N-pass image of the first display.
fn assert_every_method_matches(name: &str, mesh: &Mesh) -> RgbImage {
    let device = common::gpu().device.clone();
    let buffers = MeshBuffers::new(&device, mesh).unwrap();
    let mut first = None;
    for (spec, size) in [("slanted:45,7.5,1/6,0.2", [96, 72]), ("hubner8", [96, 72])] {
        let frame = frame(mesh, spec, size);
        let oracle = common::render(
            &mut MeshNPass::new(&device, Method::NPass).unwrap(),
            &buffers,
            &frame,
        );
        let label = spec.replace(['/', ':', ','], "_");
        for visibility in [Visibility::Exact, Visibility::Atomic, Visibility::Compute] {
            let options = MeshSinglePassOptions {
                visibility,
                ..Default::default()
            };
            if let Some(mut renderer) = common::mesh_single_pass(&device, options) {
                let image = common::render(&mut renderer, &buffers, &frame);
                common::assert_matches(&format!("{name}-{visibility:?}-{label}"), &image, &oracle);
            }
        }
        // The paper's fast mode drops subpixels where the quad's two triangles split a pixel
        // (tests/meshes/single_pass_mesh.rs bounds it at 5 %), textured or not.
        let fast = MeshSinglePassOptions {
            visibility: Visibility::Fast,
            ..Default::default()
        };
        if let Some(mut renderer) = common::mesh_single_pass(&device, fast) {
            let image = common::render(&mut renderer, &buffers, &frame);
            let diff = autostereo::image_io::compare(&image, &oracle).unwrap();
            assert!(diff.frac_off_2 < 0.05, "{name} fast {spec}: {diff:?}");
        }
        let mut tiled = MeshTiled::new(&device, TileClip::Discard).unwrap();
        let image = common::render(&mut tiled, &buffers, &frame);
        common::assert_matches(&format!("{name}-tiled-{label}"), &image, &oracle);
        let mut layered = MeshLayered::new(&device).unwrap();
        let image = common::render(&mut layered, &buffers, &frame);
        common::assert_matches(&format!("{name}-layered-{label}"), &image, &oracle);
        oracle
            .save_png(&common::out(&format!("textures_{name}_{label}.png")))
            .unwrap();
        first.get_or_insert(oracle);
    }
    first.unwrap()
}

/// Shares of the image's pixels that are red-dominant and blue-dominant.
fn red_and_blue(image: &RgbImage) -> (f64, f64) {
    let n = (image.width * image.height) as f64;
    let (mut red, mut blue) = (0.0, 0.0);
    for p in image.data.chunks_exact(3) {
        let [r, g, b] = [p[0], p[1], p[2]].map(i32::from);
        red += (r > 2 * g.max(b) && r > 60) as u8 as f64;
        blue += (b > 2 * r.max(g) && b > 60) as u8 as f64;
    }
    (red / n, blue / n)
}

#[test]
fn a_textured_gltf_renders_its_checker_in_every_method_as_the_npass_does() {
    let sampler = r#"{"wrapS":10497,"wrapT":33648,"magFilter":9729}"#;
    let file = common::input_file(
        "checker.glb",
        textured_glb(quad(0.5, 2.0), &checker_png(), sampler, ""),
    );
    let mesh = Mesh::load(&file).unwrap();
    assert_eq!(mesh.textures.len(), 1);
    assert_eq!(mesh.textures[0].wrap, [Wrap::Repeat, Wrap::Mirror]);
    assert_eq!(mesh.textures[0].filter, Filter::Linear);
    assert!(mesh.is_textured());
    let image = assert_every_method_matches("gltf_checker", &mesh);
    let (red, blue) = red_and_blue(&image);
    assert!(
        red > 0.05 && blue > 0.05,
        "red {red}, blue {blue}: the checker is not drawn"
    );
}

#[test]
fn an_obj_with_map_kd_renders_its_checker_in_every_method_as_the_npass_does() {
    let file = textured_obj(
        "checker_obj",
        quad(-0.4, 2.0),
        &checker_png(),
        "-s 1 1 checker_obj.png",
    );
    let mesh = Mesh::load(&file).unwrap();
    assert_eq!(mesh.textures.len(), 1);
    assert_eq!(mesh.textures[0].wrap, [Wrap::Repeat; 2]);
    let image = assert_every_method_matches("obj_checker", &mesh);
    let (red, blue) = red_and_blue(&image);
    assert!(
        red > 0.05 && blue > 0.05,
        "red {red}, blue {blue}: the checker is not drawn"
    );
}

/// The colour of the pixel a quarter of the way in from each corner of a one-view render of a
/// quad facing the camera: which texel quadrant shows where.
fn quadrant_colours(mesh: &Mesh) -> [[u8; 3]; 4] {
    let device = common::gpu().device.clone();
    let buffers = MeshBuffers::new(&device, mesh).unwrap();
    let size = [64, 64];
    let image = common::render(
        &mut MeshNPass::new(&device, Method::NPass).unwrap(),
        &buffers,
        &frame(mesh, "lenticular:1", size),
    );
    image
        .save_png(&common::out("textures_quadrants.png"))
        .unwrap();
    let at = |x: u32, y: u32| [0, 1, 2].map(|c| image.get(x, y, c));
    [at(26, 26), at(38, 26), at(26, 38), at(38, 38)]
}

fn dominant(rgb: [u8; 3]) -> char {
    match rgb.map(u32::from) {
        [r, g, b] if r > 120 && g > 120 && b < 80 => 'y',
        [r, g, b] if r > 2 * g.max(b) => 'r',
        [r, g, b] if g > 2 * r.max(b) => 'g',
        [r, g, b] if b > 2 * r.max(g) => 'b',
        _ => '?',
    }
}

#[test]
fn textures_land_the_right_way_up_and_the_transform_is_applied() {
    let nearest = r#"{"magFilter":9728,"wrapS":33071,"wrapT":33071}"#;
    let gltf = common::input_file(
        "quadrants.glb",
        textured_glb(quad(0.0, 1.0), &quadrants_png(), nearest, ""),
    );
    let colours = quadrant_colours(&Mesh::load(&gltf).unwrap()).map(dominant);
    assert_eq!(
        colours,
        ['r', 'g', 'b', 'y'],
        "glTF: top-left, top-right, bottom-left, bottom-right"
    );
    let obj = textured_obj(
        "quadrants_obj",
        quad(0.0, 1.0),
        &quadrants_png(),
        "quadrants_obj.png",
    );
    let colours = quadrant_colours(&Mesh::load(&obj).unwrap()).map(dominant);
    assert_eq!(
        colours,
        ['r', 'g', 'b', 'y'],
        "OBJ (v up) lands as glTF does"
    );
    // KHR_texture_transform: scale (−1, 1) with offset (1, 0) mirrors u: green and red swap.
    let mirrored = r#","extensions":{"KHR_texture_transform":{"offset":[1,0],"scale":[-1,1]}}"#;
    let gltf = common::input_file(
        "quadrants_mirrored.glb",
        textured_glb(quad(0.0, 1.0), &quadrants_png(), nearest, mirrored),
    );
    let colours = quadrant_colours(&Mesh::load(&gltf).unwrap()).map(dominant);
    assert_eq!(colours, ['g', 'r', 'y', 'b'], "the transform mirrors u");
}

#[test]
fn a_texture_that_cannot_be_read_is_said_and_the_mesh_drawn_in_its_colours() {
    let file = textured_obj("missing_map", quad(0.0, 1.0), &checker_png(), "nowhere.png");
    let mesh = Mesh::load(&file).unwrap();
    assert!(mesh.textures.is_empty() && !mesh.is_textured());
    // A map_Kd with no file is a malformed MTL line, named.
    let error = Mesh::check_mtl_text("newmtl m\nmap_Kd -s 2 2\n", std::path::Path::new("m.mtl"))
        .unwrap_err()
        .to_string();
    assert!(
        error.contains("MTL line 2") && error.contains("names no file"),
        "{error}"
    );
}
