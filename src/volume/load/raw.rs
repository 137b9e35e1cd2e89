//! Raw volumes: samples only, everything else from the caller.

use std::path::Path;

use super::{data_bytes, decode, format_error, to_volume, SampleType};
use crate::advice::{Advice, Setting};
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

impl RawSpec {
    /// A raw volume as the fuzzer feeds it (fuzz/fuzz_targets/raw.rs, replayed on stable by
    /// tests/formats/fuzz_regressions.rs): the description from the first 12 bytes (dimensions as three
    /// little-endian u16, the sample type and byte order, the z spacing, the header length),
    /// the file's bytes after them; `None` for fewer than 12 bytes.
    #[cfg(feature = "fuzzing")]
    pub fn from_fuzz_input(data: &[u8]) -> Option<(Self, &[u8])> {
        const KINDS: [SampleType; 8] = [
            SampleType::U8,
            SampleType::I8,
            SampleType::U16,
            SampleType::I16,
            SampleType::U32,
            SampleType::I32,
            SampleType::F32,
            SampleType::F64,
        ];
        let (head, file) = data.split_at_checked(12)?;
        let half = |i: usize| u16::from_le_bytes([head[i], head[i + 1]]);
        let spec = Self {
            dims: [half(0), half(2), half(4)].map(u32::from),
            kind: KINDS[usize::from(head[6]) % KINDS.len()],
            big_endian: head[7] & 1 == 1,
            spacing: [1.0, 1.0, 1.0 + f32::from(head[8])],
            header_bytes: u64::from(half(10)),
        };
        Some((spec, file))
    }
}

/// Load a raw volume; the file must hold exactly `header_bytes` + the samples (its size is
/// checked before it is read).
pub fn load_raw(path: &Path, spec: &RawSpec) -> Result<Volume> {
    let needed = needed_bytes(path, spec)?;
    let actual = crate::file::check_regular(path)?.len();
    check_length(path, spec, actual, needed)?;
    let bytes = std::fs::read(path).map_err(|e| Error::io(path, e))?;
    parse_raw(&bytes, path, spec)
}

/// A raw volume from the bytes of a file `path` (named in errors): exactly `header_bytes` + the
/// samples `spec` describes.
pub fn parse_raw(bytes: &[u8], path: &Path, spec: &RawSpec) -> Result<Volume> {
    let needed = needed_bytes(path, spec)?;
    check_length(path, spec, bytes.len() as u64, needed)?;
    let samples = decode(
        &bytes[spec.header_bytes as usize..],
        spec.kind,
        spec.big_endian,
    );
    to_volume(path, spec.dims, spec.spacing, samples, spec.kind)
}

/// The header plus the samples, checked for overflow and the voxel limit.
fn needed_bytes(path: &Path, spec: &RawSpec) -> Result<u64> {
    data_bytes(spec.dims.map(u64::from), spec.kind)
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
        })
}

fn check_length(path: &Path, spec: &RawSpec, actual: u64, needed: u64) -> Result<()> {
    if actual == needed {
        return Ok(());
    }
    let reason = format!(
        "{} bytes, but {} after a {}-byte header need {needed}{}",
        actual,
        super::samples(spec.dims, spec.kind),
        spec.header_bytes,
        if actual < needed { " (truncated?)" } else { "" },
    );
    // The fix for a file with more bytes than described, where they are a header.
    let advice = (actual > needed).then(|| {
        let header = actual - needed + spec.header_bytes;
        Advice::text("; ")
            .then(Setting::RawHeaderBytes(header))
            .then_text(" if the samples are at the end")
    });
    Err(Error::Volume {
        path: path.to_path_buf(),
        reason,
        advice,
    })
}
