//! The library's error type: one variant per failure a user can act on.

use std::path::PathBuf;

use crate::advice::{tail, Advice, Setting};
use crate::data_kind::DataKind;
use crate::param::Param;

/// Everything the library can fail with. User input never panics; it lands here.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// No wgpu adapter matched the requested backends / name.
    #[error("no GPU adapter found (backends: {backends}{name}); {available}")]
    NoAdapter {
        /// The backends that were searched.
        backends: String,
        /// The adapter-name filter, formatted for the message.
        name: String,
        /// The adapters there are on any backend and how to pick one (`WGPU_ADAPTER_NAME`,
        /// `WGPU_BACKEND`), or how to install one where there is none.
        available: String,
    },
    /// The adapter lacks a capability a requested mode needs.
    #[error("{purpose} needs {missing}, which adapter '{adapter}' lacks; {instead}")]
    MissingFeature {
        /// Adapter name and backend, e.g. `llvmpipe (LLVM 15.0.6, 256 bits) (Gl)`.
        adapter: String,
        /// The missing capabilities in words, with wgpu's feature names.
        missing: String,
        /// What needed them (a mode, as the user chose it).
        purpose: String,
        /// What to use instead.
        instead: Advice,
    },
    /// A size or count is above what the adapter allows.
    #[error("{what} = {value} exceeds the adapter limit {limit}{}", tail(.advice))]
    LimitExceeded {
        /// Which quantity.
        what: String,
        /// The requested value.
        value: u64,
        /// The adapter's limit.
        limit: u64,
        /// The parameter that sets the quantity, where the caller sets it directly (views,
        /// groups, the image size): the most it may be is then `limit`.
        param: Option<Param>,
        /// What to do instead, where there is a way round the limit.
        advice: Option<Advice>,
    },
    /// A frame too wide for a mode that renders one column per subpixel: the adapter's
    /// texture width limit divided by the columns per pixel is the widest frame it renders.
    #[error("a frame {} pixels wide is too wide for {mode}, which renders at subpixel resolution: {per_pixel} columns per pixel, {columns} in all, over the adapter's limit of {limit}; {mode} renders at most {max_width} pixels wide (else use {instead})", .size[0])]
    SubpixelWidth {
        /// The frame's size in pixels, as the caller asked for it.
        size: [u32; 2],
        /// Columns per pixel (subpixels, 3 on RGB panels).
        per_pixel: u32,
        /// The columns the mode's images would have: width × `per_pixel`.
        columns: u64,
        /// The adapter's largest texture side.
        limit: u32,
        /// The widest frame the mode renders: `limit / per_pixel`.
        max_width: u32,
        /// The mode, as the library names it (e.g. `Visibility::Exact`).
        mode: Setting,
        /// The mode to use instead, as the library names it.
        instead: Advice,
    },
    /// An input, or a renderer's per-view images, would need more memory than the budget
    /// (`crate::budget`; on the GPU too: software adapters allocate it from the same RAM).
    #[error("{what} needs {bytes} bytes, over the memory budget of {budget} bytes (raise it with {}, to at least {raise_to})", Setting::MaxMemory)]
    MemoryBudget {
        /// What would be allocated, in words.
        what: String,
        /// Its cost.
        bytes: u64,
        /// The budget.
        budget: u64,
        /// The smallest round figure the budget must be raised to (`budget::rounded_up`).
        raise_to: String,
    },
    /// Device creation failed.
    #[error("could not create a device on '{adapter}': {source}")]
    RequestDevice {
        /// Adapter name.
        adapter: String,
        /// wgpu's reason.
        source: wgpu::RequestDeviceError,
    },
    /// A parameter is outside its valid range (zero views, 0×0 image, NaN separation…).
    #[error("invalid {param}: {}{}", printable(.reason), tail(.advice))]
    InvalidParameter {
        /// The parameter.
        param: Param,
        /// What is wrong with it.
        reason: String,
        /// What to do about it, where the library names a setting.
        advice: Option<Advice>,
    },
    /// A display specification string could not be understood.
    #[error("display spec '{spec}': {reason}")]
    DisplaySpec {
        /// The spec as given.
        spec: String,
        /// What is wrong with it.
        reason: String,
    },
    /// A Looking Glass calibration file is unreadable or incomplete.
    #[error("calibration file {path}: {}", printable(.reason))]
    Calibration {
        /// The file.
        path: PathBuf,
        /// What is wrong with it.
        reason: String,
    },
    /// A mesh file is malformed.
    #[error("mesh {path}: {}", printable(.reason))]
    Mesh {
        /// The file.
        path: PathBuf,
        /// What is wrong with it.
        reason: String,
    },
    /// A point-cloud file is malformed, truncated or of an unsupported kind.
    #[error("point cloud {path}: {}", printable(.reason))]
    Points {
        /// The file.
        path: PathBuf,
        /// What is wrong with it.
        reason: String,
    },
    /// A 3D Gaussian splat file (graphdeco PLY, `.splat`, `.spz`) is malformed, truncated or
    /// of an unsupported variant.
    #[error("Gaussian splats {path}: {}", printable(.reason))]
    Gaussians {
        /// The file.
        path: PathBuf,
        /// What is wrong with it.
        reason: String,
    },
    /// A volume file is malformed, truncated or of an unsupported kind.
    #[error("volume {path}: {}{}", printable(.reason), tail(.advice))]
    Volume {
        /// The file.
        path: PathBuf,
        /// What is wrong with it.
        reason: String,
        /// What to do about it, where the library names a setting.
        advice: Option<Advice>,
    },
    /// A file of an unknown format, of another kind of data than the command renders, or of
    /// a format this build does not read.
    #[error("{path}: {}", printable(.reason))]
    Format {
        /// The file.
        path: PathBuf,
        /// What it is and what reads it.
        reason: String,
    },
    /// A file holds another kind of data than it was read as (`wanted`), or a kind that is
    /// not a scene (`wanted: None`: an image given to [`crate::load`]).
    #[error("{path}: this is {} ({}), {}", .holds.article(), printable(.detail), wrong_kind_advice(*.holds, *.wanted))]
    WrongKind {
        /// The file.
        path: PathBuf,
        /// The kind it holds.
        holds: DataKind,
        /// The kind it was read as; `None` where any scene was asked for.
        wanted: Option<DataKind>,
        /// Its format and what tells the kind ("NRRD", "PLY, 12 faces").
        detail: String,
    },
    /// An image could not be read or written.
    #[error("image {path}: {}{}", printable(.reason), tail(.advice))]
    Image {
        /// The file.
        path: PathBuf,
        /// What is wrong with it.
        reason: String,
        /// What to do about it, where the library names a setting.
        advice: Option<Advice>,
    },
    /// A video could not be read or written (`video` feature).
    #[error("video {path}: {}", printable(.reason))]
    Video {
        /// The file.
        path: PathBuf,
        /// What is wrong with it.
        reason: String,
    },
    /// I/O on a named file. The message carries the OS error, so it is deliberately not also
    /// the error's `source()`: printers of the error chain (`anyhow`'s `{:#}`) show it once.
    #[error("{path}: {error}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The OS error.
        error: std::io::Error,
    },
    /// `Renderer::encode` was called for a frame its renderer was not prepared for.
    #[error(
        "{renderer}: encode needs prepare() for this frame first ({frame}; prepared: {prepared})"
    )]
    NotPrepared {
        /// The renderer.
        renderer: &'static str,
        /// What the frame needs (display specialisation, size, scene).
        frame: String,
        /// What the renderer was last prepared for.
        prepared: String,
    },
    /// The GPU reported a validation or out-of-memory error for an operation.
    #[error("GPU error during {operation}: {message}")]
    Gpu {
        /// What was being done.
        operation: String,
        /// wgpu's message.
        message: String,
    },
}

