//! Volume rendering by ray marching in a compute pass (`wgsl/volume/raycast.wgsl`): the
//! single-pass method (each pixel marches the rays of its K views and writes the spatial image)
//! and, with the same kernel and the same samples, the N-pass baseline and the single view.
//! The duplication methods' volume form marches every view of every pixel in one dispatch
//! (z = view) into texture-array layers (`raycast_layered.wgsl`) or the tiles of a quilt atlas
//! (`raycast_tiled.wgsl`), then composites.

mod prepared;
mod references;

pub(crate) use prepared::{PreparedFor, VolumeEncode};

use super::resources::{VolumeParams, VolumeResources};
use crate::error::{Error, Result};
use crate::frame::Frame;
use crate::gpu::pipeline::{bind_group_layout, compilation, uniform_entry};
use crate::param::Param;
use crate::render::atlas::{Atlas, AtlasCompositor, TileSampling};
use crate::render::npass::NPassHarness;
use crate::render::pipeline_cache::PipelineCache;
use crate::render::quilt::QuiltLayout;
use crate::render::specialize::Specialization;
use crate::render::Method;
use crate::render::ViewLayers;
use crate::render::{begin_prepare, Made, Prepared, Renderer};
use crate::target::SpatialTarget;
use crate::volume::{VolumeScene, VolumeSettings};

/// Ray-marching volume renderer for one [`Method`].
pub struct VolumeRaycaster {
    method: Method,
    settings: VolumeSettings,
    resources: VolumeResources,
    output_layout: wgpu::BindGroupLayout,
    pipelines: PipelineCache<RaycastPipelineKey, wgpu::ComputePipeline>,
    /// N-pass and layered only.
    npass: Option<NPassHarness>,
    /// Tiled only: composites the quilt atlas into the spatial image.
    compositor: Option<AtlasCompositor>,
    /// What `prepare` made for its frame: the tiled method's atlas (`None` for the others).
    prepared: Option<Prepared<PreparedFor, Option<Atlas>>>,
    /// The parallel camera model's crop, recorded last.
    crop: crate::render::camera_crop::CameraCrop,
}

/// Where a dispatch writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Output {
    /// The spatial target (single pass, single view) or one N-pass layer per dispatch.
    Image,
    /// Every layer of the N-pass array in one dispatch.
    Layers,
    /// Every tile of a quilt atlas in one dispatch.
    Atlas,
    /// A warp's reference views, colour and nearness layers, in one dispatch.
    References,
}

impl Output {
    fn of(method: Method) -> Result<Self> {
        match method {
            Method::SinglePass | Method::SingleView | Method::NPass => Ok(Self::Image),
            Method::Layered => Ok(Self::Layers),
            Method::Tiled => Ok(Self::Atlas),
            Method::Warp => Ok(Self::References),
            Method::Mrt => Err(Error::invalid(
                Param::Method,
                "mrt renders meshes only: its point is one depth buffer shared by the views of \
                 a draw, and volumes have no depth buffer; tiled and layered duplicate a \
                 volume's views",
            )),
        }
    }

    fn stage(self) -> &'static str {
        match self {
            Self::Image => "volume/raycast.wgsl",
            Self::Layers => "volume/raycast_layered.wgsl",
            Self::Atlas => "volume/raycast_tiled.wgsl",
            Self::References => "volume/raycast_reference.wgsl",
        }
    }

    fn layout(self, device: &wgpu::Device) -> wgpu::BindGroupLayout {
        let storage_of = |binding, format, view_dimension| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::COMPUTE,
            ty: wgpu::BindingType::StorageTexture {
                access: wgpu::StorageTextureAccess::WriteOnly,
                format,
                view_dimension,
            },
            count: None,
        };
        let storage = |view_dimension| storage_of(0, crate::target::SPATIAL_FORMAT, view_dimension);
        let quilt = uniform_entry(1, wgpu::ShaderStages::COMPUTE);
        let d2 = wgpu::TextureViewDimension::D2;
        match self {
            Self::Image => bind_group_layout(device, "volume output", &[storage(d2)]),
            Self::Layers => bind_group_layout(
                device,
                "volume output layers",
                &[storage(wgpu::TextureViewDimension::D2Array)],
            ),
            Self::Atlas => bind_group_layout(device, "volume output atlas", &[storage(d2), quilt]),
            Self::References => bind_group_layout(
                device,
                "volume reference views",
                &[
                    storage(wgpu::TextureViewDimension::D2Array),
                    storage_of(
                        1,
                        crate::warp::references::REFERENCE_NEARNESS_FORMAT,
                        wgpu::TextureViewDimension::D2Array,
                    ),
                ],
            ),
        }
    }
}

