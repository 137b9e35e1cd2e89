//! Per-view resolution (`Frame::view_scale`, `--view-scale`): the methods that render view
//! images render them at S × the size and up-sample them when compositing. Oracle: each view
//! rendered alone at the small size (a `view:N,V` display, full resolution), up-sampled on the
//! CPU with the bilinear filter of `wgsl/shared/upsample.wgsl` and interleaved with the CPU mask.

use crate::common;

use autostereo::display::Display;
use autostereo::frame::Frame;
use autostereo::image_io::{compare, RgbImage};
use autostereo::mesh::{Mesh, MeshBuffers};
use autostereo::mesh::{
    MeshLayered, MeshMrt, MeshNPass, MeshSinglePass, MeshSinglePassOptions, MeshTiled, TileClip,
};
use autostereo::points::DEFAULT_EPSILON_FRACTION;
use autostereo::points::{GroupCount, PointCloud, SplatScene};
use autostereo::points::{PointSplatter, SplatOptions};
use autostereo::render::quilt::QuiltLayout;
use autostereo::render::{Method, Renderer};
use autostereo::volume::VolumeRaycaster;
use autostereo::volume::VolumeSettings;

/// `image` (`src` texels) at `dst` pixels, bilinearly, as `bilinear_at` / `bilinear_mix` do:
/// pixel centres onto texel centres, texels clamped to the image.
fn upsample(image: &RgbImage, dst: [u32; 2]) -> Vec<[f32; 3]> {
    let src = [image.width, image.height];
    let axis = |x: u32, a: usize| {
        let p = (x as f32 + 0.5) * src[a] as f32 / dst[a] as f32 - 0.5;
        let f = p.floor();
        let last = (src[a] - 1) as f32;
        (
            f.clamp(0.0, last) as u32,
            (f + 1.0).clamp(0.0, last) as u32,
            p - f,
        )
    };
    let texel = |x: u32, y: u32, c: u32| image.get(x, y, c) as f32 / 255.0;
    let mix = |a: f32, b: f32, t: f32| a * (1.0 - t) + b * t;
    let mut out = Vec::new();
    for y in 0..dst[1] {
        let (y0, y1, wy) = axis(y, 1);
        for x in 0..dst[0] {
            let (x0, x1, wx) = axis(x, 0);
            out.push([0, 1, 2].map(|c| {
                let top = mix(texel(x0, y0, c), texel(x1, y0, c), wx);
                let bottom = mix(texel(x0, y1, c), texel(x1, y1, c), wx);
                mix(top, bottom, wy)
            }));
        }
    }
    out
}

/// The oracle: each view alone at `frame`'s view size by `alone`, up-sampled, interleaved.
fn oracle<S: ?Sized>(alone: &mut dyn Renderer<S>, scene: &S, frame: &Frame) -> RgbImage {
    let n = frame.camera.views;
    let views: Vec<Vec<[f32; 3]>> = (0..n)
        .map(|v| {
            let one = Frame {
                display: Display::parse(&format!("view:{n},{v}")).unwrap(),
                size: frame.view_size(),
                view_scale: [1.0; 2],
                ..frame.clone()
            };
            upsample(&common::render(alone, scene, &one), frame.size)
        })
        .collect();
    let mask = frame.display.mask();
    let [w, h] = frame.size;
    let mut image = RgbImage::new(w, h);
    for y in 0..h {
        for x in 0..w {
            for c in 0..3 {
                let v = mask.view(x, y, c) as usize;
                let value = views[v][(y * w + x) as usize][c as usize];
                image.set(x, y, c, (value * 255.0).round() as u8);
            }
        }
    }
    image
}

/// Scaled renders of `method`s agree with the oracle to one level in 255.
fn assert_upsampled<S: ?Sized>(
    name: &str,
    renderers: &mut [(&str, Box<dyn Renderer<S>>)],
    alone: &mut dyn Renderer<S>,
    scene: &S,
    frame: &Frame,
) {
    let expected = oracle(alone, scene, frame);
    for (method, renderer) in renderers.iter_mut() {
        let image = common::render(renderer.as_mut(), scene, frame);
        let diff = compare(&image, &expected).unwrap();
        let full = Frame {
            view_scale: [1.0; 2],
            ..frame.clone()
        };
        let at_full = common::render(renderer.as_mut(), scene, &full);
        let tag = format!("{name} {method} S={}", frame.view_scale_text());
        if diff.max_abs_err > 1 {
            let path = common::save_diff(&tag.replace(' ', "_"), &image, &expected);
            panic!("{tag}: {diff:?} (diff image {})", path.display());
        }
        assert!(
            compare(&image, &at_full).unwrap().frac_off_2 > 0.001,
            "{tag}: the scaled render equals the full-size one"
        );
    }
}

