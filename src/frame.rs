//! What one frame needs besides the scene: camera, display, lighting, image size, background.
//! Every renderer takes a [`Frame`] and binds its [`FrameUniform`] at group 0, binding 0.

use bytemuck::{Pod, Zeroable};
use glam::Vec3;

use crate::camera::{CameraUniform, MultiViewCamera};
use crate::display::{Display, MaskUniform};
use crate::error::{Error, Result};
use crate::param::Param;

/// Eye-space directional Blinn-Phong light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    /// Direction towards the light, eye space (normalised on use).
    pub direction: Vec3,
    /// Ambient intensity.
    pub ambient: f32,
    /// Diffuse intensity.
    pub diffuse: f32,
    /// Specular intensity.
    pub specular: f32,
    /// Specular exponent.
    pub shininess: f32,
}

impl Default for Light {
    fn default() -> Self {
        Self {
            direction: Vec3::new(-0.4, 0.5, 1.0),
            ambient: 0.15,
            diffuse: 0.75,
            specular: 0.3,
            shininess: 32.0,
        }
    }
}

/// GPU form of [`Light`]. Keep in sync with `struct Light` in `wgsl/shared/shading.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct LightUniform {
    direction: [f32; 4],
    ambient: [f32; 4],
    diffuse: [f32; 4],
    specular: [f32; 4],
}
const _: () = assert!(std::mem::size_of::<LightUniform>() == 64);
crate::shader::gpu_layout!(
    LightUniform,
    "Light",
    [direction, ambient, diffuse, specular]
);

impl From<&Light> for LightUniform {
    fn from(l: &Light) -> Self {
        let d = l.direction.try_normalize().unwrap_or(Vec3::Z);
        Self {
            direction: d.extend(0.0).to_array(),
            ambient: [l.ambient; 4],
            diffuse: [l.diffuse; 4],
            specular: [l.specular, l.specular, l.specular, l.shininess],
        }
    }
}

/// Per-frame constants. Keep in sync with `struct Frame` in `wgsl/shared/frame.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct FrameUniform {
    camera: CameraUniform,
    mask: MaskUniform,
    light: LightUniform,
    background: [f32; 4],
}
const _: () = assert!(std::mem::size_of::<FrameUniform>() == 352);
crate::shader::gpu_layout!(FrameUniform, "Frame", [camera, mask, light, background]);

impl FrameUniform {
    /// Replace the display mask (tools that need only the mask start from a zeroed uniform).
    pub fn set_mask(&mut self, mask: MaskUniform) {
        self.mask = mask;
    }
}

/// Camera + display + output settings of one rendered spatial image.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    /// The multi-view camera (its `views` must equal the display's).
    pub camera: MultiViewCamera,
    /// The display whose mask interleaves the views.
    pub display: Display,
    /// Lighting.
    pub light: Light,
    /// Image size in pixels.
    pub size: [u32; 2],
    /// Background colour (linear RGBA).
    pub background: [f32; 4],
    /// Per-view resolution (Yalçın & Çapın's view LOD): the methods that render view images
    /// (N-pass, tiled, layered, MRT) render them at this share of `size` in x and in y and
    /// up-sample them bilinearly when compositing; `[1, 1]` = full size (exact). Each in
    /// (0, 1]. The two may differ: the view images keep the camera's aspect whatever their
    /// own, so e.g. Looking Glass's square 857×857 quilt tiles of a 16:9 panel are
    /// `[857/3840, 857/2160]` ([`Frame::scale_views_to`]). The single pass and the single view
    /// have no view images and refuse anything but `[1, 1]`.
    pub view_scale: [f32; 2],
}

impl Frame {
    /// A frame with the default light and a black background.
    pub fn new(camera: MultiViewCamera, display: Display, size: [u32; 2]) -> Result<Self> {
        let frame = Self {
            camera,
            display,
            light: Light::default(),
            size,
            background: [0.0, 0.0, 0.0, 1.0],
            view_scale: [1.0; 2],
        };
        frame.validate()?;
        Ok(frame)
    }

