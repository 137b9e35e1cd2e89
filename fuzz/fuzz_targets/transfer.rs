#![no_main]
//! Transfer-function text (`scalar r g b a` lines).
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let _ = autostereo::volume::TransferFunction::parse(&text);
});
