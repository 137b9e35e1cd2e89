//! Volumes: single pass (compute path with and without empty-space skipping; slice path with
//! exact and paper α) vs N-pass vs single view, side by side in one process on one adapter, 512²,
//! N = 8 and 64 over the same baseline,
//! on the built-in head (96³) and VolPack's brainsmall.den (128×128×84, from `data/fetch`).
//!
//! `data/fetch && cargo bench --bench volume`   (report: `python3 docs/tools/bench_table.py volume`)

mod common;

use std::path::Path;

use autostereo::camera::MultiViewCamera;
use autostereo::display::Display;
use autostereo::frame::Frame;
use autostereo::gpu::GpuContext;
use autostereo::render::{Method, Renderer};
use autostereo::target::SpatialTarget;
use autostereo::timing::FrameTimer;
use autostereo::volume::{generate, load, TransferFunction, Volume};
use autostereo::volume::{AlphaMode, VolumeScene};
use criterion::{criterion_group, criterion_main, Criterion};
use glam::Mat4;

use autostereo::volume::VolumeSettings;
use autostereo::{RendererOptions, VolumeOptions, VolumePath};
use common::{configure, gpu_iter, SIZE};

fn data_sets() -> Vec<(&'static str, Volume, &'static str)> {
    let brain = Path::new(env!("CARGO_MANIFEST_DIR")).join("data/fetched/brainsmall.den");
    let brain = load::load_den(&brain)
        .unwrap_or_else(|e| panic!("{e}\nrun data/fetch first to get brainsmall.den"));
    let brain = Volume::new(brain.dims, [1.0, 1.0, 1.5], brain.data).unwrap();
    vec![
        ("head", generate::ct_head(96).unwrap(), "ct-skin"),
        ("brainsmall", brain, "mri"),
    ]
}

fn bench(c: &mut Criterion) {
    let ctx = GpuContext::new(&Default::default()).expect("GPU adapter");
    let (device, queue) = (&ctx.device, &ctx.queue);
    let target = SpatialTarget::new(device, SIZE).unwrap();
    let timer = FrameTimer::new(device, queue);
    let of = |method, path, skip_empty| -> Box<dyn Renderer<VolumeScene>> {
        let options = RendererOptions {
            volume: VolumeOptions {
                path,
                settings: VolumeSettings {
                    skip_empty,
                    ..Default::default()
                },
            },
            ..RendererOptions::new(method)
        };
        options.volume_renderer(device).unwrap()
    };
    let ray = VolumePath::RayMarch;
    let mut methods: Vec<(&str, Box<dyn Renderer<VolumeScene>>)> = vec![
        ("single-pass (compute)", of(Method::SinglePass, ray, true)),
        (
            "single-pass (compute, no skipping)",
            of(Method::SinglePass, ray, false),
        ),
        (
            "single-pass (slices, exact α)",
            of(
                Method::SinglePass,
                VolumePath::Slices(AlphaMode::Exact),
                true,
            ),
        ),
        (
            "single-pass (slices, paper α)",
            of(
                Method::SinglePass,
                VolumePath::Slices(AlphaMode::Paper),
                true,
            ),
        ),
        ("n-pass", of(Method::NPass, ray, true)),
        ("single-view", of(Method::SingleView, ray, true)),
        ("tiled", of(Method::Tiled, ray, true)),
        ("layered", of(Method::Layered, ray, true)),
    ];
    for (name, volume, tf) in data_sets() {
        let transfer = TransferFunction::preset(tf).unwrap();
        let rotation = Mat4::from_rotation_x(-90f32.to_radians());
        let scene = VolumeScene::new(device, queue, &volume, transfer, rotation).unwrap();
        for views in [8u32, 64] {
            let display = Display::parse(&format!("slanted:{views},8,2/3,7/6")).unwrap();
            // The views span a fixed baseline (that of the default 8-view camera), as a display's
            // views share one viewing cone: more views are denser, not wider.
            let mut camera =
                MultiViewCamera::framing(volume.bounds(), views, None, 30f32.to_radians(), 1.0)
                    .unwrap();
            camera.separation *= 7.0 / (views - 1) as f32;
            let frame = Frame::new(camera, display, SIZE).unwrap();
            let mut group = c.benchmark_group(format!("volume/{name}/N{views}"));
            configure(&mut group);
            for (method, renderer) in &mut methods {
                group.bench_function(*method, |b| {
                    renderer.prepare(device, queue, &scene, &frame).unwrap();
                    gpu_iter(b, &timer, device, queue, |e| {
                        renderer.encode(device, e, &scene, &frame, &target)
                    })
                });
            }
            group.finish();
        }
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
