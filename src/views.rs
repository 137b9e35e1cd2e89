//! Looking at a spatial image on an ordinary screen: extract one view zone, make an anaglyph.

use crate::display::Mask;
use crate::image_io::RgbImage;

/// What an eye in view zone `view` sees of `spatial`: subpixels of that view keep their value,
/// every other subpixel takes the nearest subpixel of the same channel and view in its row
/// (black if the row has none).
pub fn extract_view(spatial: &RgbImage, mask: &Mask, view: u32) -> RgbImage {
    let (w, h) = (spatial.width, spatial.height);
    let mut out = RgbImage::new(w, h);
    let mut source: Vec<Option<u32>> = vec![None; w as usize];
    for y in 0..h {
        for c in 0..3 {
            // Nearest matching x, from two sweeps: left-to-right then right-to-left.
            let mut last = None;
            for x in 0..w {
                if mask.view(x, y, c) == view {
                    last = Some(x);
                }
                source[x as usize] = last;
            }
            let mut next = None;
            for x in (0..w).rev() {
                if mask.view(x, y, c) == view {
                    next = Some(x);
                }
                let nearest = match (source[x as usize], next) {
                    (Some(l), Some(r)) => Some(if x - l <= r - x { l } else { r }),
                    (l, r) => l.or(r),
                };
                if let Some(sx) = nearest {
                    out.set(x, y, c, spatial.get(sx, y, c));
                }
            }
        }
    }
    out
}

/// Red/cyan anaglyph: red from view `left`, green and blue from view `right`.
pub fn anaglyph(spatial: &RgbImage, mask: &Mask, left: u32, right: u32) -> RgbImage {
    let l = extract_view(spatial, mask, left);
    let r = extract_view(spatial, mask, right);
    let mut out = r;
    for (o, l) in out.data.chunks_exact_mut(3).zip(l.data.chunks_exact(3)) {
        // Luminance of the left view into red keeps colour objects visible to both eyes.
        let luma = 0.299 * l[0] as f32 + 0.587 * l[1] as f32 + 0.114 * l[2] as f32;
        o[0] = luma.round().clamp(0.0, 255.0) as u8;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::display::{Display, DisplayKind};

    #[test]
    fn extracting_a_view_keeps_its_subpixels_and_fills_the_rest_from_them() {
        let display = Display::new(DisplayKind::Hubner8).unwrap();
        let mask = display.mask();
        let (w, h) = (24, 12);
        // Each subpixel's value = 10 · its view: the extracted view must be uniform.
        let mut spatial = RgbImage::new(w, h);
        for y in 0..h {
            for x in 0..w {
                for c in 0..3 {
                    spatial.set(x, y, c, 10 * mask.view(x, y, c) as u8);
                }
            }
        }
        for v in 0..8 {
            let e = extract_view(&spatial, &mask, v);
            assert!(e.data.iter().all(|&b| b == 10 * v as u8), "view {v}");
        }
    }
}
