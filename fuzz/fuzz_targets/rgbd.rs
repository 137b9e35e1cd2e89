#![no_main]
//! RGB-D images from bytes: one side-by-side image, and the same bytes as a colour + depth
//! pair (PNG decoding, sizes, the depth map's luma, resampling).
use autostereo::rgbd::{DepthMapOptions, RgbdImage};
use std::path::Path;

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let options = DepthMapOptions {
        invert: data.len().is_multiple_of(2),
        resample: true,
    };
    let name = Path::new("fuzz.png");
    let _ = RgbdImage::side_by_side_from_bytes(data, name, options);
    let _ = RgbdImage::from_bytes(data, data, [name, name], options);
});
