//! LAS and LAZ lidar point clouds, through the `las` crate (LAZ by its `laz` decoder): every
//! point's position and, in the formats that have it, its RGB colour. Positions are kept
//! relative to the header's bounding box centre, in f64 until then: lidar coordinates are
//! hundreds of kilometres from their origin (UTM), where an f32 would keep only decimetres.
//! The renderers frame the cloud's own bounds, so the shift moves nothing on screen.

use std::path::Path;

use glam::DVec3;

use super::PointCloud;
use crate::error::{Error, Result};

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
    crate::points::check_point_budget(n).map_err(|e| e.to_string())?;
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

// The size scan. The las crate zero-fills an extended VLR's 64-bit length and computes the
// end of the points as count × record length (an overflow from a LAS 1.4 count); the laz
// crate reserves its chunk table for the count the table's header gives, panics on a laszip
// VLR without items (and sums its items' sizes in 16 bits, then splits records by that sum),
// and zero-fills each layer of a LAS 1.4 (layered) chunk to the 32-bit size the chunk's
// header declares. So before the crates see a file, its public header, VLRs, EVLRs, LAZ chunk
// table header and layered chunk headers are read here and every size checked against the
// file.

/// The laszip VLR that describes a LAZ file's compression.
const LASZIP_USER_ID: &[u8] = b"laszip encoded";
const LASZIP_RECORD_ID: u16 = 22204;
/// A VLR's header (reserved, user id, record id, 16-bit length, description), an EVLR's (the
/// same with a 64-bit length).
const VLR_HEADER: u64 = 54;
const EVLR_HEADER: u64 = 60;
/// LASzip's default chunk size (points), written in place of a point-wise file's 0.
const LASZIP_CHUNK_SIZE_DEFAULT: u32 = 50_000;
/// What the laz decoder holds per extra byte of a record: an adaptive 256-symbol model
/// (about 2.3 KiB) in each of 4 contexts.
const LAZ_BYTES_PER_EXTRA_BYTE: u64 = 10 << 10;

/// `N` little-endian bytes at `at`, if the file has them.
fn le<const N: usize>(bytes: &[u8], at: u64) -> Option<[u8; N]> {
    let at = usize::try_from(at).ok()?;
    bytes.get(at..at.checked_add(N)?)?.try_into().ok()
}

fn u16_at(bytes: &[u8], at: u64) -> Option<u16> {
    le(bytes, at).map(u16::from_le_bytes)
}

fn u32_at(bytes: &[u8], at: u64) -> Option<u32> {
    le(bytes, at).map(u32::from_le_bytes)
}

fn u64_at(bytes: &[u8], at: u64) -> Option<u64> {
    le(bytes, at).map(u64::from_le_bytes)
}

