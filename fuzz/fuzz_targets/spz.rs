#![no_main]
//! Niantic .spz bytes (gzip): a clear error or Gaussians, never a panic.
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let _ = autostereo::gaussians::load::parse_spz(data, "fuzz.spz".as_ref());
});
