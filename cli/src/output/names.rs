//! The files an output is written to: the quilt's grid and its Looking Glass name (a name
//! that says another quilt refused), per-view file names, and every name a run will write
//! (for `Claims::check`).

use std::path::{Path, PathBuf};

use anyhow::{bail, Result};
use autostereo::frame::Frame;
use autostereo::render::quilt_image::{strip_quilt_suffix, QuiltChoice, QuiltImage, QuiltName};

use super::flags::{OutputArg, OutputArgs};

/// The size of the one image `--output`'s format makes of `frame` (every format but views).
pub fn image_size(frame: &Frame, output: &OutputArgs) -> Result<[u32; 2]> {
    Ok(match output.format.stereo(frame.size) {
        Some((format, eye)) => format.output_size(eye),
        None if output.format == OutputArg::Quilt => frame_quilt(frame, output)?.size,
        None => frame.size,
    })
}

/// The quilt `--output quilt` writes for `frame` (the library's rule, `Display::quilt`):
/// `--quilt` and `--quilt-size` override the grid and the image's size; `--view-size` /
/// `--view-scale` set the tiles' size. An MP4 `--out` without `--quilt-size` gets a quilt
/// H.264 encodes (`video::h264_quilt_size`).
pub fn frame_quilt(frame: &Frame, output: &OutputArgs) -> Result<QuiltImage> {
    let scaled = frame.view_scale != [1.0; 2];
    let mut choice = QuiltChoice {
        grid: output.quilt_grid,
        size: output.quilt_size,
        tile: scaled.then(|| frame.view_size()),
    };
    let mp4 = output
        .out
        .as_deref()
        .and_then(autostereo::video::VideoFormat::of_path)
        == Some(autostereo::video::VideoFormat::Mp4);
    let quilt = quilt_for(frame, output, &choice)?;
    match autostereo::video::h264_quilt_size(quilt.size, frame.size)
        .filter(|_| mp4 && choice.size.is_none())
    {
        Some(size) => {
            choice = QuiltChoice {
                size: Some(size),
                tile: None,
                ..choice
            };
            quilt_for(frame, output, &choice)
        }
        None => Ok(quilt),
    }
}

fn quilt_for(frame: &Frame, output: &OutputArgs, choice: &QuiltChoice) -> Result<QuiltImage> {
    frame
        .display
        .quilt(frame.camera.views, frame.size, choice)
        .map_err(|e| match (&e, output.quilt_grid) {
            (
                autostereo::Error::InvalidParameter {
                    param: autostereo::Param::Quilt,
                    reason,
                    ..
                },
                Some([c, r]),
            ) => {
                // The library says the grid and suggests one; here both as the flag.
                let said = format!("{c}x{r}: ");
                let reason = reason.strip_prefix(&said).unwrap_or(reason);
                anyhow::anyhow!(
                    "--quilt {c}x{r}: {}",
                    reason.replace("e.g. ", "e.g. --quilt ")
                )
            }
            _ => e.into(),
        })
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
        let video = autostereo::video::VideoFormat::of_path(out);
        if let Some(format) = video {
            format.check_size(out, image_size(frame, output)?)?;
        }
        let outs: Vec<PathBuf> = match (turntable, video) {
            (Some(frames), None) => (0..frames).map(|k| numbered(out, k, quilt)).collect(),
            _ => vec![out.clone()],
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
fn check_quilt_name(out: &Path, quilt: &QuiltImage) -> Result<()> {
    let name = out
        .file_name()
        .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
    let stem = out
        .file_stem()
        .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
    let base = strip_quilt_suffix(&stem);
    let Some(said) = (base != stem).then(|| QuiltName::parse(&name)).flatten() else {
        return Ok(());
    };
    // The exact suffix this layout writes is its own even where rounding its aspect to four
    // decimals moves it by more than 1 % (tiles thinner than 1:200).
    if quilt.says(&said) || stem.ends_with(&quilt.suffix()) {
        return Ok(());
    }
    let (cols, rows, aspect) = (said.cols, said.rows, said.aspect);
    let layout = &quilt.layout;
    let ours = format!("{base}{}.png", quilt.suffix());
    if (cols, rows) == (layout.cols, layout.rows) {
        bail!(
            "--out {}: the name says views of aspect {aspect}, but this quilt's are {:.4}; name \
             it {ours} (or {base}.png: the suffix is added)",
            out.display(),
            quilt.aspect
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
        true => strip_quilt_suffix(&stem),
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
