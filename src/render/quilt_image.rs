//! A quilt as an image file, in Looking Glass's convention (docs/DISPLAYS.md, "Quilts"): a
//! grid of `cols × rows` tiles of whole pixels, floor(W / cols) × floor(H / rows), laid from
//! the image's bottom-left corner (view 0) with the remainder on the right and at the top
//! unused; each view is shown at the aspect the name says (`…_qs{cols}x{rows}a{aspect}`), the
//! tile stretched to it whatever its own pixel aspect. [`QuiltLayout`] is the grid of tiles
//! alone, as the tiled methods' atlases use it.

use std::path::{Path, PathBuf};

use crate::advice::{Advice, Setting};
use crate::error::{Error, Result};
use crate::image_io::RgbImage;
use crate::param::Param;
use crate::render::quilt::QuiltLayout;

/// What a Looking Glass quilt's name says: `…_qs{cols}x{rows}a{aspect}`, optionally followed
/// by `z{zoom}` and `f{focus}` (in either order) as some Looking Glass tools write them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuiltName {
    /// Tiles per row.
    pub cols: u32,
    /// Rows of tiles.
    pub rows: u32,
    /// The aspect (width / height) each view is shown at.
    pub aspect: f32,
    /// `z…`: the zoom the quilt asks to be shown at, where the name has it.
    pub zoom: Option<f32>,
    /// `f…`: the focus (parallax shift) the quilt asks for, where the name has it.
    pub focus: Option<f32>,
}

impl QuiltName {
    /// The quilt suffix in `name` (a file name or stem), if it has one: the last `_qs`.
    pub fn parse(name: &str) -> Option<Self> {
        let at = name.rfind("_qs")?;
        let rest = &name[at + 3..];
        let (cols, rest) = rest.split_once('x')?;
        let (rows, rest) = rest.split_once('a')?;
        let (aspect, mut rest) = number(rest)?;
        let (cols, rows): (u32, u32) = (cols.parse().ok()?, rows.parse().ok()?);
        let (mut zoom, mut focus) = (None, None);
        while let Some(tag) = rest.chars().next().filter(|c| matches!(c, 'z' | 'f')) {
            let Some((value, after)) = number(&rest[1..]) else {
                break;
            };
            match tag {
                'z' => zoom = Some(value),
                _ => focus = Some(value),
            }
            rest = after;
        }
        (cols > 0 && rows > 0 && aspect > 0.0).then_some(Self {
            cols,
            rows,
            aspect,
            zoom,
            focus,
        })
    }
}

/// A finite number at the start of `text` (digits, one point, a leading minus), and the rest.
fn number(text: &str) -> Option<(f32, &str)> {
    let end = text
        .char_indices()
        .find(|&(i, c)| !(c.is_ascii_digit() || c == '.' || (c == '-' && i == 0)))
        .map_or(text.len(), |(i, _)| i);
    let digits = text[..end].trim_end_matches('.');
    let value: f32 = digits.parse().ok()?;
    value.is_finite().then_some((value, &text[digits.len()..]))
}

/// What a caller fixes of the quilt [`crate::display::Display::quilt`] makes; `None` leaves it
/// to the display.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct QuiltChoice {
    /// The grid, columns × rows.
    pub grid: Option<[u32; 2]>,
    /// The image's size in pixels (tiles are floor(size / grid)).
    pub size: Option<[u32; 2]>,
    /// The tile's size in pixels, where views are rendered at a size of their own (the
    /// image is then the grid of them).
    pub tile: Option<[u32; 2]>,
}

/// A quilt image: its tiles, its size in pixels and the aspect its views are shown at.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuiltImage {
    /// The grid, the whole-pixel tile and the views the quilt holds.
    pub layout: QuiltLayout,
    /// The image's size (at least the grid's; the rest unused).
    pub size: [u32; 2],
    /// The aspect (width / height) each view is shown at: the display's for a Looking Glass
    /// quilt. Tiles are stretched to it.
    pub aspect: f32,
    /// The zoom the quilt's name asks for (read, not applied).
    pub zoom: Option<f32>,
    /// The focus the quilt's name asks for (read, not applied).
    pub focus: Option<f32>,
}

