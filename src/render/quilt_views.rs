//! Which of a quilt's views a display shows: the quilt's views are its tiles up to the last
//! one that is not all black (Looking Glass quilts may leave the last tiles empty); a display
//! of fewer views takes them spread across the quilt's cone, not its first N (one edge of it).
//! What `autostereo interleave` and the Python package decide before they interleave a quilt.

use crate::image_io::RgbImage;
use crate::render::quilt::QuiltLayout;

/// The views the tiles `image` of a quilt of `grid` hold: its tiles up to the last one that
/// is not all black.
pub fn views_held(image: &RgbImage, grid: &QuiltLayout) -> u32 {
    let tiles = grid.cols * grid.rows;
    (0..tiles)
        .rev()
        .find(|&t| {
            let [x0, y0] = grid.tile_origin(t);
            (y0..y0 + grid.tile[1]).any(|y| {
                let row = (y as usize * image.width as usize + x0 as usize) * 3;
                image.data[row..row + grid.tile[0] as usize * 3]
                    .iter()
                    .any(|&b| b != 0)
            })
        })
        .map_or(0, |t| t + 1)
}

/// The `n` quilt views of `q` (n ≤ q) a display of `n` views shows: view i ←
/// round(i·(q−1)/(n−1)), spread across the quilt's cone; one view: the middle.
pub fn spread_views(n: u32, q: u32) -> Vec<u32> {
    // No views to spread over: every display view shows the one there is.
    let q = q.max(1);
    if n == 0 {
        return Vec::new();
    }
    if n == 1 {
        return vec![(q - 1) / 2];
    }
    (0..n)
        .map(|i| {
            let num = u64::from(i) * u64::from(q - 1);
            let den = u64::from(n - 1);
            ((2 * num + den) / (2 * den)) as u32
        })
        .collect()
}

/// A quilt of `layout` whose tile i is `image`'s tile `picked[i]` (same grid).
pub fn pick_tiles(image: &RgbImage, layout: &QuiltLayout, picked: &[u32]) -> RgbImage {
    let mut out = RgbImage::new(image.width, image.height);
    let row_bytes = layout.tile[0] as usize * 3;
    for (i, &t) in picked.iter().enumerate() {
        let [dx, dy] = layout.tile_origin(i as u32);
        let [sx, sy] = layout.tile_origin(t);
        for y in 0..layout.tile[1] {
            let src = ((sy + y) as usize * image.width as usize + sx as usize) * 3;
            let dst = ((dy + y) as usize * image.width as usize + dx as usize) * 3;
            out.data[dst..dst + row_bytes].copy_from_slice(&image.data[src..src + row_bytes]);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn views_spread_across_the_cone() {
        assert_eq!(spread_views(8, 45), [0, 6, 13, 19, 25, 31, 38, 44]);
        assert_eq!(spread_views(8, 8), (0..8).collect::<Vec<_>>());
        assert_eq!(spread_views(1, 45), [22]);
        assert_eq!(spread_views(2, 45), [0, 44]);
    }
}
