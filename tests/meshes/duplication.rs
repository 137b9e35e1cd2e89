//! The per-view duplication methods (tiled, layered, MRT) against the N-pass oracle on meshes,
//! on several displays and N = 1, 2, 8, 45 ([`common::DISPLAYS`]); the tile clip; MRT's
//! occlusion error explained by the shared depth buffer; the quilt round trip (meshes, points,
//! volumes).

use crate::common;

use autostereo::frame::Frame;
use autostereo::image_io::{compare, RgbImage};
use autostereo::mesh::{Mesh, MeshBuffers};
use autostereo::mesh::{MeshMrt, MeshNPass, MeshTiled, TileClip};
use autostereo::points::{GroupCount, PointCloud, SplatScene};
use autostereo::render::atlas::{Atlas, QuiltInterleaver};
use autostereo::render::batches::batches;
use autostereo::render::quilt::QuiltLayout;
use autostereo::render::quilt_image::{QuiltImage, QuiltName};
use autostereo::render::{Method, Renderer};
use autostereo::target::SpatialTarget;
use autostereo::{AnyRenderer, AnyScene, RendererOptions};

fn mesh_frame(mesh: &Mesh, spec: &str, size: [u32; 2]) -> Frame {
    common::frame(mesh.bounds().unwrap(), spec, 0.15, 1.0, size)
}

#[test]
fn mesh_tiled_and_layered_match_the_npass() {
    let mesh = Mesh::torus_scene();
    let ctx = common::gpu();
    let buffers = MeshBuffers::new(&ctx.device, &mesh).unwrap();
    let clips: Vec<TileClip> = if ctx
        .device
        .features()
        .contains(wgpu::Features::CLIP_DISTANCES)
    {
        vec![TileClip::ClipDistances, TileClip::Discard]
    } else {
        let error = MeshTiled::new(&ctx.device, TileClip::ClipDistances)
            .err()
            .unwrap();
        common::assert_missing_feature(&ctx.device, &error, "TileClip::Discard");
        vec![TileClip::Discard]
    };
    drop(ctx);
    for &(spec, size) in common::DISPLAYS {
        let frame = mesh_frame(&mesh, spec, size);
        let device = &common::gpu().device.clone();
        let oracle = common::render(
            &mut MeshNPass::new(device, Method::NPass).unwrap(),
            &buffers,
            &frame,
        );
        for &clip in &clips {
            let mut tiled = MeshTiled::new(device, clip).unwrap();
            let image = common::render(&mut tiled, &buffers, &frame);
            common::assert_matches(&format!("tiled-{}-{spec}", clip.name()), &image, &oracle);
        }
        let mut layered = autostereo::mesh::MeshLayered::new(device).unwrap();
        let image = common::render(&mut layered, &buffers, &frame);
        let name = format!("layered-{spec}");
        let diff = common::assert_matches(&name, &image, &oracle);
        eprintln!("{name} ({}): {diff:?}", layered.describe());
    }
}

/// The clip matters: a copy that is not clipped to its tile spills into its neighbours. A mesh
/// far wider than the view shows it (the tiled image then differs from the N-pass); this keeps
/// the tiled tests from passing by a layout that never overlaps.
#[test]
fn tiles_clip_geometry_that_leaves_the_view() {
    let mut mesh = Mesh::torus_scene();
    let bounds = mesh.bounds().unwrap();
    // A wide floor crossing every tile edge, behind the tori.
    let r = bounds.radius();
    let c = bounds.center();
    mesh.append(&Mesh::rectangle(
        [c.x - 20.0 * r, c.y - 20.0 * r],
        [c.x + 20.0 * r, c.y + 20.0 * r],
        c.z - 1.5 * r,
        [0.9, 0.8, 0.2, 1.0],
    ));
    let frame = common::frame(bounds, "lenticular:8", 0.15, 1.0, [96, 64]);
    let device = common::gpu().device.clone();
    let buffers = MeshBuffers::new(&device, &mesh).unwrap();
    let oracle = common::render(
        &mut MeshNPass::new(&device, Method::NPass).unwrap(),
        &buffers,
        &frame,
    );
    let mut tiled = MeshTiled::new(&device, TileClip::Discard).unwrap();
    let image = common::render(&mut tiled, &buffers, &frame);
    common::assert_matches("tiled-wide-floor", &image, &oracle);
}

/// Per-view depth maps from the tiled render's one depth buffer (view v = its tile).
fn view_depths(tiled: &MeshTiled, frame: &Frame) -> Vec<Vec<f32>> {
    let ctx = common::gpu();
    let atlas = tiled.atlas().unwrap();
    let depth = atlas.read_depth(&ctx.device, &ctx.queue).unwrap();
    let [aw, _] = atlas.layout.size();
    let [w, h] = frame.size;
    (0..frame.camera.views)
        .map(|v| {
            let [ox, oy] = atlas.layout.tile_origin(v);
            let mut out = Vec::with_capacity((w * h) as usize);
            for y in 0..h {
                for x in 0..w {
                    out.push(depth[((oy + y) * aw + ox + x) as usize]);
                }
            }
            out
        })
        .collect()
}

