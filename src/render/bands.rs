//! Frames too large for the adapter in one piece, rendered in bands: a panel's 3840×2160 or
//! 7680×4320 can need more than one storage binding (the exact visibility's per-subpixel keys),
//! one texture (subpixel-wide group images) or one allocation holds. When the wrapped renderer's
//! `prepare` refuses the whole frame for its size, [`Banded`] splits the image into equal bands
//! (halving the larger side until one prepares), renders each as a frame of its own
//! ([`Frame::band`]: the same cameras through that part of the focal window, the mask moved
//! with it) into one band-sized target, and copies it into place. Every pixel is rendered
//! exactly as in the whole frame; the last band of a row or column is moved back inside the
//! image, overlapping its neighbour, so that all bands have one size (one prepared state).

use crate::camera::CameraModel;
use crate::error::{Error, Result};
use crate::frame::Frame;
use crate::param::Param;
use crate::render::{Method, Renderer};
use crate::target::SpatialTarget;

/// Smallest band side tried before giving up: below this the frame's own error stands.
const MIN_BAND_SIDE: u32 = 64;

/// A renderer that falls back to bands when a frame is too large for it in one piece.
pub struct Banded<S: ?Sized> {
    inner: Box<dyn Renderer<S>>,
    method: Method,
    /// Split even frames that fit into bands of at most this many pixels.
    max_band_pixels: Option<u64>,
    plan: Option<BandPlan>,
}

/// How the last prepared frame is split.
struct BandPlan {
    /// The whole frame's size.
    size: [u32; 2],
    /// Each band's size.
    band: [u32; 2],
    /// Each band's top-left pixel.
    origins: Vec<[u32; 2]>,
    /// Where each band is rendered before it is copied into place.
    target: SpatialTarget,
}

impl<S: ?Sized> Banded<S> {
    /// Wrap `inner`, which renders with `method`. `max_band_pixels`: render in bands of at
    /// most this many pixels even where the whole frame fits (`None`: only where it does not).
    pub fn new(inner: Box<dyn Renderer<S>>, method: Method, max_band_pixels: Option<u64>) -> Self {
        Self {
            inner,
            method,
            max_band_pixels,
            plan: None,
        }
    }

    /// The bands of the last prepared frame: (band size, count); `None` when it renders whole.
    pub fn bands(&self) -> Option<([u32; 2], usize)> {
        self.plan.as_ref().map(|p| (p.band, p.origins.len()))
    }

    /// Why `frame` cannot be banded, if it cannot.
    fn unbandable(&self, frame: &Frame) -> Option<&'static str> {
        if self.method == Method::Warp {
            return Some("the warp shifts pixels across band edges");
        }
        if frame.camera.model == CameraModel::Parallel {
            return Some("the parallel camera's crop depends on the whole image");
        }
        None
    }
}

/// Whether `error` says the frame is too large for the adapter (so smaller pieces may fit). The
/// caller's own memory budget (`crate::budget`) is not the adapter's: its refusal stands.
fn too_large(error: &Error) -> bool {
    match error {
        Error::LimitExceeded { .. } | Error::SubpixelWidth { .. } => true,
        Error::Gpu { message, .. } => {
            let message = message.to_ascii_lowercase();
            message.contains("out of memory") || message.contains("outofmemory")
        }
        _ => false,
    }
}

/// Band sizes to try for a `size` image: halve the larger side, each time, down to
/// [`MIN_BAND_SIDE`].
fn band_sizes(size: [u32; 2]) -> Vec<[u32; 2]> {
    let mut sizes = Vec::new();
    let mut band = size;
    loop {
        let i = usize::from(band[1] > band[0]);
        let half = band[i].div_ceil(2);
        if half < MIN_BAND_SIDE {
            return sizes;
        }
        band[i] = half;
        sizes.push(band);
    }
}

/// The top-left pixels of `band`-sized bands covering a `size` image, the last of each row and
/// column moved back inside the image.
fn origins(size: [u32; 2], band: [u32; 2]) -> Vec<[u32; 2]> {
    let starts = |side: u32, step: u32| -> Vec<u32> {
        (0..side.div_ceil(step))
            .map(|i| (i * step).min(side - step))
            .collect()
    };
    let (xs, ys) = (starts(size[0], band[0]), starts(size[1], band[1]));
    ys.iter()
        .flat_map(|&y| xs.iter().map(move |&x| [x, y]))
        .collect()
}

