//! The K group images of the splat geometry pass (one array layer per group, never per view)
//! and the depth buffer their z-tests share.

use std::ops::Range;

use super::pipelines::{PIXEL_FORMAT, SUBPIXEL_FORMAT};
use crate::error::Result;
use crate::gpu::pipeline::{begin_pass, cleared};
use crate::param::Param;
use crate::render::ViewLayers;

pub(super) struct GroupImages {
    pub layers: ViewLayers,
    pub key: GroupImagesKey,
}

/// What the group images are made for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct GroupImagesKey {
    /// Image size in texels (K·W × H for subpixel images).
    pub size: [u32; 2],
    pub groups: u32,
    /// Exact per-subpixel depth (RG32 texels) instead of one per pixel.
    pub subpixel: bool,
}

impl GroupImages {
    /// Bytes the images of `key` take, with their depth buffer.
    pub fn bytes(key: GroupImagesKey) -> u64 {
        let area = key.size[0] as u64 * key.size[1] as u64;
        Self::texture_bytes(key) + area * 4
    }

    /// Bytes of the group images' one array texture (without the depth buffer).
    pub fn texture_bytes(key: GroupImagesKey) -> u64 {
        let texel = if key.subpixel { 8 } else { 16 };
        let area = key.size[0] as u64 * key.size[1] as u64;
        let layers = crate::render::view_layers::array_layers_for(key.size, key.groups);
        area * texel * layers as u64
    }

    pub fn new(device: &wgpu::Device, key: GroupImagesKey) -> Result<Self> {
        let GroupImagesKey {
            size,
            groups,
            subpixel,
        } = key;
        let format = if subpixel {
            SUBPIXEL_FORMAT
        } else {
            PIXEL_FORMAT
        };
        let layers = ViewLayers::with_format(
            device,
            ("splat group images", Param::Groups),
            size,
            groups,
            format,
            wgpu::TextureUsages::empty(),
        )?;
        Ok(Self { layers, key })
    }
}

/// One geometry pass per splat group (`group_ranges`), each into its own layer of `images`
/// with their shared depth buffer, cleared first: `pipeline` with `bind_groups` (group index =
/// position; each with its dynamic offsets), every group's splats × 6 vertices, `instances`.
/// `area`: the top-left part of the images the draws' clip space maps onto (a tiled band
/// shorter than the images, which are sized for the tallest band); all of them when `None`.
#[allow(clippy::too_many_arguments)]
pub(super) fn draw_groups(
    encoder: &mut wgpu::CommandEncoder,
    label: &str,
    images: &ViewLayers,
    group_ranges: &[Range<u32>],
    pipeline: &wgpu::RenderPipeline,
    bind_groups: &[(&wgpu::BindGroup, &[u32])],
    instances: Range<u32>,
    area: Option<[u32; 2]>,
) {
    for (range, layer) in group_ranges.iter().zip(&images.layer_views) {
        let mut pass = begin_pass(
            encoder,
            label,
            cleared(layer, [0.0; 4]),
            Some(&images.depth_view),
        );
        if let Some([w, h]) = area {
            pass.set_viewport(0.0, 0.0, w as f32, h as f32, 0.0, 1.0);
        }
        pass.set_pipeline(pipeline);
        for (i, (group, offsets)) in bind_groups.iter().enumerate() {
            pass.set_bind_group(i as u32, *group, offsets);
        }
        pass.draw(range.start * 6..range.end * 6, instances.clone());
    }
}