    /// A frame for putting images made elsewhere on `display` (quilts, RGB-D pictures): only
    /// the display's mask, its N and the size matter, so the camera is a placeholder framing
    /// of the unit cube.
    pub fn for_display(display: Display, size: [u32; 2]) -> Result<Self> {
        let bounds =
            crate::camera::Bounds::of_points([Vec3::splat(-1.0), Vec3::ONE]).expect("two points");
        let aspect = size[0].max(1) as f32 / size[1].max(1) as f32;
        let camera =
            MultiViewCamera::framing(bounds, display.views(), None, 30f32.to_radians(), aspect)?;
        Self::new(camera, display, size)
    }

    /// Check the camera, the size and that camera and display agree on N.
    pub fn validate(&self) -> Result<()> {
        self.camera.validate()?;
        if self.size[0] == 0 || self.size[1] == 0 {
            return Err(Error::invalid(
                Param::Size,
                format!(
                    "{}x{}: width and height must be at least 1",
                    self.size[0], self.size[1]
                ),
            ));
        }
        if !self.view_scale.iter().all(|s| *s > 0.0 && *s <= 1.0) {
            return Err(Error::invalid(
                Param::ViewScale,
                format!("{}: each must be in (0, 1]", self.view_scale_text()),
            ));
        }
        if self.camera.views != self.display.views() {
            return Err(Error::invalid(
                Param::Views,
                format!(
                    "camera has {} views but the display has {}",
                    self.camera.views,
                    self.display.views()
                ),
            ));
        }
        Ok(())
    }

    /// Size of the view images at [`Frame::view_scale`]: each side rounded up (a thousandth
    /// of a pixel forgiven, so that `scale_views_to` gives back its size), at least 1.
    pub fn view_size(&self) -> [u32; 2] {
        let side = |size: u32, scale: f32| {
            ((size as f64 * scale as f64 - 1e-3).ceil() as u32).clamp(1, size)
        };
        [
            side(self.size[0], self.view_scale[0]),
            side(self.size[1], self.view_scale[1]),
        ]
    }

    /// Set [`Frame::view_scale`] so that the view images are `size` pixels (each side at most
    /// the frame's: view images are never larger than the spatial image).
    pub fn scale_views_to(&mut self, size: [u32; 2]) -> Result<()> {
        if size.contains(&0) || size[0] > self.size[0] || size[1] > self.size[1] {
            return Err(Error::invalid(
                Param::ViewImageSize,
                format!(
                    "{}x{}: each side must be in 1 ..= the frame's {}x{}",
                    size[0], size[1], self.size[0], self.size[1]
                ),
            ));
        }
        self.view_scale = [0, 1].map(|i| size[i] as f32 / self.size[i] as f32);
        debug_assert_eq!(self.view_size(), size);
        Ok(())
    }

    /// The frame the view images are rendered with: this one at [`Frame::view_size`] (the
    /// camera's aspect is unchanged, so each view sees what it sees at full size).
    pub fn for_view_images(&self) -> Frame {
        Frame {
            size: self.view_size(),
            view_scale: [1.0; 2],
            ..self.clone()
        }
    }

    /// The part of this frame's image at `origin` of `size` pixels, as a frame of its own: the
    /// same cameras looking through that part of the focal window (an off-centre window:
    /// [`MultiViewCamera::window_offset`]) and the display's mask moved by `origin`, so that
    /// rendering it gives exactly those pixels of the whole frame's image
    /// ([`crate::render::Banded`] renders frames too large for the adapter this way).
    pub fn band(&self, origin: [u32; 2], size: [u32; 2]) -> Frame {
        let [w, h] = self.size.map(|v| v as f32);
        let [bw, bh] = size.map(|v| v as f32);
        let window = self.camera.focal_window();
        let band = window * glam::Vec2::new(bw / w, bh / h);
        let centre = glam::Vec2::new(
            ((origin[0] as f32 + 0.5 * bw) / w - 0.5) * window.x,
            (0.5 - (origin[1] as f32 + 0.5 * bh) / h) * window.y,
        );
        let mut camera = self.camera.clone();
        camera.fov_y = 2.0 * (0.5 * band.y / camera.focal_distance).atan();
        camera.aspect = band.x / band.y;
        camera.window_offset += centre;
        let mut display = self.display.clone();
        // A band lies within the frame (its origin below the frame's size, far below 2³¹), so
        // `as i32` keeps it; wrapping, as the mask's own sums do (modulo 2³²).
        display.origin = [
            display.origin[0].wrapping_add(origin[0] as i32),
            display.origin[1].wrapping_add(origin[1] as i32),
        ];
        Frame {
            camera,
            display,
            size,
            ..self.clone()
        }
    }

