//! Orders a compute pass's writes after earlier draws' reads of the same storage buffers on
//! wgpu's GL backend (docs/DESIGN.md §7).
//!
//! wgpu-hal's GL backend emits `glMemoryBarrier` only after storage *writes*; a later write
//! after earlier reads gets none. llvmpipe defers draws but runs compute at once, so when a
//! second frame is encoded before the submit, its cover pass overwrites the cover data the
//! first frame's draws have not read yet. A no-op compute pass that binds the buffers
//! read-write, recorded before the writing pass, turns that transition into write → write,
//! for which wgpu does emit the barrier. Other backends order it themselves: nothing is
//! recorded there.

use super::pipeline::storage_entry;
use crate::error::Result;

/// The no-op pass for two storage buffers; `None` of it on backends that need none.
pub(crate) struct StorageFence {
    fence: Option<(wgpu::BindGroupLayout, wgpu::ComputePipeline)>,
}

impl StorageFence {
    pub fn new(device: &wgpu::Device) -> Result<Self> {
        if device.adapter_info().backend != wgpu::Backend::Gl {
            return Ok(Self { fence: None });
        }
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("storage fence"),
            entries: &[
                storage_entry(0, false, wgpu::ShaderStages::COMPUTE),
                storage_entry(1, false, wgpu::ShaderStages::COMPUTE),
            ],
        });
        let module = crate::shader::module(device, "gpu/storage_fence.wgsl")?;
        let pipeline = crate::gpu::checked(device, "building the storage fence", || {
            let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some("storage fence"),
                bind_group_layouts: &[Some(&layout)],
                immediate_size: 0,
            });
            device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                label: Some("storage fence"),
                layout: Some(&pipeline_layout),
                module: &module,
                entry_point: Some("cs_main"),
                compilation_options: Default::default(),
                cache: None,
            })
        })?;
        Ok(Self {
            fence: Some((layout, pipeline)),
        })
    }

    /// Record the fence for `buffers` before a pass that writes them (no-op off GL).
    pub fn encode(
        &self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        buffers: [&wgpu::Buffer; 2],
    ) {
        let Some((layout, pipeline)) = &self.fence else {
            return;
        };
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("storage fence"),
            layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: buffers[0].as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: buffers[1].as_entire_binding(),
                },
            ],
        });
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("storage fence"),
            timestamp_writes: None,
        });
        pass.set_pipeline(pipeline);
        pass.set_bind_group(0, &group, &[]);
        pass.dispatch_workgroups(1, 1, 1);
    }
}
