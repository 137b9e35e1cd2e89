//! The per-view duplication methods (tiled, layered) against the N-pass oracle on point
//! splats, on several displays and N = 1, 2, 8, 45 ([`common::DISPLAYS`]), whole and chunked by
//! texture size.

use crate::common;

use autostereo::points::DEFAULT_EPSILON_FRACTION;
use autostereo::points::{GroupCount, PointCloud, SplatScene};
use autostereo::points::{PointSplatter, SplatOptions};
use autostereo::render::quilt::QuiltLayout;
use autostereo::render::{Method, Renderer};

#[test]
fn points_tiled_and_layered_match_the_npass() {
    let (splats, _) = PointCloud::torus_scene().complete(1.0).unwrap();
    let device = common::gpu().device.clone();
    let scene = SplatScene::new(&device, &splats, GroupCount::Auto).unwrap();
    let options = SplatOptions::for_scene(&scene, DEFAULT_EPSILON_FRACTION);
    let error = PointSplatter::new(&device, Method::Mrt, options)
        .err()
        .unwrap();
    assert!(error.to_string().contains("meshes only"), "{error}");
    for &(spec, size) in common::DISPLAYS {
        let frame = common::frame(splats.bounds().unwrap(), spec, 0.15, 1.0, size);
        let mut npass = PointSplatter::new(&device, Method::NPass, options).unwrap();
        let oracle = common::render(&mut npass, &scene, &frame);
        for method in [Method::Tiled, Method::Layered] {
            let mut renderer = PointSplatter::new(&device, method, options).unwrap();
            let image = common::render(&mut renderer, &scene, &frame);
            let name = format!("points-{method}-{spec}");
            let diff = common::assert_matches(&name, &image, &oracle);
            eprintln!("{name} ({}): {diff:?}", renderer.describe());
        }
    }
}

/// Where every view's group images would outgrow one texture (a panel's size: 1920×1080,
/// N = 8 needs 4 GB), the views go in chunks that reuse one set of group images: bands of tile
/// rows (tiled) or runs of views (layered). Forced here with a small per-texture cap that lets
/// about half the views fit, the chunked renders still match the N-pass.
#[test]
fn points_chunked_by_texture_size_match_the_npass() {
    let (splats, _) = PointCloud::torus_scene().complete(1.0).unwrap();
    let device = common::gpu().device.clone();
    let scene = SplatScene::new(&device, &splats, GroupCount::Auto).unwrap();
    let groups = scene.groups() as u64;
    assert!(groups >= 3, "the caps below split only with ≥ 3 groups");
    let options = SplatOptions::for_scene(&scene, DEFAULT_EPSILON_FRACTION);
    for &(spec, size) in &common::DISPLAYS[1..] {
        let frame = common::frame(splats.bounds().unwrap(), spec, 0.15, 1.0, size);
        let views = frame.camera.views;
        let mut npass = PointSplatter::new(&device, Method::NPass, options).unwrap();
        let oracle = common::render(&mut npass, &scene, &frame);
        // 16 bytes per group texel; one spare layer of slack (`ViewLayers` may add one).
        let texel = |area: u64| area * 16;
        let atlas = QuiltLayout::for_views(views, size).size();
        let atlas_area = atlas[0] as u64 * atlas[1] as u64;
        let view_area = size[0] as u64 * size[1] as u64;
        let caps = [
            (Method::Tiled, texel(atlas_area) * (groups / 2 + 1), "bands"),
            (
                Method::Layered,
                texel(view_area) * (groups * views as u64 / 2 + 1),
                "runs",
            ),
        ];
        for (method, cap, chunks) in caps {
            let mut renderer = PointSplatter::new(&device, method, options).unwrap();
            renderer.set_max_image_bytes(cap);
            let image = common::render(&mut renderer, &scene, &frame);
            let how = renderer.describe();
            // Without multiview (GL) layered is the N-pass itself: one view's images at a time.
            let single_views = method == Method::Layered && how.contains("no multiview");
            assert!(
                single_views || how.contains(chunks),
                "{spec} {method}: {how}"
            );
            let name = format!("points-{method}-chunked-{spec}");
            let diff = common::assert_matches(&name, &image, &oracle);
            eprintln!("{name} ({how}): {diff:?}");
        }
        // A cap below one view's group images is refused with the sizes, not a GPU error.
        let mut tiny = PointSplatter::new(&device, Method::Tiled, options).unwrap();
        tiny.set_max_image_bytes(1024);
        let ctx = common::gpu();
        let error = tiny
            .prepare(&ctx.device, &ctx.queue, &scene, &frame)
            .unwrap_err();
        assert!(error.to_string().contains("one row of tiles"), "{error}");
    }
}
