//! The paper's volume path (§3.3.1, §3.5.1): view-aligned proxy slices drawn back to front,
//! per fragment the K views' samples offset per Eq. 1, pre-integrated and shaded, blended
//! "over" (`wgsl/volume/slices.wgsl`). Two α modes: the paper's mean α per pixel, and exact
//! per-channel α with dual-source blending.

use bytemuck::{Pod, Zeroable};
use glam::{Vec3, Vec4Swizzles};

use super::raycast::{PreparedFor, VolumeEncode};
use super::resources::VolumeResources;
use crate::error::{Error, Result};
use crate::frame::Frame;
use crate::gpu::pipeline::{begin_pass, cleared, over_per_channel_pipeline};
use crate::gpu::texture::{texture_2d_reusing, Texture2d};
use crate::param::Param;
use crate::render::accumulation::AccumulationResolve;
use crate::render::pipeline_cache::PipelineCache;
use crate::render::specialize::Specialization;
use crate::render::{begin_prepare, prepared_state, Prepared, Renderer};
use crate::target::SpatialTarget;
use crate::volume::options::AlphaMode;
use crate::volume::VolumePath;
use crate::volume::{VolumeScene, VolumeSettings};

/// Accumulation format: float, so hundreds of blended slices don't quantise.
const ACCUMULATION_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba16Float;

/// One proxy slice. Keep in sync with `struct Slice` in `wgsl/volume/slices.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
struct SliceRect {
    depth: [f32; 4],
    rect: [f32; 4],
}
const _: () = assert!(std::mem::size_of::<SliceRect>() == 32);
crate::shader::gpu_layout!(SliceRect, "Slice", [depth, rect]);
#[cfg(test)]
pub(crate) const SLICE_LAYOUT: crate::shader::GpuLayout = SliceRect::GPU_LAYOUT;

/// Single-pass volume rendering with proxy slices.
pub struct VolumeSlicer {
    alpha: AlphaMode,
    settings: VolumeSettings,
    resources: VolumeResources,
    slices_layout: wgpu::BindGroupLayout,
    pipelines: PipelineCache<Specialization, wgpu::RenderPipeline>,
    resolve: AccumulationResolve,
    /// The prepared frame's accumulation texture (float: hundreds of slices do not quantise).
    prepared: Option<Prepared<PreparedFor, Texture2d>>,
    /// The parallel camera model's crop, recorded last.
    crop: crate::render::camera_crop::CameraCrop,
}

/// `param` refused for the slices: `reason` is the ray-marching feature it sets.
fn slices_have_none(param: Param, reason: String, alpha: AlphaMode) -> Error {
    use crate::advice::{Advice, Setting};
    let slices = Setting::VolumePath(VolumePath::Slices(alpha));
    Error::InvalidParameter {
        param,
        reason: format!("{reason}; the proxy slices"),
        advice: Some(Advice::text(" (").then(slices).then_text(") have none")),
    }
}

impl VolumeSlicer {
    /// Needs `DUAL_SOURCE_BLENDING` (per-channel blend factors). Of `settings`, the slices use
    /// the step and shading; the ray-marching approximations (sample sharing, probes) are
    /// refused, and empty-space skipping does not apply (slices are rasterised whole).
    pub fn new(device: &wgpu::Device, alpha: AlphaMode, settings: VolumeSettings) -> Result<Self> {
        settings.validate()?;
        if settings.share_samples > 0.0 {
            return Err(slices_have_none(
                Param::SampleSharing,
                format!(
                    "{}: sharing samples among a pixel's rays is a ray-marching approximation",
                    settings.share_samples
                ),
                alpha,
            ));
        }
        if settings.empty_stride > 1 {
            return Err(slices_have_none(
                Param::EmptyStride,
                format!(
                    "{}: probing is part of ray marching's empty-space skipping",
                    settings.empty_stride
                ),
                alpha,
            ));
        }
        crate::gpu::require_features(
            device,
            wgpu::Features::DUAL_SOURCE_BLENDING,
            "the proxy-slice volume path",
            crate::advice::Advice::text("use ")
                .then(crate::advice::Setting::VolumePath(VolumePath::RayMarch))
                .then_text(" (the ray-marching compute path)"),
        )?;
        let resources = VolumeResources::new(device, wgpu::ShaderStages::VERTEX_FRAGMENT);
        let layout = |label, ty| {
            device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                label: Some(label),
                entries: &[wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
                    ty,
                    count: None,
                }],
            })
        };
        let slices_layout = layout(
            "volume slices",
            wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Storage { read_only: true },
                has_dynamic_offset: false,
                min_binding_size: None,
            },
        );
        let resolve = AccumulationResolve::new(device, &resources.frame_layout)?;
        Ok(Self {
            alpha,
            settings,
            resources,
            slices_layout,
            pipelines: PipelineCache::new("volume slice"),
            resolve,
            prepared: None,
            crop: crate::render::camera_crop::CameraCrop::new(device)?,
        })
    }

    fn ensure_pipeline(&mut self, device: &wgpu::Device, spec: Specialization) -> Result<()> {
        let (alpha, resources, slices_layout) = (self.alpha, &self.resources, &self.slices_layout);
        let exact = (alpha == AlphaMode::Exact) as u32 as f64;
        let constants = spec.constants(&[("EXACT_ALPHA", exact)]);
        self.pipelines.prepare(device, spec, |modules| {
            let layout = resources.pipeline_layout(device, "volume slices", slices_layout);
            let module = modules.get(device, "volume/slices.wgsl")?;
            Ok(over_per_channel_pipeline(
                device,
                "volume slices",
                &layout,
                &module,
                &constants,
                ACCUMULATION_FORMAT,
            ))
        })?;
        Ok(())
    }
}

