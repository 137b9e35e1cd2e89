//! The RGB-D warp: one full-screen pass from the reference image straight into the spatial
//! image (`wgsl/warp/rgbd.wgsl`): each subpixel warps its own view's sample, no per-view
//! images. Views differ by a horizontal shift proportional to (nearness − focus) and to the
//! view's position t ∈ [−1, 1] among the display's N.

use super::uniform::WarpUniform;
use super::{WarpOptions, WarpPath};
use crate::error::Result;
use crate::frame::{Frame, FrameBinding};
use crate::gpu::pass_params::constants_buffer;
use crate::gpu::pipeline::{
    bind_group_layout, draw_fullscreen, fullscreen_pipeline, uniform_entry,
};
use crate::gpu::texture::texture_2d_layout_entry;
use crate::param::Param;
use crate::render::npass::NPassHarness;
use crate::render::{begin_prepare, check_prepared, check_target, Renderer};
use crate::rgbd::RgbdScene;
use crate::target::{SpatialTarget, SPATIAL_FORMAT};

/// The predicted shift (reference pixels) of a sample at `nearness` in view `view` of `views`.
pub fn predicted_shift(
    options: &WarpOptions,
    width: u32,
    nearness: f32,
    view: u32,
    views: u32,
) -> f32 {
    let t = if views > 1 {
        2.0 * view as f32 / (views - 1) as f32 - 1.0
    } else {
        0.0
    };
    WarpUniform::rgbd_parallax(options, width) * t * (nearness - options.focus)
}

/// RGB-D image → spatial image (or one view of it), in one full-screen pass.
pub struct RgbdWarp {
    options: WarpOptions,
    layout: wgpu::BindGroupLayout,
    pipeline: wgpu::RenderPipeline,
    frame: FrameBinding,
    /// The per-view path's images and compositing.
    npass: NPassHarness,
    prepared: Option<PreparedFor>,
}

/// What an [`RgbdWarp`] was prepared for: everything a frame or scene can change that the
/// prepared state depends on (the per-view path's layers follow the frame's size, views and
/// view size; the checks follow the display and camera model).
#[derive(Clone, Debug, PartialEq)]
struct PreparedFor {
    image: [u32; 2],
    size: [u32; 2],
    views: u32,
    view_size: [u32; 2],
    display: crate::display::Display,
    camera: crate::camera::CameraModel,
    options: WarpOptions,
}

impl PreparedFor {
    fn of(scene: &RgbdScene, frame: &Frame, options: WarpOptions) -> Self {
        Self {
            image: scene.size,
            size: frame.size,
            views: frame.camera.views,
            view_size: frame.view_size(),
            display: frame.display.clone(),
            camera: frame.camera.model,
            options,
        }
    }
}

impl RgbdWarp {
    /// Build the pipeline (`options` are checked here and, as `set_options` may change them,
    /// again at every `prepare`).
    pub fn new(device: &wgpu::Device, options: WarpOptions) -> Result<Self> {
        options.check()?;
        let frame_layout = crate::frame::frame_bind_group_layout(device);
        let layout = bind_group_layout(
            device,
            "rgbd warp",
            &[
                texture_2d_layout_entry(0, wgpu::ShaderStages::FRAGMENT),
                texture_2d_layout_entry(1, wgpu::ShaderStages::FRAGMENT),
                uniform_entry(2, wgpu::ShaderStages::FRAGMENT),
            ],
        );
        let module = crate::shader::module(device, "warp/rgbd.wgsl")?;
        let pipeline = fullscreen_pipeline(
            device,
            "rgbd warp",
            &module,
            &[Some(&frame_layout), Some(&layout)],
            SPATIAL_FORMAT,
        );
        Ok(Self {
            options,
            layout,
            pipeline,
            frame: FrameBinding::new(device, &frame_layout),
            npass: NPassHarness::new(device, &frame_layout)?,
            prepared: None,
        })
    }

    /// The options frames are warped with.
    pub fn options(&self) -> WarpOptions {
        self.options
    }

    /// Change the options (e.g. the view of a per-view image); takes effect at the next
    /// `prepare`.
    pub fn set_options(&mut self, options: WarpOptions) {
        self.options = options;
        self.prepared = None;
    }
}

impl Renderer<RgbdScene> for RgbdWarp {
    fn prepare(
        &mut self,
        device: &wgpu::Device,
        _queue: &wgpu::Queue,
        scene: &RgbdScene,
        frame: &Frame,
    ) -> Result<()> {
        begin_prepare(device, frame, &mut self.prepared)?;
        frame.check_full_views("RGB-D warp")?;
        if frame.camera.model != crate::camera::CameraModel::Skewed {
            return Err(crate::error::Error::invalid(
                Param::Camera,
                format!(
                    "{}: an RGB-D image is warped into skewed views only",
                    frame.camera.model
                ),
            ));
        }
        self.options.check()?;
        self.options.check_view(frame.camera.views)?;
        if self.options.path == WarpPath::PerView {
            self.npass.prepare(device, frame)?;
        }
        self.prepared = Some(PreparedFor::of(scene, frame, self.options));
        Ok(())
    }

    fn encode(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        scene: &RgbdScene,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()> {
        check_target(frame, target)?;
        let wanted = PreparedFor::of(scene, frame, self.options);
        check_prepared("RgbdWarp", &self.prepared, &wanted)?;
        self.frame.write(device, frame);
        if self.options.path == WarpPath::Direct {
            let group = self.bind_group(device, scene, &self.options);
            draw_fullscreen(
                encoder,
                "rgbd warp",
                &self.pipeline,
                &[&self.frame.bind_group, &group],
                &target.view,
            );
            return Ok(());
        }
        for (v, layer) in self.npass.layers()?.layer_views.iter().enumerate() {
            let options = WarpOptions {
                view: Some(v as u32),
                ..self.options
            };
            let group = self.bind_group(device, scene, &options);
            draw_fullscreen(
                encoder,
                "rgbd warp (one view)",
                &self.pipeline,
                &[&self.frame.bind_group, &group],
                layer,
            );
        }
        self.npass.composite(device, encoder, &self.frame, target)?;
        Ok(())
    }
}

impl RgbdWarp {
    /// The textures of `scene` and the constants of `options` (a buffer of the frame's own).
    fn bind_group(
        &self,
        device: &wgpu::Device,
        scene: &RgbdScene,
        options: &WarpOptions,
    ) -> wgpu::BindGroup {
        let uniform = WarpUniform::for_rgbd(options, scene.size);
        let constants = constants_buffer(
            device,
            "rgbd warp constants",
            wgpu::BufferUsages::UNIFORM,
            bytemuck::bytes_of(&uniform),
        );
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("rgbd warp"),
            layout: &self.layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&scene.color),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::TextureView(&scene.nearness),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: constants.as_entire_binding(),
                },
            ],
        })
    }
}
