#![no_main]
//! One DICOM file's bytes as a volume (a slice or a multi-frame file): a clear error or a
//! volume, never a panic.
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let _ = autostereo::volume::load::parse_dicom(data, "fuzz.dcm".as_ref());
});
