#![no_main]
//! A raw volume: its description (what `--raw-dims`, `--raw-type`, `--raw-big-endian` and
//! `--raw-header` give) from the first 12 bytes, the file's bytes after them.
use autostereo::volume::load::{parse_raw, RawSpec, SampleType};

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

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    if data.len() < 12 {
        return;
    }
    let half = |i: usize| u16::from_le_bytes([data[i], data[i + 1]]);
    let spec = RawSpec {
        dims: [half(0), half(2), half(4)].map(u32::from),
        kind: KINDS[data[6] as usize % KINDS.len()],
        big_endian: data[7] & 1 == 1,
        spacing: [1.0, 1.0, 1.0 + f32::from(data[8])],
        header_bytes: u64::from(half(10)),
    };
    let _ = parse_raw(&data[12..], "fuzz.raw".as_ref(), &spec);
});
