#![no_main]
//! VolPack .den bytes.
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let _ = autostereo::volume::load::parse_den(data, "fuzz.den".as_ref());
});
