//! What the benches share: GPU-timed criterion iterations and the bench scenes' settings.

use std::time::Duration;

use autostereo::timing::FrameTimer;

/// Image size of every bench.
pub const SIZE: [u32; 2] = [512, 512];

/// A benchmark group with the settings every bench uses: 10 samples, a token warm-up (the
/// first frame compiles shaders; criterion's sampling then discards nothing), 1 s.
pub fn configure<M: criterion::measurement::Measurement>(
    group: &mut criterion::BenchmarkGroup<'_, M>,
) {
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(1))
        .measurement_time(Duration::from_secs(1));
}

/// Criterion iterations timed on the GPU (timestamps where the adapter has them, else submit +
/// wait) rather than by the CPU clock.
pub fn gpu_iter(
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
