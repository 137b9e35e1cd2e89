#![no_main]
//! LAS and LAZ bytes: a clear error or a point cloud, never a panic.
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let _ = autostereo::points::las::parse(data.to_vec());
});
