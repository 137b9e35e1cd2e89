//! The spatial image into a texture the caller made (a window surface, a viewer's own
//! texture): one full-screen pass, pixel for pixel (`wgsl/render/output.wgsl`).
//!
//! Renderers write a [`SpatialTarget`] (RGBA8, storage-capable: the compute paths need that);
//! surfaces rarely have `STORAGE_BINDING` and are often BGRA8 or sRGB. The interleaved subpixel
//! values must reach the panel unchanged, so the copy samples nothing (no filtering) and, for
//! sRGB formats, decodes before the hardware re-encodes.

use crate::error::{Error, Result};
use crate::gpu::pipeline::{draw_fullscreen, fullscreen_pipeline_with};
use crate::gpu::texture::texture_2d_layout_entry;
use crate::param::Param;
use crate::target::SpatialTarget;

/// Formats an [`OutputBlit`] writes.
pub const OUTPUT_FORMATS: [wgpu::TextureFormat; 4] = [
    wgpu::TextureFormat::Rgba8Unorm,
    wgpu::TextureFormat::Rgba8UnormSrgb,
    wgpu::TextureFormat::Bgra8Unorm,
    wgpu::TextureFormat::Bgra8UnormSrgb,
];

/// Copies a spatial image into a caller's texture of one format, byte for byte per channel.
pub struct OutputBlit {
    format: wgpu::TextureFormat,
    layout: wgpu::BindGroupLayout,
    pipeline: wgpu::RenderPipeline,
}

impl OutputBlit {
    /// The pass for targets of `format`: one of [`OUTPUT_FORMATS`] (a clear error otherwise).
    pub fn new(device: &wgpu::Device, format: wgpu::TextureFormat) -> Result<Self> {
        if !OUTPUT_FORMATS.contains(&format) {
            return Err(Error::invalid(
                Param::TargetFormat,
                format!(
                    "{format:?}: the spatial image can go to {OUTPUT_FORMATS:?} (8-bit per \
                     channel, so that every subpixel value reaches the panel unchanged)"
                ),
            ));
        }
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("output source"),
            entries: &[texture_2d_layout_entry(0, wgpu::ShaderStages::FRAGMENT)],
        });
        let module = crate::shader::module(device, "render/output.wgsl")?;
        let srgb = f64::from(u8::from(format.is_srgb()));
        let pipeline = crate::gpu::checked(device, "building the output pass", || {
            fullscreen_pipeline_with(
                device,
                "output",
                &module,
                &[Some(&layout)],
                format,
                &[("SRGB_TARGET", srgb)],
            )
        })?;
        Ok(Self {
            format,
            layout,
            pipeline,
        })
    }

    /// The format this pass writes.
    pub fn format(&self) -> wgpu::TextureFormat {
        self.format
    }

    /// Record the copy of `source` into `target`, a 2D texture of this pass's format, the
    /// source's size and with `RENDER_ATTACHMENT` usage (a surface texture, say); the source
    /// needs `TEXTURE_BINDING` (every `SpatialTarget::new` has it). Each is checked, with a
    /// clear error. The pass writes the texture's own format (views of another format would
    /// re-encode the values).
    pub fn encode(
        &self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        source: &SpatialTarget,
        target: &wgpu::Texture,
    ) -> Result<()> {
        let problem = if target.format() != self.format {
            Some(format!(
                "format {:?}, but this output pass writes {:?} (make one per format)",
                target.format(),
                self.format
            ))
        } else if !target
            .usage()
            .contains(wgpu::TextureUsages::RENDER_ATTACHMENT)
        {
            Some(format!(
                "usage {:?} lacks RENDER_ATTACHMENT",
                target.usage()
            ))
        } else if [target.width(), target.height()] != source.size() {
            Some(format!(
                "size {}x{} differs from the spatial image's {}x{}",
                target.width(),
                target.height(),
                source.size()[0],
                source.size()[1]
            ))
        } else if target.dimension() != wgpu::TextureDimension::D2 || target.sample_count() != 1 {
            Some("must be a single-sample 2D texture".to_string())
        } else {
            None
        };
        if let Some(problem) = problem {
            return Err(Error::invalid(Param::TargetTexture, problem));
        }
        let usage = source.texture.usage();
        if !usage.contains(wgpu::TextureUsages::TEXTURE_BINDING) {
            return Err(Error::invalid(
                Param::SpatialTarget,
                format!("usage {usage:?} lacks TEXTURE_BINDING, which the output pass samples"),
            ));
        }
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("output source"),
            layout: &self.layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::TextureView(&source.view),
            }],
        });
        let view = target.create_view(&wgpu::TextureViewDescriptor {
            label: Some("output target"),
            base_mip_level: 0,
            mip_level_count: Some(1),
            base_array_layer: 0,
            array_layer_count: Some(1),
            dimension: Some(wgpu::TextureViewDimension::D2),
            ..Default::default()
        });
        draw_fullscreen(encoder, "output", &self.pipeline, &[&group], &view);
        Ok(())
    }
}
