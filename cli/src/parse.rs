//! Flag values: the parsers clap calls (sizes, points, view pairs, counts, methods, `auto`),
//! and the check every output path gets. Nothing here knows a command.

use anyhow::{bail, Result};
use autostereo::render::Method;
use clap::builder::TypedValueParser;

/// `WxH` → [w, h], both ≥ 1.
pub fn parse_size(s: &str) -> Result<[u32; 2], String> {
    let (w, h) = s
        .split_once(['x', 'X'])
        .ok_or_else(|| format!("'{s}' is not WIDTHxHEIGHT"))?;
    let parse = |v: &str| {
        v.trim()
            .parse::<u32>()
            .map_err(|_| format!("'{s}' is not WIDTHxHEIGHT"))
    };
    let size = [parse(w)?, parse(h)?];
    if size[0] == 0 || size[1] == 0 {
        return Err(format!("size {s}: width and height must be at least 1"));
    }
    Ok(size)
}

/// Most timed frames a command accepts: enough for any median, never an overflow.
pub const MAX_FRAMES: u32 = 100_000;

/// `--frames`: 1 ..= [`MAX_FRAMES`].
pub fn frames_parser() -> clap::builder::RangedI64ValueParser<u32> {
    clap::value_parser!(u32).range(1..=i64::from(MAX_FRAMES))
}

/// `--view-scale`: a number in (0, 1].
pub fn parse_view_scale(s: &str) -> Result<f32, String> {
    match s.trim().parse::<f32>() {
        Ok(v) if v > 0.0 && v <= 1.0 => Ok(v),
        _ => Err(format!("'{s}' is not a number in (0, 1]")),
    }
}

/// `A,B` → [a, b] of `T`; errors say `names` (e.g. "A,B") and `numbers`, what they must be.
fn parse_two<T: std::str::FromStr>(s: &str, names: &str, numbers: &str) -> Result<[T; 2], String> {
    let (a, b) = s
        .split_once(',')
        .ok_or_else(|| format!("'{s}' is not {names}"))?;
    let parse = |v: &str| {
        v.trim()
            .parse::<T>()
            .map_err(|_| format!("'{s}' is not {numbers}"))
    };
    Ok([parse(a)?, parse(b)?])
}

/// `--eyes L,R`: the left and right views.
pub fn parse_eyes(s: &str) -> Result<[u32; 2], String> {
    parse_two(s, "L,R", "two view numbers L,R")
}

/// A point X,Y in pixels, either negative: a virtual desktop (X11, Wayland, Windows) puts a
/// monitor left of or above the primary at negative coordinates, and a window's origin on a
/// panel is negative where the window starts left of or above it (`--origin`, `--position`).
pub fn parse_point(s: &str) -> Result<[i32; 2], String> {
    parse_two(s, "X,Y", "two whole numbers X,Y (negative allowed)")
}

/// The same file: the same path, or both existing and canonically the same.
pub fn same_file(a: &std::path::Path, b: &std::path::Path) -> bool {
    a == b
        || matches!(
            (std::fs::canonicalize(a), std::fs::canonicalize(b)),
            (Ok(x), Ok(y)) if x == y
        )
}

/// Fail unless `path` is a `.png` in an existing directory (so errors come before minutes of
/// rendering, and no empty file is left behind).
pub fn check_output(path: &std::path::Path) -> Result<()> {
    let png = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("png"));
    if !png {
        bail!("{}: only PNG is written (name it .png)", path.display());
    }
    check_directory(path)
}

/// `check_output` for an output that may also be a video (`.mp4`, `.gif`).
pub fn check_output_or_video(path: &std::path::Path) -> Result<()> {
    let png = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("png"));
    if !png && !crate::output::video::is_video(path) {
        bail!(
            "{}: PNG, MP4 or GIF is written (name it .png, .mp4 or .gif)",
            path.display()
        );
    }
    check_directory(path)
}

fn check_directory(path: &std::path::Path) -> Result<()> {
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        if !dir.is_dir() {
            bail!("output directory {} does not exist", dir.display());
        }
    }
    Ok(())
}

/// A flag's value: one of the library's `T`, or `auto` (`None`: the library picks).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OrAuto<T>(pub Option<T>);

impl<T: clap::ValueEnum + Clone + Send + Sync + 'static> OrAuto<T> {
    /// The parser of `auto` (which means `auto_help`) and of `T`'s values.
    pub fn parser(auto_help: &'static str) -> impl TypedValueParser<Value = Self> {
        let values = std::iter::once(clap::builder::PossibleValue::new("auto").help(auto_help))
            .chain(T::value_variants().iter().filter_map(T::to_possible_value));
        clap::builder::PossibleValuesParser::new(values)
            .map(|name| OrAuto(T::from_str(&name, false).ok()))
    }
}

/// `--clusters auto|C`: view clusters of the single pass's compute rasteriser (C ≥ 1).
pub fn view_clusters(text: &str) -> Result<autostereo::mesh::ViewClusters, String> {
    use autostereo::mesh::ViewClusters;
    if text == "auto" {
        return Ok(ViewClusters::PerTriangle);
    }
    match text.parse::<u32>() {
        Ok(c) if c >= 1 => Ok(ViewClusters::Fixed(c)),
        _ => Err(format!(
            "'{text}': expected auto or a cluster count of at least 1"
        )),
    }
}

/// `--method NAME`: one of the library's [`Method`] names.
pub fn method_parser() -> impl clap::builder::TypedValueParser<Value = Method> {
    clap::builder::PossibleValuesParser::new(Method::ALL.map(|m| m.name()))
        .map(|name| name.parse::<Method>().expect("one of the possible values"))
}
