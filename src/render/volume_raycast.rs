//! Volume rendering by ray marching in a compute pass (`wgsl/volume_raycast.wgsl`): the
//! single-pass method (each pixel marches the rays of its K views and writes the spatial image)
//! and, with the same kernel and the same samples, the N-pass baseline and the single view.

use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering};

use glam::{Mat4, Vec3};

use super::renderer::{check_target, Renderer};
use super::specialize::Specialization;
use super::volume_resources::{VolumeParams, VolumeResources};
use super::{Compositor, ViewLayers};
use crate::error::{Error, Result};
use crate::frame::Frame;
use crate::target::SpatialTarget;
use crate::volume::{BrickRanges, TransferFunction, Volume, VolumeTexture};

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
    /// Gradients + scalar (private: the brick ranges and the id describe this data).
    texture: VolumeTexture,
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
    /// Jump over bricks the transfer function makes fully transparent (ray-marching path;
    /// exact: the image is the same bit for bit, see `volume::bricks`).
    pub skip_empty: bool,
    /// Scalar ranges per brick of the uploaded volume.
    bricks: BrickRanges,
    /// Identifies the uploaded volume for caches of data derived from it.
    id: u64,
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
        // Everything is checked before the upload.
        volume.validate()?;
        let voxel = volume.min_spacing();
        let step = step.unwrap_or(0.5 * voxel);
        check_scene(volume.extent(), &transfer, step, model)?;
        let texture = VolumeTexture::new_validated(device, queue, volume)?;
        static NEXT_ID: AtomicU64 = AtomicU64::new(0);
        Ok(Self {
            texture,
            extent: volume.extent(),
            voxel,
            transfer,
            step,
            model,
            shade: true,
            skip_empty: true,
            bricks: BrickRanges::new(volume),
            id: NEXT_ID.fetch_add(1, Ordering::Relaxed),
        })
    }

    /// Check the public fields a caller may have changed since [`VolumeScene::new`]: the
    /// renderers call this before every frame.
    pub fn validate(&self) -> Result<()> {
        check_scene(self.extent, &self.transfer, self.step, self.model)
    }

    /// The uploaded volume (gradients + scalar).
    pub fn texture(&self) -> &VolumeTexture {
        &self.texture
    }

    /// Scalar ranges per brick (empty-space skipping).
    pub fn bricks(&self) -> &BrickRanges {
        &self.bricks
    }

    /// Identifies the uploaded volume: caches of data derived from it key on this.
    pub(crate) fn id(&self) -> u64 {
        self.id
    }

    /// Sampling distance for `slices` samples across the box diagonal.
    pub fn step_for_slices(volume: &Volume, slices: u32) -> f32 {
        volume.extent().length() / slices.max(1) as f32
    }
}

/// Transfer function, sampling step (positive, at most [`MAX_SAMPLES_PER_RAY`] samples across the
/// box diagonal) and volume rotation (finite) of a scene whose box is `extent`.
fn check_scene(extent: Vec3, transfer: &TransferFunction, step: f32, model: Mat4) -> Result<()> {
    transfer.validate()?;
    let diagonal = extent.length();
    if !(step.is_finite() && step > 0.0 && diagonal / step <= MAX_SAMPLES_PER_RAY) {
        return Err(Error::invalid(
            "sampling step",
            format!(
                "{step}: must be positive and at least {} (the box diagonal / {MAX_SAMPLES_PER_RAY})",
                diagonal / MAX_SAMPLES_PER_RAY
            ),
        ));
    }
    if !model.is_finite() {
        return Err(Error::invalid("volume rotation", "not finite"));
    }
    Ok(())
}

/// Ray-marching volume renderer for one [`VolumeMethod`].
pub struct VolumeRaycaster {
    method: VolumeMethod,
    resources: VolumeResources,
    output_layout: wgpu::BindGroupLayout,
    /// Per display specialisation and empty-space skipping (on/off).
    pipelines: HashMap<(Specialization, bool), wgpu::ComputePipeline>,
    layers: Option<ViewLayers>,
    compositor: Option<Compositor>,
}

