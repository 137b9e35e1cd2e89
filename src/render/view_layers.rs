//! N per-view images in one 2D texture array: the N-pass baselines' render targets.

use crate::error::{Error, Result};
use crate::gpu::check_size_2d;
use crate::param::Param;
use crate::target::SPATIAL_FORMAT;

/// One RGBA8 layer per view, plus a shared depth buffer.
pub struct ViewLayers {
    /// The array texture (layer i = view i).
    pub texture: wgpu::Texture,
    /// All layers, for sampling in the compositor.
    pub array_view: wgpu::TextureView,
    /// One render-attachment view per layer.
    pub layer_views: Vec<wgpu::TextureView>,
    /// Depth buffer reused by every view pass.
    pub depth_view: wgpu::TextureView,
    /// Their share of the memory budget.
    _charge: crate::budget::GpuCharge,
}

/// Depth format of every mesh pass.
pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

/// The depth test every mesh pass uses: keep the nearest, write it. Equal depths keep the
/// first drawn, which the single-pass modes reproduce by preferring the lower triangle id.
pub(crate) fn nearest_depth_test() -> wgpu::DepthStencilState {
    wgpu::DepthStencilState {
        format: DEPTH_FORMAT,
        depth_write_enabled: Some(true),
        depth_compare: Some(wgpu::CompareFunction::Less),
        stencil: Default::default(),
        bias: Default::default(),
    }
}

impl ViewLayers {
    /// Allocate `views` layers of `size`, after checking the limits.
    pub fn new(device: &wgpu::Device, size: [u32; 2], views: u32) -> Result<Self> {
        Self::with_format(
            device,
            ("view layers", Param::Views),
            size,
            views,
            SPATIAL_FORMAT,
            wgpu::TextureUsages::STORAGE_BINDING | wgpu::TextureUsages::COPY_SRC,
        )
    }

    /// `layers` render-attachment layers of `format` (also sampled, plus `usage`) named
    /// `what` in errors (the layers' name, and the parameter that counts them), and a depth
    /// buffer, after checking the limits.
    pub fn with_format(
        device: &wgpu::Device,
        (what, counted_by): (&str, Param),
        size: [u32; 2],
        layers: u32,
        format: wgpu::TextureFormat,
        usage: wgpu::TextureUsages,
    ) -> Result<Self> {
        check_size_2d(device, size[0], size[1])?;
        let allocated = array_layers_for(size, layers);
        let most = most_layers(size, device.limits().max_texture_array_layers);
        if layers > most {
            return Err(Error::LimitExceeded {
                what: format!("{what} (texture array layers)"),
                value: layers.into(),
                limit: most.into(),
                param: Some(counted_by),
                advice: None,
            });
        }
        let texel = crate::budget::texel_bytes(format);
        let bytes = size[0] as u64 * size[1] as u64 * (texel * allocated as u64 + 4);
        let charge = crate::budget::charge_gpu(
            || {
                format!(
                    "{layers} {what} of {}x{} ({format:?}) and their depth",
                    size[0], size[1]
                )
            },
            bytes,
        )?;
        let extent = |layers| wgpu::Extent3d {
            width: size[0],
            height: size[1],
            depth_or_array_layers: layers,
        };
        let scope = device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
        let texture = device.create_texture(&wgpu::TextureDescriptor {
            label: Some(what),
            size: extent(allocated),
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT
                | wgpu::TextureUsages::TEXTURE_BINDING
                | usage,
            view_formats: &[],
        });
        let depth = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("view depth"),
            size: extent(1),
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: DEPTH_FORMAT,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
            view_formats: &[],
        });
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(Error::Gpu {
                operation: format!("allocating {layers} {what} of {}x{}", size[0], size[1]),
                message: e.to_string(),
            });
        }
        let array_view = texture.create_view(&wgpu::TextureViewDescriptor {
            label: Some("view layers"),
            dimension: Some(wgpu::TextureViewDimension::D2Array),
            array_layer_count: Some(layers),
            ..Default::default()
        });
        let layer_views = (0..layers)
            .map(|i| {
                texture.create_view(&wgpu::TextureViewDescriptor {
                    label: Some("view layer"),
                    dimension: Some(wgpu::TextureViewDimension::D2),
                    base_array_layer: i,
                    array_layer_count: Some(1),
                    ..Default::default()
                })
            })
            .collect();
        Ok(Self {
            texture,
            array_view,
            layer_views,
            depth_view: depth.create_view(&Default::default()),
            _charge: charge,
        })
    }

    /// Size of each layer in texels.
    pub fn size(&self) -> [u32; 2] {
        [self.texture.width(), self.texture.height()]
    }

    /// Usable layers (views or groups); the texture may hold one spare (`array_layers_for`).
    pub fn layers(&self) -> u32 {
        self.layer_views.len() as u32
    }

    /// GPU bytes of the texture (spare layer included) and its depth buffer.
    pub fn bytes(&self, bytes_per_texel: u64) -> u64 {
        let [w, h] = self.size();
        let allocated = self.texture.depth_or_array_layers() as u64;
        w as u64 * h as u64 * (bytes_per_texel * allocated + 4)
    }
}

