//! Point splats: single pass (exact and paper depth) vs N-pass vs single view, side by side in
//! one process on one adapter. The Stanford dragon's 437k vertices (normals and radii
//! estimated), 512², N = 2, 8 and 64 on a slanted subpixel display (K = 3) with the views over a
//! fixed baseline. N-pass only at N = 2 and 8: it grows linearly and N = 64 would take ~10 min.
//!
//! `data/fetch && cargo bench --bench points`   (report: `python3 docs/tools/bench_table.py points`)

mod common;

use std::path::Path;

use autostereo::camera::MultiViewCamera;
use autostereo::display::Display;
use autostereo::frame::Frame;
use autostereo::gpu::GpuContext;
use autostereo::points::{GroupCount, PointCloud, SplatScene};
use autostereo::points::{PointSplatter, SplatDepth, SplatOptions};
use autostereo::render::{Method, Renderer};
use autostereo::target::SpatialTarget;
use autostereo::timing::FrameTimer;
use common::{configure, gpu_iter, SIZE};
use criterion::{criterion_group, criterion_main, Criterion};

fn bench(c: &mut Criterion) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("data/fetched/dragon_vrip.ply");
    let cloud = PointCloud::load(&path)
        .unwrap_or_else(|e| panic!("{e}\nrun data/fetch first to get the Stanford dragon"));
    let (splats, completion) = cloud.complete(1.0).unwrap();
    let ctx = GpuContext::new(&Default::default()).expect("GPU adapter");
    let (device, queue) = (&ctx.device, &ctx.queue);
    let scene = SplatScene::new(device, &splats, GroupCount::Auto).unwrap();
    eprintln!(
        "dragon: {} points, normals + radii estimated in {:.0} ms, {} groups in {:.0} ms",
        splats.len(),
        completion.estimate_ms,
        scene.groups(),
        scene.grouping_ms
    );
    let target = SpatialTarget::new(device, SIZE).unwrap();
    let timer = FrameTimer::new(device, queue);
    let options = |depth| SplatOptions {
        depth,
        ..SplatOptions::for_scene(&scene, 0.01)
    };
    let splatter = |method, depth| PointSplatter::new(device, method, options(depth)).unwrap();
    let mut methods: Vec<(&str, PointSplatter)> = vec![
        (
            "single-pass (exact depth)",
            splatter(Method::SinglePass, SplatDepth::Exact),
        ),
        (
            "single-pass (paper depth)",
            splatter(Method::SinglePass, SplatDepth::Paper),
        ),
        ("n-pass", splatter(Method::NPass, SplatDepth::Exact)),
        (
            "single-view",
            splatter(Method::SingleView, SplatDepth::Exact),
        ),
        ("tiled", splatter(Method::Tiled, SplatDepth::Exact)),
        ("layered", splatter(Method::Layered, SplatDepth::Exact)),
    ];
    for views in [2u32, 8, 64] {
        let display = Display::parse(&format!("slanted:{views},8,2/3,7/6")).unwrap();
        let mut camera = MultiViewCamera::framing(
            splats.bounds().unwrap(),
            views,
            None,
            30f32.to_radians(),
            1.0,
        )
        .unwrap();
        camera.separation *= 7.0 / (views - 1) as f32;
        let frame = Frame::new(camera, display, SIZE).unwrap();
        let mut group = c.benchmark_group(format!("points/dragon/N{views}"));
        configure(&mut group);
        for (name, renderer) in &mut methods {
            if *name == "n-pass" && views > 8 {
                continue;
            }
            group.bench_function(*name, |b| {
                renderer.prepare(device, queue, &scene, &frame).unwrap();
                gpu_iter(b, &timer, device, queue, |e| {
                    renderer.encode(device, e, &scene, &frame, &target)
                })
            });
        }
        group.finish();
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
