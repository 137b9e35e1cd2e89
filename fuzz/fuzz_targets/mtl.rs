#![no_main]
//! MTL text as the OBJ loader reads it.
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let _ = autostereo::mesh::Mesh::check_mtl_text(&text, "fuzz.mtl".as_ref());
});
