//! [`SceneWarp`]: reference views through the scene's own renderer, the nearness range of
//! each of their rows (`wgsl/warp/row_bounds.wgsl`: it bounds the search), then one
//! full-screen warp pass (`wgsl/warp/references.wgsl`) straight into the spatial image, or into N
//! view images first ([`WarpPath::PerView`], Beck's way).

use super::references::{reference_frame, ReferenceImages, ReferenceRenderer};
use super::uniform::WarpUniform;
use super::{WarpOptions, WarpPath};
use crate::error::{Error, Result};
use crate::frame::{Frame, FrameBinding};
use crate::gpu::gpu_buffer::GpuBuffer;
use crate::gpu::pass_params::constants_buffer;
use crate::gpu::pipeline::{
    bind_group_layout, compilation, draw_fullscreen, fullscreen_pipeline, pipeline_layout,
    storage_entry, uniform_entry,
};
use crate::param::Param;
use crate::render::npass::NPassHarness;
use crate::render::{begin_prepare, check_target, prepared_state, PreparedState, Renderer};
use crate::target::{SpatialTarget, SPATIAL_FORMAT};

/// `options` checked for rendered references: one view everywhere is the RGB-D warp's.
fn check_options(options: &WarpOptions) -> Result<()> {
    options.check()?;
    if let Some(view) = options.view {
        return Err(Error::invalid(
            Param::View,
            format!(
                "{view}: one view everywhere is an RGB-D warp's option; a scene's views come \
                 from its references (the per-view path renders every view's image)"
            ),
        ));
    }
    Ok(())
}

/// What a [`SceneWarp`] was prepared for.
#[derive(Clone, Debug, PartialEq)]
struct PreparedFor {
    size: [u32; 2],
    views: u32,
    references: u32,
}

/// What `prepare` made for a frame: the reference images of its size and R.
struct Prepared {
    key: PreparedFor,
    images: ReferenceImages,
}

impl PreparedState for Prepared {
    type Key = PreparedFor;

    fn key(&self) -> &PreparedFor {
        &self.key
    }
}

/// [`crate::render::Method::Warp`] for scenes of type `S`: R reference views rendered by a
/// [`ReferenceRenderer`] of `S`, then warped into every view.
pub struct SceneWarp<S: ?Sized> {
    options: WarpOptions,
    references: Box<dyn ReferenceRenderer<S>>,
    /// Per reference and row, the nearness range of its surfaces (2 × f32).
    row_bounds: GpuBuffer,
    bounds_layout: wgpu::BindGroupLayout,
    bounds_pipeline: wgpu::ComputePipeline,
    layout: wgpu::BindGroupLayout,
    pipeline: wgpu::RenderPipeline,
    frame: FrameBinding,
    npass: NPassHarness,
    prepared: Option<Prepared>,
    /// The parallel camera model's crop, recorded last.
    crop: crate::render::camera_crop::CameraCrop,
    /// One texel the nearness is copied into before the row-bounds pass reads it (see
    /// `settle_references`).
    settle: wgpu::Texture,
}

