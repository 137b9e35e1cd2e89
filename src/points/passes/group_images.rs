//! The K group images of the splat geometry pass (one array layer per group, never per view)
//! and the depth buffer their z-tests share.

use super::pipelines::{PIXEL_FORMAT, SUBPIXEL_FORMAT};
use crate::error::Result;
use crate::render::ViewLayers;

pub(super) struct GroupImages {
    pub layers: ViewLayers,
    /// (image size in texels, groups, subpixel)
    pub key: ([u32; 2], u32, bool),
}

impl GroupImages {
    /// Bytes `groups` images of `size` texels take, with their depth buffer.
    pub fn bytes(size: [u32; 2], groups: u32, subpixel: bool) -> u64 {
        let texel = if subpixel { 8 } else { 16 };
        let area = size[0] as u64 * size[1] as u64;
        area * (texel * groups as u64 + 4)
    }

    /// `size` is the image size in texels (K·W × H for subpixel images).
    pub fn new(device: &wgpu::Device, size: [u32; 2], groups: u32, subpixel: bool) -> Result<Self> {
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
        Ok(Self {
            layers,
            key: (size, groups, subpixel),
        })
    }
}
