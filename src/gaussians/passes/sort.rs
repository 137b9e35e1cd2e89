//! The depth sort every Gaussian method shares: one order for all views, back to front in the
//! centre camera's eye depth (skewed and parallel cameras move the views along the camera's x
//! axis, which changes no eye depth). On the GPU: keys from `wgsl/gaussians/sort_keys.wgsl`,
//! then a bitonic sort (`wgsl/gaussians/sort_step.wgsl`, one dispatch per step); on the CPU:
//! the same keys sorted by the standard library and uploaded with the frame (measured against
//! each other by `autostereo-bench`).

use bytemuck::{Pod, Zeroable};

use super::super::scene::GaussianScene;
use crate::error::Result;
use crate::frame::{Frame, FrameBinding};
use crate::gpu::gpu_buffer::GpuBuffer;
use crate::gpu::pass_params::{constants_buffer, PassParams};
use crate::gpu::pipeline::{bind_group_layout, compilation, pipeline_layout, storage_entry};

/// Threads per workgroup of both sort stages.
const WORKGROUP: u32 = 256;

/// Where the depth sort runs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum SortOn {
    /// Keys and a bitonic sort in compute passes: nothing leaves the GPU.
    #[default]
    Gpu,
    /// The keys sorted on the CPU each frame and uploaded with it.
    Cpu,
}

impl SortOn {
    /// Lower-case name (CLI, reports).
    pub fn name(self) -> &'static str {
        match self {
            Self::Gpu => "gpu",
            Self::Cpu => "cpu",
        }
    }
}

/// One bitonic step. Keep in sync with `struct SortStep` in `wgsl/gaussians/sort_step.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub(crate) struct SortStep {
    k: u32,
    j: u32,
    _pad0: u32,
    _pad1: u32,
}
crate::shader::gpu_layout!(SortStep, "SortStep", [k, j]);

/// The sort's pipelines and scratch.
pub(crate) struct DepthSort {
    on: SortOn,
    keys_pipeline: wgpu::ComputePipeline,
    step_pipeline: wgpu::ComputePipeline,
    keys_layout: wgpu::BindGroupLayout,
    step_layout: wgpu::BindGroupLayout,
    keys: GpuBuffer,
    values: GpuBuffer,
    steps: PassParams<SortStep>,
    /// The last CPU order (read back by tests through [`DepthSort::read_order`]).
    cpu_order: Vec<u32>,
}

/// The sort's length: the power of two at or above `count` (at least 2).
fn padded(count: u32) -> u32 {
    count.max(2).next_power_of_two()
}

/// The CPU's order of `scene` for `frame`: farthest first, Gaussians outside the near and far
/// planes left out (the same keys as the GPU's, so the same order up to ties).
pub fn cpu_order(scene: &GaussianScene, frame: &Frame) -> Vec<u32> {
    let m = frame.camera.eye_from_world;
    let (near, far) = (frame.camera.near, frame.camera.far);
    let mut keyed: Vec<(u32, u32)> = scene
        .means
        .iter()
        .enumerate()
        .filter_map(|(i, p)| {
            let depth = -m.transform_point3(*p).z;
            (depth > near && depth < far).then_some((!depth.to_bits(), i as u32))
        })
        .collect();
    keyed.sort_unstable();
    keyed.into_iter().map(|(_, i)| i).collect()
}

