//! A mesh's textures on the GPU: every texel in one storage buffer (RGBA8, sRGB-encoded, one
//! `u32` each) and a table of where each texture starts and how it wraps and filters, bound
//! as group 3 (bindings 0 and 1) by every mesh stage that shades, and sampled by
//! `wgsl/mesh/shared/texture.wgsl`. Storage rather than a texture atlas: no packing, exact
//! wrapping at each texture's own edges, and the same loads on every backend.

use bytemuck::{Pod, Zeroable};
use wgpu::util::DeviceExt;

use super::{Filter, Texture, Wrap};
use crate::error::Result;
use crate::gpu::gpu_buffer::check_storage_bytes;
use crate::gpu::pipeline::{bind_group_layout, storage_entry};

/// The bind group every shading mesh stage reads its textures from.
pub(crate) const TEXTURE_GROUP: u32 = 3;

/// One texture's entry in the table. Keep in sync with `MeshTexture` in
/// `wgsl/mesh/shared/texture.wgsl` (checked by src/shader.rs's tests).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct GpuTexture {
    /// Index of the first texel (row-major, top row first).
    pub offset: u32,
    /// Width in texels.
    pub width: u32,
    /// Height in texels.
    pub height: u32,
    /// `WRAP_*` along u.
    pub wrap_u: u32,
    /// `WRAP_*` along v.
    pub wrap_v: u32,
    /// `FILTER_*` (`filter` is a WGSL reserved word).
    pub filtering: u32,
    /// Keeps the 8-word stride.
    pub _pad: [u32; 2],
}
crate::shader::gpu_layout!(
    GpuTexture,
    "MeshTexture",
    [offset, width, height, wrap_u, wrap_v, filtering]
);

fn wrap_code(wrap: Wrap) -> u32 {
    match wrap {
        Wrap::Repeat => 0,
        Wrap::Clamp => 1,
        Wrap::Mirror => 2,
    }
}

fn filter_code(filter: Filter) -> u32 {
    match filter {
        Filter::Nearest => 0,
        Filter::Linear => 1,
    }
}

/// The group-3 layout: texels, then the table (read-only storage, fragment stage).
pub(crate) fn texture_bind_group_layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
    let fs = wgpu::ShaderStages::FRAGMENT;
    bind_group_layout(
        device,
        "mesh textures",
        &[storage_entry(0, true, fs), storage_entry(1, true, fs)],
    )
}

/// The textures' buffers and their bind group.
pub struct TextureBuffers {
    /// Group [`TEXTURE_GROUP`] of the shading mesh stages.
    pub bind_group: wgpu::BindGroup,
    _charge: crate::budget::GpuCharge,
}

impl TextureBuffers {
    /// Upload `textures` (none: one white texel and one entry, as storage cannot be empty).
    pub fn new(device: &wgpu::Device, textures: &[Texture]) -> Result<Self> {
        super::texture::check_textures(textures)?;
        let mut texels: Vec<u32> = Vec::new();
        let mut table = Vec::with_capacity(textures.len().max(1));
        for t in textures {
            table.push(GpuTexture {
                offset: texels.len() as u32,
                width: t.image.width(),
                height: t.image.height(),
                wrap_u: wrap_code(t.wrap[0]),
                wrap_v: wrap_code(t.wrap[1]),
                filtering: filter_code(t.filter),
                _pad: [0; 2],
            });
            texels.extend(
                t.image
                    .as_raw()
                    .chunks_exact(4)
                    .map(|p| u32::from_le_bytes([p[0], p[1], p[2], p[3]])),
            );
        }
        if texels.is_empty() {
            texels.push(u32::MAX);
        }
        if table.is_empty() {
            table.push(GpuTexture::zeroed());
        }
        let texel_bytes = texels.len() as u64 * 4;
        check_storage_bytes(device, "texture texel bytes", texel_bytes)?;
        let charge = crate::budget::charge_gpu(
            || format!("the mesh's {} textures", textures.len()),
            texel_bytes + table.len() as u64 * 32,
        )?;
        let storage = |label, contents: &[u8]| {
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents,
                usage: wgpu::BufferUsages::STORAGE,
            })
        };
        let texel_buffer = storage("mesh texels", bytemuck::cast_slice(&texels));
        let table_buffer = storage("mesh texture table", bytemuck::cast_slice(&table));
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("mesh textures"),
            layout: &texture_bind_group_layout(device),
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: texel_buffer.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: table_buffer.as_entire_binding(),
                },
            ],
        });
        Ok(Self {
            bind_group,
            _charge: charge,
        })
    }
}
