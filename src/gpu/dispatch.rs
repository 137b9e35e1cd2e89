//! Compute dispatch sizes: one splitter for every one-dimensional workload.

/// Workgroups for `groups` one-dimensional workgroups, split over x and y within the
/// per-dimension limit. Shaders linearise `group.y · groups.x + group.x` and skip indices past
/// their count.
pub(crate) fn dispatch_2d(device: &wgpu::Device, groups: u32) -> [u32; 2] {
    let max = device.limits().max_compute_workgroups_per_dimension.max(1);
    let x = groups.clamp(1, max);
    [x, groups.div_ceil(x).max(1)]
}
