//! The K group images of the splat geometry pass (one array layer per group, never per view)
//! and the depth buffer their z-tests share.

use super::pipelines::{PIXEL_FORMAT, SUBPIXEL_FORMAT};
use crate::error::Result;
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
            "splat group images",
            size,
            groups,
            format,
            wgpu::TextureUsages::empty(),
        )?;
        Ok(Self { layers, key })
    }
}
