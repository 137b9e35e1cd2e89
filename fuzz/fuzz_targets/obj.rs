#![no_main]
//! OBJ text (materials are not read from memory): a clear error or a mesh, never a panic.
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let _ = autostereo::mesh::Mesh::from_obj_text(&text, "fuzz.obj".as_ref());
});
