//! One texture holding every view as a tile of a Looking Glass quilt (`quilt.rs`): the tiled
//! method's render target (with its one depth buffer), a quilt read from a file, and the
//! compositing from either into the spatial image (`wgsl/render/composite_atlas.wgsl`).

use super::quilt::QuiltLayout;
use super::view_layers::DEPTH_FORMAT;
use crate::error::{Error, Result};
use crate::frame::FrameBinding;
use crate::gpu::pipeline::{
    bind_group_layout, draw_fullscreen, fullscreen_pipeline, uniform_entry,
};
use crate::gpu::texture::{texture_2d, texture_2d_layout_entry, Texture2d};
use crate::image_io::RgbImage;
use crate::param::Param;
use crate::target::{SpatialTarget, SPATIAL_FORMAT};

/// The atlas texture (RGBA8, quilt layout) and, for rendering into it, one depth buffer.
pub struct Atlas {
    /// Where each view's tile is.
    pub layout: QuiltLayout,
    /// The colour atlas (render attachment, sampled, storage-writable, copy source).
    pub(crate) color: Texture2d,
    /// One depth buffer for every tile (render attachment, sampled), if rendered into.
    pub(crate) depth: Option<Texture2d>,
}

impl Atlas {
    /// An atlas of `layout`, with a depth buffer if `with_depth`, after checking its size
    /// against the device limits.
    pub fn new(device: &wgpu::Device, layout: QuiltLayout, with_depth: bool) -> Result<Self> {
        let size = layout.size();
        let limit = device.limits().max_texture_dimension_2d;
        if size[0] > limit || size[1] > limit || size.contains(&0) {
            return Err(Error::LimitExceeded {
                what: format!(
                    "quilt atlas side ({}x{} tiles of {}x{})",
                    layout.cols, layout.rows, layout.tile[0], layout.tile[1]
                ),
                value: size[0].max(size[1]).into(),
                limit: limit.into(),
                param: None,
                advice: None,
            });
        }
        let usage = wgpu::TextureUsages::RENDER_ATTACHMENT
            | wgpu::TextureUsages::TEXTURE_BINDING
            | wgpu::TextureUsages::STORAGE_BINDING
            | wgpu::TextureUsages::COPY_SRC
            | wgpu::TextureUsages::COPY_DST;
        let scope = device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
        let color = texture_2d(device, "quilt atlas", size, SPATIAL_FORMAT, usage)?;
        let depth = with_depth
            .then(|| {
                let usage =
                    wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING;
                texture_2d(device, "quilt atlas depth", size, DEPTH_FORMAT, usage)
            })
            .transpose()?;
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(Error::Gpu {
                operation: format!("allocating a {}x{} quilt atlas", size[0], size[1]),
                message: e.to_string(),
            });
        }
        Ok(Self {
            layout,
            color,
            depth,
        })
    }

    /// An atlas holding `image`, a quilt of `layout` (its size must be the layout's).
    pub fn from_image(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        image: &RgbImage,
        layout: QuiltLayout,
    ) -> Result<Self> {
        if [image.width, image.height] != layout.size() {
            return Err(Error::invalid(
                Param::Quilt,
                format!(
                    "image is {}x{}, a {}x{} grid of {}x{} tiles is {}x{}",
                    image.width,
                    image.height,
                    layout.cols,
                    layout.rows,
                    layout.tile[0],
                    layout.tile[1],
                    layout.size()[0],
                    layout.size()[1]
                ),
            ));
        }
        let atlas = Self::new(device, layout, false)?;
        let rgba: Vec<u8> = image
            .data
            .chunks_exact(3)
            .flat_map(|p| [p[0], p[1], p[2], 255])
            .collect();
        queue.write_texture(
            atlas.color.texture.as_image_copy(),
            &rgba,
            wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(image.width * 4),
                rows_per_image: None,
            },
            atlas.color.texture.size(),
        );
        Ok(atlas)
    }

    /// The colour texture (RGBA8 with the spatial image's encoding).
    pub fn texture(&self) -> &wgpu::Texture {
        &self.color.texture
    }

    /// Whether this atlas is `layout` (and has depth if `with_depth`).
    pub fn fits(&self, layout: &QuiltLayout, with_depth: bool) -> bool {
        self.layout == *layout && self.depth.is_some() == with_depth
    }

    /// The quilt as an image (rows top-down, view 0 bottom-left).
    pub fn read(&self, device: &wgpu::Device, queue: &wgpu::Queue) -> Result<RgbImage> {
        let rgba = crate::readback::read_texture_rgba8(device, queue, &self.color.texture, 0)?;
        Ok(RgbImage::from_rgba(self.layout.size(), &rgba))
    }

    /// The depth buffer as f32 texels (rows top-down), if there is one.
    pub fn read_depth(&self, device: &wgpu::Device, queue: &wgpu::Queue) -> Result<Vec<f32>> {
        let depth = self.depth.as_ref().ok_or_else(|| {
            Error::invalid(
                Param::QuiltAtlas,
                "has no depth buffer (only tiled renders do)",
            )
        })?;
        super::depth_readback::read_depth(device, queue, &depth.texture)
    }

    /// GPU bytes (colour and depth).
    pub fn bytes(&self) -> u64 {
        let [w, h] = self.layout.size();
        let per_texel = if self.depth.is_some() { 8 } else { 4 };
        w as u64 * h as u64 * per_texel
    }
}

