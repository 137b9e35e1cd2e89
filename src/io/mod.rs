//! Readers more than one primitive shares: PLY (meshes, point clouds, Gaussian splats).

pub mod ply;
