//! The RGB-D warp: one full-screen pass from the reference image straight into the spatial
//! image (`wgsl/rgbd/warp.wgsl`): each subpixel warps its own view's sample, no per-view
//! images. Views differ by a horizontal shift proportional to (nearness − focus) and to the
//! view's position t ∈ [−1, 1] among the display's N.

use bytemuck::{Pod, Zeroable};

use super::RgbdScene;
use crate::error::{Error, Result};
use crate::frame::{Frame, FrameBinding};
use crate::render::npass::NPassHarness;
use crate::render::pass_params::constants_buffer;
use crate::render::pipeline::{
    bind_group_layout, draw_fullscreen, fullscreen_pipeline, uniform_entry,
};
use crate::render::texture::texture_2d_layout_entry;
use crate::render::{begin_prepare, check_prepared, check_target, Renderer};
use crate::target::{SpatialTarget, SPATIAL_FORMAT};
pub use crate::warp::WarpPath;

/// Parallax of depthiness 1: a point at nearness 1 with the focus at 0 shifts by this share
/// of the image width in the outermost views (either way: 6 % between them).
pub const PARALLAX_PER_DEPTHINESS: f32 = 0.03;

/// Neighbouring samples warped further apart than this (reference pixels) straddle a
/// disocclusion: the hole between them is filled from the far one. Slopes that stretch the
/// surface less are interpolated.
pub const DEFAULT_HOLE_GAP: f32 = 2.0;

/// How the RGB-D image becomes views.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WarpOptions {
    /// Nearness that lands on the display plane (zero parallax), 0…1.
    pub focus: f32,
    /// Parallax scale: 1 shifts nearness 1 (focus 0) by 3 % of the width in the outermost
    /// views ([`PARALLAX_PER_DEPTHINESS`]); negative reverses depth.
    pub depthiness: f32,
    /// See [`DEFAULT_HOLE_GAP`].
    pub hole_gap: f32,
    /// Render this one view everywhere instead of the mask's (per-view images, quilts).
    pub view: Option<u32>,
    /// Write the hole mask instead of colour: 255 on every subpixel that was filled (a
    /// disocclusion, or the image's edge where a view has no source), 0 on those seen.
    pub hole_mask: bool,
    /// See [`WarpPath`].
    pub path: WarpPath,
}

impl Default for WarpOptions {
    fn default() -> Self {
        Self {
            focus: 0.5,
            depthiness: 1.0,
            hole_gap: DEFAULT_HOLE_GAP,
            view: None,
            hole_mask: false,
            path: WarpPath::Direct,
        }
    }
}

impl WarpOptions {
    fn validate(&self, views: u32) -> Result<()> {
        if !(0.0..=1.0).contains(&self.focus) {
            return Err(Error::invalid(
                "focus",
                format!("{}: a nearness in 0…1", self.focus),
            ));
        }
        if !self.depthiness.is_finite() || self.depthiness.abs() > 100.0 {
            return Err(Error::invalid(
                "depthiness",
                format!("{}: a finite scale within ±100", self.depthiness),
            ));
        }
        if !(self.hole_gap.is_finite() && self.hole_gap >= 1.0) {
            return Err(Error::invalid(
                "hole gap",
                format!("{}: at least 1 pixel", self.hole_gap),
            ));
        }
        if self.view.is_some() && self.path == WarpPath::PerView {
            return Err(Error::invalid(
                "view",
                "the per-view path warps every view; one view is the direct path's".to_string(),
            ));
        }
        if let Some(v) = self.view.filter(|&v| v >= views) {
            return Err(Error::invalid(
                "view",
                format!("{v}: the display has views 0…{}", views - 1),
            ));
        }
        Ok(())
    }
}

/// The warp's constants. Keep in sync with `struct Warp` in `wgsl/rgbd/warp.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct WarpUniform {
    /// Size of the reference image.
    pub reference: [u32; 2],
    /// Shift in reference pixels per unit of (nearness − focus) at view position t = +1.
    pub parallax: f32,
    /// Nearness with no shift.
    pub focus: f32,
    /// `u32::MAX`: each subpixel's view from the mask.
    pub fixed_view: u32,
    /// See [`DEFAULT_HOLE_GAP`].
    pub hole_gap: f32,
    /// 1: the hole mask instead of colour ([`WarpOptions::hole_mask`]).
    pub hole_mask: u32,
    #[doc(hidden)]
    pub _pad: u32,
}
crate::shader::gpu_layout!(
    WarpUniform,
    "Warp",
    [reference, parallax, focus, fixed_view, hole_gap, hole_mask]
);

impl WarpUniform {
    /// The constants of `options` for a reference of `size`. Views further right (higher t)
    /// see near points further left: the shift is −t · depthiness · 3 % · width per unit.
    pub fn new(options: &WarpOptions, size: [u32; 2]) -> Self {
        Self {
            reference: size,
            parallax: -options.depthiness * PARALLAX_PER_DEPTHINESS * size[0] as f32,
            focus: options.focus,
            fixed_view: options.view.unwrap_or(u32::MAX),
            hole_gap: options.hole_gap,
            hole_mask: u32::from(options.hole_mask),
            _pad: 0,
        }
    }
}

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
    WarpUniform::new(options, [width, 1]).parallax * t * (nearness - options.focus)
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
    /// Build the pipeline.
    pub fn new(device: &wgpu::Device, options: WarpOptions) -> Result<Self> {
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
        let module = crate::shader::module(device, "rgbd/warp.wgsl")?;
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
                "camera",
                format!(
                    "{}: an RGB-D image is warped into skewed views only",
                    frame.camera.model
                ),
            ));
        }
        self.options.validate(frame.camera.views)?;
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
        for (v, layer) in self.npass.layers().layer_views.iter().enumerate() {
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
        self.npass.composite(device, encoder, &self.frame, target);
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
        let uniform = WarpUniform::new(options, scene.size);
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
