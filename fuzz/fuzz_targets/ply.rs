#![no_main]
//! PLY bytes (ASCII and binary).
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let _ = autostereo::io::ply::parse(data);
});
