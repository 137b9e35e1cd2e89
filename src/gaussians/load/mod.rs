//! Gaussian splat files: graphdeco's `.ply` ([`parse_ply`]), antimatter15's `.splat`
//! ([`parse_splat`]) and Niantic's `.spz` ([`parse_spz`]). Each checks its counts against the
//! bytes present and the memory budget before allocating, and names the file and the problem.

mod ply;
mod splat;
mod spz;

use std::path::Path;

pub use ply::parse_ply;
pub use splat::parse_splat;
pub use spz::parse_spz;

pub(super) use super::unit_rotation as rotation;
use super::Gaussians;
use crate::error::{Error, Result};

/// Load a Gaussian splat file of any format this build reads, told by its first bytes, else
/// its extension; a file of another kind is refused as what it is (`Error::WrongKind`).
pub(super) fn load(path: &Path) -> Result<Gaussians> {
    use crate::formats::{expect, DataKind, Format};
    let format = expect(path, DataKind::Gaussians)?;
    let limit = crate::file::MAX_TEXT_BYTES;
    let bytes = crate::file::read_bounded(path, limit, "the Gaussian splat file limit")?;
    match format {
        Format::Ply => parse_ply(&bytes, path),
        Format::Splat => parse_splat(&bytes, path),
        Format::Spz => parse_spz(&bytes, path),
        other => Err(error(
            path,
            format!("{other} is not a Gaussian splat format"),
        )),
    }
}

/// The error for `path`.
fn error(path: &Path, reason: impl Into<String>) -> Error {
    Error::Gaussians {
        path: path.into(),
        reason: reason.into(),
    }
}

/// `gaussians` after [`Gaussians::validate`]'s checks, which every loader ends with.
fn checked(gaussians: Gaussians, path: &Path) -> Result<Gaussians> {
    match gaussians.problem() {
        Some(reason) => Err(error(path, reason)),
        None => Ok(gaussians),
    }
}