/// A depth array texture and its share of the memory budget.
pub(crate) struct DepthArray {
    pub texture: wgpu::Texture,
    _charge: crate::budget::GpuCharge,
}

/// A depth array of `layers` layers of `size` (multiview passes: one depth layer per view
/// layer): `last` where it already fits, else a new one (`last` freed first).
pub(crate) fn depth_array(
    last: Option<DepthArray>,
    device: &wgpu::Device,
    size: [u32; 2],
    layers: u32,
) -> Result<DepthArray> {
    let fits = |d: &DepthArray| {
        let d = &d.texture;
        [d.width(), d.height()] == size && d.depth_or_array_layers() == layers
    };
    match last {
        Some(depth) if fits(&depth) => return Ok(depth),
        last => drop(last), // free before allocating the replacement
    }
    let bytes = u64::from(size[0]) * u64::from(size[1]) * u64::from(layers) * 4;
    let what = || format!("{layers} depth layers of {}x{}", size[0], size[1]);
    let charge = crate::budget::charge_gpu(what, bytes)?;
    let texture = device.create_texture(&wgpu::TextureDescriptor {
        label: Some("multiview depth"),
        size: wgpu::Extent3d {
            width: size[0],
            height: size[1],
            depth_or_array_layers: layers,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: DEPTH_FORMAT,
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
        view_formats: &[],
    });
    Ok(DepthArray {
        texture,
        _charge: charge,
    })
}

/// Layers `first .. first + count` of `texture` as one array view (a multiview attachment).
pub(crate) fn layer_range(texture: &wgpu::Texture, first: u32, count: u32) -> wgpu::TextureView {
    texture.create_view(&wgpu::TextureViewDescriptor {
        label: Some("multiview layers"),
        dimension: Some(wgpu::TextureViewDimension::D2Array),
        base_array_layer: first,
        array_layer_count: Some(count),
        ..Default::default()
    })
}

/// Array layers to allocate for `layers` usable ones of `size`: never 1, and never a multiple
/// of 6 when the layers are square. wgpu's GL backend picks the GL texture target from the
/// descriptor alone: one layer makes a plain `TEXTURE_2D` and square multiples of 6 make a cube
/// map, and a `texture_2d_array` binding of either reads zeros (docs/DESIGN.md §7). One spare
/// layer keeps every adapter on the same, array, path.
pub(crate) fn array_layers_for(size: [u32; 2], layers: u32) -> u32 {
    let cube_like = size[0] == size[1] && layers.is_multiple_of(6);
    if layers <= 1 || cube_like {
        layers + 1
    } else {
        layers
    }
}

/// The most usable layers of `size` whose array (a spare included: [`array_layers_for`]) fits
/// an adapter's `limit` of array layers: the count a caller may ask for.
pub(crate) fn most_layers(size: [u32; 2], limit: u32) -> u32 {
    (1..=limit)
        .rev()
        .find(|&n| array_layers_for(size, n) <= limit)
        .unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::array_layers_for;

    #[test]
    fn layer_counts_avoid_what_gl_takes_for_2d_or_cube_textures() {
        assert_eq!(array_layers_for([64, 64], 1), 2);
        assert_eq!(array_layers_for([64, 32], 1), 2);
        assert_eq!(array_layers_for([64, 64], 6), 7);
        assert_eq!(array_layers_for([64, 64], 12), 13);
        assert_eq!(array_layers_for([64, 32], 6), 6);
        assert_eq!(array_layers_for([64, 64], 8), 8);
    }
}