/// How tiles of another size than the spatial image are sampled when compositing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TileSampling {
    /// The texel whose centre is nearest (quilts from files: what Looking Glass software does).
    Nearest,
    /// Bilinear within the tile (the view images of `Frame::view_scale`).
    Bilinear,
}

/// Compositing from an atlas into the spatial image.
pub struct AtlasCompositor {
    pipeline: wgpu::RenderPipeline,
    layout: wgpu::BindGroupLayout,
}

impl AtlasCompositor {
    /// Build the pipeline; `frame_layout` is the shared group-0 layout.
    pub fn new(device: &wgpu::Device, frame_layout: &wgpu::BindGroupLayout) -> Result<Self> {
        let layout = bind_group_layout(
            device,
            "composite atlas",
            &[
                texture_2d_layout_entry(0, wgpu::ShaderStages::FRAGMENT),
                uniform_entry(1, wgpu::ShaderStages::FRAGMENT),
            ],
        );
        let module = crate::shader::module(device, "render/composite_atlas.wgsl")?;
        let pipeline = fullscreen_pipeline(
            device,
            "composite atlas",
            &module,
            &[Some(frame_layout), Some(&layout)],
            SPATIAL_FORMAT,
        );
        Ok(Self { pipeline, layout })
    }

    /// Record the compositing of `atlas` into `target` with `frame`'s mask, tiles of another
    /// size than the target sampled as `sampling` says.
    pub fn encode(
        &self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        frame: &FrameBinding,
        atlas: &Atlas,
        target: &SpatialTarget,
        sampling: TileSampling,
    ) {
        let uniform = atlas
            .layout
            .uniform_for_panel(target.size(), sampling == TileSampling::Bilinear);
        let quilt = atlas.layout.uniform_buffer(device, uniform);
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("composite atlas"),
            layout: &self.layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&atlas.color.view),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: quilt.as_entire_binding(),
                },
            ],
        });
        draw_fullscreen(
            encoder,
            "composite atlas",
            &self.pipeline,
            &[&frame.bind_group, &group],
            &target.view,
        );
    }
}

/// A quilt (an [`Atlas`], e.g. read from a file with [`Atlas::from_image`]) interleaved for a
/// display: the frame's mask picks each subpixel's view tile.
pub struct QuiltInterleaver {
    compositor: AtlasCompositor,
    frame: FrameBinding,
}

impl QuiltInterleaver {
    /// Build the compositing pipeline.
    pub fn new(device: &wgpu::Device) -> Result<Self> {
        let frame_layout = crate::frame::frame_bind_group_layout(device);
        Ok(Self {
            compositor: AtlasCompositor::new(device, &frame_layout)?,
            frame: FrameBinding::new(device, &frame_layout),
        })
    }

    /// Record the interleaving of `atlas` for `frame`'s display into `target`. Fails when the
    /// quilt holds fewer views than the display shows or the target is not the frame's size.
    pub fn encode(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        atlas: &Atlas,
        frame: &crate::frame::Frame,
        target: &SpatialTarget,
    ) -> Result<()> {
        super::check_target(frame, target)?;
        if atlas.layout.views < frame.camera.views {
            return Err(Error::invalid(
                Param::Quilt,
                format!(
                    "holds {} views, the display shows {}",
                    atlas.layout.views, frame.camera.views
                ),
            ));
        }
        self.frame.write(device, frame);
        self.compositor.encode(
            device,
            encoder,
            &self.frame,
            atlas,
            target,
            TileSampling::Nearest,
        );
        Ok(())
    }

    /// Encode, submit and wait.
    pub fn render(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        atlas: &Atlas,
        frame: &crate::frame::Frame,
        target: &SpatialTarget,
    ) -> Result<()> {
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("interleave quilt"),
        });
        self.encode(device, &mut encoder, atlas, frame, target)?;
        queue.submit([encoder.finish()]);
        crate::readback::wait_idle(device)
    }
}
