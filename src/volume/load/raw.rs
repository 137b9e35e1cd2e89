//! Raw volumes: samples only, everything else from the caller.

use std::path::Path;

use super::{data_bytes, decode, format_error, to_volume, SampleType};
use crate::error::{Error, Result};
use crate::volume::Volume;

/// How to read a raw file.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RawSpec {
    /// Voxels along x, y, z (x fastest).
    pub dims: [u32; 3],
    /// Sample type.
    pub kind: SampleType,
    /// Samples are big-endian.
    pub big_endian: bool,
    /// Voxel spacing.
    pub spacing: [f32; 3],
    /// Bytes to skip at the start (a header the format doesn't describe).
    pub header_bytes: u64,
}

/// Load a raw volume; the file must hold exactly `header_bytes` + the samples.
pub fn load_raw(path: &Path, spec: &RawSpec) -> Result<Volume> {
    let needed = data_bytes(spec.dims.map(u64::from), spec.kind)
        .map_err(|e| format_error(path, e.to_string()))?
        .checked_add(spec.header_bytes)
        .ok_or_else(|| {
            format_error(
                path,
                format!(
                    "a {}-byte header plus the samples overflow a file size",
                    spec.header_bytes
                ),
            )
        })?;
    let actual = crate::file::check_regular(path)?.len();
    if actual != needed {
        return Err(format_error(
            path,
            format!(
                "{} bytes, but {:?} {:?} samples after a {}-byte header need {needed}{}",
                actual,
                spec.dims,
                spec.kind,
                spec.header_bytes,
                if actual < needed { " (truncated?)" } else { "" }
            ),
        ));
    }
    let bytes = std::fs::read(path).map_err(|e| Error::io(path, e))?;
    let samples = decode(
        &bytes[spec.header_bytes as usize..],
        spec.kind,
        spec.big_endian,
    );
    to_volume(path, spec.dims, spec.spacing, samples, spec.kind)
}
