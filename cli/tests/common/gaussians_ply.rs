//! A small 3D Gaussian splat scene written as graphdeco's binary PLY (what the trainer writes:
//! `x y z nx ny nz f_dc_* f_rest_* opacity scale_* rot_*`, `f_rest_*` channel-major, log
//! scales, opacity logits, unnormalised (w, x, y, z) rotations), for the CLI's tests. The
//! essentials of tests/formats/gaussians_formats/' writer.

use std::path::{Path, PathBuf};

/// A tiny LCG (Knuth's MMIX constants): uniform in [lo, hi).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self, lo: f32, hi: f32) -> f32 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        lo + (hi - lo) * ((self.0 >> 40) as f32 / (1u64 << 24) as f32)
    }
}

/// Gaussians in [`write`]'s scene.
pub const COUNT: usize = 60;

/// SH degree of [`write`]'s scene.
pub const DEGREE: u32 = 1;

/// The PLY bytes of `COUNT` anisotropic, overlapping Gaussians of SH degree 1 in a box about
/// the origin (wider than tall, nothing symmetric), from a fixed seed.
pub fn bytes() -> Vec<u8> {
    let rest = 3 * 3; // (degree + 1)² − 1 coefficients per channel
    let mut header = format!("ply\nformat binary_little_endian 1.0\nelement vertex {COUNT}\n");
    let mut names: Vec<String> = [
        "x", "y", "z", "nx", "ny", "nz", "f_dc_0", "f_dc_1", "f_dc_2",
    ]
    .map(String::from)
    .to_vec();
    names.extend((0..rest).map(|j| format!("f_rest_{j}")));
    names.extend(
        [
            "opacity", "scale_0", "scale_1", "scale_2", "rot_0", "rot_1", "rot_2", "rot_3",
        ]
        .map(String::from),
    );
    for n in &names {
        header += &format!("property float {n}\n");
    }
    header += "end_header\n";
    let mut bytes = header.into_bytes();
    let mut r = Lcg(3030);
    for _ in 0..COUNT {
        let mut values = vec![r.next(-1.2, 1.2), r.next(-0.7, 0.7), r.next(-0.8, 0.8)];
        values.extend([0.0; 3]);
        values.extend([0; 3].map(|_| r.next(-1.6, 1.6)));
        values.extend((0..rest).map(|_| r.next(-0.4, 0.4)));
        values.push(r.next(-1.0, 4.0));
        values.extend([0; 3].map(|_| r.next(-3.5, -1.6)));
        values.extend([0; 4].map(|_| r.next(-1.0, 1.0)));
        for v in values {
            bytes.extend(v.to_le_bytes());
        }
    }
    bytes
}

/// [`bytes`] written to `dir/name` (once per call; tests in parallel write distinct names).
pub fn write(dir: &Path, name: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, bytes()).unwrap();
    path
}