/// MRT's error, measured: where it differs from the N-pass, the subpixel's view has a nearer
/// surface of another view of its pass in front (the shared depth buffer), as the tiled
/// render's per-view depth maps show. N = 1 is exact; on the torus scene at N = 8 the error is
/// real (it is the method's, not hidden).
#[test]
fn mrt_error_is_what_the_shared_depth_buffer_explains() {
    let mesh = Mesh::torus_scene();
    let device = common::gpu().device.clone();
    let buffers = MeshBuffers::new(&device, &mesh).unwrap();
    for &(spec, size) in common::DISPLAYS {
        let frame = mesh_frame(&mesh, spec, size);
        let oracle = common::render(
            &mut MeshNPass::new(&device, Method::NPass).unwrap(),
            &buffers,
            &frame,
        );
        let mut mrt = MeshMrt::new(&device).unwrap();
        let image = common::render(&mut mrt, &buffers, &frame);
        let mut tiled = MeshTiled::new(&device, TileClip::Auto).unwrap();
        common::render(&mut tiled, &buffers, &frame);
        let depths = view_depths(&tiled, &frame);
        let passes = batches(frame.camera.views, mrt.views_per_pass());
        let pass_of = |v: u32| passes.iter().find(|r| r.contains(&v)).unwrap().clone();
        let mask = frame.display.mask();
        let [w, h] = frame.size;
        let (mut wrong, mut unexplained) = (0usize, 0usize);
        for y in 0..h {
            for x in 0..w {
                let i = (y * w + x) as usize;
                for c in 0..3 {
                    if image.get(x, y, c).abs_diff(oracle.get(x, y, c)) <= 2 {
                        continue;
                    }
                    wrong += 1;
                    let v = mask.view(x, y, c);
                    let own = depths[v as usize][i];
                    let hidden = pass_of(v).any(|u| u != v && depths[u as usize][i] < own);
                    unexplained += usize::from(!hidden);
                }
            }
        }
        let subpixels = (w * h * 3) as usize;
        let diff = compare(&image, &oracle).unwrap();
        eprintln!(
            "mrt {spec}: {diff:?}; {wrong} wrong subpixels, {unexplained} not explained by the \
             shared depth"
        );
        if frame.camera.views == 1 {
            assert_eq!(wrong, 0, "{spec}: one view per pass is exact");
        }
        if frame.camera.views == 8 {
            assert!(
                wrong > subpixels / 100,
                "{spec}: the shared depth must show"
            );
        }
        // Edges where tiled and N-pass rasterise a pixel differently are the only slack.
        assert!(
            unexplained * 1000 <= subpixels,
            "{spec}: {unexplained} of {wrong} wrong subpixels unexplained"
        );
    }
}

/// The quilt of a tiled render, written as a Looking Glass PNG and interleaved again for the
/// same display, is the tiled method's spatial image, bit for bit.
#[test]
fn quilt_out_interleaved_again_is_the_tiled_image() {
    let mesh = Mesh::torus_scene();
    let device = common::gpu().device.clone();
    let buffers = MeshBuffers::new(&device, &mesh).unwrap();
    let (scene, bounds) = common::head_scene();
    let volume = AnyScene::Volume(Box::new(scene));
    let meshes = AnyScene::Mesh(buffers);
    let (splats, _) = PointCloud::torus_scene().complete(1.0).unwrap();
    let points = AnyScene::Points(SplatScene::new(&device, &splats, GroupCount::Auto).unwrap());
    let cases = [
        (&meshes, mesh.bounds().unwrap()),
        (&volume, bounds),
        (&points, splats.bounds().unwrap()),
    ];
    for (scene, bounds) in cases {
        for &(spec, size) in &common::DISPLAYS[2..] {
            let frame = common::frame(bounds, spec, 0.15, 1.0, size);
            let mut tiled =
                AnyRenderer::new(&device, scene, &RendererOptions::new(Method::Tiled)).unwrap();
            let spatial = common::render(&mut tiled, scene, &frame);
            let ctx = common::gpu();
            let atlas = tiled.atlas().unwrap();
            let path = QuiltImage::of_tiles(atlas.layout)
                .file_name(&common::out_dir().join(format!("quilt-{}.png", scene.primitive())));
            atlas
                .read(&ctx.device, &ctx.queue)
                .unwrap()
                .save_png(&path)
                .unwrap();
            let name = path.file_name().unwrap().to_str().unwrap();
            let named = QuiltName::parse(name).unwrap();
            let (cols, rows, aspect) = (named.cols, named.rows, named.aspect);
            let quilt = RgbImage::load_png(&path).unwrap();
            let tile = [quilt.width / cols, quilt.height / rows];
            assert!((tile[0] as f32 / tile[1] as f32 - aspect).abs() < 1e-3);
            let layout = QuiltLayout::with_grid(cols, rows, tile, frame.camera.views).unwrap();
            let atlas = Atlas::from_image(&ctx.device, &ctx.queue, &quilt, layout).unwrap();
            let target = SpatialTarget::new(&ctx.device, frame.size).unwrap();
            let mut interleaver = QuiltInterleaver::new(&ctx.device).unwrap();
            interleaver
                .render(&ctx.device, &ctx.queue, &atlas, &frame, &target)
                .unwrap();
            let again = target.read(&ctx.device, &ctx.queue).unwrap();
            assert_eq!(again.data, spatial.data, "{} {spec}", scene.primitive());
        }
    }
}
