//! The Looking Glass quilt layout: N view images tiled into one atlas, view 0 bottom-left,
//! left → right then bottom → top. The tiled method renders into this layout, so its atlas is
//! a quilt as it stands; `wgsl/shared/quilt.wgsl` addresses tiles the same way. A quilt as an
//! image file (its size, the aspect its views are shown at, its name) is
//! [`crate::render::quilt_image::QuiltImage`].

use crate::error::{Error, Result};
use crate::param::Param;

/// Keep in sync with `Quilt` in wgsl/shared/quilt.wgsl.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct QuiltUniform {
    /// Tiles per row and per column.
    pub grid: [u32; 2],
    /// Size of one tile in texels.
    pub tile: [u32; 2],
    /// The spatial image's size when compositing (the tile's otherwise).
    pub panel: [u32; 2],
    /// Compositing: 1 = up-sample tiles bilinearly, 0 = nearest texel.
    pub bilinear: u32,
    /// Padding.
    pub _pad: u32,
}

crate::shader::gpu_layout!(QuiltUniform, "Quilt", [grid, tile, panel, bilinear]);
const _: () = assert!(std::mem::size_of::<QuiltUniform>() == 32);

/// A grid of `cols × rows` tiles of `tile` texels holding `views` views.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct QuiltLayout {
    /// Tiles per row.
    pub cols: u32,
    /// Rows of tiles.
    pub rows: u32,
    /// Size of one view's tile in texels.
    pub tile: [u32; 2],
    /// Views stored (≤ cols × rows; the last tiles may be empty).
    pub views: u32,
}

impl QuiltLayout {
    /// The grid for `views` tiles of `tile`: the smallest largest side (so that the atlas fits
    /// the texture limits best), then the fewest empty tiles, then more columns than rows.
    pub fn for_views(views: u32, tile: [u32; 2]) -> Self {
        let views = views.max(1);
        let (cols, rows) = (1..=views)
            .map(|cols| (cols, views.div_ceil(cols)))
            .min_by_key(|&(cols, rows)| {
                let side = (cols as u64 * tile[0] as u64).max(rows as u64 * tile[1] as u64);
                (side, cols * rows - views, rows)
            })
            .expect("at least one grid");
        Self {
            cols,
            rows,
            tile,
            views,
        }
    }

    /// A given grid; fails when it has fewer tiles than `views`.
    pub fn with_grid(cols: u32, rows: u32, tile: [u32; 2], views: u32) -> Result<Self> {
        if cols == 0 || rows == 0 || (cols as u64 * rows as u64) < views as u64 {
            return Err(Error::invalid(
                Param::Quilt,
                format!("a {cols}x{rows} grid cannot hold {views} views"),
            ));
        }
        Ok(Self {
            cols,
            rows,
            tile,
            views,
        })
    }

    /// Size of the whole atlas in texels.
    pub fn size(&self) -> [u32; 2] {
        [
            self.cols.saturating_mul(self.tile[0]),
            self.rows.saturating_mul(self.tile[1]),
        ]
    }

    /// Top-left texel of view `view`'s tile (image rows top-down; view 0 is bottom-left).
    pub fn tile_origin(&self, view: u32) -> [u32; 2] {
        // Saturating: a grid read from a file name may be far beyond any texture (the atlas
        // refuses it by size before anything is drawn).
        let col = view % self.cols.max(1);
        let row_from_top = self.rows.saturating_sub(1 + view / self.cols.max(1));
        [
            col.saturating_mul(self.tile[0]),
            row_from_top.saturating_mul(self.tile[1]),
        ]
    }

    /// Width / height of one view.
    pub fn aspect(&self) -> f32 {
        self.tile[0] as f32 / self.tile[1] as f32
    }

    /// The GPU form (panel = one tile, nearest texel).
    pub fn uniform(&self) -> QuiltUniform {
        self.uniform_for_panel(self.tile, false)
    }

    /// The GPU form for compositing onto a `panel`-sized image, tiles up-sampled bilinearly
    /// or by the nearest texel.
    pub fn uniform_for_panel(&self, panel: [u32; 2], bilinear: bool) -> QuiltUniform {
        QuiltUniform {
            grid: [self.cols, self.rows],
            tile: self.tile,
            panel,
            bilinear: u32::from(bilinear),
            _pad: 0,
        }
    }

    /// `uniform` in a uniform buffer of its own (for one frame's bind group).
    pub(crate) fn uniform_buffer(
        &self,
        device: &wgpu::Device,
        uniform: QuiltUniform,
    ) -> wgpu::Buffer {
        crate::gpu::pass_params::constants_buffer(
            device,
            "quilt layout",
            wgpu::BufferUsages::UNIFORM,
            bytemuck::bytes_of(&uniform),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grids_hold_every_view_and_stay_compact() {
        for views in 1..=100 {
            let q = QuiltLayout::for_views(views, [512, 512]);
            assert!(q.cols * q.rows >= views, "{views}: {q:?}");
            assert!(
                q.cols * q.rows - views < q.cols.max(q.rows),
                "{views}: {q:?}"
            );
        }
        let q = QuiltLayout::for_views(8, [512, 512]);
        assert_eq!((q.cols, q.rows), (3, 3));
        let q = QuiltLayout::for_views(45, [420, 560]);
        assert!(q.size()[0].max(q.size()[1]) <= 3360, "{q:?}");
    }

    #[test]
    fn view_zero_is_bottom_left_then_left_to_right_bottom_to_top() {
        let q = QuiltLayout::with_grid(3, 2, [10, 20], 5).unwrap();
        assert_eq!(q.tile_origin(0), [0, 20]);
        assert_eq!(q.tile_origin(2), [20, 20]);
        assert_eq!(q.tile_origin(3), [0, 0]);
        assert_eq!(q.tile_origin(4), [10, 0]);
        assert!(QuiltLayout::with_grid(2, 2, [1, 1], 5).is_err());
    }
}
