//! The files an output is written to: the quilt's grid and its Looking Glass name (a name
//! that says another quilt refused), per-view file names, and every name a run will write
//! (for `Claims::check`).

use std::path::{Path, PathBuf};

use anyhow::{bail, Result};
use autostereo::display::Display;
use autostereo::frame::Frame;
use autostereo::render::quilt::QuiltLayout;

use super::flags::{OutputArg, OutputArgs};

/// The quilt of `views` views `--output quilt` writes for `display` at `size` (and the
/// viewer's quilt preview shows): the `--quilt` grid, else a Looking Glass's own (the family's
/// grid, tiles of the panel's aspect within the family's quilt size), else the grid for the
/// view count; tiles of the Looking Glass's size, else of `size`.
fn quilt_layout(
    display: &Display,
    views: u32,
    size: [u32; 2],
    grid: Option<[u32; 2]>,
) -> Result<QuiltLayout> {
    let Some([cols, rows]) = grid else {
        return Ok(display.quilt(views, size));
    };
    let tile = display.default_quilt(views).map_or(size, |q| q.tile);
    let layout = QuiltLayout::with_grid(cols, rows, tile, views)
        .map_err(|e| anyhow::anyhow!("--quilt {cols}x{rows}: {e}"))?;
    // A whole empty row plays as blank views in Looking Glass software.
    let empty = u64::from(cols) * u64::from(rows) - u64::from(views);
    if empty >= u64::from(cols) {
        let fit = QuiltLayout::for_views(views, tile);
        bail!(
            "--quilt {cols}x{rows}: {empty} of its tiles would be empty for {views} \
             views (a whole row or more); give a grid with fewer, e.g. --quilt {}x{}",
            fit.cols,
            fit.rows
        );
    }
    Ok(layout)
}

/// The quilt `--output quilt` writes for `frame`: `--view-size` / `--view-scale` set the
/// tiles' size, over a Looking Glass's own.
pub fn frame_quilt(frame: &Frame, output: &OutputArgs) -> Result<QuiltLayout> {
    let scaled = frame.view_scale != [1.0; 2];
    let size = if scaled {
        frame.view_size()
    } else {
        frame.size
    };
    let mut layout = quilt_layout(&frame.display, frame.camera.views, size, output.quilt_grid)?;
    if scaled {
        layout.tile = size;
    }
    Ok(layout)
}