    /// Fail unless [`Frame::view_scale`] is 1: for `method`, which renders no view images.
    pub fn check_full_views(&self, method: &str) -> Result<()> {
        if self.view_scale == [1.0; 2] {
            return Ok(());
        }
        Err(Error::invalid(
            Param::ViewScale,
            format!(
                "{}: the {method} method renders no view images to scale (only n-pass, tiled, \
                 layered and mrt do)",
                self.view_scale_text()
            ),
        ))
    }

    /// The view scale as the user gave it: one number when x and y agree, else `x,y`.
    pub fn view_scale_text(&self) -> String {
        match self.view_scale {
            [x, y] if x == y => format!("{x}"),
            [x, y] => format!("{x},{y}"),
        }
    }

    /// The uniform bound at group 0.
    pub fn uniform(&self) -> FrameUniform {
        FrameUniform {
            camera: self.camera.uniform(self.size),
            mask: self.display.mask().uniform(),
            light: (&self.light).into(),
            background: self.background,
        }
    }
}

/// The group-0 layout every pipeline shares: the frame uniform at binding 0.
pub fn frame_bind_group_layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("frame"),
        entries: &[wgpu::BindGroupLayoutEntry {
            binding: 0,
            visibility: wgpu::ShaderStages::VERTEX_FRAGMENT | wgpu::ShaderStages::COMPUTE,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Uniform,
                has_dynamic_offset: false,
                min_binding_size: wgpu::BufferSize::new(std::mem::size_of::<FrameUniform>() as u64),
            },
            count: None,
        }],
    })
}

/// A uniform buffer holding a [`FrameUniform`] and its group-0 bind group. Each
/// [`FrameBinding::write`] makes a new buffer with the frame's constants instead of a queue
/// write, so frames encoded one after the other before one submit each keep their own
/// (`src/gpu/pass_params.rs`).
pub struct FrameBinding {
    layout: wgpu::BindGroupLayout,
    /// Bind group for group 0.
    pub bind_group: wgpu::BindGroup,
}

impl FrameBinding {
    /// Allocate for `layout` (from [`frame_bind_group_layout`]), zeroed until the first write.
    pub fn new(device: &wgpu::Device, layout: &wgpu::BindGroupLayout) -> Self {
        let bind_group = Self::bind(device, layout, &FrameUniform::zeroed());
        Self {
            layout: layout.clone(),
            bind_group,
        }
    }

    fn bind(
        device: &wgpu::Device,
        layout: &wgpu::BindGroupLayout,
        uniform: &FrameUniform,
    ) -> wgpu::BindGroup {
        let buffer = crate::gpu::pass_params::constants_buffer(
            device,
            "frame uniform",
            wgpu::BufferUsages::UNIFORM,
            bytemuck::bytes_of(uniform),
        );
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("frame"),
            layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: buffer.as_entire_binding(),
            }],
        })
    }

    /// `frame`'s constants, for the passes recorded next.
    pub fn write(&mut self, device: &wgpu::Device, frame: &Frame) {
        self.write_uniform(device, &frame.uniform());
    }

    /// A prepared uniform, for the passes recorded next.
    pub fn write_uniform(&mut self, device: &wgpu::Device, uniform: &FrameUniform) {
        self.bind_group = Self::bind(device, &self.layout, uniform);
    }
}
