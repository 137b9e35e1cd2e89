#![no_main]
//! VTK XML image data (`.vti`) bytes: ascii, base64 and appended arrays, zlib blocks: a clear
//! error or a volume, never a panic.
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let _ = autostereo::volume::load::parse_vti(data, "fuzz.vti".as_ref());
});
