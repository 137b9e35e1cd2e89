//! Meshes: single-pass (every visibility mode) vs N-pass vs single view vs the duplication
//! methods (tiled, layered, MRT), side by side in one process on one adapter. Full Stanford dragon (871k triangles) and res2 (203k), 512²,
//! N = 8 (the paper's 8-view display) and N = 32 (a slanted display with the same lens).
//! GPU time per frame from timestamp queries where the adapter has them.
//!
//! `data/fetch && cargo bench --bench mesh`   (report: `python3 docs/tools/bench_table.py mesh`)

mod common;

use std::path::Path;

use autostereo::camera::MultiViewCamera;
use autostereo::display::Display;
use autostereo::frame::Frame;
use autostereo::gpu::GpuContext;
use autostereo::mesh::{Mesh, MeshBuffers};
use autostereo::mesh::{
    MeshLayered, MeshMrt, MeshNPass, MeshSinglePass, MeshSinglePassOptions, MeshTiled, TileClip,
    Visibility,
};
use autostereo::render::{Method, Renderer};
use autostereo::target::SpatialTarget;
use autostereo::timing::FrameTimer;
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};

use common::{configure, gpu_iter, SIZE};

fn load(name: &str) -> Mesh {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("data/fetched")
        .join(name);
    Mesh::load_obj(&path)
        .unwrap_or_else(|e| panic!("{e}\nrun data/fetch first to get the Stanford dragon"))
}

fn bench(c: &mut Criterion) {
    let ctx = GpuContext::new(&Default::default()).expect("GPU adapter");
    let (device, queue) = (&ctx.device, &ctx.queue);
    let target = SpatialTarget::new(device, SIZE).unwrap();
    let timer = FrameTimer::new(device, queue);
    let mut npass = MeshNPass::new(device, Method::NPass).unwrap();
    let mut single_view = MeshNPass::new(device, Method::SingleView).unwrap();
    let mut single_pass: Vec<(&str, MeshSinglePass)> = [
        Visibility::Compute,
        Visibility::Atomic,
        Visibility::Exact,
        Visibility::Fast,
    ]
    .into_iter()
    .filter(|v| device.features().contains(v.required_features()))
    .map(|visibility| {
        let options = MeshSinglePassOptions {
            visibility,
            ..Default::default()
        };
        (
            visibility.name(),
            MeshSinglePass::new(device, options).unwrap(),
        )
    })
    .collect();
    let mut duplication: Vec<(&str, Box<dyn Renderer<MeshBuffers>>)> = vec![
        (
            "tiled",
            Box::new(MeshTiled::new(device, TileClip::Auto).unwrap()),
        ),
        ("layered", Box::new(MeshLayered::new(device).unwrap())),
        ("mrt", Box::new(MeshMrt::new(device).unwrap())),
    ];
    for (mesh_name, file) in [
        ("dragon", "dragon_vrip.obj"),
        ("dragon-res2", "dragon_vrip_res2.obj"),
    ] {
        let mesh = load(file);
        let buffers = MeshBuffers::new(device, &mesh).unwrap();
        for views in [8u32, 32] {
            let display = Display::parse(&format!("slanted:{views},8,2/3,7/6")).unwrap();
            let camera = MultiViewCamera::framing(
                mesh.bounds().unwrap(),
                views,
                None,
                30f32.to_radians(),
                1.0,
            )
            .unwrap();
            let frame = Frame::new(camera, display, SIZE).unwrap();
            let mut group = c.benchmark_group(format!("mesh/{mesh_name}/N{views}"));
            configure(&mut group);
            for (name, renderer) in &mut single_pass {
                group.bench_function(BenchmarkId::new("single-pass", *name), |b| {
                    renderer.prepare(device, queue, &buffers, &frame).unwrap();
                    gpu_iter(b, &timer, device, queue, |e| {
                        renderer.encode(device, e, &buffers, &frame, &target)
                    })
                });
            }
            group.bench_function("n-pass", |b| {
                npass.prepare(device, queue, &buffers, &frame).unwrap();
                gpu_iter(b, &timer, device, queue, |e| {
                    npass.encode(device, e, &buffers, &frame, &target)
                })
            });
            group.bench_function("single-view", |b| {
                single_view
                    .prepare(device, queue, &buffers, &frame)
                    .unwrap();
                gpu_iter(b, &timer, device, queue, |e| {
                    single_view.encode(device, e, &buffers, &frame, &target)
                })
            });
            for (name, renderer) in &mut duplication {
                group.bench_function(*name, |b| {
                    renderer.prepare(device, queue, &buffers, &frame).unwrap();
                    gpu_iter(b, &timer, device, queue, |e| {
                        renderer.encode(device, e, &buffers, &frame, &target)
                    })
                });
            }
            group.finish();
        }
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