impl VolumeRaycaster {
    /// Prepare layouts and the sampler; pipelines are built per display specialisation.
    /// `settings` are checked here; sample sharing is the single pass's alone.
    pub fn new(device: &wgpu::Device, method: Method, settings: VolumeSettings) -> Result<Self> {
        let output = Output::of(method)?;
        settings.validate()?;
        if settings.share_samples > 0.0 && method != Method::SinglePass {
            return Err(Error::invalid(
                Param::SampleSharing,
                format!(
                    "{}: sharing samples among a pixel's rays is part of the single pass, not of \
                     the {method} method",
                    settings.share_samples
                ),
            ));
        }
        let resources = VolumeResources::new(device, wgpu::ShaderStages::COMPUTE);
        let output_layout = output.layout(device);
        let npass = match method {
            Method::NPass | Method::Layered => {
                Some(NPassHarness::new(device, &resources.frame_layout)?)
            }
            _ => None,
        };
        let compositor = match output {
            Output::Atlas => Some(AtlasCompositor::new(device, &resources.frame_layout)?),
            _ => None,
        };
        Ok(Self {
            method,
            settings,
            resources,
            output_layout,
            pipelines: PipelineCache::new("volume ray-marching"),
            npass,
            compositor,
            prepared: None,
            crop: crate::render::camera_crop::CameraCrop::new(device)?,
        })
    }

    /// The pipeline for `key`, with the empty-space skipping code compiled in or out (an
    /// override constant: without it the march is the plain loop, no look-up overhead).
    fn ensure_pipeline(&mut self, device: &wgpu::Device, key: RaycastPipelineKey) -> Result<()> {
        let (resources, output_layout) = (&self.resources, &self.output_layout);
        let stage = Output::of(self.method)?.stage();
        self.pipelines.prepare(device, key, |modules| {
            let layout = resources.pipeline_layout(device, "volume raycast", output_layout);
            let module = modules.get(device, stage)?;
            let skip = f64::from(u8::from(key.skip_empty));
            let track = f64::from(u8::from(stage == Output::References.stage()));
            let mut extra = vec![("SKIP_EMPTY", skip), ("TRACK_DEPTH", track)];
            if stage == Output::Image.stage() {
                extra.push(("SHARE_SAMPLES", f64::from(u8::from(key.share_samples))));
            }
            extra.push(("EMPTY_STRIDE", f64::from(key.empty_stride)));
            extra.push(("THIN_ALPHA", f64::from(f32::from_bits(key.thin_alpha_bits))));
            extra.push(("PROJECTION", f64::from(key.projection)));
            extra.push(("ISO_VALUE", f64::from(f32::from_bits(key.iso_bits))));
            let constants = key.spec.constants(&extra);
            Ok(
                device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                    label: Some("volume raycast"),
                    layout: Some(&layout),
                    module: &module,
                    entry_point: Some("cs_main"),
                    compilation_options: compilation(&constants),
                    cache: None,
                }),
            )
        })?;
        Ok(())
    }

    /// The end of every prepare: the pipeline for `key`, then `key` (with `atlas`, the tiled
    /// method's) is what was prepared.
    fn finish_prepare(
        &mut self,
        device: &wgpu::Device,
        key: PreparedFor,
        atlas: Option<Atlas>,
    ) -> Result<()> {
        self.ensure_pipeline(device, RaycastPipelineKey::from(key))?;
        self.prepared = Some(Prepared { key, made: atlas });
        Ok(())
    }

    /// The sampling and shading settings frames are rendered with.
    pub fn settings(&self) -> &VolumeSettings {
        &self.settings
    }

    /// Per-view images of the last N-pass render, if any.
    pub fn view_layers(&self) -> Option<&ViewLayers> {
        self.npass.as_ref()?.view_layers()
    }
}

