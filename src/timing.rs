//! GPU frame timing: timestamp queries where the device has them, else submit + wait.

use std::time::Instant;

use crate::error::{Error, Result};

/// Times encoded work, one frame at a time.
pub struct FrameTimer {
    queries: Option<(wgpu::QuerySet, wgpu::Buffer, wgpu::Buffer)>,
    period_ns: f32,
}

/// How a [`FrameTimer`] measures.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum TimingSource {
    /// GPU timestamp queries around the frame's commands.
    Timestamps,
    /// Wall clock around submit + wait.
    SubmitWait,
}

impl FrameTimer {
    /// Use timestamps if the device has `TIMESTAMP_QUERY_INSIDE_ENCODERS`.
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue) -> Self {
        let needed =
            wgpu::Features::TIMESTAMP_QUERY | wgpu::Features::TIMESTAMP_QUERY_INSIDE_ENCODERS;
        let queries = device.features().contains(needed).then(|| {
            let set = device.create_query_set(&wgpu::QuerySetDescriptor {
                label: Some("frame timestamps"),
                ty: wgpu::QueryType::Timestamp,
                count: 2,
            });
            let resolve = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("timestamp resolve"),
                size: 16,
                usage: wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
                mapped_at_creation: false,
            });
            let read = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("timestamp read"),
                size: 16,
                usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
                mapped_at_creation: false,
            });
            (set, resolve, read)
        });
        Self {
            queries,
            period_ns: queue.get_timestamp_period(),
        }
    }

    /// What this timer measures with.
    pub fn source(&self) -> TimingSource {
        if self.queries.is_some() {
            TimingSource::Timestamps
        } else {
            TimingSource::SubmitWait
        }
    }

    /// Record one frame with `encode`, submit, wait, and return its duration in ms.
    pub fn time_frame(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encode: impl FnOnce(&mut wgpu::CommandEncoder) -> Result<()>,
    ) -> Result<f64> {
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("timed frame"),
        });
        if let Some((set, _, _)) = &self.queries {
            encoder.write_timestamp(set, 0);
        }
        encode(&mut encoder)?;
        if let Some((set, resolve, read)) = &self.queries {
            encoder.write_timestamp(set, 1);
            encoder.resolve_query_set(set, 0..2, resolve, 0);
            encoder.copy_buffer_to_buffer(resolve, 0, read, 0, 16);
        }
        let start = Instant::now();
        queue.submit([encoder.finish()]);
        crate::readback::wait_idle(device)?;
        let wall_ms = start.elapsed().as_secs_f64() * 1e3;
        let Some((_, _, read)) = &self.queries else {
            return Ok(wall_ms);
        };
        let (tx, rx) = std::sync::mpsc::channel();
        read.map_async(wgpu::MapMode::Read, .., move |r| {
            let _ = tx.send(r);
        });
        crate::readback::wait_idle(device)?;
        let gpu_err = |m: String| Error::Gpu {
            operation: "reading timestamps".into(),
            message: m,
        };
        rx.recv()
            .map_err(|e| gpu_err(e.to_string()))?
            .map_err(|e| gpu_err(e.to_string()))?;
        let ticks: [u64; 2] = {
            let view = read
                .get_mapped_range(..)
                .map_err(|e| gpu_err(e.to_string()))?;
            bytemuck::pod_read_unaligned(&view[..16])
        };
        read.unmap();
        let gpu_ms = ticks[1].wrapping_sub(ticks[0]) as f64 * self.period_ns as f64 / 1e6;
        // Timestamps that do not bracket the work: lavapipe was seen writing the closing one
        // before a compute dispatch over a z range had run (the layered volume dispatch
        // reported 2.2 ms for frames that took 270 ms of wall time). Where the GPU time is
        // under half the submit-to-idle wall time of a frame that took long enough for the
        // difference to be no submission overhead, the wall time is the measurement.
        if gpu_ms < 0.5 * wall_ms && wall_ms > 10.0 {
            return Ok(wall_ms);
        }
        Ok(gpu_ms)
    }
}

/// Median of a sample (NaN for an empty one).
pub fn median(samples: &[f64]) -> f64 {
    let mut v = samples.to_vec();
    v.sort_by(|a, b| a.total_cmp(b));
    match v.len() {
        0 => f64::NAN,
        n if n % 2 == 1 => v[n / 2],
        n => 0.5 * (v[n / 2 - 1] + v[n / 2]),
    }
}
