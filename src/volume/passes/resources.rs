//! What every volume renderer binds at group 1: the volume texture, a linear sampler, the
//! pre-integration table (cached per transfer function and sampling distance), the per-dispatch
//! [`VolumeParams`] (dynamic offsets) and the empty-space distances (cached per volume and
//! transfer function).

use bytemuck::{Pod, Zeroable};
use glam::{Mat3, Mat4, Vec3};

use crate::error::Result;
use crate::frame::{frame_bind_group_layout, Frame, FrameBinding};
use crate::gpu::pass_params::PassParams;
use crate::render::Made;
use crate::volume::{
    EmptyDistanceTexture, PreintegrationTable, PreintegrationTexture, TransferFunction,
};
use crate::volume::{VolumeScene, VolumeSettings};

/// Per-dispatch constants. Keep in sync with `struct VolumeParams` in `wgsl/volume/shared/volume.wgsl`.
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
    share_tolerance: f32,
    clip_count: u32,
    _pad: u32,
    clip: [[f32; 4]; crate::volume::MAX_CLIP_PLANES],
}
const _: () = assert!(std::mem::size_of::<VolumeParams>() == 256);
crate::shader::gpu_layout!(
    VolumeParams,
    "VolumeParams",
    [
        tex_from_eye,
        normal_from_tex,
        step,
        fixed_offset,
        use_mask,
        max_samples,
        shade,
        share_tolerance,
        clip_count,
        clip
    ]
);

/// The pre-integration table and what it was made for.
struct UploadedTable {
    transfer: TransferFunction,
    step_voxels: f32,
    texture: PreintegrationTexture,
}

/// The empty-space distances and what they were made for: (scene id, transfer function), or
/// `None` for the one-texel stand-in of a march that does not skip (a slice pass, or
/// `--no-skip-empty`), which binds the texture but never reads it.
struct UploadedDistances {
    made_for: Option<(u64, TransferFunction)>,
    texture: EmptyDistanceTexture,
}

pub(crate) struct VolumeResources {
    pub frame: FrameBinding,
    pub frame_layout: wgpu::BindGroupLayout,
    pub volume_layout: wgpu::BindGroupLayout,
    sampler: wgpu::Sampler,
    pub params: PassParams<VolumeParams>,
    table: Option<UploadedTable>,
    /// Empty-space distances for (scene id, transfer function).
    distances: Option<UploadedDistances>,
}