fn scaled(frame: &Frame, s: f32) -> Frame {
    let mut frame = frame.clone();
    frame.view_scale = [s; 2];
    frame.validate().unwrap();
    frame
}

#[test]
fn mesh_view_images_are_the_small_views_upsampled() {
    let mesh = Mesh::torus_scene();
    let device = common::gpu().device.clone();
    let buffers = MeshBuffers::new(&device, &mesh).unwrap();
    let base = common::frame(mesh.bounds().unwrap(), "hubner8", 0.15, 1.0, [96, 64]);
    // 0.3 rounds up to 29×20: a different aspect than the panel's, same camera; 32×48 scales
    // x and y apart (tall tiles of a wide frame, as Looking Glass's square quilt tiles are).
    let mut anisotropic = base.clone();
    anisotropic.scale_views_to([32, 48]).unwrap();
    for frame in [scaled(&base, 0.5), scaled(&base, 0.3), anisotropic] {
        let mut renderers: Vec<(&str, Box<dyn Renderer<MeshBuffers>>)> = vec![
            (
                "n-pass",
                Box::new(MeshNPass::new(&device, Method::NPass).unwrap()),
            ),
            (
                "tiled",
                Box::new(MeshTiled::new(&device, TileClip::Discard).unwrap()),
            ),
            ("layered", Box::new(MeshLayered::new(&device).unwrap())),
        ];
        let mut alone = MeshNPass::new(&device, Method::NPass).unwrap();
        assert_upsampled("mesh", &mut renderers, &mut alone, &buffers, &frame);
    }
    // MRT's shared depth makes its views differ from the N-pass's (tests/duplication.rs); at
    // a scale it must still composite from small view images: close to its own full size.
    let frame = scaled(&base, 0.5);
    let mut mrt = MeshMrt::new(&device).unwrap();
    let small = common::render(&mut mrt, &buffers, &frame);
    let full = common::render(&mut mrt, &buffers, &base);
    let diff = compare(&small, &full).unwrap();
    assert!(diff.frac_off_2 > 0.001 && diff.psnr_db > 20.0, "{diff:?}");
}

/// Duplication at a panel's size draws its views in chunks that reuse one set of group images
/// (bands of tile rows, runs of views): forced here with caps that fit three tile rows of the
/// 8-row atlas (bands of 3, 3 and 2 rows: the shorter band drawn into images sized for the
/// taller) and about half the views, at a view scale.
fn assert_chunked_splats_are_upsampled(
    device: &wgpu::Device,
    splats: &autostereo::points::Splats,
    scene: &SplatScene,
    options: SplatOptions,
) {
    let base = common::frame(
        splats.bounds().unwrap(),
        "slanted:45,7.5,1/6,0.2",
        0.15,
        1.0,
        [80, 60],
    );
    let frame = scaled(&base, 0.5);
    let groups = scene.groups() as u64;
    assert!(groups > 3, "three rows fit only with more than 3 groups");
    let [tw, th] = frame.view_size().map(u64::from);
    let atlas = QuiltLayout::for_views(frame.camera.views, frame.view_size());
    assert_eq!(atlas.rows, 8, "{atlas:?}");
    // 16 bytes per group texel; one spare layer of slack (`ViewLayers` may add one).
    let tiled_cap = 16 * atlas.cols as u64 * tw * 3 * th * (groups + 1);
    let views = frame.camera.views as u64;
    let layered_cap = 16 * tw * th * (groups * views / 2 + 1);
    let mut alone = PointSplatter::new(device, Method::NPass, options).unwrap();
    let expected = oracle(&mut alone, scene, &frame);
    for (method, cap, chunks) in [
        (Method::Tiled, tiled_cap, "3 bands"),
        (Method::Layered, layered_cap, "runs"),
    ] {
        let mut renderer = PointSplatter::new(device, method, options).unwrap();
        renderer.set_max_image_bytes(cap);
        let image = common::render(&mut renderer, scene, &frame);
        let how = renderer.describe();
        // Without multiview (GL) layered is the N-pass itself: one view's images at a time.
        let single_views = method == Method::Layered && how.contains("no multiview");
        assert!(single_views || how.contains(chunks), "{method}: {how}");
        let diff = compare(&image, &expected).unwrap();
        if diff.max_abs_err > 1 {
            let tag = format!("points_{method}_chunked_S{}", frame.view_scale_text());
            let path = common::save_diff(&tag, &image, &expected);
            panic!("{tag} ({how}): {diff:?} (diff image {})", path.display());
        }
    }
}