impl DepthSort {
    pub fn new(
        device: &wgpu::Device,
        on: SortOn,
        frame_layout: &wgpu::BindGroupLayout,
        scene_layout: &wgpu::BindGroupLayout,
    ) -> Result<Self> {
        let compute = wgpu::ShaderStages::COMPUTE;
        let keys_layout = bind_group_layout(
            device,
            "gaussian sort keys",
            &[
                storage_entry(0, false, compute),
                storage_entry(1, false, compute),
            ],
        );
        let step_layout = bind_group_layout(
            device,
            "gaussian sort step",
            &[
                storage_entry(0, false, compute),
                storage_entry(1, false, compute),
                PassParams::<SortStep>::layout_entry(2, compute),
            ],
        );
        let constants = [("WORKGROUP", WORKGROUP as f64)];
        let pipeline = |stage: &str, layouts: &[Option<&wgpu::BindGroupLayout>]| {
            let module = crate::shader::module(device, stage)?;
            let layout = pipeline_layout(device, stage, layouts);
            crate::gpu::checked(device, "building the Gaussian depth sort", || {
                device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                    label: Some(stage),
                    layout: Some(&layout),
                    module: &module,
                    entry_point: Some("cs_main"),
                    compilation_options: compilation(&constants),
                    cache: None,
                })
            })
        };
        let keys_pipeline = pipeline(
            "gaussians/sort_keys.wgsl",
            &[Some(frame_layout), Some(scene_layout), Some(&keys_layout)],
        )?;
        let step_pipeline = pipeline("gaussians/sort_step.wgsl", &[Some(&step_layout)])?;
        let storage = wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC;
        Ok(Self {
            on,
            keys_pipeline,
            step_pipeline,
            keys_layout,
            step_layout,
            keys: GpuBuffer::new(device, "gaussian sort keys", storage),
            values: GpuBuffer::new(device, "gaussian sort values", storage),
            steps: PassParams::new(device, "gaussian sort steps"),
            cpu_order: Vec::new(),
        })
    }

    /// Scratch for `scene`'s sort (the GPU's keys and values, a power of two long).
    pub fn prepare(&mut self, device: &wgpu::Device, scene: &GaussianScene) -> Result<()> {
        if self.on == SortOn::Cpu {
            return Ok(());
        }
        let bytes = u64::from(padded(scene.count)) * 4;
        let what = |name: &str| {
            let name = name.to_string();
            move || {
                format!(
                    "{name} ({} Gaussians, padded to a power of two)",
                    scene.count
                )
            }
        };
        self.keys
            .ensure(device, what("Gaussian sort key bytes"), bytes)?;
        self.values
            .ensure(device, what("Gaussian sort value bytes"), bytes)?;
        Ok(())
    }

    /// Record this frame's sort; the buffer of Gaussian indices in draw order (entries past
    /// the scene's count are culled by the splat pass).
    pub fn encode(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        scene: &GaussianScene,
        frame: &Frame,
        frame_binding: &FrameBinding,
        scene_group: &wgpu::BindGroup,
    ) -> Result<wgpu::Buffer> {
        if self.on == SortOn::Cpu {
            let mut order = cpu_order(scene, frame);
            self.cpu_order = order.clone();
            // Culled Gaussians are not drawn: fill with an index past the scene.
            order.resize(scene.count.max(1) as usize, scene.count);
            return Ok(constants_buffer(
                device,
                "gaussian order",
                wgpu::BufferUsages::STORAGE,
                bytemuck::cast_slice(&order),
            ));
        }
        let n = padded(scene.count);
        let keys_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("gaussian sort keys"),
            layout: &self.keys_layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: self.keys.binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: self.values.binding(),
                },
            ],
        });
        let mut steps = Vec::new();
        let mut k = 2;
        while k <= n {
            let mut j = k / 2;
            while j > 0 {
                steps.push(SortStep {
                    k,
                    j,
                    _pad0: 0,
                    _pad1: 0,
                });
                j /= 2;
            }
            k *= 2;
        }
        self.steps.write(device, &steps);
        let step_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("gaussian sort step"),
            layout: &self.step_layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: self.keys.binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: self.values.binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: self.steps.binding(),
                },
            ],
        });
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("gaussian depth sort"),
            timestamp_writes: None,
        });
        pass.set_pipeline(&self.keys_pipeline);
        pass.set_bind_group(0, &frame_binding.bind_group, &[]);
        pass.set_bind_group(1, scene_group, &[0]);
        pass.set_bind_group(2, &keys_group, &[]);
        let (x, y) = groups(device, n.div_ceil(WORKGROUP));
        pass.dispatch_workgroups(x, y, 1);
        pass.set_pipeline(&self.step_pipeline);
        let (x, y) = groups(device, (n / 2).div_ceil(WORKGROUP));
        for i in 0..steps.len() {
            pass.set_bind_group(0, &step_group, &[self.steps.offset(i)]);
            pass.dispatch_workgroups(x, y, 1);
        }
        drop(pass);
        Ok(self.values.buffer().clone())
    }

    /// The order of the last frame: Gaussian indices, farthest first, culled ones left out.
    pub fn read_order(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        count: u32,
    ) -> Result<Vec<u32>> {
        if self.on == SortOn::Cpu {
            return Ok(self.cpu_order.clone());
        }
        let bytes =
            crate::readback::read_buffer(device, queue, self.values.buffer(), self.values.used())?;
        let values: Vec<u32> = bytemuck::pod_collect_to_vec(&bytes);
        Ok(values.into_iter().filter(|&i| i < count).collect())
    }
}

/// A 2D grid of `groups` workgroups within the per-dimension limit.
fn groups(device: &wgpu::Device, groups: u32) -> (u32, u32) {
    let max = device.limits().max_compute_workgroups_per_dimension;
    if groups <= max {
        (groups.max(1), 1)
    } else {
        (max, groups.div_ceil(max))
    }
}
