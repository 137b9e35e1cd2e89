//! Volume rendering by ray marching in a compute pass (`wgsl/volume_raycast.wgsl`): the
//! single-pass method (each pixel marches the rays of its K views and writes the spatial image)
//! and, with the same kernel and the same samples, the N-pass baseline and the single view.

use std::collections::HashMap;

use bytemuck::{Pod, Zeroable};
use glam::{Mat3, Mat4, Vec3};

use super::renderer::Renderer;
use super::specialize::Specialization;
use super::{Compositor, ViewLayers};
use crate::error::{Error, Result};
use crate::frame::{frame_bind_group_layout, Frame, FrameBinding};
use crate::target::SpatialTarget;
use crate::volume::{
    PreintegrationTable, PreintegrationTexture, TransferFunction, Volume, VolumeTexture,
};

/// Which rays a [`VolumeRaycaster`] evaluates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VolumeMethod {
    /// Per pixel, the K rays of the pixel's views, straight into the spatial image.
    SinglePass,
    /// One render per view into its own layer, then mask compositing.
    NPass,
    /// The centre camera only.
    SingleView,
}

/// A volume ready to render: GPU texture, box size, classification and sampling.
pub struct VolumeScene {
    /// Gradients + scalar.
    pub texture: VolumeTexture,
    /// World-space size of the box (centred at the origin before `model`).
    pub extent: Vec3,
    /// Smallest voxel spacing (the unit of transfer-function opacity).
    pub voxel: f32,
    /// Transfer function.
    pub transfer: TransferFunction,
    /// Distance Δ between samples along the eye depth, world units.
    pub step: f32,
    /// Volume → world transform (rotation of the volume).
    pub model: Mat4,
    /// Blinn-Phong shading from the gradients (off: emission-absorption only).
    pub shade: bool,
}

/// Most samples a ray may take (a guard, and the bound on `--step`).
pub const MAX_SAMPLES_PER_RAY: f32 = 16384.0;

impl VolumeScene {
    /// Upload `volume`; sampling distance `step` world units (default: half the smallest voxel
    /// spacing).
    pub fn new(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        volume: &Volume,
        transfer: TransferFunction,
        step: Option<f32>,
        model: Mat4,
    ) -> Result<Self> {
        let voxel = volume.min_spacing();
        let step = step.unwrap_or(0.5 * voxel);
        let diagonal = volume.extent().length();
        if !(step.is_finite() && step > 0.0 && diagonal / step <= MAX_SAMPLES_PER_RAY) {
            return Err(Error::invalid(
                "sampling step",
                format!("{step}: must be positive and at least {} (the box diagonal / {MAX_SAMPLES_PER_RAY})", diagonal / MAX_SAMPLES_PER_RAY),
            ));
        }
        if !model.is_finite() {
            return Err(Error::invalid("volume rotation", "not finite"));
        }
        Ok(Self {
            texture: VolumeTexture::new(device, queue, volume)?,
            extent: volume.extent(),
            voxel,
            transfer,
            step,
            model,
            shade: true,
        })
    }

    /// Sampling distance for `slices` samples across the box diagonal.
    pub fn step_for_slices(volume: &Volume, slices: u32) -> f32 {
        volume.extent().length() / slices.max(1) as f32
    }
}

/// Per-dispatch constants. Keep in sync with `struct VolumeParams` in `wgsl/volume_raycast.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct VolumeParams {
    tex_from_eye: [[f32; 4]; 4],
    normal_from_tex: [[f32; 4]; 4],
    step: f32,
    fixed_offset: f32,
    use_mask: u32,
    max_samples: u32,
    shade: u32,
    _pad: [u32; 3],
}
const _: () = assert!(std::mem::size_of::<VolumeParams>() == 160);

/// Ray-marching volume renderer for one [`VolumeMethod`].
pub struct VolumeRaycaster {
    method: VolumeMethod,
    frame: FrameBinding,
    frame_layout: wgpu::BindGroupLayout,
    volume_layout: wgpu::BindGroupLayout,
    output_layout: wgpu::BindGroupLayout,
    sampler: wgpu::Sampler,
    pipelines: HashMap<Specialization, wgpu::ComputePipeline>,
    params: Option<(wgpu::Buffer, u32)>,
    params_stride: u64,
    table: Option<(TransferFunction, f32, PreintegrationTexture)>,
    layers: Option<ViewLayers>,
    compositor: Option<Compositor>,
}

