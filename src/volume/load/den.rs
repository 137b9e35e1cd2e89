//! VolPack `.den` density files (the format of VolPack's examples, e.g. `brainsmall.den`).
//!
//! Header (VolPack `denfile.c`): 29 shorts — `map_version` (1, or 0x0100 when written on a
//! machine of the other byte order), then `orig_min/max/len`, `extr_min/max/len`,
//! `map_min/max/len` (3 each), `map_warps` — and one int `map_length` = the product of
//! `map_len`; then `map_length` unsigned bytes, x fastest.

use std::path::Path;

use super::{format_error, to_volume, SampleType};
use crate::error::{Error, Result};
use crate::volume::{check_dims, Volume};

const HEADER_BYTES: usize = 29 * 2 + 4;

/// Load a `.den` file (unit spacing: the format has none).
pub fn load_den(path: &Path) -> Result<Volume> {
    crate::file::check_regular(path)?;
    let bytes = std::fs::read(path).map_err(|e| Error::io(path, e))?;
    parse_den(&bytes, path)
}

/// A `.den` file's `bytes` (`path` names it in errors).
pub fn parse_den(bytes: &[u8], path: &Path) -> Result<Volume> {
    if bytes.len() < HEADER_BYTES {
        return Err(format_error(
            path,
            format!(
                "{} bytes: shorter than the 62-byte .den header",
                bytes.len()
            ),
        ));
    }
    let big_endian = match [bytes[0], bytes[1]] {
        [1, 0] => false,
        [0, 1] => true,
        other => {
            return Err(format_error(
                path,
                format!("not a .den file (version bytes {other:?}, expected 1)"),
            ))
        }
    };
    let short = |i: usize| {
        let b = [bytes[2 * i], bytes[2 * i + 1]];
        if big_endian {
            i16::from_be_bytes(b)
        } else {
            i16::from_le_bytes(b)
        }
    };
    // map_len is shorts 25..28 (after version, 8 triples).
    let map_len = [short(25), short(26), short(27)];
    if map_len.iter().any(|&l| l <= 0) {
        return Err(format_error(
            path,
            format!("invalid dimensions {map_len:?} in the header"),
        ));
    }
    let len4: [u8; 4] = bytes[58..62].try_into().expect("4 bytes");
    let map_length = if big_endian {
        i32::from_be_bytes(len4)
    } else {
        i32::from_le_bytes(len4)
    };
    let dims = map_len.map(|l| l as u64);
    let count = check_dims(dims).map_err(|e| format_error(path, e.to_string()))?;
    if map_length as i64 != count as i64 {
        return Err(format_error(
            path,
            format!("inconsistent header: map_length {map_length} ≠ {map_len:?}"),
        ));
    }
    let data = &bytes[HEADER_BYTES..];
    if (data.len() as u64) < count {
        return Err(format_error(
            path,
            format!("truncated: {} of {count} density bytes", data.len()),
        ));
    }
    let samples = data[..count as usize].iter().map(|&b| b as f32).collect();
    to_volume(
        path,
        map_len.map(|l| l as u32),
        [1.0; 3],
        samples,
        SampleType::U8,
    )
}
