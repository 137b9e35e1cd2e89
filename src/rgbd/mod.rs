//! RGB-D images — a colour image and a depth map (a phone's portrait photo, a depth
//! estimator's output, a render's Z buffer) — turned into any display's spatial image by
//! warping each subpixel's view straight from the one reference (docs/WARPING.md).
//!
//! Data and loaders here, and the GPU form ([`RgbdScene`]); the warp is
//! [`crate::warp::RgbdWarp`] (`wgsl/warp/rgbd.wgsl`).

mod scene;

use std::path::Path;

use crate::advice::{Advice, Setting};
use crate::error::{Error, Result};
use crate::image_io::{decode, decode_bytes, RgbImage};
use crate::param::Param;

pub use scene::{RgbdScene, NEARNESS_MAP_FORMAT};

/// A colour image and, per pixel, its nearness: 0 = far … 1 = near (normalised depth map
/// values, white = near unless the map is inverted on loading).
#[derive(Clone, Debug, PartialEq)]
pub struct RgbdImage {
    /// The picture.
    pub color: RgbImage,
    /// `width · height` values in 0…1, rows top-down.
    pub nearness: Vec<f32>,
}

/// How a depth map is read.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DepthMapOptions {
    /// Black = near (the map stores distance rather than nearness).
    pub invert: bool,
    /// Resample a depth map of another size than the colour image (bilinear) instead of
    /// refusing it.
    pub resample: bool,
}

impl RgbdImage {
    /// `color` with `nearness` (one value in 0…1 per pixel; NaN or out-of-range values are
    /// refused by name).
    pub fn new(color: RgbImage, nearness: Vec<f32>) -> Result<Self> {
        let pixels = color.width as usize * color.height as usize;
        if nearness.len() != pixels {
            return Err(Error::invalid(
                Param::DepthMap,
                format!(
                    "{} values for a {}x{} colour image ({pixels} pixels)",
                    nearness.len(),
                    color.width,
                    color.height
                ),
            ));
        }
        if let Some(i) = nearness.iter().position(|d| !(0.0..=1.0).contains(d)) {
            return Err(Error::invalid(
                Param::DepthMap,
                format!("value {} at pixel {i} is outside 0…1", nearness[i]),
            ));
        }
        Ok(Self { color, nearness })
    }

    /// `color` at one nearness everywhere (a flat picture at that depth).
    pub fn flat(color: RgbImage, nearness: f32) -> Result<Self> {
        let pixels = color.width as usize * color.height as usize;
        Self::new(color, vec![nearness; pixels])
    }

    /// Width and height.
    pub fn size(&self) -> [u32; 2] {
        [self.color.width, self.color.height]
    }

    /// Nearness of pixel (x, y).
    pub fn nearness_at(&self, x: u32, y: u32) -> f32 {
        self.nearness[y as usize * self.color.width as usize + x as usize]
    }

    /// A colour PNG and a depth PNG (8 or 16 bit, grey or colour: its luma is the depth).
    pub fn load(color: &Path, depth: &Path, options: DepthMapOptions) -> Result<Self> {
        Self::pair_of(decode(color)?, color, decode(depth)?, depth, options)
    }

    /// [`RgbdImage::load`] from the two files' bytes (`names`: colour, depth, for errors).
    pub fn from_bytes(
        color: &[u8],
        depth: &[u8],
        names: [&Path; 2],
        options: DepthMapOptions,
    ) -> Result<Self> {
        let [color_name, depth_name] = names;
        Self::pair_of(
            decode_bytes(color, color_name)?,
            color_name,
            decode_bytes(depth, depth_name)?,
            depth_name,
            options,
        )
    }

    fn pair_of(
        color_image: image::DynamicImage,
        color: &Path,
        depth_image: image::DynamicImage,
        depth: &Path,
        options: DepthMapOptions,
    ) -> Result<Self> {
        let rgb = color_image.to_rgb8();
        let color_image = RgbImage {
            width: rgb.width(),
            height: rgb.height(),
            data: rgb.into_raw(),
        };
        let size = [depth_image.width(), depth_image.height()];
        let values = luma_of(&depth_image);
        let want = [color_image.width, color_image.height];
        let values = if size == want {
            values
        } else if options.resample {
            resample_bilinear(&values, size, want)
        } else {
            return Err(Error::Image {
                path: depth.to_path_buf(),
                reason: format!(
                    "depth map is {}x{}, the colour image {} is {}x{}",
                    size[0],
                    size[1],
                    color.display(),
                    want[0],
                    want[1]
                ),
                advice: Some(
                    Advice::text(" (resample it with ")
                        .then(Setting::DepthResample)
                        .then_text(", or give maps of one size)"),
                ),
            });
        };
        Self::new(color_image, nearness_of(values, options.invert))
    }