impl VolumeRaycaster {
    /// Prepare layouts and the sampler; pipelines are built per display specialisation.
    pub fn new(device: &wgpu::Device, method: VolumeMethod) -> Result<Self> {
        let cs = wgpu::ShaderStages::COMPUTE;
        let entry = |binding, ty| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: cs,
            ty,
            count: None,
        };
        let texture = |dim| wgpu::BindingType::Texture {
            sample_type: wgpu::TextureSampleType::Float { filterable: true },
            view_dimension: dim,
            multisampled: false,
        };
        let volume_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("volume"),
            entries: &[
                entry(0, texture(wgpu::TextureViewDimension::D3)),
                entry(
                    1,
                    wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
                ),
                entry(2, texture(wgpu::TextureViewDimension::D2)),
                entry(
                    3,
                    wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Uniform,
                        has_dynamic_offset: true,
                        min_binding_size: wgpu::BufferSize::new(
                            std::mem::size_of::<VolumeParams>() as u64,
                        ),
                    },
                ),
            ],
        });
        let output_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("volume output"),
            entries: &[entry(
                0,
                wgpu::BindingType::StorageTexture {
                    access: wgpu::StorageTextureAccess::WriteOnly,
                    format: crate::target::SPATIAL_FORMAT,
                    view_dimension: wgpu::TextureViewDimension::D2,
                },
            )],
        });
        let frame_layout = frame_bind_group_layout(device);
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("volume linear clamp"),
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            ..Default::default()
        });
        let align = device.limits().min_uniform_buffer_offset_alignment as u64;
        let compositor = match method {
            VolumeMethod::NPass => Some(Compositor::new(device, &frame_layout)?),
            _ => None,
        };
        Ok(Self {
            method,
            frame: FrameBinding::new(device, &frame_layout),
            frame_layout,
            volume_layout,
            output_layout,
            sampler,
            pipelines: HashMap::new(),
            params: None,
            params_stride: (std::mem::size_of::<VolumeParams>() as u64).div_ceil(align) * align,
            table: None,
            layers: None,
            compositor,
        })
    }

    fn pipeline(
        &mut self,
        device: &wgpu::Device,
        spec: Specialization,
    ) -> Result<&wgpu::ComputePipeline> {
        if !self.pipelines.contains_key(&spec) {
            let module = crate::shader::module(device, "volume_raycast.wgsl")?;
            let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some("volume raycast"),
                bind_group_layouts: &[
                    Some(&self.frame_layout),
                    Some(&self.volume_layout),
                    Some(&self.output_layout),
                ],
                immediate_size: 0,
            });
            let constants = spec.constants(&[]);
            let pipeline = crate::gpu::checked(device, "building the volume pipeline", || {
                device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                    label: Some("volume raycast"),
                    layout: Some(&layout),
                    module: &module,
                    entry_point: Some("cs_main"),
                    compilation_options: wgpu::PipelineCompilationOptions {
                        constants: &constants,
                        zero_initialize_workgroup_memory: true,
                    },
                    cache: None,
                })
            })?;
            self.pipelines.insert(spec, pipeline);
        }
        Ok(&self.pipelines[&spec])
    }

    /// The pre-integration table, rebuilt only when the transfer function or the sampling
    /// distance (in voxels) changed.
    fn table(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        scene: &VolumeScene,
    ) -> Result<&wgpu::TextureView> {
        let step_voxels = scene.step / scene.voxel;
        let fresh = self
            .table
            .as_ref()
            .is_some_and(|(tf, step, _)| *tf == scene.transfer && *step == step_voxels);
        if !fresh {
            let table = PreintegrationTable::new(&scene.transfer, step_voxels)?;
            let texture = PreintegrationTexture::new(device, queue, &table);
            self.table = Some((scene.transfer.clone(), step_voxels, texture));
        }
        Ok(&self.table.as_ref().expect("built above").2.view)
    }

    fn params(
        &self,
        scene: &VolumeScene,
        frame: &Frame,
        use_mask: bool,
        fixed_offset: f32,
    ) -> VolumeParams {
        let eye_from_model = frame.camera.eye_from_world * scene.model;
        let tex_from_model =
            Mat4::from_translation(Vec3::splat(0.5)) * Mat4::from_scale(scene.extent.recip());
        let tex_from_eye = tex_from_model * eye_from_model.inverse();
        let normal = Mat3::from_mat4(eye_from_model).inverse().transpose();
        let max_samples = (scene.extent.length() / scene.step).ceil() as u32 + 2;
        VolumeParams {
            tex_from_eye: tex_from_eye.to_cols_array_2d(),
            normal_from_tex: Mat4::from_mat3(normal).to_cols_array_2d(),
            step: scene.step,
            fixed_offset,
            use_mask: use_mask as u32,
            max_samples,
            shade: scene.shade as u32,
            _pad: [0; 3],
        }
    }

    fn write_params(&mut self, device: &wgpu::Device, queue: &wgpu::Queue, all: &[VolumeParams]) {
        let count = all.len() as u32;
        if self.params.as_ref().is_none_or(|(_, c)| *c < count) {
            let buffer = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("volume params"),
                size: self.params_stride * count as u64,
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            self.params = Some((buffer, count));
        }
        let mut bytes = vec![0u8; (self.params_stride * count as u64) as usize];
        for (i, p) in all.iter().enumerate() {
            let at = i * self.params_stride as usize;
            bytes[at..at + std::mem::size_of::<VolumeParams>()]
                .copy_from_slice(bytemuck::bytes_of(p));
        }
        queue.write_buffer(&self.params.as_ref().expect("allocated above").0, 0, &bytes);
    }

    /// Per-view images of the last N-pass render, if any.
    pub fn view_layers(&self) -> Option<&ViewLayers> {
        self.layers.as_ref()
    }
}