/// Check the sizes a LAS or LAZ file declares against its length (see above). What the las
/// crate refuses cleanly by itself (a short header, a bad signature) is left to it. Gives the
/// byte of a point-wise LAZ file's chunk size when it reads as variable (0 or `u32::MAX`), for
/// [`parse`] to make it fixed.
fn check_sizes(bytes: &[u8]) -> std::result::Result<Option<usize>, String> {
    let size = bytes.len() as u64;
    if bytes.len() < 227 || &bytes[..4] != b"LASF" {
        return Ok(None);
    }
    let field = |at: u64| u32_at(bytes, at).unwrap_or(0);
    let version = (bytes[24], bytes[25]);
    let header_size = u16_at(bytes, 94).unwrap_or(0);
    let offset = u64::from(field(96));
    let vlrs = field(100);
    let compressed = bytes[104] & 0x80 != 0;
    let record = u64::from(u16_at(bytes, 105).unwrap_or(0));
    let mut points = u64::from(field(107));
    // As the las crate reads the header: the waveform start from 1.3, the EVLRs and 64-bit
    // point count in 1.4 (the legacy count wins when it is not 0), then any padding.
    let mut read = 227u64;
    if version == (1, 3) {
        read = 235;
    }
    let mut evlrs = None;
    if version == (1, 4) {
        let (Some(start), Some(count), Some(count_64)) =
            (u64_at(bytes, 235), u32_at(bytes, 243), u64_at(bytes, 247))
        else {
            return Ok(None);
        };
        if points == 0 {
            points = count_64;
        }
        if start > 0 && count > 0 {
            evlrs = Some((start, count));
        }
        read = 375;
    }
    let standard = match version {
        v if v <= (1, 2) => 227,
        (1, 3) => 235,
        _ => 375,
    };
    read += u64::from(header_size.saturating_sub(standard));
    // The VLRs, one after another from the end of the header.
    let mut at = read;
    let mut laszip = None;
    for k in 0..vlrs {
        if size.saturating_sub(at) < VLR_HEADER {
            return Err(format!(
                "truncated: the header lists {vlrs} VLRs, the file ends in VLR {k} (byte {at})"
            ));
        }
        let len = u64::from(u16_at(bytes, at + 20).unwrap_or(0));
        let data = at + VLR_HEADER;
        if len > size - data {
            return Err(format!(
                "VLR {k} at byte {at} declares {len} bytes, but only {} are left in the file",
                size - data
            ));
        }
        let user = &bytes[at as usize + 2..at as usize + 18];
        let user = user.split(|&b| b == 0).next().unwrap_or(user);
        if laszip.is_none()
            && user == LASZIP_USER_ID
            && u16_at(bytes, at + 18) == Some(LASZIP_RECORD_ID)
        {
            laszip = Some((data, &bytes[data as usize..(data + len) as usize]));
        }
        at = data + len;
    }
    // The point records (uncompressed: all of them in the file).
    let end_of_points = points
        .checked_mul(record)
        .and_then(|b| b.checked_add(offset))
        .ok_or_else(|| format!("{points} points of {record} bytes: more than a file holds"))?;
    if !compressed && end_of_points > size {
        return Err(format!(
            "truncated: the header says {points} points of {record} bytes from byte {offset}, \
             but the file has {size} bytes"
        ));
    }
    let mut pointwise_chunk_size = None;
    if compressed {
        check_laz(bytes, laszip.map(|(_, vlr)| vlr), offset, points, record)?;
        // A point-wise compressor (1) and a chunk size laz reads as variable.
        if let Some((data, vlr)) = laszip {
            if u16_at(vlr, 0) == Some(1) && matches!(u32_at(vlr, 12), Some(0 | u32::MAX)) {
                pointwise_chunk_size = Some(data as usize + 12);
            }
        }
    }
    // The EVLRs (las 0.11 reads the first), each header and length in the file.
    if let Some((start, count)) = evlrs {
        let mut at = start;
        for k in 0..count {
            if size.saturating_sub(at) < EVLR_HEADER {
                if k == 0 {
                    return Err(format!(
                        "the header's first EVLR, at byte {start}, lies past the end of the file \
                         ({size} bytes)"
                    ));
                }
                break;
            }
            let len = u64_at(bytes, at + 20).unwrap_or(0);
            let data = at + EVLR_HEADER;
            if len > size - data {
                return Err(format!(
                    "EVLR {k} at byte {at} declares {len} bytes, but only {} are left in the file",
                    size - data
                ));
            }
            at = data + len;
        }
    }
    Ok(pointwise_chunk_size)
}

