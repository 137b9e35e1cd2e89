//! Gaussians on the GPU: one storage buffer of means, opacities and world-space covariances,
//! one of SH coefficients as half floats (two per word: a degree-3 scene takes 96 bytes a
//! Gaussian instead of 192, so twice as many fit one storage binding), uploaded once.

use bytemuck::{Pod, Zeroable};
use glam::Vec3;
use wgpu::util::DeviceExt;

use super::Gaussians;
use crate::camera::Bounds;
use crate::error::Result;
use crate::gpu::gpu_buffer::check_storage_bytes;
use crate::param::Param;

/// One Gaussian. Keep in sync with `struct Gaussian` in `wgsl/gaussians/shared/gaussian.wgsl`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable, PartialEq)]
pub struct GaussianGpu {
    /// World-space mean and opacity (after the sigmoid).
    pub mean_opacity: [f32; 4],
    /// World-space covariance xx, xy, xz, yy.
    pub cov_a: [f32; 4],
    /// yz, zz and two unused.
    pub cov_b: [f32; 4],
}
const _: () = assert!(std::mem::size_of::<GaussianGpu>() == 48);
crate::shader::gpu_layout!(GaussianGpu, "Gaussian", [mean_opacity, cov_a, cov_b]);

/// Gaussians uploaded: what every frame reads.
pub struct GaussianScene {
    /// One [`GaussianGpu`] per Gaussian.
    pub geometry: wgpu::Buffer,
    /// SH coefficients, RGB per coefficient, as f16 pairs.
    pub sh: wgpu::Buffer,
    /// Number of Gaussians.
    pub count: u32,
    /// SH degree (0 to 3).
    pub sh_degree: u32,
    /// The means (the CPU depth sort reads them).
    pub means: Vec<Vec3>,
    /// Bounding box of the means.
    pub bounds: Bounds,
    /// The buffers' share of the memory budget.
    _charge: crate::budget::GpuCharge,
}

impl GaussianScene {
    /// Upload `gaussians` (validated) after checking each buffer against the device's
    /// storage-binding limit and the memory budget.
    pub fn new(device: &wgpu::Device, gaussians: &Gaussians) -> Result<Self> {
        gaussians.validate()?;
        let n = gaussians.len() as u64;
        let geometry_bytes = n * std::mem::size_of::<GaussianGpu>() as u64;
        let halves = n * gaussians.coefficients() as u64 * 3;
        let sh_bytes = halves.div_ceil(2).max(1) * 4;
        check_storage_bytes(
            device,
            format!("Gaussian buffer bytes ({n} Gaussians × 48)"),
            geometry_bytes,
        )?;
        check_storage_bytes(
            device,
            format!(
                "SH buffer bytes ({n} Gaussians × {} coefficients × 3 halves)",
                gaussians.coefficients()
            ),
            sh_bytes,
        )?;
        let charge = crate::budget::charge_gpu(
            || format!("{n} Gaussians on the GPU"),
            geometry_bytes + sh_bytes,
        )?;
        let geometry: Vec<GaussianGpu> = (0..gaussians.len())
            .map(|i| {
                let c = gaussians.covariance(i);
                let p = gaussians.positions[i];
                GaussianGpu {
                    mean_opacity: [p.x, p.y, p.z, gaussians.opacities[i]],
                    cov_a: [c.x_axis.x, c.y_axis.x, c.z_axis.x, c.y_axis.y],
                    cov_b: [c.z_axis.y, c.z_axis.z, 0.0, 0.0],
                }
            })
            .collect();
        let sh = pack_halves(gaussians.sh.iter().flatten().copied());
        let buffer = |label: &str, contents: &[u8]| {
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents,
                usage: wgpu::BufferUsages::STORAGE,
            })
        };
        Ok(Self {
            geometry: buffer("gaussians", bytemuck::cast_slice(&geometry)),
            sh: buffer("gaussian sh", bytemuck::cast_slice(&sh)),
            count: gaussians.len() as u32,
            sh_degree: gaussians.sh_degree,
            means: gaussians.positions.clone(),
            bounds: gaussians.bounds().ok_or_else(|| {
                crate::error::Error::invalid(Param::Gaussians, "the means have no finite bounds")
            })?,
            _charge: charge,
        })
    }

    /// SH coefficients per Gaussian, `(degree + 1)²`.
    pub fn coefficients(&self) -> u32 {
        (self.sh_degree + 1) * (self.sh_degree + 1)
    }
}

/// `values` as f16, two per word (the first in the low half, as WGSL's `unpack2x16float`
/// reads them); never empty.
fn pack_halves(values: impl Iterator<Item = f32>) -> Vec<u32> {
    let mut words = Vec::new();
    let mut low: Option<u16> = None;
    for v in values {
        let h = half::f16::from_f32(v).to_bits();
        match low.take() {
            None => low = Some(h),
            Some(l) => words.push(u32::from(l) | (u32::from(h) << 16)),
        }
    }
    if let Some(l) = low {
        words.push(u32::from(l));
    }
    if words.is_empty() {
        words.push(0);
    }
    words
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn halves_pack_low_first_and_pad_the_last_word() {
        let words = pack_halves([1.0f32, -2.0, 0.5].into_iter());
        assert_eq!(words.len(), 2);
        let h = |v: f32| u32::from(half::f16::from_f32(v).to_bits());
        assert_eq!(words[0], h(1.0) | (h(-2.0) << 16));
        assert_eq!(words[1], h(0.5));
    }
}
