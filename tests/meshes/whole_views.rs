//! Images of whole views (`render::render_view`, `render_quilt`, `render_stereo`): what they
//! assemble, against each view's frame built here by hand and rendered by the N-pass (the
//! renderers' own exactness is the other modules'): a quilt's every tile at the tile's own
//! aspect, empty tiles black, and a side-by-side pair's two halves.

use crate::common;

use autostereo::display::Display;
use autostereo::frame::Frame;
use autostereo::image_io::RgbImage;
use autostereo::mesh::{Mesh, MeshBuffers, MeshNPass};
use autostereo::render::quilt::QuiltLayout;
use autostereo::render::quilt_image::QuiltImage;
use autostereo::render::{render_quilt, render_stereo, Method, StereoFormat};
use autostereo::{AnyRenderer, AnyScene, RendererOptions};

/// View `v` of `frame` at `size`, seen at `aspect`, by the N-pass.
fn npass_view(
    buffers: &MeshBuffers,
    frame: &Frame,
    v: u32,
    size: [u32; 2],
    aspect: f32,
) -> RgbImage {
    let device = &common::gpu().device.clone();
    let mut eye = Frame {
        display: Display::parse(&format!("view:{},{v}", frame.camera.views)).unwrap(),
        size,
        ..frame.clone()
    };
    eye.camera.aspect = aspect;
    common::render(
        &mut MeshNPass::new(device, Method::NPass).unwrap(),
        buffers,
        &eye,
    )
}

/// The `size` region of `image` at `origin`.
fn crop(image: &RgbImage, origin: [u32; 2], size: [u32; 2]) -> RgbImage {
    let mut out = RgbImage::new(size[0], size[1]);
    for y in 0..size[1] {
        let src = (((origin[1] + y) * image.width + origin[0]) * 3) as usize;
        let dst = (y * size[0] * 3) as usize;
        let row = (size[0] * 3) as usize;
        out.data[dst..dst + row].copy_from_slice(&image.data[src..src + row]);
    }
    out
}

/// The torus scene on `lenticular:N` at 64×48, its buffers, and the N-pass as `AnyRenderer`.
struct Setup {
    frame: Frame,
    buffers: MeshBuffers,
    scene: AnyScene,
    npass: AnyRenderer,
}

fn setup(views: u32) -> Setup {
    let mesh = Mesh::torus_scene();
    let spec = format!("lenticular:{views}");
    let frame = common::frame(mesh.bounds().unwrap(), &spec, 0.15, 1.0, [64, 48]);
    let device = &common::gpu().device.clone();
    let scene = AnyScene::Mesh(MeshBuffers::new(device, &mesh).unwrap());
    let options = RendererOptions {
        method: Method::NPass,
        ..Default::default()
    };
    Setup {
        frame,
        buffers: MeshBuffers::new(device, &mesh).unwrap(),
        npass: AnyRenderer::new(device, &scene, &options).unwrap(),
        scene,
    }
}

/// Looking Glass's quilt: tiles of any pixel aspect (20×30 here) hold views shown at the
/// quilt's aspect (the frame's 4/3: stretched), laid from the bottom-left of an image with a
/// remainder (61×61: the top row and right column unused, black, like the empty sixth tile).
#[test]
fn a_quilt_holds_every_view_at_the_quilts_aspect_and_black_empty_tiles() {
    let Setup {
        frame,
        buffers,
        scene,
        mut npass,
    } = setup(5);
    let ctx = common::gpu();
    let layout = QuiltLayout::with_grid(3, 2, [20, 30], 5).unwrap();
    let image = QuiltImage::new(layout, [61, 61], 4.0 / 3.0).unwrap();
    let quilt = render_quilt(&ctx.device, &ctx.queue, &mut npass, &scene, &frame, &image).unwrap();
    drop(ctx);
    assert_eq!([quilt.width, quilt.height], [61, 61]);
    let origin = |v: u32| {
        let [x, y] = layout.tile_origin(v);
        [x, y + 1]
    };
    for v in 0..5 {
        let tile = crop(&quilt, origin(v), layout.tile);
        let oracle = npass_view(&buffers, &frame, v, layout.tile, 4.0 / 3.0);
        common::assert_matches(&format!("quilt-tile-{v}"), &tile, &oracle);
    }
    let empty = crop(&quilt, origin(5), layout.tile);
    assert!(
        empty.data.iter().all(|&b| b == 0),
        "the empty tile is not black"
    );
    let top = crop(&quilt, [0, 0], [61, 1]);
    let right = crop(&quilt, [60, 0], [1, 61]);
    assert!(
        top.data.iter().chain(&right.data).all(|&b| b == 0),
        "the remainder is not black"
    );
}

#[test]
fn a_side_by_side_pair_is_the_two_views_at_the_frames_aspect() {
    let Setup {
        frame,
        buffers,
        scene,
        mut npass,
    } = setup(8);
    let ctx = common::gpu();
    let eye = [32, 48];
    let format = StereoFormat::SideBySide;
    let pair = render_stereo(
        &ctx.device,
        &ctx.queue,
        &mut npass,
        &scene,
        &frame,
        format,
        eye,
        [2, 6],
    )
    .unwrap();
    drop(ctx);
    assert_eq!([pair.width, pair.height], [64, 48]);
    for (v, x) in [(2, 0), (6, 32)] {
        // The half-width forms squeeze: each eye keeps the frame's aspect.
        let oracle = npass_view(&buffers, &frame, v, eye, frame.camera.aspect);
        common::assert_matches(
            &format!("side-by-side-{v}"),
            &crop(&pair, [x, 0], eye),
            &oracle,
        );
    }
}
