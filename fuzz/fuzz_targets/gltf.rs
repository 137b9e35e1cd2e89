#![no_main]
//! glTF bytes (GLB or JSON with data: URIs) as a mesh (Mesh::parse; a glTF's external buffers are not read from memory): a
//! clear error or a mesh, never a panic.
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let _ = autostereo::mesh::Mesh::parse(data, autostereo::formats::Format::Gltf, "fuzz".as_ref());
});