/// `text` with its control characters escaped (`\u{1b}`, `\n`): a reason that quotes a file
/// never moves the cursor, rings or retitles the terminal it is printed on, whichever reader
/// built it.
pub(crate) fn printable(text: &str) -> std::borrow::Cow<'_, str> {
    if text.chars().any(char::is_control) {
        text.chars()
            .map(|c| match c.is_control() {
                true => c.escape_debug().to_string(),
                false => c.to_string(),
            })
            .collect::<String>()
            .into()
    } else {
        text.into()
    }
}

/// What to do with a file of kind `holds` read as `wanted`.
fn wrong_kind_advice(holds: DataKind, wanted: Option<DataKind>) -> String {
    match (holds, wanted) {
        (DataKind::Image, None) => {
            "not a scene: images are read as RGB-D colour or depth maps, or as quilts".into()
        }
        (_, None) => format!("read it as {}", holds.article()),
        (_, Some(wanted)) => format!("not {}: read it as {}", wanted.article(), holds.article()),
    }
}

/// Longest piece of a file's text an error quotes, in characters.
const QUOTED_CHARS: usize = 40;

/// `text` read from a file, quoted for an error message: in single quotes, control characters
/// escaped, at most 40 characters (then `…`). The one way readers echo what they could not
/// understand, so that a binary file named `.nrrd` shows as `'\u{1b}[31m…'`, never raw.
pub(crate) fn quote(text: impl AsRef<str>) -> String {
    let mut chars = text.as_ref().chars();
    let head: String = chars.by_ref().take(QUOTED_CHARS).collect();
    let more = if chars.next().is_some() { "…" } else { "" };
    format!("'{}{more}'", printable(&head))
}

/// Result alias for the library.
pub type Result<T, E = Error> = std::result::Result<T, E>;

impl Error {
    pub(crate) fn io(path: &std::path::Path, error: std::io::Error) -> Self {
        Error::Io {
            path: path.to_path_buf(),
            error,
        }
    }

    /// `Err(SubpixelWidth)` when a `size` frame at `per_pixel` columns per pixel is wider
    /// than `device` allows; `mode` renders so, `instead` does not.
    pub(crate) fn check_subpixel_width(
        device: &wgpu::Device,
        size: [u32; 2],
        per_pixel: u32,
        mode: Setting,
        instead: Advice,
    ) -> Result<()> {
        let limit = device.limits().max_texture_dimension_2d;
        let columns = u64::from(size[0]) * u64::from(per_pixel);
        if per_pixel > 1 && columns > u64::from(limit) {
            return Err(Error::SubpixelWidth {
                size,
                per_pixel,
                columns,
                limit,
                max_width: limit / per_pixel,
                mode,
                instead,
            });
        }
        Ok(())
    }

    pub(crate) fn invalid(param: Param, reason: impl Into<String>) -> Self {
        Error::InvalidParameter {
            param,
            reason: reason.into(),
            advice: None,
        }
    }

    /// The advice in this error's message, each as the message says it (the library's terms):
    /// a tool that names settings in its own words replaces each with [`Advice::words`].
    pub fn advice(&self) -> Vec<Advice> {
        match self {
            Error::MissingFeature { instead, .. } => vec![instead.clone()],
            Error::SubpixelWidth { mode, instead, .. } => vec![(*mode).into(), instead.clone()],
            Error::MemoryBudget { .. } => vec![Setting::MaxMemory.into()],
            Error::LimitExceeded { advice, .. }
            | Error::InvalidParameter { advice, .. }
            | Error::Volume { advice, .. }
            | Error::Image { advice, .. } => advice.iter().cloned().collect(),
            _ => Vec::new(),
        }
    }
}
