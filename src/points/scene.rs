//! Splats on the GPU: one storage buffer sorted by group, so that group k is a contiguous range
//! drawn into its own target.

use std::ops::Range;
use std::time::Instant;

use bytemuck::{Pod, Zeroable};
use wgpu::util::DeviceExt;

use super::groups::{self, GroupCount, Grouping};
use super::Splats;
use crate::camera::Bounds;
use crate::error::{Error, Result};
use crate::gpu::gpu_buffer::check_storage_bytes;
use crate::param::Param;

/// One splat. Keep in sync with `struct Splat` in `wgsl/points/shared/splat.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable, PartialEq)]
pub struct GpuSplat {
    /// World-space centre.
    pub position: [f32; 3],
    /// Disk radius.
    pub radius: f32,
    /// World-space unit normal.
    pub normal: [f32; 3],
    /// Linear RGBA8 colour (`pack4x8unorm`).
    pub color: u32,
}
const _: () = assert!(std::mem::size_of::<GpuSplat>() == 32);
crate::shader::gpu_layout!(GpuSplat, "Splat", [position, radius, normal, color]);

fn pack_color(c: [f32; 3]) -> u32 {
    let q = |v: f32| (v.clamp(0.0, 1.0) * 255.0).round() as u32;
    q(c[0]) | (q(c[1]) << 8) | (q(c[2]) << 16) | (255 << 24)
}

/// Splats uploaded and grouped: the per-cloud preprocessing, done once, reused every frame.
pub struct SplatScene {
    /// The splats, group by group.
    pub buffer: wgpu::Buffer,
    /// Number of splats.
    pub count: u32,
    /// Splat index range of each group.
    pub group_ranges: Vec<Range<u32>>,
    /// Overlapping pairs that share a group (see [`Grouping::conflicts`]).
    pub conflicts: u64,
    /// Time the grouping took, ms.
    pub grouping_ms: f64,
    /// Bounding box of the centres.
    pub bounds: Bounds,
    /// Median splat radius (scale for ε).
    pub median_radius: f32,
    /// The buffer's share of the memory budget.
    _charge: crate::budget::GpuCharge,
}

impl SplatScene {
    /// Group `splats` and upload them. Checks the buffer size against the device's limits first.
    pub fn new(device: &wgpu::Device, splats: &Splats, count: GroupCount) -> Result<Self> {
        splats.validate()?;
        if let GroupCount::Fixed(k) = count {
            // One texture-array layer per group: check before grouping allocates per group.
            let limit = device.limits().max_texture_array_layers;
            if k == 0 {
                return Err(Error::invalid(Param::Groups, "0: need at least one group"));
            }
            // With the spare layer a square group image may need (array_layers_for).
            let most = crate::render::view_layers::most_layers([1, 1], limit);
            if k > most {
                return Err(Error::LimitExceeded {
                    what: "splat groups".into(),
                    value: k.into(),
                    limit: most.into(),
                    param: Some(Param::Groups),
                    advice: None,
                });
            }
        }
        let bytes = (splats.len() as u64) * std::mem::size_of::<GpuSplat>() as u64;
        check_storage_bytes(
            device,
            format!("splat buffer bytes ({} splats × 32)", splats.len()),
            bytes,
        )?;
        let charge = crate::budget::charge_gpu(
            || format!("the splat buffer ({} splats × 32 bytes)", splats.len()),
            bytes,
        )?;
        let start = Instant::now();
        let grouping = groups::assign(splats, count);
        let grouping_ms = start.elapsed().as_secs_f64() * 1e3;
        Ok(Self::with_grouping(
            device,
            splats,
            &grouping,
            grouping_ms,
            charge,
        ))
    }

    /// Upload with `grouping` (made by [`groups::assign`] for these `splats`).
    fn with_grouping(
        device: &wgpu::Device,
        splats: &Splats,
        grouping: &Grouping,
        grouping_ms: f64,
        charge: crate::budget::GpuCharge,
    ) -> Self {
        let sizes = grouping.sizes();
        let mut starts: Vec<u32> = sizes
            .iter()
            .scan(0u32, |acc, s| {
                let start = *acc;
                *acc += s;
                Some(start)
            })
            .collect();
        let group_ranges = starts.iter().zip(&sizes).map(|(&s, &n)| s..s + n).collect();
        let mut data = vec![GpuSplat::zeroed(); splats.len()];
        for (i, &g) in grouping.group_of.iter().enumerate() {
            let slot = &mut starts[g as usize];
            data[*slot as usize] = GpuSplat {
                position: splats.positions[i].to_array(),
                radius: splats.radii[i],
                normal: splats.normals[i].to_array(),
                color: pack_color(splats.colors[i]),
            };
            *slot += 1;
        }
        let buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("splats"),
            contents: bytemuck::cast_slice(&data),
            usage: wgpu::BufferUsages::STORAGE,
        });
        Self {
            buffer,
            count: splats.len() as u32,
            group_ranges,
            conflicts: grouping.conflicts,
            grouping_ms,
            bounds: splats.bounds().expect("not empty"),
            median_radius: splats.median_radius(),
            _charge: charge,
        }
    }

    /// Number of groups K.
    pub fn groups(&self) -> u32 {
        self.group_ranges.len() as u32
    }

    /// Bytes of the splat buffer.
    pub fn buffer_bytes(&self) -> u64 {
        self.buffer.size()
    }
}
