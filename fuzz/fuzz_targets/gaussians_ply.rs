#![no_main]
//! graphdeco 3DGS PLY bytes: a clear error or Gaussians, never a panic.
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let _ = autostereo::gaussians::load::parse_ply(data, "fuzz.ply".as_ref());
});
