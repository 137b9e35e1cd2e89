#![no_main]
//! MetaImage bytes (a detached data file is looked up in an empty directory): a clear error or a
//! volume, never a panic.
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let dir = std::env::temp_dir().join("autostereo-fuzz-empty");
    let _ = std::fs::create_dir_all(&dir);
    let _ = autostereo::volume::load::parse_metaimage(data, &dir.join("fuzz.metaimage"));
});
