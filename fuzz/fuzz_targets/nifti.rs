#![no_main]
//! NIfTI-1 bytes, gzip or not (a detached data file is looked up in an empty directory): a clear error or a
//! volume, never a panic.
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let dir = std::env::temp_dir().join("autostereo-fuzz-empty");
    let _ = std::fs::create_dir_all(&dir);
    let _ = autostereo::volume::load::parse_nifti(data, &dir.join("fuzz.nifti"));
});
