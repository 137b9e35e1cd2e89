//! CPU images: RGB8 buffers, PNG I/O, and the comparison metrics used against the N-pass oracle.

use std::path::Path;

use crate::error::{Error, Result};
use crate::param::Param;

/// A tightly packed RGB8 image, rows top-down.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RgbImage {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width · height · 3` bytes.
    pub data: Vec<u8>,
}

/// Most pixels a CPU image may have (3 bytes each): 2²⁸ (768 MiB); an 8K panel has 33 M.
pub const MAX_IMAGE_PIXELS: u64 = 1 << 28;

impl RgbImage {
    /// Check a size before an image of it is allocated: both sides ≥ 1, at most
    /// [`MAX_IMAGE_PIXELS`] pixels.
    pub fn check_size(width: u32, height: u32) -> Result<()> {
        if width == 0 || height == 0 {
            return Err(Error::invalid(
                Param::ImageSize,
                format!("{width}x{height}: width and height must be at least 1"),
            ));
        }
        let pixels = u64::from(width) * u64::from(height);
        if pixels > MAX_IMAGE_PIXELS {
            return Err(Error::invalid(
                Param::ImageSize,
                format!("{width}x{height}: {pixels} pixels, more than {MAX_IMAGE_PIXELS}"),
            ));
        }
        Ok(())
    }

    /// A black image.
    pub fn new(width: u32, height: u32) -> Self {
        Self {
            width,
            height,
            data: vec![0; width as usize * height as usize * 3],
        }
    }

    /// Drop the alpha channel of tightly packed RGBA8 rows.
    pub fn from_rgba(size: [u32; 2], rgba: &[u8]) -> Self {
        Self {
            width: size[0],
            height: size[1],
            data: rgba
                .chunks_exact(4)
                .flat_map(|p| [p[0], p[1], p[2]])
                .collect(),
        }
    }

    /// Channel `c` of pixel (x, y).
    #[inline]
    pub fn get(&self, x: u32, y: u32, c: u32) -> u8 {
        self.data[self.index(x, y, c)]
    }

    /// Set channel `c` of pixel (x, y).
    #[inline]
    pub fn set(&mut self, x: u32, y: u32, c: u32, v: u8) {
        let i = self.index(x, y, c);
        self.data[i] = v;
    }

    #[inline]
    fn index(&self, x: u32, y: u32, c: u32) -> usize {
        (y as usize * self.width as usize + x as usize) * 3 + c as usize
    }

    /// The image as PNG (RGB8) bytes; `Err` in words.
    pub fn png_bytes(&self) -> std::result::Result<Vec<u8>, String> {
        use image::ImageEncoder;
        let mut png = Vec::new();
        image::codecs::png::PngEncoder::new(&mut png)
            .write_image(
                &self.data,
                self.width,
                self.height,
                image::ExtendedColorType::Rgb8,
            )
            .map_err(|e| e.to_string())?;
        Ok(png)
    }

    /// Write a PNG (RGB8).
    /// Encoded in memory first: the file is created only once the PNG exists, so a failure
    /// leaves no empty or partial file behind.
    pub fn save_png(&self, path: &Path) -> Result<()> {
        let png = self.png_bytes().map_err(|reason| Error::Image {
            path: path.to_path_buf(),
            reason,
            advice: None,
        })?;
        std::fs::write(path, png).map_err(|e| Error::io(path, e))
    }

    /// Read an image file as RGB8: PNG, or JPEG with the `jpeg` feature (told by its first
    /// bytes; its size checked against the image limits and the memory budget before it is
    /// decoded). A file of another kind is refused as what it is (`Error::WrongKind`).
    pub fn load(path: &Path) -> Result<Self> {
        let rgb = decode(path)?.to_rgb8();
        Ok(Self {
            width: rgb.width(),
            height: rgb.height(),
            data: rgb.into_raw(),
        })
    }

