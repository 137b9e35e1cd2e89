#![no_main]
//! Legacy VTK (`.vtk`) bytes, STRUCTURED_POINTS ASCII or BINARY: a clear error or a volume,
//! never a panic.
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let _ = autostereo::volume::load::parse_vtk(data, "fuzz.vtk".as_ref());
});
