#![no_main]
//! NRRD bytes with attached data (raw or gzip); a detached `data file:` is looked up in an
//! empty directory.
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let dir = std::env::temp_dir().join("autostereo-fuzz-empty");
    let _ = std::fs::create_dir_all(&dir);
    let _ = autostereo::volume::load::parse_nrrd(data, &dir.join("fuzz.nrrd"));
});
