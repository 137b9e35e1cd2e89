//! The Looking Glass quilt layout: N view images tiled into one atlas, view 0 bottom-left,
//! left → right then bottom → top. The tiled method renders into this layout, so its atlas is
//! a quilt as it stands; `wgsl/shared/quilt.wgsl` addresses tiles the same way.

use std::path::{Path, PathBuf};

use crate::advice::{Advice, Setting};
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

    /// The layout of a quilt image of `size` pixels named `name`: the grid from `grid`, else
    /// from the name's `_qs{cols}x{rows}a{aspect}`; tiles are the size over the grid (which
    /// must divide it); the quilt holds `views` views (≤ cols × rows: Looking Glass quilts
    /// often leave the last tiles empty). A name's aspect that disagrees with the tiles' by
    /// more than 1 % is refused: the grid would then be a guess.
    pub fn for_image(
        name: &str,
        size: [u32; 2],
        grid: Option<[u32; 2]>,
        views: u32,
    ) -> Result<Self> {
        let named = parse_quilt_name(name);
        let [cols, rows] = match (grid, named) {
            (Some(grid), _) => grid,
            (None, Some((cols, rows, _))) => [cols, rows],
            (None, None) => {
                return Err(Error::InvalidParameter {
                    param: Param::Quilt,
                    reason: format!(
                        "{name}: no grid; name it …_qs{{cols}}x{{rows}}a{{aspect}}.png (Looking \
                         Glass's convention) or give the grid"
                    ),
                    advice: Some(Advice::text(" (").then(Setting::QuiltGrid).then_text(")")),
                })
            }
        };
        if cols == 0 || rows == 0 || !size[0].is_multiple_of(cols) || !size[1].is_multiple_of(rows)
        {
            return Err(Error::invalid(
                Param::Quilt,
                format!(
                    "{name} is {}x{}, which a {cols}x{rows} grid does not divide into whole tiles",
                    size[0], size[1]
                ),
            ));
        }
        let tile = [size[0] / cols, size[1] / rows];
        if let (None, Some((_, _, aspect))) = (grid, named) {
            let tiles = tile[0] as f32 / tile[1] as f32;
            if (tiles / aspect - 1.0).abs() > 0.01 {
                return Err(Error::invalid(
                    Param::Quilt,
                    format!(
                        "{name}: the name says views of aspect {aspect}, its {cols}x{rows} tiles \
                         of {}x{} have {tiles:.4}",
                        tile[0], tile[1]
                    ),
                ));
            }
        }
        Self::with_grid(cols, rows, tile, views)
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

    /// The Looking Glass name suffix, `_qs{cols}x{rows}a{aspect}`.
    pub fn suffix(&self) -> String {
        let aspect = format!("{:.4}", self.aspect());
        let aspect = aspect.trim_end_matches('0').trim_end_matches('.');
        format!("_qs{}x{}a{aspect}", self.cols, self.rows)
    }

    /// Whether a name's grid and view aspect (`parse_quilt_name`) say this layout: the same
    /// grid, the aspect within 1 % (as [`QuiltLayout::for_image`] reads a name).
    pub fn says(&self, (cols, rows, aspect): (u32, u32, f32)) -> bool {
        (cols, rows) == (self.cols, self.rows) && (self.aspect() / aspect - 1.0).abs() <= 0.01
    }

    /// `path` named as Looking Glass software expects: this layout's suffix before the
    /// extension, in place of a suffix the name already ends in (`x_qs3x3a1.png` for a 5×9
    /// quilt is `x_qs5x9a0.75.png`, not `x_qs3x3a1_qs5x9a0.75.png`); a name whose suffix
    /// already says this layout ([`QuiltLayout::says`]) is kept as it is.
    pub fn file_name(&self, path: &Path) -> PathBuf {
        let stem = path
            .file_stem()
            .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
        let suffix = self.suffix();
        let named = parse_quilt_name(&stem).filter(|_| strip_quilt_suffix(&stem) != stem);
        if stem.ends_with(&suffix) || named.is_some_and(|said| self.says(said)) {
            return path.to_path_buf();
        }
        let ext = path
            .extension()
            .map_or_else(|| "png".to_string(), |e| e.to_string_lossy().into_owned());
        let base = strip_quilt_suffix(&stem);
        path.with_file_name(format!("{base}{suffix}.{ext}"))
    }
}

/// `stem` without the Looking Glass suffix it ends in (`_qs{cols}x{rows}a{aspect}`), if any.
pub fn strip_quilt_suffix(stem: &str) -> &str {
    let Some(at) = stem.rfind("_qs") else {
        return stem;
    };
    let whole = stem[at + 3..]
        .chars()
        .all(|c| c.is_ascii_digit() || matches!(c, 'x' | 'a' | '.'));
    if whole && parse_quilt_name(&stem[at..]).is_some() {
        &stem[..at]
    } else {
        stem
    }
}

/// Grid and view aspect read from a Looking Glass quilt name (`…_qs5x9a0.75.png`), if it has
/// one.
pub fn parse_quilt_name(name: &str) -> Option<(u32, u32, f32)> {
    let at = name.rfind("_qs")?;
    let rest = &name[at + 3..];
    let (cols, rest) = rest.split_once('x')?;
    let (rows, rest) = rest.split_once('a')?;
    let aspect: String = rest
        .chars()
        .take_while(|c| c.is_ascii_digit() || *c == '.')
        .collect();
    let aspect = aspect.trim_end_matches('.');
    let (cols, rows, aspect) = (
        cols.parse().ok()?,
        rows.parse().ok()?,
        aspect.parse::<f32>().ok()?,
    );
    (cols > 0 && rows > 0 && aspect.is_finite() && aspect > 0.0).then_some((cols, rows, aspect))
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

    #[test]
    fn names_follow_looking_glass_and_parse_back() {
        let q = QuiltLayout::with_grid(5, 9, [420, 560], 45).unwrap();
        assert_eq!(q.suffix(), "_qs5x9a0.75");
        let named = q.file_name(Path::new("out/dragon.png"));
        assert_eq!(named, Path::new("out/dragon_qs5x9a0.75.png"));
        assert_eq!(q.file_name(&named), named);
        let name = named.file_name().unwrap().to_str().unwrap();
        assert_eq!(parse_quilt_name(name), Some((5, 9, 0.75)));
        let square = QuiltLayout::with_grid(3, 3, [64, 64], 8).unwrap();
        assert_eq!(square.suffix(), "_qs3x3a1");
        // A name's own suffix is replaced, not doubled; other `_qs` text is kept.
        assert_eq!(
            q.file_name(Path::new("out/dragon_qs3x3a1.png")),
            Path::new("out/dragon_qs5x9a0.75.png")
        );
        assert_eq!(strip_quilt_suffix("a_qs3x3a1.7778"), "a");
        assert_eq!(strip_quilt_suffix("a_qs3x3a1_final"), "a_qs3x3a1_final");
        assert_eq!(strip_quilt_suffix("a_qsx"), "a_qsx");
        assert_eq!(parse_quilt_name("x_qs3x3a1.png"), Some((3, 3, 1.0)));
        assert_eq!(parse_quilt_name("plain.png"), None);
        assert_eq!(parse_quilt_name("x_qs0x3a1.png"), None);
        assert_eq!(parse_quilt_name("x_qs3x3a.png"), None);
    }
}
