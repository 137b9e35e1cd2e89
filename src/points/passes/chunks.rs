//! Duplication keeps a copy of every splat group image per view, which at a panel's size
//! outgrows what one texture may take (1920×1080, N = 8, 15 groups: 4 GB). The views are then
//! drawn and composited in chunks that reuse one set of group images, as few chunks as fit:
//! bands of whole tile rows of the atlas (tiled) or runs of consecutive views (layered).

use std::ops::Range;

use super::group_images::{GroupImages, GroupImagesKey};
use crate::error::{Error, Result};
use crate::render::batches::batches;
use crate::render::quilt::QuiltLayout;

/// The largest group-image texture duplication allocates. Vulkan guarantees every device a
/// `maxMemoryAllocationSize` of at least 1 GiB (lavapipe has 2 GiB and fails a 4 GB image as
/// "Out of Memory"); wgpu exposes no such limit, so the guaranteed size is the one to plan by.
pub(super) const MAX_IMAGE_BYTES: u64 = 1 << 30;

/// One band of the tiled method: whole tile rows of the atlas, drawn as a quilt of their own.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Band {
    /// The band's grid of tiles and the views it holds (its tile 0 is view `first_view`).
    pub layout: QuiltLayout,
    pub first_view: u32,
    /// The atlas texel row of the band's top row.
    pub row: u32,
}

impl Band {
    pub fn views(&self) -> Range<u32> {
        self.first_view..self.first_view + self.layout.views
    }
}

/// The tiled atlas `atlas` split into the fewest, most even bands of tile rows whose group
/// images (`groups` layers) each fit one texture of at most `max_bytes`.
pub(super) fn tiled_bands(atlas: &QuiltLayout, groups: u32, max_bytes: u64) -> Result<Vec<Band>> {
    let key = |rows: u32| GroupImagesKey {
        size: [atlas.cols * atlas.tile[0], rows * atlas.tile[1]],
        groups,
        subpixel: false,
    };
    let fit = (1..=atlas.rows)
        .rev()
        .find(|&rows| GroupImages::texture_bytes(key(rows)) <= max_bytes)
        .ok_or_else(|| too_large("one row of tiles", key(1), max_bytes))?;
    // Rows counted from the top: view 0 is bottom-left, so the top band holds the last views.
    Ok(batches(atlas.rows, fit)
        .into_iter()
        .map(|top| {
            let first_view = (atlas.rows - top.end) * atlas.cols;
            let end = ((atlas.rows - top.start) * atlas.cols).min(atlas.views);
            Band {
                layout: QuiltLayout {
                    rows: top.len() as u32,
                    views: end - first_view,
                    ..*atlas
                },
                first_view,
                row: top.start * atlas.tile[1],
            }
        })
        .collect())
}

/// `views` of `size` split into the fewest, most even runs whose group images (`groups`
/// layers per view) each fit one texture of at most `max_bytes` and `max_layers` layers.
pub(super) fn layered_chunks(
    views: u32,
    size: [u32; 2],
    groups: u32,
    max_layers: u32,
    max_bytes: u64,
) -> Result<Vec<Range<u32>>> {
    let key = |run: u32| GroupImagesKey {
        size,
        groups: groups.saturating_mul(run),
        subpixel: false,
    };
    let fits = |run: u32| {
        let key = key(run);
        let layers = crate::render::view_layers::array_layers_for(key.size, key.groups);
        layers <= max_layers && GroupImages::texture_bytes(key) <= max_bytes
    };
    let fit = (1..=views.max(1))
        .rev()
        .find(|&run| fits(run))
        .ok_or_else(|| too_large("one view", key(1), max_bytes))?;
    Ok(batches(views, fit))
}

fn too_large(what: &str, key: GroupImagesKey, max_bytes: u64) -> Error {
    Error::LimitExceeded {
        what: format!(
            "bytes of the splat group images of {what} ({} groups of {}×{} texels, one texture; \
             fewer groups or a smaller image fit)",
            key.groups, key.size[0], key.size[1]
        ),
        value: GroupImages::texture_bytes(key),
        limit: max_bytes,
        param: None,
        advice: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const GIB: u64 = 1 << 30;

    #[test]
    fn small_atlases_are_one_band() {
        let atlas = QuiltLayout::for_views(8, [512, 512]);
        let bands = tiled_bands(&atlas, 15, GIB).unwrap();
        assert_eq!(bands.len(), 1);
        assert_eq!(bands[0].layout, atlas);
        assert_eq!((bands[0].first_view, bands[0].row), (0, 0));
    }

    #[test]
    fn panel_sized_atlases_split_into_bands_that_cover_every_view_once() {
        // 1920×1080, N = 8: 2 × 4 tiles, 4 GB of group images for 15 groups.
        let atlas = QuiltLayout::for_views(8, [1920, 1080]);
        let bands = tiled_bands(&atlas, 15, GIB).unwrap();
        assert!(bands.len() > 1);
        let mut covered: Vec<u32> = bands.iter().flat_map(Band::views).collect();
        covered.sort_unstable();
        assert_eq!(covered, (0..8).collect::<Vec<_>>());
        for band in &bands {
            let key = GroupImagesKey {
                size: band.layout.size(),
                groups: 15,
                subpixel: false,
            };
            assert!(GroupImages::texture_bytes(key) <= GIB);
            // Each view's tile in the band sits where it sits in the atlas.
            for v in band.views() {
                let local = band.layout.tile_origin(v - band.first_view);
                let global = atlas.tile_origin(v);
                assert_eq!([local[0], local[1] + band.row], global, "view {v}");
            }
        }
    }

    #[test]
    fn partly_empty_top_rows_keep_the_views_they_have() {
        let atlas = QuiltLayout::for_views(45, [256, 256]);
        assert!(atlas.cols * atlas.rows > 45);
        let bands = tiled_bands(&atlas, 15, 256 << 20).unwrap();
        assert!(bands.len() > 1);
        let top = bands[0];
        assert_eq!(top.views().end, 45);
        for v in top.views() {
            let local = top.layout.tile_origin(v - top.first_view);
            assert_eq!([local[0], local[1] + top.row], atlas.tile_origin(v));
        }
    }

    #[test]
    fn layered_runs_fit_bytes_and_layers() {
        assert_eq!(
            layered_chunks(8, [512, 512], 15, 2048, GIB).unwrap(),
            vec![0..8]
        );
        let runs = layered_chunks(8, [1920, 1080], 15, 2048, GIB).unwrap();
        assert_eq!(runs, vec![0..2, 2..4, 4..6, 6..8]);
        let runs = layered_chunks(64, [64, 64], 15, 256, GIB).unwrap();
        assert!(runs.iter().all(|r| r.len() as u32 * 15 < 256));
        assert_eq!(runs.last().unwrap().end, 64);
    }

    #[test]
    fn one_view_over_a_texture_is_a_clear_error() {
        let err = layered_chunks(8, [3840, 2160], 15, 2048, GIB).unwrap_err();
        let text = err.to_string();
        assert!(
            text.contains("one view") && text.contains("15 groups"),
            "{text}"
        );
        let atlas = QuiltLayout::for_views(8, [3840, 2160]);
        assert!(tiled_bands(&atlas, 15, GIB).is_err());
    }
}
