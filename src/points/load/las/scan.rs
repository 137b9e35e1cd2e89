//! The size scan. The las crate zero-fills an extended VLR's 64-bit length and computes the
//! end of the points as count × record length (an overflow from a LAS 1.4 count); the laz
//! crate reserves its chunk table for the count the table's header gives, panics on a laszip
//! VLR without items (and sums its items' sizes in 16 bits, then splits records by that sum),
//! and zero-fills each layer of a LAS 1.4 (layered) chunk to the 32-bit size the chunk's
//! header declares. So before the crates see a file, its public header, VLRs, EVLRs, LAZ chunk
//! table header and layered chunk headers are read here and every size checked against the
//! file.

/// The laszip VLR that describes a LAZ file's compression.
const LASZIP_USER_ID: &[u8] = b"laszip encoded";
pub(super) const LASZIP_RECORD_ID: u16 = 22204;
/// A VLR's header (reserved, user id, record id, 16-bit length, description), an EVLR's (the
/// same with a 64-bit length).
pub(super) const VLR_HEADER: u64 = 54;
const EVLR_HEADER: u64 = 60;
/// LASzip's default chunk size (points), written in place of a point-wise file's 0.
pub(super) const LASZIP_CHUNK_SIZE_DEFAULT: u32 = 50_000;
/// What the laz decoder holds per extra byte of a record: an adaptive 256-symbol model
/// (about 2.3 KiB) in each of 4 contexts.
const LAZ_BYTES_PER_EXTRA_BYTE: u64 = 10 << 10;

/// `N` little-endian bytes at `at`, if the file has them.
fn le<const N: usize>(bytes: &[u8], at: u64) -> Option<[u8; N]> {
    let at = usize::try_from(at).ok()?;
    bytes.get(at..at.checked_add(N)?)?.try_into().ok()
}

pub(super) fn u16_at(bytes: &[u8], at: u64) -> Option<u16> {
    le(bytes, at).map(u16::from_le_bytes)
}

pub(super) fn u32_at(bytes: &[u8], at: u64) -> Option<u32> {
    le(bytes, at).map(u32::from_le_bytes)
}

pub(super) fn u64_at(bytes: &[u8], at: u64) -> Option<u64> {
    le(bytes, at).map(u64::from_le_bytes)
}

/// Check the sizes a LAS or LAZ file declares against its length (see above). What the las
/// crate refuses cleanly by itself (a short header, a bad signature) is left to it. Gives the
/// byte of a point-wise LAZ file's chunk size when it reads as variable (0 or `u32::MAX`), for
/// [`parse`] to make it fixed.
pub(super) fn check_sizes(bytes: &[u8]) -> std::result::Result<Option<usize>, String> {
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