impl VolumeResources {
    /// Layouts for group 1 visible to `stages`.
    pub fn new(device: &wgpu::Device, stages: wgpu::ShaderStages) -> Self {
        let entry = |binding, ty| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: stages,
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
                PassParams::<VolumeParams>::layout_entry(3, stages),
                entry(
                    4,
                    wgpu::BindingType::Texture {
                        sample_type: wgpu::TextureSampleType::Uint,
                        view_dimension: wgpu::TextureViewDimension::D3,
                        multisampled: false,
                    },
                ),
            ],
        });
        let frame_layout = frame_bind_group_layout(device);
        Self {
            frame: FrameBinding::new(device, &frame_layout),
            frame_layout,
            volume_layout,
            sampler: device.create_sampler(&wgpu::SamplerDescriptor {
                label: Some("volume linear clamp"),
                mag_filter: wgpu::FilterMode::Linear,
                min_filter: wgpu::FilterMode::Linear,
                ..Default::default()
            }),
            params: PassParams::new(device, "volume params"),
            table: None,
            distances: None,
        }
    }

    /// The layout of a volume pipeline: frame (group 0), volume (group 1), the pipeline's own
    /// `group2`.
    pub fn pipeline_layout(
        &self,
        device: &wgpu::Device,
        label: &str,
        group2: &wgpu::BindGroupLayout,
    ) -> wgpu::PipelineLayout {
        device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some(label),
            bind_group_layouts: &[
                Some(&self.frame_layout),
                Some(&self.volume_layout),
                Some(group2),
            ],
            immediate_size: 0,
        })
    }

    /// Constants for one dispatch: all K views per pixel (`use_mask`) or one camera at `offset`.
    pub fn params(
        scene: &VolumeScene,
        settings: &VolumeSettings,
        frame: &Frame,
        use_mask: bool,
        fixed_offset: f32,
    ) -> VolumeParams {
        let eye_from_model = frame.camera.eye_from_world * scene.model;
        let tex_from_model =
            Mat4::from_translation(Vec3::splat(0.5)) * Mat4::from_scale(scene.extent.recip());
        let normal = Mat3::from_mat4(eye_from_model).inverse().transpose();
        let step = settings.step_length(scene);
        let (clip, clip_count) = crate::volume::clip::texture_planes(scene);
        VolumeParams {
            tex_from_eye: (tex_from_model * eye_from_model.inverse()).to_cols_array_2d(),
            normal_from_tex: Mat4::from_mat3(normal).to_cols_array_2d(),
            step,
            fixed_offset,
            use_mask: use_mask as u32,
            max_samples: (scene.extent.length() / step).ceil() as u32 + 2,
            shade: settings.shade as u32,
            share_tolerance: settings.share_samples,
            clip_count,
            _pad: 0,
            clip,
        }
    }

    /// Upload what `scene` needs: the pre-integration table (rebuilt only when the transfer
    /// function or step changed) and the empty-space distances (per volume and transfer
    /// function; where the pass does not `skip`, a one-texel stand-in). Each upload goes into a
    /// new texture, never over one a frame may still use. The scene's public fields and the
    /// settings are checked first.
    pub fn upload(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        scene: &VolumeScene,
        settings: &VolumeSettings,
        skip: bool,
    ) -> Result<()> {
        scene.validate()?;
        settings.validate_for(scene)?;
        if !self.table_fresh(scene, settings) {
            let step_voxels = settings.step_length(scene) / scene.voxel;
            let table = PreintegrationTable::new(&scene.transfer, step_voxels)?;
            self.table = Some(UploadedTable {
                transfer: scene.transfer.clone(),
                step_voxels,
                texture: PreintegrationTexture::new(device, queue, &table),
            });
        }
        if !self.distances_fresh(scene, skip) {
            let made_for = skip.then(|| (scene.id(), scene.transfer.clone()));
            let (grid, distances) = match skip {
                true => (scene.cells().grid, scene.cells().distances(&scene.transfer)),
                false => ([1; 3], vec![0]),
            };
            // The old texture's budget charge goes first (a frame still using it keeps it).
            self.distances = None;
            self.distances = Some(UploadedDistances {
                made_for,
                texture: EmptyDistanceTexture::new(device, queue, grid, &distances)?,
            });
        }
        Ok(())
    }

    fn table_fresh(&self, scene: &VolumeScene, settings: &VolumeSettings) -> bool {
        let step_voxels = settings.step_length(scene) / scene.voxel;
        self.table
            .as_ref()
            .is_some_and(|t| t.transfer == scene.transfer && t.step_voxels == step_voxels)
    }

    fn distances_fresh(&self, scene: &VolumeScene, skip: bool) -> bool {
        self.distances.as_ref().is_some_and(|d| match &d.made_for {
            Some((id, transfer)) => skip && *id == scene.id() && *transfer == scene.transfer,
            None => !skip,
        })
    }

    /// Whether [`VolumeResources::upload`] ran for `scene` as it is now (the same volume,
    /// transfer function and step) and `skip`.
    pub fn uploaded_for(&self, scene: &VolumeScene, settings: &VolumeSettings, skip: bool) -> bool {
        self.table_fresh(scene, settings) && self.distances_fresh(scene, skip)
    }

    /// This frame's constants and the dispatches' (buffers of their own, no queue writes),
    /// then the group-1 bind group over what [`VolumeResources::upload`] made.
    pub fn bind(
        &mut self,
        device: &wgpu::Device,
        scene: &VolumeScene,
        frame: &Frame,
        dispatches: &[VolumeParams],
    ) -> Result<wgpu::BindGroup> {
        self.frame.write(device, frame);
        self.params.write(device, dispatches);
        let table = &self
            .table
            .made("the volume's pre-integration table")?
            .texture
            .view;
        let distances = &self
            .distances
            .made("the volume's empty-space distances")?
            .texture
            .view;
        Ok(device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("volume"),
            layout: &self.volume_layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&scene.texture().view),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::Sampler(&self.sampler),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: wgpu::BindingResource::TextureView(table),
                },
                wgpu::BindGroupEntry {
                    binding: 3,
                    resource: self.params.binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 4,
                    resource: wgpu::BindingResource::TextureView(distances),
                },
            ],
        }))
    }
}