impl QuiltImage {
    /// A quilt of `layout`'s tiles in an image of `size` (at least `layout.size()`), its views
    /// shown at `aspect`.
    pub fn new(layout: QuiltLayout, size: [u32; 2], aspect: f32) -> Result<Self> {
        let grid = layout.size();
        if size[0] < grid[0] || size[1] < grid[1] {
            return Err(Error::invalid(
                Param::QuiltSize,
                format!(
                    "{}x{}: smaller than {}x{} tiles of {}x{} ({}x{})",
                    size[0],
                    size[1],
                    layout.cols,
                    layout.rows,
                    layout.tile[0],
                    layout.tile[1],
                    grid[0],
                    grid[1]
                ),
            ));
        }
        if !(aspect.is_finite() && aspect > 0.0) {
            return Err(Error::invalid(
                Param::Quilt,
                format!("view aspect {aspect}: must be a positive number"),
            ));
        }
        Ok(Self {
            layout,
            size,
            aspect,
            zoom: None,
            focus: None,
        })
    }

    /// A quilt image that is exactly its tiles, views shown at the tiles' own aspect.
    pub fn of_tiles(layout: QuiltLayout) -> Self {
        Self {
            layout,
            size: layout.size(),
            aspect: layout.aspect(),
            zoom: None,
            focus: None,
        }
    }

    /// The quilt of `views` views with a `cols × rows` grid in an image of `size`: tiles of
    /// floor(W / cols) × floor(H / rows) (Looking Glass's rule), views shown at `aspect`.
    pub fn in_size(grid: [u32; 2], size: [u32; 2], views: u32, aspect: f32) -> Result<Self> {
        let [cols, rows] = grid;
        if cols == 0 || rows == 0 || size[0] < cols || size[1] < rows {
            return Err(Error::invalid(
                Param::Quilt,
                format!(
                    "a {cols}x{rows} grid does not fit an image of {}x{} (tiles need one pixel \
                     at least)",
                    size[0], size[1]
                ),
            ));
        }
        let tile = [size[0] / cols, size[1] / rows];
        Self::new(
            QuiltLayout::with_grid(cols, rows, tile, views)?,
            size,
            aspect,
        )
    }

