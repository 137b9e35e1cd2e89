//! N-pass vs single-view mesh rendering, side by side in one process on one adapter.
//! GPU time per frame from timestamp queries where available (see `autostereo::timing`).
//!
//! `cargo bench --bench mesh_baseline`

use std::time::Duration;

use autostereo::camera::MultiViewCamera;
use autostereo::display::Display;
use autostereo::frame::Frame;
use autostereo::gpu::GpuContext;
use autostereo::mesh::{Mesh, MeshBuffers};
use autostereo::render::MeshBaseline;
use autostereo::target::SpatialTarget;
use autostereo::timing::FrameTimer;
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};

fn bench(c: &mut Criterion) {
    let ctx = GpuContext::new(&Default::default()).expect("GPU adapter");
    let (device, queue) = (&ctx.device, &ctx.queue);
    let mesh = Mesh::torus_scene();
    let buffers = MeshBuffers::new(device, &mesh).unwrap();
    let size = [512, 512];
    let target = SpatialTarget::new(device, size).unwrap();
    let mut renderer = MeshBaseline::new(device).unwrap();
    let timer = FrameTimer::new(device, queue);
    let mut group = c.benchmark_group(format!("mesh torus 512² on {}", ctx.adapter_label()));
    group
        .sample_size(20)
        .warm_up_time(Duration::from_millis(500));
    for views in [8, 32] {
        let display = Display::parse(&format!("lenticular:{views}")).unwrap();
        let camera =
            MultiViewCamera::framing(mesh.bounds().unwrap(), views, None, 0.5, 1.0).unwrap();
        let frame = Frame::new(camera, display, size).unwrap();
        group.bench_function(BenchmarkId::new("n-pass", views), |b| {
            gpu_iter(b, &timer, device, queue, |e| {
                renderer.encode(device, queue, e, &buffers, &frame, &target)
            })
        });
        group.bench_function(BenchmarkId::new("single-view", views), |b| {
            gpu_iter(b, &timer, device, queue, |e| {
                renderer.encode_single_view(device, queue, e, &buffers, &frame, &target)
            })
        });
    }
    group.finish();
}

/// Criterion iterations timed on the GPU (timestamps) rather than by the CPU clock.
fn gpu_iter(
    b: &mut criterion::Bencher,
    timer: &FrameTimer,
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    mut encode: impl FnMut(&mut wgpu::CommandEncoder) -> autostereo::Result<()>,
) {
    b.iter_custom(|iters| {
        let mut total_ms = 0.0;
        for _ in 0..iters {
            total_ms += timer.time_frame(device, queue, &mut encode).unwrap();
        }
        Duration::from_secs_f64(total_ms / 1e3)
    })
}

criterion_group!(benches, bench);
criterion_main!(benches);