impl Renderer<VolumeScene> for VolumeRaycaster {
    fn encode(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        scene: &VolumeScene,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()> {
        frame.validate()?;
        if target.size() != frame.size {
            return Err(Error::invalid(
                "target",
                format!(
                    "size {:?} differs from the frame's {:?}",
                    target.size(),
                    frame.size
                ),
            ));
        }
        self.frame.write(queue, frame);
        let camera = &frame.camera;
        // One dispatch per camera: all K views per pixel, or one fixed camera per view / centre.
        let dispatches: Vec<VolumeParams> = match self.method {
            VolumeMethod::SinglePass => vec![self.params(scene, frame, true, 0.0)],
            VolumeMethod::SingleView => vec![self.params(scene, frame, false, 0.0)],
            VolumeMethod::NPass => (0..camera.views)
                .map(|i| self.params(scene, frame, false, camera.view_offset(i)))
                .collect(),
        };
        self.write_params(device, queue, &dispatches);
        if self.method == VolumeMethod::NPass
            && self.layers.as_ref().map(|l| l.key()) != Some((frame.size, camera.views))
        {
            self.layers = None;
            self.layers = Some(ViewLayers::new(device, frame.size, camera.views)?);
        }
        let table = self.table(device, queue, scene)?.clone();
        let volume_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("volume"),
            layout: &self.volume_layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&scene.texture.view),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::Sampler(&self.sampler),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: wgpu::BindingResource::TextureView(&table),
                },
                wgpu::BindGroupEntry {
                    binding: 3,
                    resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                        buffer: &self.params.as_ref().expect("written above").0,
                        offset: 0,
                        size: wgpu::BufferSize::new(std::mem::size_of::<VolumeParams>() as u64),
                    }),
                },
            ],
        });
        let outputs: Vec<wgpu::TextureView> = match (&self.method, &self.layers) {
            (VolumeMethod::NPass, Some(layers)) => layers.layer_views.clone(),
            _ => vec![target.view.clone()],
        };
        let spec = Specialization::of(frame);
        self.pipeline(device, spec)?;
        let pipeline = &self.pipelines[&spec];
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("volume raycast"),
                timestamp_writes: None,
            });
            pass.set_pipeline(pipeline);
            pass.set_bind_group(0, &self.frame.bind_group, &[]);
            for (i, output) in outputs.iter().enumerate() {
                let output_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some("volume output"),
                    layout: &self.output_layout,
                    entries: &[wgpu::BindGroupEntry {
                        binding: 0,
                        resource: wgpu::BindingResource::TextureView(output),
                    }],
                });
                pass.set_bind_group(1, &volume_group, &[(i as u64 * self.params_stride) as u32]);
                pass.set_bind_group(2, &output_group, &[]);
                pass.dispatch_workgroups(frame.size[0].div_ceil(8), frame.size[1].div_ceil(8), 1);
            }
        }
        if let (Some(compositor), Some(layers)) = (&self.compositor, &self.layers) {
            compositor.encode(device, encoder, &self.frame, &layers.array_view, target);
        }
        Ok(())
    }
}