/// Back-to-front proxy slices: for each segment [kΔ, (k+1)Δ] inside the box and [near, far],
/// the NDC rectangle covering the box's cross-sections at both depths in every view.
fn slices(scene: &VolumeScene, step: f32, frame: &Frame) -> Vec<SliceRect> {
    let camera = &frame.camera;
    let eye_from_model = camera.eye_from_world * scene.model;
    let half = scene.extent * 0.5;
    let corners: Vec<Vec3> = (0..8)
        .map(|i| {
            let s = Vec3::new(
                if i & 1 == 0 { -1.0 } else { 1.0 },
                if i & 2 == 0 { -1.0 } else { 1.0 },
                if i & 4 == 0 { -1.0 } else { 1.0 },
            );
            (eye_from_model * (s * half).extend(1.0)).xyz()
        })
        .collect();
    let edges = (0..8usize)
        .flat_map(|a| [1usize, 2, 4].map(move |bit| (a, a | bit)))
        .filter(|(a, b)| a != b);
    let edges: Vec<(Vec3, Vec3)> = edges.map(|(a, b)| (corners[a], corners[b])).collect();
    // Each view's own depths of the corners: the slices are at the same depths in every view,
    // which for turned (toe-in) cameras are not the centre's.
    let toe_in = camera.model == crate::camera::CameraModel::ToeIn;
    let offsets: Vec<f32> = if toe_in {
        (0..camera.views).map(|i| camera.view_offset(i)).collect()
    } else {
        vec![0.0]
    };
    let depths: Vec<f32> = offsets
        .iter()
        .flat_map(|&vd| {
            let turn = glam::Mat4::from_rotation_y(-camera.toe_in_angle(vd));
            let origin = Vec3::new(vd, 0.0, 0.0);
            let corners = &corners;
            (0..8).map(move |i| match toe_in {
                true => -turn.transform_point3(corners[i] - origin).z,
                false => -corners[i].z,
            })
        })
        .collect();
    let d_min = depths
        .iter()
        .copied()
        .fold(f32::INFINITY, f32::min)
        .max(camera.near);
    let d_max = depths
        .iter()
        .copied()
        .fold(f32::NEG_INFINITY, f32::max)
        .min(camera.far);
    let (fd, spread) = (camera.focal_distance, camera.max_offset());
    let (window, centre) = (camera.focal_window(), camera.window_offset);
    let pad = window / glam::Vec2::new(frame.size[0] as f32, frame.size[1] as f32) / 16.0;
    // The cross-section of the box at depth d, projected and widened for every view.
    let section = |d: f32, lo: &mut glam::Vec2, hi: &mut glam::Vec2| {
        for (a, b) in &edges {
            let (da, db) = (-a.z, -b.z);
            if (da - d) * (db - d) > 0.0 || da == db {
                continue;
            }
            let p = *a + (*b - *a) * ((d - da) / (db - da));
            let s = fd / d;
            let x = p.x * s;
            let w = spread * (1.0 - s).abs();
            *lo = lo.min(glam::Vec2::new(x - w, p.y * s));
            *hi = hi.max(glam::Vec2::new(x + w, p.y * s));
        }
    };
    let (k0, k1) = ((d_min / step).ceil() as i64, (d_max / step).floor() as i64);
    let mut out = Vec::new();
    for k in (k0..k1).rev() {
        let d = k as f32 * step;
        let (mut lo, mut hi) = (
            glam::Vec2::splat(f32::INFINITY),
            glam::Vec2::splat(f32::NEG_INFINITY),
        );
        if toe_in {
            // Turned views cut the box along turned planes: cover the whole image.
            (lo, hi) = (centre - window * 0.5, centre + window * 0.5);
        } else {
            section(d, &mut lo, &mut hi);
            section(d + step, &mut lo, &mut hi);
        }
        if lo.x > hi.x {
            continue;
        }
        let to_ndc = |v: glam::Vec2| {
            ((v - centre) / (window * 0.5)).clamp(glam::Vec2::splat(-2.0), glam::Vec2::splat(2.0))
        };
        let (lo, hi) = (to_ndc(lo - pad), to_ndc(hi + pad));
        out.push(SliceRect {
            depth: [d, 0.0, 0.0, 0.0],
            rect: [lo.x, lo.y, hi.x, hi.y],
        });
    }
    out
}