    /// A side-by-side RGB-D image: colour in the left half, depth in the right half.
    pub fn load_side_by_side(path: &Path, options: DepthMapOptions) -> Result<Self> {
        Self::side_by_side_of(decode(path)?, path, options)
    }

    /// [`RgbdImage::load_side_by_side`] from the file's bytes (`name` for errors).
    pub fn side_by_side_from_bytes(
        bytes: &[u8],
        name: &Path,
        options: DepthMapOptions,
    ) -> Result<Self> {
        Self::side_by_side_of(decode_bytes(bytes, name)?, name, options)
    }

    fn side_by_side_of(
        image: image::DynamicImage,
        path: &Path,
        options: DepthMapOptions,
    ) -> Result<Self> {
        let size = [image.width(), image.height()];
        if size[0] < 2 || !size[0].is_multiple_of(2) {
            return Err(Error::Image {
                path: path.to_path_buf(),
                reason: format!(
                    "a side-by-side RGB-D image needs an even width (colour | depth), this is \
                     {}x{}",
                    size[0], size[1]
                ),
                advice: None,
            });
        }
        let (rgb, luma) = (image.to_rgb8(), luma_of(&image));
        let half = size[0] / 2;
        let mut color = RgbImage::new(half, size[1]);
        let mut depth = Vec::with_capacity(half as usize * size[1] as usize);
        for y in 0..size[1] {
            for x in 0..half {
                for c in 0..3 {
                    color.set(x, y, c, rgb.get_pixel(x, y)[c as usize]);
                }
                depth.push(luma[(y * size[0] + half + x) as usize]);
            }
        }
        Self::new(color, nearness_of(depth, options.invert))
    }
}

/// Normalised luma (8-bit maps scale to 0…1 as 16-bit ones do).
fn luma_of(image: &image::DynamicImage) -> Vec<f32> {
    let luma = image.to_luma16();
    luma.into_raw()
        .into_iter()
        .map(|v| v as f32 / 65535.0)
        .collect()
}

fn nearness_of(values: Vec<f32>, invert: bool) -> Vec<f32> {
    if invert {
        values.into_iter().map(|v| 1.0 - v).collect()
    } else {
        values
    }
}

/// Bilinear resampling of a `from`-sized map to `to` (pixel centres aligned).
fn resample_bilinear(values: &[f32], from: [u32; 2], to: [u32; 2]) -> Vec<f32> {
    let at = |x: u32, y: u32| values[(y * from[0] + x) as usize];
    let coord = |i: u32, n: u32, m: u32| {
        let s = ((i as f32 + 0.5) * n as f32 / m as f32 - 0.5).clamp(0.0, (n - 1) as f32);
        let lo = s.floor() as u32;
        (lo, (lo + 1).min(n - 1), s - lo as f32)
    };
    let mut out = Vec::with_capacity(to[0] as usize * to[1] as usize);
    for y in 0..to[1] {
        let (y0, y1, fy) = coord(y, from[1], to[1]);
        for x in 0..to[0] {
            let (x0, x1, fx) = coord(x, from[0], to[0]);
            let top = at(x0, y0) * (1.0 - fx) + at(x1, y0) * fx;
            let bottom = at(x0, y1) * (1.0 - fx) + at(x1, y1) * fx;
            out.push(top * (1.0 - fy) + bottom * fy);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn resampling_keeps_constants_and_ramps() {
        let flat = resample_bilinear(&[0.25; 6], [3, 2], [7, 5]);
        assert!(flat.iter().all(|&v| (v - 0.25).abs() < 1e-6));
        let ramp: Vec<f32> = (0..4).map(|x| x as f32 / 3.0).collect();
        let same = resample_bilinear(&ramp, [4, 1], [4, 1]);
        assert_eq!(same, ramp);
    }

    #[test]
    fn bad_maps_are_refused_by_name() {
        let color = RgbImage::new(4, 2);
        let err = RgbdImage::new(color.clone(), vec![0.5; 7]).unwrap_err();
        assert!(err.to_string().contains("7 values"), "{err}");
        let mut values = vec![0.5; 8];
        values[3] = f32::NAN;
        let err = RgbdImage::new(color, values).unwrap_err();
        assert!(err.to_string().contains("pixel 3"), "{err}");
    }
}