#[test]
fn points_and_volume_view_images_are_the_small_views_upsampled() {
    let device = common::gpu().device.clone();
    let (splats, _) = PointCloud::torus_scene().complete(1.0).unwrap();
    let scene = SplatScene::new(&device, &splats, GroupCount::Auto).unwrap();
    let options = SplatOptions::for_scene(&scene, DEFAULT_EPSILON_FRACTION);
    let base = common::frame(
        splats.bounds().unwrap(),
        "lenticular:8",
        0.15,
        1.0,
        [96, 64],
    );
    let frame = scaled(&base, 0.5);
    let splatter = |m| Box::new(PointSplatter::new(&device, m, options).unwrap());
    let mut renderers: Vec<(&str, Box<dyn Renderer<SplatScene>>)> = vec![
        ("n-pass", splatter(Method::NPass)),
        ("tiled", splatter(Method::Tiled)),
        ("layered", splatter(Method::Layered)),
    ];
    let mut alone = PointSplatter::new(&device, Method::NPass, options).unwrap();
    assert_upsampled("points", &mut renderers, &mut alone, &scene, &frame);
    assert_chunked_splats_are_upsampled(&device, &splats, &scene, options);

    let (volume, bounds) = common::head_scene();
    let base = common::frame(bounds, "hubner8", 0.1, 1.0, [64, 64]);
    let frame = scaled(&base, 0.5);
    let raycaster =
        |m| Box::new(VolumeRaycaster::new(&device, m, VolumeSettings::default()).unwrap());
    let mut renderers: Vec<(&str, Box<dyn Renderer<_>>)> = vec![
        ("n-pass", raycaster(Method::NPass)),
        ("tiled", raycaster(Method::Tiled)),
        ("layered", raycaster(Method::Layered)),
    ];
    let mut alone =
        VolumeRaycaster::new(&device, Method::NPass, VolumeSettings::default()).unwrap();
    assert_upsampled("volume", &mut renderers, &mut alone, &volume, &frame);
}

#[test]
fn view_sizes_round_up_and_methods_without_view_images_refuse_a_scale() {
    let mesh = Mesh::torus_scene();
    let base = common::frame(mesh.bounds().unwrap(), "hubner8", 0.15, 1.0, [96, 64]);
    assert_eq!(scaled(&base, 1.0).view_size(), [96, 64]);
    assert_eq!(scaled(&base, 0.3).view_size(), [29, 20]);
    assert_eq!(scaled(&base, 1e-6).view_size(), [1, 1]);
    // Any view size, of any aspect, is what it asks for (Looking Glass's square tiles of a
    // 16:9 panel among them); larger than the frame is refused by name.
    let mut panel = common::frame(mesh.bounds().unwrap(), "hubner8", 0.15, 1.0, [3840, 2160]);
    for size in [[857, 857], [1, 2160], [3840, 1], [3839, 2159], [420, 560]] {
        panel.scale_views_to(size).unwrap();
        assert_eq!(panel.view_size(), size);
    }
    let error = panel.scale_views_to([857, 2161]).unwrap_err().to_string();
    assert!(
        error.contains("view image size") && error.contains("857x2161"),
        "{error}"
    );
    for bad in [0.0, -0.5, 1.5, f32::NAN] {
        let mut frame = base.clone();
        frame.view_scale = [bad, 0.5];
        let error = frame.validate().unwrap_err().to_string();
        assert!(
            error.contains("view scale") && error.contains("(0, 1]"),
            "{error}"
        );
    }
    let device = common::gpu().device.clone();
    let buffers = MeshBuffers::new(&device, &mesh).unwrap();
    let frame = scaled(&base, 0.5);
    let mut refusing: Vec<(&str, Box<dyn Renderer<MeshBuffers>>)> = vec![
        (
            "single-pass",
            Box::new(MeshSinglePass::new(&device, MeshSinglePassOptions::default()).unwrap()),
        ),
        (
            "single-view",
            Box::new(MeshNPass::new(&device, Method::SingleView).unwrap()),
        ),
    ];
    for (name, renderer) in refusing.iter_mut() {
        let ctx = common::gpu();
        let error = renderer
            .prepare(&ctx.device, &ctx.queue, &buffers, &frame)
            .unwrap_err()
            .to_string();
        assert!(
            error.contains("view scale") && error.contains(*name),
            "{name}: {error}"
        );
    }
    for (args, expect) in [
        (&["mesh", "--view-scale", "0"][..], "(0, 1]"),
        (&["mesh", "--view-scale", "1.5"][..], "(0, 1]"),
        (
            &["mesh", "--method", "single-pass", "--view-scale", "0.5"][..],
            "the single-pass method renders no view images",
        ),
        (
            &["volume", "--method", "warp", "--view-scale", "0.5"][..],
            "the warp method renders no view images",
        ),
    ] {
        let (ok, err) = common::cli(&common::measuring(args));
        assert!(!ok && err.contains(expect), "{args:?}: {err}");
    }
}