    /// The quilt in an image of `size` pixels named `name`, read as Looking Glass reads it: the
    /// grid from `grid`, else from the name's `_qs{cols}x{rows}a{aspect}`; tiles of
    /// floor(W / cols) × floor(H / rows) from the bottom-left, the remainder ignored; views
    /// shown at the name's aspect (the tiles' own where only `grid` says the layout). The
    /// quilt holds `views` views (≤ cols × rows: quilts often leave the last tiles empty).
    pub fn read(name: &str, size: [u32; 2], grid: Option<[u32; 2]>, views: u32) -> Result<Self> {
        let named = QuiltName::parse(name);
        let [cols, rows] = match (grid, named) {
            (Some(grid), _) => grid,
            (None, Some(named)) => [named.cols, named.rows],
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
        if cols == 0 || rows == 0 || size[0] < cols || size[1] < rows {
            return Err(Error::invalid(
                Param::Quilt,
                format!(
                    "{name} is {}x{}, too small for a {cols}x{rows} grid of whole-pixel tiles",
                    size[0], size[1]
                ),
            ));
        }
        let tile = [size[0] / cols, size[1] / rows];
        let layout = QuiltLayout::with_grid(cols, rows, tile, views)?;
        let aspect = named.map_or(layout.aspect(), |n| n.aspect);
        Ok(Self {
            zoom: named.and_then(|n| n.zoom),
            focus: named.and_then(|n| n.focus),
            ..Self::new(layout, size, aspect)?
        })
    }

    /// The pixels the tiles cover, cut from `image` (of this quilt's size): the bottom-left
    /// `cols·tile × rows·tile` (the remainder is not the quilt's).
    pub fn tiles(&self, image: &RgbImage) -> Result<RgbImage> {
        if [image.width, image.height] != self.size {
            return Err(Error::invalid(
                Param::Quilt,
                format!(
                    "the image is {}x{}, the quilt {}x{}",
                    image.width, image.height, self.size[0], self.size[1]
                ),
            ));
        }
        let [w, h] = self.layout.size();
        let top = self.size[1] - h;
        let mut out = RgbImage::new(w, h);
        let row = w as usize * 3;
        for y in 0..h {
            let src = ((top + y) as usize * image.width as usize) * 3;
            let dst = y as usize * row;
            out.data[dst..dst + row].copy_from_slice(&image.data[src..src + row]);
        }
        Ok(out)
    }

    /// `tiles` (an image of the grid's size) placed at the bottom-left of an image of this
    /// quilt's size, the remainder black.
    pub fn image(&self, tiles: &RgbImage) -> Result<RgbImage> {
        let [w, h] = self.layout.size();
        if [tiles.width, tiles.height] != [w, h] {
            return Err(Error::invalid(
                Param::Quilt,
                format!(
                    "the tiles are {}x{}, the grid {w}x{h}",
                    tiles.width, tiles.height
                ),
            ));
        }
        if self.size == [w, h] {
            return Ok(tiles.clone());
        }
        RgbImage::check_size(self.size[0], self.size[1])?;
        let mut out = RgbImage::new(self.size[0], self.size[1]);
        let top = self.size[1] - h;
        let row = w as usize * 3;
        for y in 0..h {
            let src = y as usize * row;
            let dst = ((top + y) as usize * out.width as usize) * 3;
            out.data[dst..dst + row].copy_from_slice(&tiles.data[src..src + row]);
        }
        Ok(out)
    }

    /// The Looking Glass name suffix, `_qs{cols}x{rows}a{aspect}` (the aspect to four decimals,
    /// trailing zeros dropped).
    pub fn suffix(&self) -> String {
        let aspect = format!("{:.4}", self.aspect);
        let aspect = aspect.trim_end_matches('0').trim_end_matches('.');
        format!("_qs{}x{}a{aspect}", self.layout.cols, self.layout.rows)
    }

    /// Whether a name says this quilt: the same grid, the aspect within 1 % (as Looking Glass
    /// names round it).
    pub fn says(&self, name: &QuiltName) -> bool {
        (name.cols, name.rows) == (self.layout.cols, self.layout.rows)
            && (self.aspect / name.aspect - 1.0).abs() <= 0.01
    }

    /// `path` named as Looking Glass software expects: this quilt's suffix before the
    /// extension, in place of a suffix the name already ends in (`x_qs3x3a1.png` for a 5×9
    /// quilt is `x_qs5x9a0.75.png`, not `x_qs3x3a1_qs5x9a0.75.png`); a name whose suffix
    /// already says this quilt ([`QuiltImage::says`]) is kept as it is.
    pub fn file_name(&self, path: &Path) -> PathBuf {
        let stem = path
            .file_stem()
            .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
        let suffix = self.suffix();
        let named = QuiltName::parse(&stem).filter(|_| strip_quilt_suffix(&stem) != stem);
        if stem.ends_with(&suffix) || named.is_some_and(|said| self.says(&said)) {
            return path.to_path_buf();
        }
        let ext = path
            .extension()
            .map_or_else(|| "png".to_string(), |e| e.to_string_lossy().into_owned());
        let base = strip_quilt_suffix(&stem);
        path.with_file_name(format!("{base}{suffix}.{ext}"))
    }
}

/// `stem` without the Looking Glass suffix it ends in (`_qs{cols}x{rows}a{aspect}` and any
/// `z`/`f` after it), if any.
pub fn strip_quilt_suffix(stem: &str) -> &str {
    let Some(at) = stem.rfind("_qs") else {
        return stem;
    };
    let whole = stem[at + 3..]
        .chars()
        .all(|c| c.is_ascii_digit() || matches!(c, 'x' | 'a' | 'z' | 'f' | '.' | '-'));
    if whole && QuiltName::parse(&stem[at..]).is_some() {
        &stem[..at]
    } else {
        stem
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_follow_looking_glass_and_parse_back() {
        let layout = QuiltLayout::with_grid(5, 9, [420, 560], 45).unwrap();
        let q = QuiltImage::of_tiles(layout);
        assert_eq!(q.suffix(), "_qs5x9a0.75");
        let named = q.file_name(Path::new("out/dragon.png"));
        assert_eq!(named, Path::new("out/dragon_qs5x9a0.75.png"));
        assert_eq!(q.file_name(&named), named);
        let said = QuiltName::parse(named.to_str().unwrap()).unwrap();
        assert_eq!((said.cols, said.rows, said.aspect), (5, 9, 0.75));
        let square = QuiltImage::of_tiles(QuiltLayout::with_grid(3, 3, [64, 64], 8).unwrap());
        assert_eq!(square.suffix(), "_qs3x3a1");
        // A name's own suffix is replaced, not doubled; other `_qs` text is kept.
        assert_eq!(
            q.file_name(Path::new("out/dragon_qs3x3a1.png")),
            Path::new("out/dragon_qs5x9a0.75.png")
        );
        assert_eq!(strip_quilt_suffix("a_qs3x3a1.7778"), "a");
        assert_eq!(strip_quilt_suffix("a_qs8x6a0.75z1.2f-0.5"), "a");
        assert_eq!(strip_quilt_suffix("a_qs3x3a1_final"), "a_qs3x3a1_final");
        assert_eq!(strip_quilt_suffix("a_qsx"), "a_qsx");
        assert_eq!(QuiltName::parse("plain.png"), None);
        assert_eq!(QuiltName::parse("x_qs0x3a1.png"), None);
        assert_eq!(QuiltName::parse("x_qs3x3a.png"), None);
        assert_eq!(QuiltName::parse("x_qs3x3a-1.png"), None);
    }

    #[test]
    fn zoom_and_focus_are_read_where_the_name_has_them() {
        let n = QuiltName::parse("scan_qs8x6a0.75z1.25f-0.4.mp4").unwrap();
        assert_eq!((n.cols, n.rows, n.aspect), (8, 6, 0.75));
        assert_eq!((n.zoom, n.focus), (Some(1.25), Some(-0.4)));
        let n = QuiltName::parse("scan_qs8x6a0.75f2.png").unwrap();
        assert_eq!((n.zoom, n.focus), (None, Some(2.0)));
        let n = QuiltName::parse("scan_qs8x6a0.75.png").unwrap();
        assert_eq!((n.zoom, n.focus), (None, None));
    }

    /// Looking Glass's own quilts: a gen-3 16" 5999² 7×7 quilt named a1.778 (tiles 857², of
    /// aspect 1, shown at 16:9) and a gen-2 4096² 5×9 one (tiles 819×455, one pixel left over
    /// at the top and right).
    #[test]
    fn whole_pixel_tiles_from_the_bottom_left_shown_at_the_names_aspect() {
        let q = QuiltImage::read("lkg_qs7x7a1.778.png", [5999, 5999], None, 49).unwrap();
        assert_eq!(
            (q.layout.cols, q.layout.rows, q.layout.tile),
            (7, 7, [857, 857])
        );
        assert_eq!(q.aspect, 1.778);
        let q = QuiltImage::read("x_qs5x9a1.77.jpg", [4096, 4096], None, 45).unwrap();
        assert_eq!(q.layout.tile, [819, 455]);
        assert_eq!(q.layout.size(), [4095, 4095]);
        // The grid from the flag: the tiles' own aspect.
        let q = QuiltImage::read("plain.png", [300, 200], Some([3, 2]), 6).unwrap();
        assert_eq!((q.layout.tile, q.aspect), ([100, 100], 1.0));
        assert!(QuiltImage::read("plain.png", [300, 200], None, 6).is_err());
        assert!(QuiltImage::read("x_qs9x9a1.png", [8, 8], None, 1).is_err());
        // Cut and placed back: the tiles are the bottom-left, the remainder black.
        let q = QuiltImage::read("t_qs2x2a1.png", [5, 5], None, 4).unwrap();
        let mut image = RgbImage::new(5, 5);
        for y in 0..5 {
            for x in 0..5 {
                image.set(x, y, 0, (10 * y + x) as u8);
            }
        }
        let tiles = q.tiles(&image).unwrap();
        assert_eq!([tiles.width, tiles.height], [4, 4]);
        assert_eq!(
            tiles.get(0, 0, 0),
            10,
            "row 1 of the image: row 0 is left over"
        );
        let back = q.image(&tiles).unwrap();
        assert_eq!(back.get(0, 4, 0), image.get(0, 4, 0));
        assert_eq!(back.get(0, 0, 0), 0);
        assert_eq!(back.get(4, 4, 0), 0);
    }
}
