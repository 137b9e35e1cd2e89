//! A small 3D Gaussian splat scene written as graphdeco's binary PLY (what the trainer writes:
//! `x y z nx ny nz f_dc_* f_rest_* opacity scale_* rot_*`, `f_rest_*` channel-major, log
//! scales, opacity logits, unnormalised (w, x, y, z) rotations), for the CLI's tests, by
//! the library tests' writer (tests/common/graphdeco.rs).

use std::path::{Path, PathBuf};

use super::graphdeco::{write_ply, Lcg, Raw};

/// Gaussians in [`write`]'s scene.
pub const COUNT: usize = 60;

/// SH degree of [`write`]'s scene.
pub const DEGREE: u32 = 1;

/// The PLY bytes of `COUNT` anisotropic, overlapping Gaussians of SH degree 1 in a box about
/// the origin (wider than tall, nothing symmetric), from a fixed seed.
pub fn bytes() -> Vec<u8> {
    let rest = 3 * 3; // (degree + 1)² − 1 coefficients per channel
    let mut r = Lcg(3030);
    let raw: Vec<Raw> = (0..COUNT)
        .map(|_| {
            let position = [r.range(-1.2, 1.2), r.range(-0.7, 0.7), r.range(-0.8, 0.8)];
            let mut sh = [[0.0; 3]; 16];
            sh[0] = [0; 3].map(|_| r.range(-1.6, 1.6));
            // Drawn in the file's order: f_rest_* is channel-major.
            let per_channel = rest / 3;
            for i in 0..rest {
                sh[1 + i % per_channel][i / per_channel] = r.range(-0.4, 0.4);
            }
            let logit = r.range(-1.0, 4.0);
            let log_scale = [0; 3].map(|_| r.range(-3.5, -1.6));
            let rotation = [0; 4].map(|_| r.range(-1.0, 1.0));
            Raw {
                position,
                log_scale,
                rotation,
                logit,
                sh,
            }
        })
        .collect();
    write_ply(&raw, rest)
}

/// [`bytes`] written to `dir/name` (once per call; tests in parallel write distinct names).
pub fn write(dir: &Path, name: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, bytes()).unwrap();
    path
}
