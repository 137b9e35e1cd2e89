//! The library's error type: one variant per failure a user can act on.

use std::path::PathBuf;

/// Everything the library can fail with. User input never panics; it lands here.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// No wgpu adapter matched the requested backends / name.
    #[error("no GPU adapter found (backends: {backends}{name}); on a machine without a GPU install Mesa's lavapipe: apt-get install mesa-vulkan-drivers libvulkan1")]
    NoAdapter {
        /// The backends that were searched.
        backends: String,
        /// The adapter-name filter, formatted for the message.
        name: String,
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
        instead: String,
    },
    /// A size or count is above what the adapter allows.
    #[error("{what} = {value} exceeds the adapter limit {limit}")]
    LimitExceeded {
        /// Which quantity.
        what: String,
        /// The requested value.
        value: u64,
        /// The adapter's limit.
        limit: u64,
    },
    /// An input, or a renderer's per-view images, would need more memory than the budget
    /// (`crate::budget`; on the GPU too: software adapters allocate it from the same RAM).
    #[error("{what} needs {bytes} bytes, over the memory budget of {budget} bytes (raise it with budget::set_max_memory)")]
    MemoryBudget {
        /// What would be allocated, in words.
        what: String,
        /// Its cost.
        bytes: u64,
        /// The budget.
        budget: u64,
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
    #[error("invalid {name}: {reason}")]
    InvalidParameter {
        /// The parameter's name as the user knows it.
        name: &'static str,
        /// What is wrong with it.
        reason: String,
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
    #[error("calibration file {path}: {reason}")]
    Calibration {
        /// The file.
        path: PathBuf,
        /// What is wrong with it.
        reason: String,
    },
    /// A mesh file is malformed.
    #[error("mesh {path}: {reason}")]
    Mesh {
        /// The file.
        path: PathBuf,
        /// What is wrong with it.
        reason: String,
    },
    /// A point-cloud file is malformed, truncated or of an unsupported kind.
    #[error("point cloud {path}: {reason}")]
    Points {
        /// The file.
        path: PathBuf,
        /// What is wrong with it.
        reason: String,
    },
    /// A 3D Gaussian splat file (graphdeco PLY, `.splat`, `.spz`) is malformed, truncated or
    /// of an unsupported variant.
    #[error("Gaussian splats {path}: {reason}")]
    Gaussians {
        /// The file.
        path: PathBuf,
        /// What is wrong with it.
        reason: String,
    },
    /// A volume file is malformed, truncated or of an unsupported kind.
    #[error("volume {path}: {reason}")]
    Volume {
        /// The file.
        path: PathBuf,
        /// What is wrong with it.
        reason: String,
    },
    /// A file of an unknown format, of another kind of data than the command renders, or of
    /// a format this build does not read.
    #[error("{path}: {reason}")]
    Format {
        /// The file.
        path: PathBuf,
        /// What it is and what reads it.
        reason: String,
    },
    /// An image could not be read or written.
    #[error("image {path}: {reason}")]
    Image {
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

/// Result alias for the library.
pub type Result<T, E = Error> = std::result::Result<T, E>;

impl Error {
    pub(crate) fn io(path: &std::path::Path, error: std::io::Error) -> Self {
        Error::Io {
            path: path.to_path_buf(),
            error,
        }
    }

    pub(crate) fn invalid(name: &'static str, reason: impl Into<String>) -> Self {
        Error::InvalidParameter {
            name,
            reason: reason.into(),
        }
    }
}