/// What a ray-marching pipeline is specialised for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
struct RaycastPipelineKey {
    /// The display's K and N.
    spec: Specialization,
    /// Empty-space skipping compiled in.
    skip_empty: bool,
    /// Sample sharing among a pixel's rays compiled in (single pass, K = 3 only).
    share_samples: bool,
    /// Probing stride through transparent material (1: the exact march).
    empty_stride: u32,
    /// Thin-material threshold of the probes (`f32::to_bits`: a key must hash).
    thin_alpha_bits: u32,
    /// `Projection::code` (0: compositing).
    projection: u32,
    /// The isosurface's scalar (`f32::to_bits`).
    iso_bits: u32,
}

impl From<PreparedFor> for RaycastPipelineKey {
    fn from(prepared: PreparedFor) -> Self {
        Self {
            spec: prepared.spec,
            skip_empty: prepared.skip_empty,
            share_samples: prepared.share_samples,
            empty_stride: prepared.empty_stride,
            thin_alpha_bits: prepared.thin_alpha_bits,
            projection: prepared.projection,
            iso_bits: prepared.iso_bits,
        }
    }
}

impl VolumeRaycaster {
    /// The frame this method renders with: the methods that render view images render them
    /// (everything but the final compositing) with [`Frame::for_view_images`]; the others have
    /// none to scale.
    fn own_frame(&self, frame: &Frame) -> Result<Frame> {
        match self.method {
            Method::NPass | Method::Tiled | Method::Layered => Ok(frame.for_view_images()),
            other => {
                frame.check_full_views(other.name())?;
                Ok(frame.clone())
            }
        }
    }
}

impl Renderer<VolumeScene> for VolumeRaycaster {
    fn prepare(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        scene: &VolumeScene,
        frame: &Frame,
    ) -> Result<()> {
        let last_atlas = self.prepared.take().and_then(|p| p.made);
        begin_prepare(device, frame, &mut self.prepared)?;
        if self.method == Method::Warp {
            return Err(crate::warp::references::not_a_frame_renderer(
                "VolumeRaycaster",
            ));
        }
        let frame = &self.own_frame(frame)?;
        let key = PreparedFor::of(&self.settings, frame, self.method);
        self.resources
            .upload(device, queue, scene, &self.settings, key.skip_empty)?;
        if let Some(npass) = &mut self.npass {
            npass.prepare(device, frame)?;
        }
        let atlas = match self.compositor {
            Some(_) => {
                let layout = QuiltLayout::for_views(frame.camera.views, frame.size);
                Some(match last_atlas {
                    Some(atlas) if atlas.fits(&layout, false) => atlas,
                    // The last one is freed before its replacement is allocated.
                    _ => Atlas::new(device, layout, false)?,
                })
            }
            None => None,
        };
        self.finish_prepare(device, key, atlas)
    }

