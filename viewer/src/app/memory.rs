//! What the viewer's exercise run records of its memory: resident memory every 50 frames, the
//! heap in use every 10, and at the end of each period of its schedule (after a GPU wait) the
//! live GPU objects. cli/tests/viewer/ reads the report for leaks.

/// Frames between two samples of the heap in use. On GL llvmpipe the heap swings by up to
/// 100 MiB from frame to frame (frames in flight, the window system's images), so a leak is
/// judged by the median of many samples per period; a sample costs a walk of malloc's bins.
const HEAP_EVERY: u32 = 10;
/// Frames between two samples of resident memory.
const RSS_EVERY: u32 = 50;

/// The exercise run's memory samples.
#[derive(Default)]
pub(super) struct MemoryLog {
    /// Resident memory every `RSS_EVERY` frames, MiB.
    rss: Vec<f64>,
    /// Heap in use every `HEAP_EVERY` frames, MiB.
    heap: Vec<f64>,
    /// Live GPU objects and bytes at the end of each period.
    gpu_each_period: Vec<serde_json::Value>,
}

impl MemoryLog {
    /// After frame `frame`: a sample when one is due.
    pub fn after_frame(&mut self, frame: u32) {
        if frame.is_multiple_of(RSS_EVERY) {
            self.rss.extend(resident_mib());
        }
        if frame.is_multiple_of(HEAP_EVERY) {
            self.heap.extend(heap_in_use_mib());
        }
    }

    /// A sample at the end of a period: waits for the GPU first (see `live_gpu_objects`).
    pub fn end_period(&mut self, device: &wgpu::Device) {
        self.gpu_each_period.push(live_gpu_objects(device));
    }

    /// The report's memory fields.
    pub fn report(&self) -> serde_json::Value {
        serde_json::json!({
            "rss_mib_samples": self.rss,
            "rss_sample_every_frames": RSS_EVERY,
            "heap_mib_samples": self.heap,
            "heap_sample_every_frames": HEAP_EVERY,
            "gpu_objects_each_period": self.gpu_each_period,
        })
    }
}

/// Resident memory of this process in MiB (Linux), if known.
fn resident_mib() -> Option<f64> {
    let statm = std::fs::read_to_string("/proc/self/statm").ok()?;
    let pages: f64 = statm.split_whitespace().nth(1)?.parse().ok()?;
    Some(pages * 4096.0 / (1024.0 * 1024.0))
}

/// Heap in use in MiB (glibc: bytes malloc handed out and not freed, every arena and the
/// mmapped chunks). Unlike resident memory it does not move when the allocator keeps or
/// returns freed pages, so a leak is what changes it; lavapipe's and llvmpipe's "GPU" memory
/// is malloc'd too.
#[cfg(all(target_os = "linux", target_env = "gnu"))]
fn heap_in_use_mib() -> Option<f64> {
    // SAFETY: mallinfo2 only reads the allocator's statistics.
    let info = unsafe { libc::mallinfo2() };
    Some((info.uordblks + info.hblkhd) as f64 / (1024.0 * 1024.0))
}

/// Heap in use: unknown without glibc.
#[cfg(not(all(target_os = "linux", target_env = "gnu")))]
fn heap_in_use_mib() -> Option<f64> {
    None
}

/// What the device holds right now, from wgpu's internal counters. Unlike resident memory
/// (which the allocator returns to the system whenever it likes) these are exact, so an
/// exercise run can compare them one period apart. Waits for the GPU first so that what the
/// last frames dropped is really freed: this stalls, which only the exercise run does.
/// Textures are left out: wgpu-hal 30's Vulkan backend subtracts on destroy but never adds on
/// create, so that count only falls; their views and (on Vulkan) bytes stand in for them.
fn live_gpu_objects(device: &wgpu::Device) -> serde_json::Value {
    let _ = device.poll(wgpu::PollType::wait_indefinitely());
    let hal = device.get_internal_counters().hal;
    serde_json::json!({
        "buffers": hal.buffers.read(),
        "texture_views": hal.texture_views.read(),
        "bind_groups": hal.bind_groups.read(),
        "render_pipelines": hal.render_pipelines.read(),
        "compute_pipelines": hal.compute_pipelines.read(),
        "samplers": hal.samplers.read(),
        "shader_modules": hal.shader_modules.read(),
        "buffer_bytes": hal.buffer_memory.read(),
        "texture_bytes": hal.texture_memory.read(),
    })
}
