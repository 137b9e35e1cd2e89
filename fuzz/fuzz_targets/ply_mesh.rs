#![no_main]
//! PLY bytes with faces as a mesh (Mesh::parse; a glTF's external buffers are not read from memory): a
//! clear error or a mesh, never a panic.
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let _ = autostereo::mesh::Mesh::parse(data, autostereo::formats::Format::Ply, "fuzz".as_ref());
});