impl<S: ?Sized> SceneWarp<S> {
    /// Warp the references `references` renders, with `options`.
    pub fn new(
        device: &wgpu::Device,
        references: Box<dyn ReferenceRenderer<S>>,
        options: WarpOptions,
    ) -> Result<Self> {
        check_options(&options)?;
        let frame_layout = crate::frame::frame_bind_group_layout(device);
        let array = |binding, sample_type| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::FRAGMENT,
            ty: wgpu::BindingType::Texture {
                sample_type,
                view_dimension: wgpu::TextureViewDimension::D2Array,
                multisampled: false,
            },
            count: None,
        };
        let layout = bind_group_layout(
            device,
            "reference warp",
            &[
                array(0, wgpu::TextureSampleType::Float { filterable: false }),
                array(1, wgpu::TextureSampleType::Uint),
                uniform_entry(2, wgpu::ShaderStages::FRAGMENT),
                storage_entry(3, true, wgpu::ShaderStages::FRAGMENT),
            ],
        );
        let bounds_layout = bind_group_layout(
            device,
            "reference row bounds",
            &[
                wgpu::BindGroupLayoutEntry {
                    visibility: wgpu::ShaderStages::COMPUTE,
                    ..array(0, wgpu::TextureSampleType::Uint)
                },
                storage_entry(1, false, wgpu::ShaderStages::COMPUTE),
            ],
        );
        let bounds_module = crate::shader::module(device, "warp/row_bounds.wgsl")?;
        let bounds_pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some("reference row bounds"),
            layout: Some(&pipeline_layout(
                device,
                "reference row bounds",
                &[Some(&bounds_layout)],
            )),
            module: &bounds_module,
            entry_point: Some("cs_main"),
            compilation_options: compilation(&[]),
            cache: None,
        });
        let module = crate::shader::module(device, "warp/references.wgsl")?;
        let pipeline = fullscreen_pipeline(
            device,
            "reference warp",
            &module,
            &[Some(&frame_layout), Some(&layout)],
            SPATIAL_FORMAT,
        );
        Ok(Self {
            options,
            references,
            row_bounds: GpuBuffer::new(device, "reference row bounds", wgpu::BufferUsages::STORAGE),
            bounds_layout,
            bounds_pipeline,
            layout,
            pipeline,
            frame: FrameBinding::new(device, &frame_layout),
            npass: NPassHarness::new(device, &frame_layout)?,
            settle: device.create_texture(&wgpu::TextureDescriptor {
                label: Some("reference settle texel"),
                size: wgpu::Extent3d {
                    width: 1,
                    height: 1,
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: crate::warp::references::REFERENCE_NEARNESS_FORMAT,
                usage: wgpu::TextureUsages::COPY_DST,
                view_formats: &[],
            }),
            prepared: None,
            crop: crate::render::camera_crop::CameraCrop::new(device)?,
        })
    }

    /// The options frames are warped with.
    pub fn options(&self) -> WarpOptions {
        self.options
    }

    /// Change the options (e.g. the hole mask); takes effect at the next `prepare`.
    pub fn set_options(&mut self, options: WarpOptions) -> Result<()> {
        check_options(&options)?;
        self.options = options;
        self.prepared = None;
        Ok(())
    }

    /// The reference views of the last frame (layer j = reference j), if any.
    pub fn reference_images(&self) -> Option<&ReferenceImages> {
        self.prepared.as_ref().map(|p| &p.images)
    }

    /// One line on what the warp does, for reports.
    fn line(&self) -> String {
        format!(
            "{} references ({}), {:?} path",
            self.options.references,
            self.references.depth_meaning(),
            self.options.path
        )
    }

    fn needs(&self, frame: &Frame) -> PreparedFor {
        PreparedFor {
            size: frame.size,
            views: frame.camera.views,
            references: self.options.references,
        }
    }

    /// The references' textures and the constants of `view` (a buffer of the frame's own).
    fn bind_group(
        &self,
        device: &wgpu::Device,
        images: &ReferenceImages,
        frame: &Frame,
        view: Option<u32>,
    ) -> wgpu::BindGroup {
        let uniform = WarpUniform::for_references(&self.options, frame, view);
        let constants = constants_buffer(
            device,
            "reference warp constants",
            wgpu::BufferUsages::UNIFORM,
            bytemuck::bytes_of(&uniform),
        );
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("reference warp"),
            layout: &self.layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&images.color.array_view),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::TextureView(&images.nearness.array_view),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: constants.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 3,
                    resource: self.row_bounds.binding(),
                },
            ],
        })
    }

    /// Copy one texel of the nearness just rendered. Mesa 22.3's llvmpipe (GL) can start a
    /// compute dispatch that reads a texture while the rasteriser threads are still writing it
    /// from the render pass before: under load the row-bounds pass then read stale nearness
    /// (cli/tests/commands/outputs.rs saw 1.5 % of subpixels off, about one run in eight). A copy waits for
    /// the writes to finish; elsewhere it is one texel.
    fn settle_references(&self, encoder: &mut wgpu::CommandEncoder, images: &ReferenceImages) {
        encoder.copy_texture_to_texture(
            images.nearness.texture.as_image_copy(),
            self.settle.as_image_copy(),
            wgpu::Extent3d {
                width: 1,
                height: 1,
                depth_or_array_layers: 1,
            },
        );
    }

    /// Record the row-bounds pass over the references just rendered.
    fn encode_row_bounds(
        &self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        images: &ReferenceImages,
    ) {
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("reference row bounds"),
            layout: &self.bounds_layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&images.nearness.array_view),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: self.row_bounds.binding(),
                },
            ],
        });
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("reference row bounds"),
            timestamp_writes: None,
        });
        pass.set_pipeline(&self.bounds_pipeline);
        pass.set_bind_group(0, &group, &[]);
        let rows = images.size()[1];
        pass.dispatch_workgroups(rows.div_ceil(ROW_BOUNDS_WORKGROUP), images.references(), 1);
    }
}

