//! LAS and LAZ lidar point clouds, through the `las` crate (LAZ by its `laz` decoder): every
//! point's position and, in the formats that have it, its RGB colour. Positions are kept
//! relative to the header's bounding box centre, in f64 until then: lidar coordinates are
//! hundreds of kilometres from their origin (UTM), where an f32 would keep only decimetres.
//! The renderers frame the cloud's own bounds, so the shift moves nothing on screen.

use std::path::Path;

use glam::DVec3;

mod scan;

use crate::error::{Error, Result};
use crate::points::PointCloud;
use scan::{check_sizes, LASZIP_CHUNK_SIZE_DEFAULT};

/// Points decoded per batch (the whole cloud is never held twice)...
const BATCH: u64 = 1 << 16;
/// ...and at most this many bytes of records per batch (a record may be 64 KiB long).
const BATCH_BYTES: u64 = 16 << 20;

/// Load a `.las` or `.laz` file.
pub(super) fn load(path: &Path) -> Result<PointCloud> {
    let bytes = crate::file::read_bounded(path, crate::file::MAX_TEXT_BYTES, "the LAS limit")?;
    parse(bytes).map_err(|reason| Error::Points {
        path: path.into(),
        reason,
    })
}

/// Parse LAS or LAZ `bytes` (errors are plain reasons; [`load`] adds the path).
pub fn parse(bytes: Vec<u8>) -> std::result::Result<PointCloud, String> {
    let size = bytes.len() as u64;
    let mut bytes = bytes;
    // Every size the las and laz crates allocate from is checked against the file first.
    if let Some(at) = check_sizes(&bytes)? {
        // A point-wise LAZ file has no chunks, so no chunk size: LASzip 2.0 left it 0, which
        // laz reads as variable-size chunks and then panics ("Variable-size chunks, but no
        // chunk table"). LASzip ignores it, as laz does for any fixed size.
        bytes[at..at + 4].copy_from_slice(&LASZIP_CHUNK_SIZE_DEFAULT.to_le_bytes());
    }
    let mut reader = las::Reader::new(std::io::Cursor::new(bytes))
        .map_err(|e| format!("malformed LAS header: {e}"))?;
    let header = reader.header();
    let n = header.number_of_points();
    let format = *header.point_format();
    let record = u64::from(format.len()).max(1);
    crate::budget::check_points(n).map_err(|e| e.to_string())?;
    let bounds = header.bounds();
    let centre = DVec3::new(
        0.5 * (bounds.min.x + bounds.max.x),
        0.5 * (bounds.min.y + bounds.max.y),
        0.5 * (bounds.min.z + bounds.max.z),
    );
    let centre = if centre.is_finite() {
        centre
    } else {
        DVec3::ZERO
    };
    // A LAZ header's count is not bounded by the file's size: reserve no more points than it
    // has bytes, and grow as points are decoded.
    let reserve = n.min(size) as usize;
    let mut positions = Vec::with_capacity(reserve);
    let mut colors: Option<Vec<[u16; 3]>> = format.has_color.then(|| Vec::with_capacity(reserve));
    let batch_points = (BATCH_BYTES / record).clamp(1, BATCH);
    let mut read = 0u64;
    while read < n {
        let batch = reader
            .read_points(batch_points.min(n - read))
            .map_err(|e| point_error(read, n, e))?;
        if batch.is_empty() {
            return Err(format!("truncated: {read} of the header's {n} points"));
        }
        for point in batch.points() {
            let point = point.map_err(|e| format!("point {read}: {e}"))?;
            let p = (DVec3::new(point.x, point.y, point.z) - centre).as_vec3();
            if !p.is_finite() {
                return Err(format!("point {read} has a non-finite position"));
            }
            positions.push(p);
            if let Some(colors) = &mut colors {
                let c = point.color.unwrap_or_default();
                colors.push([c.red, c.green, c.blue]);
            }
            read += 1;
        }
    }
    Ok(PointCloud {
        positions,
        normals: None,
        colors: colors.map(|c| scale_colors(&c)),
        radii: None,
    })
}

/// A decoding error at point `read` of `n`; the compressed data running out (the laz decoder
/// reads past its end) said as such.
fn point_error(read: u64, n: u64, e: las::Error) -> String {
    let end = match &e {
        las::Error::Io(io) | las::Error::LasZipError(laz::LasZipError::IoError(io)) => {
            io.kind() == std::io::ErrorKind::UnexpectedEof
        }
        _ => false,
    };
    if end {
        format!(
            "point {read}: the point data ends before the header's {n} points (truncated or \
             corrupt: {e})"
        )
    } else {
        format!("point {read}: {e}")
    }
}

/// LAS colours are 16-bit, but many writers store 8-bit values in them: a cloud whose channels
/// all stay within 0…255 is read as 8-bit (as PDAL and CloudCompare do), else as 16-bit.
fn scale_colors(colors: &[[u16; 3]]) -> Vec<[f32; 3]> {
    let eight_bit = colors.iter().flatten().all(|&c| c <= 255);
    let full = if eight_bit { 255.0 } else { 65535.0 };
    colors
        .iter()
        .map(|c| c.map(|v| f32::from(v) / full))
        .collect()
}

#[cfg(test)]
mod tests;
