//! Reading files: every format (every mesh format as its OBJ), its refusals, bad input, the fuzz
//! inputs replayed; `autostereo::load`.
//! One test binary (fewer binaries: less linking, less disk); a module per theme.

#[path = "../common/mod.rs"]
mod common;

mod bad_input;
mod ct_windows;
mod draco;
mod every_format;
mod fuzz_regressions;
mod gaussians_formats;
mod mesh_formats;
mod points_las;
mod textures;
mod volume_dicom;
mod volume_formats;
mod volume_load;
mod volume_vtk;