impl<S: ?Sized> Renderer<S> for Banded<S> {
    fn prepare(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        scene: &S,
        frame: &Frame,
    ) -> Result<()> {
        // Already split for this size: the same bands (cheap when nothing else changed).
        if let Some(plan) = self.plan.as_ref().filter(|p| p.size == frame.size) {
            let band = frame.band([0, 0], plan.band);
            return self.inner.prepare(device, queue, scene, &band);
        }
        self.plan = None;
        let pixels = frame.size[0] as u64 * frame.size[1] as u64;
        let whole = match self.max_band_pixels {
            Some(max) if pixels > max => None,
            _ => match self.inner.prepare(device, queue, scene, frame) {
                Ok(()) => return Ok(()),
                Err(e) if too_large(&e) => Some(e),
                Err(e) => return Err(e),
            },
        };
        if let Some(why) = self.unbandable(frame) {
            return Err(match whole {
                Some(e) => e,
                None => Error::invalid(Param::Bands, format!("a frame cannot be banded: {why}")),
            });
        }
        let mut last = whole;
        for band in band_sizes(frame.size) {
            let band_pixels = band[0] as u64 * band[1] as u64;
            if self.max_band_pixels.is_some_and(|max| band_pixels > max) {
                continue;
            }
            match self
                .inner
                .prepare(device, queue, scene, &frame.band([0, 0], band))
            {
                Ok(()) => {
                    self.plan = Some(BandPlan {
                        size: frame.size,
                        band,
                        origins: origins(frame.size, band),
                        target: SpatialTarget::new(device, band)?,
                    });
                    log::info!(
                        "rendering {}x{} in {} bands of {}x{}",
                        frame.size[0],
                        frame.size[1],
                        origins(frame.size, band).len(),
                        band[0],
                        band[1]
                    );
                    return Ok(());
                }
                Err(e) if too_large(&e) => last = Some(e),
                Err(e) => return Err(e),
            }
        }
        Err(last.unwrap_or_else(|| {
            Error::invalid(
                Param::Bands,
                format!(
                    "no band of at least {MIN_BAND_SIDE} pixels a side fits the band size limit"
                ),
            )
        }))
    }

    fn encode(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        scene: &S,
        frame: &Frame,
        target: &SpatialTarget,
    ) -> Result<()> {
        let Some(plan) = self.plan.as_ref() else {
            return self.inner.encode(device, encoder, scene, frame, target);
        };
        crate::render::check_target(frame, target)?;
        if plan.size != frame.size {
            return Err(Error::NotPrepared {
                renderer: "Banded",
                frame: format!("{:?}", frame.size),
                prepared: format!("bands of a {:?} frame", plan.size),
            });
        }
        if !target
            .texture
            .usage()
            .contains(wgpu::TextureUsages::COPY_DST)
        {
            return Err(Error::invalid(
                Param::Target,
                "a frame rendered in bands is copied into the target, which needs COPY_DST usage",
            ));
        }
        for &origin in &plan.origins {
            let band = frame.band(origin, plan.band);
            self.inner
                .encode(device, encoder, scene, &band, &plan.target)?;
            encoder.copy_texture_to_texture(
                plan.target.texture.as_image_copy(),
                wgpu::TexelCopyTextureInfo {
                    texture: &target.texture,
                    mip_level: 0,
                    origin: wgpu::Origin3d {
                        x: origin[0],
                        y: origin[1],
                        z: 0,
                    },
                    aspect: wgpu::TextureAspect::All,
                },
                wgpu::Extent3d {
                    width: plan.band[0],
                    height: plan.band[1],
                    depth_or_array_layers: 1,
                },
            );
        }
        Ok(())
    }

    fn atlas(&self) -> Option<&crate::render::atlas::Atlas> {
        // A banded frame's atlas would hold the last band's views only.
        match self.plan {
            Some(_) => None,
            None => self.inner.atlas(),
        }
    }

    fn describe(&self) -> Option<String> {
        let bands = self.plan.as_ref().map(|p| {
            format!(
                "in {} bands of {}x{} (the whole frame exceeds the adapter's limits)",
                p.origins.len(),
                p.band[0],
                p.band[1]
            )
        });
        match (self.inner.describe(), bands) {
            (Some(a), Some(b)) => Some(format!("{a}; {b}")),
            (a, b) => a.or(b),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bands_cover_the_image_with_one_size() {
        assert_eq!(band_sizes([3840, 2160])[..2], [[1920, 2160], [1920, 1080]]);
        assert!(band_sizes([100, 100]).is_empty());
        for (size, band) in [
            ([160, 128], [80, 64]),
            ([150, 100], [75, 50]),
            ([7680, 4320], [1920, 1080]),
        ] {
            let o = origins(size, band);
            let mut covered = vec![false; (size[0] * size[1]) as usize];
            for [x, y] in o {
                assert!(x + band[0] <= size[0] && y + band[1] <= size[1]);
                for yy in y..y + band[1] {
                    for xx in x..x + band[0] {
                        covered[(yy * size[0] + xx) as usize] = true;
                    }
                }
            }
            assert!(covered.iter().all(|&c| c), "{size:?} by {band:?}");
        }
        // Odd sides: the last band overlaps its neighbour.
        assert_eq!(origins([101, 64], [51, 64]), vec![[0, 0], [50, 0]]);
    }
}