    fn encode(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        scene: &VolumeScene,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()> {
        let own = self.own_frame(frame)?;
        VolumeEncode {
            renderer: "VolumeRaycaster",
            prepared: self.prepared.as_ref().map(|p| p.key),
            resources: &self.resources,
            settings: &self.settings,
            wanted: PreparedFor::of(&self.settings, &own, self.method),
        }
        .check(scene, frame, target)?;
        // Checked just above: prepared for this frame.
        let atlas = self.prepared.as_ref().and_then(|p| p.made.as_ref());
        let full = frame;
        let frame = &own;
        let camera = &frame.camera;
        // One dispatch per camera: all K views per pixel, or one fixed camera per view /
        // centre; the duplication methods one dispatch for every view.
        let settings = &self.settings;
        let params =
            |use_mask, offset| VolumeResources::params(scene, settings, frame, use_mask, offset);
        let dispatches: Vec<VolumeParams> = match self.method {
            Method::SinglePass => vec![params(true, 0.0)],
            Method::SingleView | Method::Tiled | Method::Layered | Method::Mrt | Method::Warp => {
                vec![params(false, 0.0)]
            }
            Method::NPass => (0..camera.views)
                .map(|i| params(false, camera.view_offset(i)))
                .collect(),
        };
        let volume_group = self.resources.bind(device, scene, frame, &dispatches)?;
        let key = RaycastPipelineKey::from(PreparedFor::of(&self.settings, frame, self.method));
        let output = |resources: &[wgpu::BindingResource]| {
            let entries: Vec<_> = resources
                .iter()
                .enumerate()
                .map(|(i, resource)| wgpu::BindGroupEntry {
                    binding: i as u32,
                    resource: resource.clone(),
                })
                .collect();
            device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("volume output"),
                layout: &self.output_layout,
                entries: &entries,
            })
        };
        let view = wgpu::BindingResource::TextureView;
        // (output group, views in the dispatch's z) per dispatch.
        let outputs: Vec<(wgpu::BindGroup, u32)> = match (&self.npass, &self.compositor) {
            (_, Some(_)) => {
                let atlas = atlas.made("VolumeRaycaster atlas")?;
                let quilt = atlas.layout.uniform_buffer(device, atlas.layout.uniform());
                let group = output(&[view(&atlas.color.view), quilt.as_entire_binding()]);
                vec![(group, camera.views)]
            }
            (Some(npass), _) if self.method == Method::Layered => {
                vec![(output(&[view(&npass.layers()?.array_view)]), camera.views)]
            }
            (Some(npass), _) => npass
                .layers()?
                .layer_views
                .iter()
                .map(|layer| (output(&[view(layer)]), 1))
                .collect(),
            (None, None) => vec![(output(&[view(&target.view)]), 1)],
        };
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("volume raycast"),
                timestamp_writes: None,
            });
            pass.set_pipeline(self.pipelines.get(&key)?);
            pass.set_bind_group(0, &self.resources.frame.bind_group, &[]);
            for (i, (output_group, views)) in outputs.iter().enumerate() {
                let offset = self.resources.params.offset(i);
                pass.set_bind_group(1, &volume_group, &[offset]);
                pass.set_bind_group(2, output_group, &[]);
                let [w, h] = frame.size;
                pass.dispatch_workgroups(w.div_ceil(8), h.div_ceil(8), *views);
            }
        }
        if let Some(npass) = &self.npass {
            npass.composite(device, encoder, &self.resources.frame, target)?;
        }
        if let Some(compositor) = &self.compositor {
            let atlas = atlas.made("VolumeRaycaster atlas")?;
            compositor.encode(
                device,
                encoder,
                &self.resources.frame,
                atlas,
                target,
                TileSampling::Bilinear,
            );
        }
        if self.method != Method::SingleView {
            self.crop.encode(device, encoder, full, target);
        }
        Ok(())
    }

    fn atlas(&self) -> Option<&Atlas> {
        self.prepared.as_ref()?.made.as_ref()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gpu::{GpuContext, GpuOptions};
    use crate::volume::generate;
    use crate::volume::TransferFunction;
    use crate::volume::VolumeSettings;
    use glam::Mat4;

    /// The ray caster really skips what the distances call empty: with cell ranges falsified
    /// to "air only", every cell is skipped and the head's image changes. (That the true
    /// distances change no pixel is tests/volumes/volume.rs.)
    #[test]
    fn falsified_cell_ranges_skip_everything() {
        let ctx = GpuContext::new(&GpuOptions::default()).expect("a GPU adapter (CI: lavapipe)");
        let head = generate::ct_head(24).unwrap();
        let tf = TransferFunction::preset("ct-skin").unwrap();
        let mut scene =
            VolumeScene::new(&ctx.device, &ctx.queue, &head, tf, Mat4::IDENTITY).unwrap();
        let display = crate::display::Display::parse("hubner8").unwrap();
        let camera =
            crate::camera::MultiViewCamera::framing(head.bounds(), 8, None, 0.6, 1.0).unwrap();
        let frame = Frame::new(camera, display, [48, 48]).unwrap();
        let target = SpatialTarget::new(&ctx.device, frame.size).unwrap();
        let render = |scene: &VolumeScene| {
            let mut renderer =
                VolumeRaycaster::new(&ctx.device, Method::SinglePass, VolumeSettings::default())
                    .unwrap();
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
        scene.cells.falsify_for_tests();
        // A new volume for the distance cache.
        scene.id = u64::MAX;
        // Every cell now claims to be transparent: rays jump over the head.
        let falsified = render(&scene);
        let diff = crate::image_io::compare(&falsified, &true_image).unwrap();
        assert!(diff.frac_off_2 > 0.05, "{diff:?}");
    }
}
