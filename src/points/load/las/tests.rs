//! LAS and LAZ files made here: positions and colours read back, and every size the scan
//! checks refused by name before the crates see it.

use super::scan::{u16_at, u32_at, u64_at, LASZIP_RECORD_ID, VLR_HEADER};
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
    let laz_vlr = laz::LazVlr::from_buffer(&bytes[vlr as usize..(vlr + vlr_len) as usize]).unwrap();
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
