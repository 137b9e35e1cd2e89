//! 2D textures the passes allocate for themselves (depth buffers, id targets, scratch images).

use crate::budget::{charge_gpu, texel_bytes, GpuCharge};
use crate::error::Result;

/// A texture, its default view and its share of the memory budget.
pub(crate) struct Texture2d {
    pub texture: wgpu::Texture,
    pub view: wgpu::TextureView,
    pub charge: GpuCharge,
}

/// Create a single-mip, single-sample 2D texture of `size` and its default view, charged to
/// the memory budget (`label` names it when over).
pub(crate) fn texture_2d(
    device: &wgpu::Device,
    label: &str,
    size: [u32; 2],
    format: wgpu::TextureFormat,
    usage: wgpu::TextureUsages,
) -> Result<Texture2d> {
    let bytes = u64::from(size[0]) * u64::from(size[1]) * texel_bytes(format);
    let charge = charge_gpu(|| format!("{label} of {}x{}", size[0], size[1]), bytes)?;
    let texture = device.create_texture(&wgpu::TextureDescriptor {
        label: Some(label),
        size: wgpu::Extent3d {
            width: size[0],
            height: size[1],
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage,
        view_formats: &[],
    });
    let view = texture.create_view(&Default::default());
    Ok(Texture2d {
        texture,
        view,
        charge,
    })
}

/// `last` where it has `size`, else a new texture (`last` freed first): what a renderer keeps
/// in its prepared state from frame to frame.
pub(crate) fn texture_2d_reusing(
    last: Option<Texture2d>,
    device: &wgpu::Device,
    label: &str,
    size: [u32; 2],
    format: wgpu::TextureFormat,
    usage: wgpu::TextureUsages,
) -> Result<Texture2d> {
    match last {
        Some(t) if [t.texture.width(), t.texture.height()] == size => Ok(t),
        last => {
            drop(last); // free before allocating the replacement
            texture_2d(device, label, size, format, usage)
        }
    }
}

/// The view of `slot`, (re)allocated when missing or of another size.
pub(crate) fn cached_texture_2d<'a>(
    slot: &'a mut Option<Texture2d>,
    device: &wgpu::Device,
    label: &str,
    size: [u32; 2],
    format: wgpu::TextureFormat,
    usage: wgpu::TextureUsages,
) -> Result<&'a wgpu::TextureView> {
    if slot
        .as_ref()
        .is_none_or(|t| [t.texture.width(), t.texture.height()] != size)
    {
        *slot = None; // free before allocating the replacement
        *slot = Some(texture_2d(device, label, size, format, usage)?);
    }
    Ok(&slot.as_ref().expect("allocated above").view)
}

/// A bind-group-layout entry for a non-filtered `texture_2d<f32>` read with `textureLoad`.
pub(crate) fn texture_2d_layout_entry(
    binding: u32,
    stages: wgpu::ShaderStages,
) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: stages,
        ty: wgpu::BindingType::Texture {
            sample_type: wgpu::TextureSampleType::Float { filterable: false },
            view_dimension: wgpu::TextureViewDimension::D2,
            multisampled: false,
        },
        count: None,
    }
}