impl VolumeRaycaster {
    /// Prepare layouts and the sampler; pipelines are built per display specialisation.
    pub fn new(device: &wgpu::Device, method: VolumeMethod) -> Result<Self> {
        let resources = VolumeResources::new(device, wgpu::ShaderStages::COMPUTE);
        let output_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("volume output"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::COMPUTE,
                ty: wgpu::BindingType::StorageTexture {
                    access: wgpu::StorageTextureAccess::WriteOnly,
                    format: crate::target::SPATIAL_FORMAT,
                    view_dimension: wgpu::TextureViewDimension::D2,
                },
                count: None,
            }],
        });
        let compositor = match method {
            VolumeMethod::NPass => Some(Compositor::new(device, &resources.frame_layout)?),
            _ => None,
        };
        Ok(Self {
            method,
            resources,
            output_layout,
            pipelines: HashMap::new(),
            layers: None,
            compositor,
        })
    }

    /// The pipeline for `spec`, with the empty-space skipping code compiled in or out (an
    /// override constant: without it the march is the plain loop, no look-up overhead).
    fn ensure_pipeline(
        &mut self,
        device: &wgpu::Device,
        key: (Specialization, bool),
    ) -> Result<()> {
        let (spec, skip_empty) = key;
        if self.pipelines.contains_key(&key) {
            return Ok(());
        }
        let module = crate::shader::module(device, "volume_raycast.wgsl")?;
        let layout = self
            .resources
            .pipeline_layout(device, "volume raycast", &self.output_layout);
        let constants = spec.constants(&[("SKIP_EMPTY", f64::from(u8::from(skip_empty)))]);
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
        self.pipelines.insert(key, pipeline);
        Ok(())
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
        scene.validate()?;
        check_target(frame, target)?;
        let camera = &frame.camera;
        // One dispatch per camera: all K views per pixel, or one fixed camera per view / centre.
        let params = |use_mask, offset| VolumeResources::params(scene, frame, use_mask, offset);
        let dispatches: Vec<VolumeParams> = match self.method {
            VolumeMethod::SinglePass => vec![params(true, 0.0)],
            VolumeMethod::SingleView => vec![params(false, 0.0)],
            VolumeMethod::NPass => (0..camera.views)
                .map(|i| params(false, camera.view_offset(i)))
                .collect(),
        };
        let volume_group = self
            .resources
            .prepare(device, queue, scene, frame, &dispatches)?;
        if self.method == VolumeMethod::NPass
            && self.layers.as_ref().map(|l| l.key()) != Some((frame.size, camera.views))
        {
            self.layers = None;
            self.layers = Some(ViewLayers::new(device, frame.size, camera.views)?);
        }
        let key = (Specialization::of(frame), scene.skip_empty);
        self.ensure_pipeline(device, key)?;
        let outputs: Vec<&wgpu::TextureView> = match (&self.method, &self.layers) {
            (VolumeMethod::NPass, Some(layers)) => layers.layer_views.iter().collect(),
            _ => vec![&target.view],
        };
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("volume raycast"),
                timestamp_writes: None,
            });
            pass.set_pipeline(&self.pipelines[&key]);
            pass.set_bind_group(0, &self.resources.frame.bind_group, &[]);
            for (i, output) in outputs.iter().enumerate() {
                let output_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some("volume output"),
                    layout: &self.output_layout,
                    entries: &[wgpu::BindGroupEntry {
                        binding: 0,
                        resource: wgpu::BindingResource::TextureView(output),
                    }],
                });
                let offset = self.resources.params.offset(i);
                pass.set_bind_group(1, &volume_group, &[offset]);
                pass.set_bind_group(2, &output_group, &[]);
                pass.dispatch_workgroups(frame.size[0].div_ceil(8), frame.size[1].div_ceil(8), 1);
            }
        }
        if let (Some(compositor), Some(layers)) = (&self.compositor, &self.layers) {
            compositor.encode(
                device,
                encoder,
                &self.resources.frame,
                &layers.array_view,
                target,
            );
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gpu::{GpuContext, GpuOptions};
    use crate::volume::phantom;

    /// The ray caster really skips what the flags call transparent: with brick ranges
    /// falsified to "air only", every brick is skipped and the head's image changes. (That the
    /// true flags change no pixel is tests/volume.rs.)
    #[test]
    fn falsified_brick_ranges_skip_everything() {
        let ctx = GpuContext::new(&GpuOptions::default()).expect("a GPU adapter (CI: lavapipe)");
        let head = phantom::ct_head(24).unwrap();
        let tf = TransferFunction::preset("ct-skin").unwrap();
        let mut scene =
            VolumeScene::new(&ctx.device, &ctx.queue, &head, tf, None, Mat4::IDENTITY).unwrap();
        let display = crate::display::Display::parse("hubner8").unwrap();
        let camera =
            crate::camera::MultiViewCamera::framing(head.bounds(), 8, None, 0.6, 1.0).unwrap();
        let frame = Frame::new(camera, display, [48, 48]).unwrap();
        let target = SpatialTarget::new(&ctx.device, frame.size).unwrap();
        let render = |scene: &VolumeScene| {
            let mut renderer = VolumeRaycaster::new(&ctx.device, VolumeMethod::SinglePass).unwrap();
            renderer
                .render(&ctx.device, &ctx.queue, scene, &frame, &target)
                .unwrap();
            target.read(&ctx.device, &ctx.queue).unwrap()
        };
        let lit = |image: &crate::image_io::RgbImage| {
            image
                .data
                .chunks(3)
                .filter(|p| p.iter().any(|&v| v > 8))
                .count()
        };
        let pixels = (frame.size[0] * frame.size[1]) as usize;
        let true_image = render(&scene);
        assert!(lit(&true_image) > pixels / 10, "head not in view");
        for range in &mut scene.bricks.ranges {
            *range = [0.0, 0.0];
        }
        // A new volume for the flag cache.
        scene.id = u64::MAX;
        // Segments that cross a brick face are still marched (and marching goes on while they
        // add something), so the head does not vanish, but most of its pixels change (measured
        // with 4³ bricks: 11 % of all subpixels off by more than 2/255; the head covers 13 %).
        let falsified = render(&scene);
        let diff = crate::image_io::compare(&falsified, &true_image).unwrap();
        assert!(diff.frac_off_2 > 0.05, "{diff:?}");
    }
}