impl Renderer<VolumeScene> for VolumeSlicer {
    fn prepare(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        scene: &VolumeScene,
        frame: &Frame,
    ) -> Result<()> {
        let last = self.prepared.take().map(|p| p.made);
        begin_prepare(device, frame, &mut self.prepared)?;
        frame.check_full_views("slice-based")?;
        let key = PreparedFor::for_slices(&self.settings, frame);
        // Proxy slices are rasterised whole: nothing to skip (`key.skip_empty` is false).
        self.resources
            .upload(device, queue, scene, &self.settings, key.skip_empty)?;
        self.ensure_pipeline(device, key.spec)?;
        let accumulation = texture_2d_reusing(
            last,
            device,
            "slice accumulation",
            frame.size,
            ACCUMULATION_FORMAT,
            wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING,
        )?;
        self.prepared = Some(Prepared {
            key,
            made: accumulation,
        });
        Ok(())
    }

    fn encode(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        scene: &VolumeScene,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()> {
        let wanted = PreparedFor::for_slices(&self.settings, frame);
        VolumeEncode {
            renderer: "VolumeSlicer",
            prepared: self.prepared.as_ref().map(|p| p.key),
            resources: &self.resources,
            settings: &self.settings,
            wanted,
        }
        .check(scene, frame, target)?;
        let accumulation = &prepared_state("VolumeSlicer", &self.prepared, &wanted)?
            .made
            .view;
        let spec = Specialization::of(frame);
        let params = VolumeResources::params(scene, &self.settings, frame, true, 0.0);
        let volume_group = self.resources.bind(device, scene, frame, &[params])?;
        let rects = slices(scene, self.settings.step_length(scene), frame);
        // A buffer of this frame's own (src/gpu/pass_params.rs), never empty.
        let mut bytes = bytemuck::cast_slice::<_, u8>(&rects).to_vec();
        bytes.resize(bytes.len().max(std::mem::size_of::<SliceRect>()), 0);
        let buffer = &crate::gpu::pass_params::constants_buffer(
            device,
            "volume slices",
            wgpu::BufferUsages::STORAGE,
            &bytes,
        );
        let slices_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("volume slices"),
            layout: &self.slices_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: buffer.as_entire_binding(),
            }],
        });
        {
            // Cleared to the background: "over" blending then composites every channel over it
            // with that channel's own α.
            let color = cleared(accumulation, frame.background);
            let mut pass = begin_pass(encoder, "volume slices", color, None);
            pass.set_pipeline(self.pipelines.get(&spec)?);
            pass.set_bind_group(0, &self.resources.frame.bind_group, &[]);
            pass.set_bind_group(1, &volume_group, &[0]);
            pass.set_bind_group(2, &slices_group, &[]);
            pass.draw(0..6, 0..rects.len() as u32);
        }
        self.resolve.encode(
            device,
            encoder,
            &self.resources.frame,
            accumulation,
            &target.view,
        );
        self.crop.encode(device, encoder, frame, target);
        Ok(())
    }
}