/// A LAZ file's laszip VLR, chunk table header and layered chunk headers, and the memory its
/// decompression takes (`points` records of `record` bytes), before the laz crate sees them.
fn check_laz(
    bytes: &[u8],
    laszip: Option<&[u8]>,
    offset: u64,
    points: u64,
    record: u64,
) -> std::result::Result<(), String> {
    let size = bytes.len() as u64;
    // Without a laszip VLR, or with a short one, the las and laz crates refuse the file.
    let Some(vlr) = laszip else {
        return Ok(());
    };
    let (Some(compressor), Some(chunk_size), Some(items)) =
        (u16_at(vlr, 0), u32_at(vlr, 12), u16_at(vlr, 32))
    else {
        return Ok(());
    };
    if items == 0 {
        return Err("the laszip VLR lists no point items".into());
    }
    // Each item's size is its type's (extra bytes: any), and together they make the record.
    let (mut sum, mut extra, mut first_version, mut layers) = (0u64, 0u64, 0u16, 0u64);
    let mut layered = true;
    for i in 0..u64::from(items) {
        let at = 34 + 6 * i;
        let (Some(kind), Some(len), Some(version)) =
            (u16_at(vlr, at), u16_at(vlr, at + 2), u16_at(vlr, at + 4))
        else {
            return Ok(());
        };
        if i == 0 {
            first_version = version;
        }
        // The type's size and, in a layered (LAS 1.4) chunk, its layers.
        let (fixed, item_layers) = match kind {
            0 => (None, None),
            6 => (Some(20), None),
            7 => (Some(8), None),
            8 => (Some(6), None),
            9 => (Some(29), None),
            10 => (Some(30), Some(9)),
            11 => (Some(6), Some(1)),
            12 => (Some(8), Some(2)),
            13 => (Some(29), Some(1)),
            14 => (None, Some(u64::from(len))),
            _ => return Ok(()), // an unknown item: refused by laz
        };
        if let Some(fixed) = fixed {
            if len != fixed {
                return Err(format!(
                    "laszip item {i} (type {kind}) declares {len} bytes, its type has {fixed}"
                ));
            }
        } else {
            extra += u64::from(len);
        }
        match item_layers {
            Some(n) => layers += n,
            None => layered = false,
        }
        sum += u64::from(len);
    }
    if sum != record {
        return Err(format!(
            "the laszip VLR's items make points of {sum} bytes, the header's records are {record}"
        ));
    }
    let decompressed = points.saturating_mul(record);
    crate::budget::check(
        || format!("decompressing {points} LAZ points of {record} bytes"),
        decompressed.saturating_add(extra.saturating_mul(LAZ_BYTES_PER_EXTRA_BYTE)),
    )
    .map_err(|e| e.to_string())?;
    // Chunked compressors: the point data starts with the offset of the chunk table (when it
    // is not past the data, the file's last 8 bytes give it, as laz reads it).
    let chunked = compressor == 2 || compressor == 3;
    let first_chunk = if chunked { offset + 8 } else { offset };
    let mut table_at = None;
    if chunked {
        let Some(mut table) = le(bytes, offset).map(i64::from_le_bytes) else {
            return Err(format!(
                "truncated LAZ: no chunk table offset at byte {offset} (the file has {size} bytes)"
            ));
        };
        if table <= offset as i64 {
            table = size
                .checked_sub(8)
                .and_then(|at| le(bytes, at))
                .map_or(0, i64::from_le_bytes);
        }
        // Else no table: fixed-size chunks are read in sequence, variable ones refused.
        if table > offset as i64 {
            let table = table as u64;
            table_at = Some(table);
            let Some(chunks) = table.checked_add(4).and_then(|at| u32_at(bytes, at)) else {
                return Err(format!(
                    "truncated LAZ: its chunk table at byte {table} lies past the end of the file \
                     ({size} bytes)"
                ));
            };
            // Every chunk starts with a point stored whole, before the table (one may be
            // empty: laz writes a last chunk even of no points).
            let data = table.saturating_sub(first_chunk);
            let most = data / record.max(1) + 1;
            if u64::from(chunks) > most {
                return Err(format!(
                    "the LAZ chunk table at byte {table} lists {chunks} chunks, but the {data} \
                     bytes of points before it hold at most {most} (each starts with a \
                     {record}-byte point)"
                ));
            }
            // Variable-size chunks take each chunk's point count from the table: laz indexes
            // the table for the first chunk, and past an empty one panics.
            let variable = matches!(chunk_size, 0 | u32::MAX);
            if chunks == 0 && points > 0 && variable {
                return Err(format!(
                    "the LAZ chunk table at byte {table} lists no chunks, but the header counts \
                     {points} points in variable-size chunks"
                ));
            }
            // Variable-size chunks: laz enters a chunk after each chunk's points, reading its
            // count from the table, and panics (an index out of bounds) past the table's last
            // chunk, so the table's counts must cover the header's points. Read as laz reads it
            // (arithmetic-coded, one entry per chunk counted above); a table laz cannot read is
            // left to laz, which refuses it or (layered chunks) reads the counts from the chunks.
            if variable && chunks > 0 {
                let mut source = std::io::Cursor::new(bytes);
                source.set_position(table);
                if let Ok(entries) = laz::laszip::ChunkTable::read(&mut source, true) {
                    let held = entries
                        .as_ref()
                        .iter()
                        .fold(0u64, |sum, entry| sum.saturating_add(entry.point_count));
                    if held < points {
                        return Err(format!(
                            "the LAZ chunk table at byte {table} lists {held} points (in {chunks} \
                             chunks), but the header counts {points}"
                        ));
                    }
                }
            }
            // Fixed-size chunks (laz reads them in sequence, each of the VLR's size): as many as
            // the header's points need.
            if !variable && u64::from(chunks) * u64::from(chunk_size) < points {
                return Err(format!(
                    "the LAZ chunk table at byte {table} lists {chunks} chunks of at most \
                     {chunk_size} points each, but the header counts {points}"
                ));
            }
        }
    }
    // Layered chunks (LAS 1.4 items, versions 3 and 4): a whole point, the chunk's point count
    // and each layer's size, then the layers, which laz reads whole. It reads chunk after
    // chunk in sequence until it has the header's points.
    if layered && matches!(first_version, 3 | 4) {
        // Fixed-size chunks: as many as the points need. Variable ones: those before the table
        // (laz follows the table's point counts).
        let (per_chunk, end) = match chunk_size {
            // Point-wise (compressor 1): one chunk of all the points, whatever the size says.
            _ if compressor == 1 => (points, size),
            0 | u32::MAX => (1, table_at.unwrap_or(0)),
            n => (u64::from(n), size),
        };
        let mut at = first_chunk;
        let (mut covered, mut k) = (0u64, 0u64);
        while covered < points && at < end {
            let sizes = at + record + 4;
            let Some(end_of_sizes) = sizes.checked_add(4 * layers).filter(|&end| end <= size)
            else {
                break; // laz fails reading it, before any layer
            };
            let total: u64 = (0..layers)
                .map(|l| u64::from(u32_at(bytes, sizes + 4 * l).unwrap_or(0)))
                .sum();
            if total > size - end_of_sizes {
                return Err(format!(
                    "LAZ chunk {k} at byte {at} declares layers of {total} bytes, but only {} are \
                     left in the file",
                    size - end_of_sizes
                ));
            }
            at = end_of_sizes + total;
            covered = covered.saturating_add(per_chunk);
            k += 1;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A small cloud written by the las crate: `version`, point `format`, compressed or not,
    /// with a VLR and (LAS 1.4) an EVLR.
    fn cloud(version: (u8, u8), format: u8, compressed: bool) -> Vec<u8> {
        let mut builder = las::Builder::from(version);
        builder.point_format = las::point::Format::new(format).unwrap();
        builder.point_format.is_compressed = compressed;
        let vlr = |data| las::Vlr {
            user_id: "autostereo".into(),
            record_id: 7,
            description: "test".into(),
            data,
        };
        builder.vlrs.push(vlr(vec![1; 10]));
        if version == (1, 4) {
            builder.evlrs.push(vlr(vec![2; 16]));
        }
        let (time, color) = (
            builder.point_format.has_gps_time,
            builder.point_format.has_color,
        );
        let header = builder.into_header().unwrap();
        let mut writer = las::Writer::new(std::io::Cursor::new(Vec::new()), header).unwrap();
        for i in 0..300 {
            let t = f64::from(i);
            writer
                .write_point(las::Point {
                    x: t,
                    y: t * 0.5,
                    z: 1.0,
                    gps_time: time.then_some(t),
                    color: color.then(|| las::Color::new(i, 2 * i, 3 * i)),
                    ..Default::default()
                })
                .unwrap();
        }
        writer.into_inner().unwrap().into_inner()
    }

    fn put(bytes: &mut [u8], at: u64, value: &[u8]) {
        bytes[at as usize..at as usize + value.len()].copy_from_slice(value);
    }

    fn refused(bytes: Vec<u8>, expected: &str) {
        let e = check_sizes(&bytes).unwrap_err();
        assert!(e.contains(expected), "'{e}' lacks '{expected}'");
        // parse() gives the scan's error, without a panic.
        let e = parse(bytes).err().unwrap();
        assert!(e.contains(expected), "'{e}' lacks '{expected}'");
    }

    #[test]
    fn well_formed_files_pass_the_scan() {
        for (version, format, compressed) in [
            ((1, 2), 1, false),
            ((1, 2), 3, true),
            ((1, 4), 6, false),
            ((1, 4), 6, true),
            ((1, 4), 7, true),
        ] {
            let bytes = cloud(version, format, compressed);
            check_sizes(&bytes).unwrap();
            let cloud = parse(bytes).unwrap();
            assert_eq!(cloud.len(), 300, "{version:?} format {format}");
        }
        for seed in ["cloud.las", "cloud.laz"] {
            let path = Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("fuzz/seeds/las")
                .join(seed);
            check_sizes(&std::fs::read(path).unwrap()).unwrap();
        }
    }

    #[test]
    fn vlrs_and_evlrs_past_the_end_are_refused() {
        // The VLR's 16-bit length, after the 227-byte header of LAS 1.2.
        let mut bytes = cloud((1, 2), 1, false);
        put(&mut bytes, 227 + 20, &u16::MAX.to_le_bytes());
        refused(bytes, "VLR 0 at byte 227 declares 65535 bytes, but only");
        // More VLRs than the file holds: a second one cut short.
        let mut bytes = cloud((1, 2), 1, false);
        put(&mut bytes, 100, &2u32.to_le_bytes());
        bytes.truncate(227 + 54 + 10 + 20);
        refused(
            bytes,
            "the header lists 2 VLRs, the file ends in VLR 1 (byte 291)",
        );
        // LAS 1.4: the first EVLR past the end, and an EVLR's 64-bit length.
        let good = cloud((1, 4), 6, false);
        let mut bytes = good.clone();
        put(&mut bytes, 235, &(1u64 << 40).to_le_bytes());
        refused(
            bytes,
            "first EVLR, at byte 1099511627776, lies past the end",
        );
        let evlr = u64_at(&good, 235).unwrap();
        let mut bytes = good.clone();
        put(&mut bytes, evlr + 20, &(1u64 << 40).to_le_bytes());
        refused(
            bytes,
            &format!("EVLR 0 at byte {evlr} declares 1099511627776 bytes, but only 16"),
        );
    }

    #[test]
    fn point_counts_beyond_the_file_are_refused() {
        // LAS 1.4's 64-bit count (the legacy one 0): 2^40 points, and one that overflows.
        let mut bytes = cloud((1, 4), 6, false);
        put(&mut bytes, 107, &0u32.to_le_bytes());
        put(&mut bytes, 247, &(1u64 << 40).to_le_bytes());
        refused(
            bytes.clone(),
            "truncated: the header says 1099511627776 points of 30 bytes",
        );
        put(&mut bytes, 247, &(1u64 << 62).to_le_bytes());
        refused(
            bytes,
            "4611686018427387904 points of 30 bytes: more than a file holds",
        );
        // LAZ: a billion points of 34 bytes are over the memory budget before decompression.
        let mut bytes = cloud((1, 2), 3, true);
        put(&mut bytes, 107, &1_000_000_000u32.to_le_bytes());
        refused(bytes, "decompressing 1000000000 LAZ points of 34 bytes");
    }

    /// `good` (a LAZ file of one fixed-size chunk, its table at the end) rewritten with
    /// variable-size chunks: the laszip VLR's chunk size and a chunk table listing `counts`
    /// points (the first entry with the chunk's bytes).
    fn variable_chunks(good: &[u8], counts: &[u64]) -> Vec<u8> {
        let data = u64::from(u32_at(good, 96).unwrap());
        let table = u64_at(good, data).unwrap();
        let vlr = 227 + VLR_HEADER + 10 + VLR_HEADER;
        let mut bytes = good[..table as usize].to_vec();
        put(&mut bytes, vlr + 12, &u32::MAX.to_le_bytes());
        let vlr_len = u64::from(u16_at(&bytes, vlr - VLR_HEADER + 20).unwrap());
        let laz_vlr =
            laz::LazVlr::from_buffer(&bytes[vlr as usize..(vlr + vlr_len) as usize]).unwrap();
        assert!(laz_vlr.uses_variable_size_chunks());
        let mut entries = laz::laszip::ChunkTable::with_capacity(counts.len());
        for (k, &point_count) in counts.iter().enumerate() {
            let byte_count = if k == 0 { table - data - 8 } else { 0 };
            entries.push(laz::laszip::ChunkTableEntry {
                point_count,
                byte_count,
            });
        }
        entries.write_to(&mut bytes, &laz_vlr).unwrap();
        bytes
    }

    #[test]
    fn laz_chunk_tables_of_fewer_points_than_the_header_are_refused() {
        let good = cloud((1, 2), 3, true);
        // The whole chunk listed (and a last chunk of no points, as laz writes): read whole.
        for counts in [&[300][..], &[300, 0]] {
            let bytes = variable_chunks(&good, counts);
            check_sizes(&bytes).unwrap();
            assert_eq!(parse(bytes).unwrap().len(), 300, "{counts:?}");
        }
        // A table of 100 points, the header's 300: laz went past the table's last chunk at
        // point 100 and panicked (an index out of bounds).
        let bytes = variable_chunks(&good, &[100]);
        let table = u64_at(&bytes, u64::from(u32_at(&bytes, 96).unwrap())).unwrap();
        refused(
            bytes.clone(),
            &format!(
                "the LAZ chunk table at byte {table} lists 100 points (in 1 chunks), but the \
                 header counts 300"
            ),
        );
        let regression = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("fuzz/regressions/las/laz_table_fewer_points.laz");
        refused(
            std::fs::read(regression).unwrap(),
            "lists 100 points (in 1 chunks), but the header counts 300",
        );
        // Two chunks of 100 and 150 points.
        refused(
            variable_chunks(&good, &[100, 150]),
            "lists 250 points (in 2 chunks), but the header counts 300",
        );
        // Fixed-size chunks: one chunk of at most 200 points for the header's 300.
        let vlr = 227 + VLR_HEADER + 10 + VLR_HEADER;
        let mut bytes = good.clone();
        put(&mut bytes, vlr + 12, &200u32.to_le_bytes());
        refused(
            bytes,
            "lists 1 chunks of at most 200 points each, but the header counts 300",
        );
    }

    /// `good` (a LAZ file of one chunk, LAS 1.2) as LASzip 2.0 wrote a point-wise file:
    /// compressor 1 and `chunk_size` in the laszip VLR, the points one arithmetic-coded stream
    /// from the point offset (no chunk table offset, no table).
    fn pointwise(good: &[u8], chunk_size: u32) -> Vec<u8> {
        let data = u64::from(u32_at(good, 96).unwrap());
        let table = u64_at(good, data).unwrap();
        let mut bytes = [
            &good[..data as usize],
            &good[data as usize + 8..table as usize],
        ]
        .concat();
        let vlr = 227 + VLR_HEADER + 10 + VLR_HEADER;
        put(&mut bytes, vlr, &1u16.to_le_bytes());
        put(&mut bytes, vlr + 12, &chunk_size.to_le_bytes());
        bytes
    }

    #[test]
    fn pointwise_laz_with_a_variable_chunk_size_is_read() {
        // LASzip 2.0 left a point-wise file's chunk size 0 (it has no chunks); laz reads 0 and
        // u32::MAX as variable-size chunks, has no chunk table to follow and panicked ("Variable-
        // size chunks, but no chunk table", the fuzzer's file). The size is made fixed first.
        let good = cloud((1, 2), 3, true);
        let expected = parse(good.clone()).unwrap();
        for chunk_size in [0, u32::MAX, 50_000, 7] {
            let bytes = pointwise(&good, chunk_size);
            let vlr = 227 + VLR_HEADER + 10 + VLR_HEADER;
            let patch = matches!(chunk_size, 0 | u32::MAX).then_some(vlr as usize + 12);
            assert_eq!(
                check_sizes(&bytes).unwrap(),
                patch,
                "chunk size {chunk_size}"
            );
            let cloud = parse(bytes).unwrap();
            assert_eq!(
                cloud.positions, expected.positions,
                "chunk size {chunk_size}"
            );
            assert_eq!(cloud.colors, expected.colors, "chunk size {chunk_size}");
        }
        // The fuzzer's file (505 bytes, 40 points of format 2, compressor 1, chunk size 0): the
        // decoder's error, not a panic.
        let regression = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("fuzz/regressions/las/laz_pointwise_variable_chunks.laz");
        let bytes = std::fs::read(regression).unwrap();
        assert!(check_sizes(&bytes).unwrap().is_some());
        let e = parse(bytes).err().unwrap();
        assert!(
            e.contains("point 0: the point data ends before the header's 40 points"),
            "{e}"
        );
        // A point-wise stream cut short, the same.
        let mut bytes = pointwise(&good, 0);
        bytes.truncate(bytes.len() - 2000);
        let e = parse(bytes).err().unwrap();
        assert!(
            e.contains("the point data ends before the header's 300 points"),
            "{e}"
        );
    }

    #[test]
    fn laz_chunk_tables_and_layers_beyond_the_file_are_refused() {
        let good = cloud((1, 2), 3, true);
        let data = u64::from(u32_at(&good, 96).unwrap());
        let table = u64_at(&good, data).unwrap();
        // A chunk table header claiming 2^31 chunks.
        let mut bytes = good.clone();
        put(&mut bytes, table + 4, &(1u32 << 31).to_le_bytes());
        refused(bytes, "lists 2147483648 chunks");
        // A chunk table past the end.
        let mut bytes = good.clone();
        put(&mut bytes, data, &(1i64 << 40).to_le_bytes());
        refused(bytes, "chunk table at byte 1099511627776 lies past the end");
        // A laszip VLR without items (laz would panic), or whose items do not make the record.
        let vlr = 227 + VLR_HEADER + 10 + VLR_HEADER;
        assert_eq!(u16_at(&good, vlr - VLR_HEADER + 18), Some(LASZIP_RECORD_ID));
        let mut bytes = good.clone();
        put(&mut bytes, vlr + 32, &0u16.to_le_bytes());
        refused(bytes, "the laszip VLR lists no point items");
        let mut bytes = good.clone();
        put(&mut bytes, vlr + 34 + 2, &21u16.to_le_bytes());
        refused(
            bytes,
            "laszip item 0 (type 6) declares 21 bytes, its type has 20",
        );
        // Variable-size chunks and a chunk table of no chunks (laz indexed its empty table).
        let mut bytes = good.clone();
        put(&mut bytes, vlr + 12, &u32::MAX.to_le_bytes());
        put(&mut bytes, table + 4, &0u32.to_le_bytes());
        refused(bytes, "lists no chunks, but the header counts");
        // LAS 1.4 (layered): the first chunk's first layer of 4 GiB (after a 30-byte point
        // and the chunk's point count).
        let good = cloud((1, 4), 6, true);
        let data = u64::from(u32_at(&good, 96).unwrap());
        let mut bytes = good.clone();
        put(&mut bytes, data + 8 + 30 + 4, &0xFFFF_FFF0u32.to_le_bytes());
        refused(
            bytes,
            &format!("LAZ chunk 0 at byte {} declares layers of", data + 8),
        );
    }
}