    /// Read a PNG this project wrote (tests, examples) as RGB8, without the input checks of
    /// [`RgbImage::load`].
    pub fn load_png(path: &Path) -> Result<Self> {
        let img = image::open(path).map_err(|e| Error::Image {
            path: path.to_path_buf(),
            reason: e.to_string(),
            advice: None,
        })?;
        let rgb = img.to_rgb8();
        Ok(Self {
            width: rgb.width(),
            height: rgb.height(),
            data: rgb.into_raw(),
        })
    }
}

/// PSNR reported for identical images (JSON has no infinity).
pub const PSNR_IDENTICAL_DB: f64 = 1000.0;

/// How far an image is from a reference, over all subpixels (0–255 scale).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct ImageDiff {
    /// Peak signal-to-noise ratio in dB ([`PSNR_IDENTICAL_DB`] when identical).
    pub psnr_db: f64,
    /// Largest absolute subpixel difference.
    pub max_abs_err: u8,
    /// Share of subpixels off by more than 2/255.
    pub frac_off_2: f64,
}

/// Compare `image` with `reference` (same size required).
pub fn compare(image: &RgbImage, reference: &RgbImage) -> Result<ImageDiff> {
    if (image.width, image.height) != (reference.width, reference.height) {
        return Err(Error::invalid(
            Param::ImageSize,
            format!(
                "{}x{} vs reference {}x{}",
                image.width, image.height, reference.width, reference.height
            ),
        ));
    }
    let mut squared = 0u64;
    let mut max = 0u8;
    let mut off = 0usize;
    for (&a, &b) in image.data.iter().zip(&reference.data) {
        let d = a.abs_diff(b);
        squared += d as u64 * d as u64;
        max = max.max(d);
        off += (d > 2) as usize;
    }
    let n = image.data.len().max(1) as f64;
    let mse = squared as f64 / n;
    Ok(ImageDiff {
        psnr_db: if mse == 0.0 {
            PSNR_IDENTICAL_DB
        } else {
            10.0 * (255.0f64 * 255.0 / mse).log10()
        },
        max_abs_err: max,
        frac_off_2: off as f64 / n,
    })
}

/// Largest image file read (a PNG of the largest image `RgbImage` allows, 16-bit RGBA,
/// uncompressed, is 2 GiB: no real picture or depth map comes near).
pub const MAX_IMAGE_FILE_BYTES: u64 = 1 << 31;

/// An image file (PNG; JPEG with the `jpeg` feature) decoded: its format checked
/// ([`crate::formats`]: a file of another kind is refused as what it is), its bytes
/// read with a bound, then [`decode_bytes`].
pub(crate) fn decode(path: &Path) -> Result<image::DynamicImage> {
    crate::formats::expect(path, crate::formats::DataKind::Image)?;
    let bytes = crate::file::read_bounded(path, MAX_IMAGE_FILE_BYTES, "the image-file limit")?;
    decode_bytes(&bytes, path)
}

/// An image decoded after its size (from the header) passed the image-size and memory
/// checks; `path` names it in errors.
pub(crate) fn decode_bytes(bytes: &[u8], path: &Path) -> Result<image::DynamicImage> {
    let fail = |reason: String| Error::Image {
        path: path.to_path_buf(),
        reason,
        advice: None,
    };
    let reader = || {
        image::ImageReader::new(std::io::Cursor::new(bytes))
            .with_guessed_format()
            .map_err(|e| fail(e.to_string()))
    };
    let (w, h) = reader()?
        .into_dimensions()
        .map_err(|e| fail(e.to_string()))?;
    RgbImage::check_size(w, h).map_err(|e| fail(e.to_string()))?;
    // Decoded (up to 8 bytes per pixel), its luma (2) and the f32 values (4).
    let bytes_needed = u64::from(w) * u64::from(h) * 14;
    crate::budget::check(|| format!("image {}", path.display()), bytes_needed)?;
    let mut reader = reader()?;
    let mut limits = image::Limits::default();
    limits.max_image_width = Some(w);
    limits.max_image_height = Some(h);
    limits.max_alloc = Some(bytes_needed);
    reader.limits(limits);
    reader.decode().map_err(|e| fail(e.to_string()))
}
