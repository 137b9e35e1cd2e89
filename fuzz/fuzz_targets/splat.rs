#![no_main]
//! antimatter15 .splat bytes: a clear error or Gaussians, never a panic.
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let _ = autostereo::gaussians::load::parse_splat(data, "fuzz.splat".as_ref());
});