/// Keep in sync with `@workgroup_size` in `wgsl/warp/row_bounds.wgsl`.
const ROW_BOUNDS_WORKGROUP: u32 = 64;

impl<S: ?Sized> Renderer<S> for SceneWarp<S> {
    fn describe(&self) -> Option<String> {
        Some(self.line())
    }

    fn prepare(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        scene: &S,
        frame: &Frame,
    ) -> Result<()> {
        // The images of the last frame, reused where they fit this one.
        let last = self.prepared.take().map(|p| p.images);
        begin_prepare(device, frame, &mut self.prepared)?;
        frame.check_full_views("warp")?;
        if frame.camera.model == crate::camera::CameraModel::ToeIn {
            return Err(Error::invalid(
                Param::Camera,
                "toe-in: the warp shifts reference rows horizontally, which turned cameras do \
                 not produce (use skewed or parallel cameras, or another method)",
            ));
        }
        let references = reference_frame(frame, self.options.references)?;
        self.references
            .prepare_references(device, queue, scene, &references)?;
        let fits = |i: &ReferenceImages| {
            i.size() == frame.size && i.references() == self.options.references
        };
        let images = match last {
            Some(images) if fits(&images) => images,
            last => {
                drop(last); // free before allocating the replacement
                ReferenceImages::new(device, frame.size, self.options.references)?
            }
        };
        let rows = u64::from(frame.size[1]) * u64::from(self.options.references);
        self.row_bounds.ensure(
            device,
            || format!("{rows} reference rows' nearness range"),
            rows * 8,
        )?;
        if self.options.path == WarpPath::PerView {
            self.npass.prepare(device, frame)?;
        }
        self.prepared = Some(Prepared {
            key: self.needs(frame),
            images,
        });
        Ok(())
    }

    fn encode(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        scene: &S,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()> {
        check_target(frame, target)?;
        let images = &prepared_state("SceneWarp", &self.prepared, &self.needs(frame))?.images;
        let references = reference_frame(frame, self.options.references)?;
        self.references
            .encode_references(device, encoder, scene, &references, images)?;
        self.settle_references(encoder, images);
        self.encode_row_bounds(device, encoder, images);
        self.frame.write(device, frame);
        if self.options.path == WarpPath::Direct {
            let group = self.bind_group(device, images, frame, None);
            draw_fullscreen(
                encoder,
                "reference warp",
                &self.pipeline,
                &[&self.frame.bind_group, &group],
                &target.view,
            );
            self.crop.encode(device, encoder, frame, target);
            return Ok(());
        }
        for (v, layer) in self.npass.layers()?.layer_views.iter().enumerate() {
            let group = self.bind_group(device, images, frame, Some(v as u32));
            draw_fullscreen(
                encoder,
                "reference warp (one view)",
                &self.pipeline,
                &[&self.frame.bind_group, &group],
                layer,
            );
        }
        self.npass.composite(device, encoder, &self.frame, target)?;
        self.crop.encode(device, encoder, frame, target);
        Ok(())
    }
}
