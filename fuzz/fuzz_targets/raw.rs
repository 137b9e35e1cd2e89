#![no_main]
//! A raw volume: its description (what `--raw-dims`, `--raw-type`, `--raw-big-endian` and
//! `--raw-header` give) from the first 12 bytes, the file's bytes after them
//! (`RawSpec::from_fuzz_input`).
use autostereo::volume::load::{parse_raw, RawSpec};

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    if let Some((spec, file)) = RawSpec::from_fuzz_input(data) {
        let _ = parse_raw(file, "fuzz.raw".as_ref(), &spec);
    }
});
