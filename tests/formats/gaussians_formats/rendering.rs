//! The formats render alike (the single pass of each against the PLY's).

use super::*;

/// The same scene from each file renders alike: the single pass of each against the PLY's
/// (degree 0, which every format holds), within what each format's quantisation moves.
#[test]
fn the_formats_render_alike() {
    use autostereo::gaussians::{GaussianOptions, GaussianScene, GaussianSplatter};
    use autostereo::render::Method;
    let raw = scene();
    let files = [
        ("PLY", file("render.ply", &write_ply(&raw, 0))),
        (".splat", file("render.splat", &write_splat(&raw))),
        (".spz v2", file("render.v2.spz", &write_spz(&raw, 2, 0))),
        (".spz v3", file("render.v3.spz", &write_spz(&raw, 3, 0))),
    ];
    let mut images = Vec::new();
    for (name, path) in &files {
        let g = Gaussians::load(path).unwrap();
        let frame = common::frame(g.bounds().unwrap(), "hubner8", 0.08, 1.0, [96, 64]);
        let (scene, mut splatter) = {
            let ctx = common::gpu();
            let scene = GaussianScene::new(&ctx.device, &g).unwrap();
            let splatter =
                GaussianSplatter::new(&ctx.device, Method::SinglePass, GaussianOptions::default())
                    .unwrap();
            (scene, splatter)
        };
        images.push((*name, common::render(&mut splatter, &scene, &frame)));
    }
    let (_, ply) = &images[0];
    let lit = ply.data.iter().filter(|&&v| v > 40).count();
    assert!(
        lit > ply.data.len() / 20,
        "the scene is in view: {lit} lit subpixels"
    );
    // Measured: .splat 54.5 dB (rotations to 1/128, colour and opacity truncated), .spz v2
    // 54.0, v3 54.8 dB (positions to 2^-12, log scales to 1/16); at most 5/255 off.
    for ((name, image), min_db) in images.iter().zip([1000.0, 45.0, 45.0, 45.0]).skip(1) {
        let diff = autostereo::image_io::compare(image, ply).unwrap();
        eprintln!("{name} against the PLY: {diff:?}");
        assert!(diff.psnr_db >= min_db, "{name}: {diff:?}");
    }
}