/// The files a run will write, each with the flag that names it: `out` in `output`'s format
/// (with `turntable` frames, each frame's), then a `hole_mask`. For `Claims::check`,
/// before the run renders; a quilt `--out` whose name says another quilt is refused here.
pub fn planned(
    frame: &Frame,
    output: &OutputArgs,
    turntable: Option<u32>,
    hole_mask: Option<&Path>,
) -> Result<Vec<(PathBuf, &'static str)>> {
    let mut planned = Vec::new();
    if let Some(out) = &output.out {
        let quilt = output.format == OutputArg::Quilt;
        let layout = match quilt {
            true => Some(frame_quilt(frame, output)?),
            false => None,
        };
        if let Some(layout) = &layout {
            check_quilt_name(out, layout)?;
        }
        let outs: Vec<PathBuf> = match turntable {
            Some(frames) => (0..frames).map(|k| numbered(out, k, quilt)).collect(),
            None => vec![out.clone()],
        };
        let views = frame.camera.views;
        for out in outs {
            match (&output.format, &layout) {
                (OutputArg::Views, _) => {
                    planned.extend((0..views).map(|v| view_file(&out, v, views)))
                }
                (_, Some(layout)) => planned.push(layout.file_name(&out)),
                _ => planned.push(out),
            }
        }
    }
    let mut planned: Vec<(PathBuf, &'static str)> =
        planned.into_iter().map(|p| (p, "--out")).collect();
    planned.extend(hole_mask.map(|p| (p.to_path_buf(), "--hole-mask")));
    Ok(planned)
}

/// Refuses an `--out` whose name already says another quilt than `layout` (`x_qs5x9a0.75.png`
/// for a 3×3 quilt): the name would promise Looking Glass software a grid or aspect the file
/// does not have. An aspect within 1 % is this quilt's (as reading a quilt allows).
fn check_quilt_name(out: &Path, layout: &QuiltLayout) -> Result<()> {
    let name = out
        .file_name()
        .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
    let stem = out
        .file_stem()
        .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
    let base = autostereo::render::quilt::strip_quilt_suffix(&stem);
    let Some(said) = (base != stem)
        .then(|| autostereo::render::quilt::parse_quilt_name(&name))
        .flatten()
    else {
        return Ok(());
    };
    // The exact suffix this layout writes is its own even where rounding its aspect to four
    // decimals moves it by more than 1 % (tiles thinner than 1:200).
    if layout.says(said) || stem.ends_with(&layout.suffix()) {
        return Ok(());
    }
    let (cols, rows, aspect) = said;
    let ours = format!("{base}{}.png", layout.suffix());
    if (cols, rows) == (layout.cols, layout.rows) {
        bail!(
            "--out {}: the name says views of aspect {aspect}, but this quilt's are {:.4}; name \
             it {ours} (or {base}.png: the suffix is added)",
            out.display(),
            layout.aspect()
        );
    }
    bail!(
        "--out {}: the name says a {cols}x{rows} quilt, but this one is {}x{} ({ours}); pass \
         --quilt {cols}x{rows} for that grid, or name it {base}.png (the suffix is added)",
        out.display(),
        layout.cols,
        layout.rows
    );
}

/// `{stem}_{v}.png` next to `out`, `v` zero-padded to the digits of view `views − 1` (at
/// least two), so that a listing sorts the files in view order.
pub fn view_file(out: &Path, v: u32, views: u32) -> PathBuf {
    let digits = (views.saturating_sub(1).max(1).ilog10() + 1).max(2) as usize;
    PathBuf::from(format!(
        "{}_{v:0digits$}.png",
        out.with_extension("").display()
    ))
}

/// `{stem}_{k:04}.png` next to `out`; for a quilt (`quilt`) without the stem's `_qs…` suffix,
/// which each frame's name gets after its number.
pub fn numbered(out: &Path, k: u32, quilt: bool) -> PathBuf {
    let stem = out
        .file_stem()
        .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
    let base = match quilt {
        true => autostereo::render::quilt::strip_quilt_suffix(&stem),
        false => &stem,
    };
    out.with_file_name(format!("{base}_{k:04}.png"))
}

#[cfg(test)]
mod tests {
    #[test]
    fn view_files_are_zero_padded_to_sort_in_view_order() {
        use super::view_file;
        use std::path::{Path, PathBuf};
        let out = Path::new("dir/head.png");
        assert_eq!(view_file(out, 3, 8), PathBuf::from("dir/head_03.png"));
        assert_eq!(view_file(out, 7, 45), PathBuf::from("dir/head_07.png"));
        assert_eq!(view_file(out, 7, 101), PathBuf::from("dir/head_007.png"));
        assert_eq!(view_file(out, 0, 1), PathBuf::from("dir/head_00.png"));
        let mut names: Vec<PathBuf> = (0..45).map(|v| view_file(out, v, 45)).collect();
        let in_order = names.clone();
        names.sort();
        assert_eq!(names, in_order);
    }

    #[test]
    fn numbered_files_keep_the_directory_and_drop_the_extension() {
        use super::numbered;
        use std::path::{Path, PathBuf};
        let p = numbered(Path::new("out/head.png"), 7, false);
        assert_eq!(p, PathBuf::from("out/head_0007.png"));
        // A quilt's frames get the suffix after the number (output::write), once.
        let q = numbered(Path::new("out/b_qs2x4a1.3333.png"), 0, true);
        assert_eq!(q, PathBuf::from("out/b_0000.png"));
        let spatial = numbered(Path::new("out/b_qs2x4a1.3333.png"), 0, false);
        assert_eq!(spatial, PathBuf::from("out/b_qs2x4a1.3333_0000.png"));
    }
}
