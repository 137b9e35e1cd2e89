//! Niantic's `.spz`, versions 2 and 3 (github.com/nianticlabs/spz, `load-spz.cc`): a gzip
//! stream of a 16-byte header — magic `NGSP` (0x5053474e LE), version, point count, SH degree,
//! fractional bits, flags, a reserved byte — then the attributes one after another:
//!
//! | attribute | bytes per Gaussian | decoded |
//! |---|---|---|
//! | positions | 3 × 24-bit signed fixed point | `v · 2^−fractionalBits` |
//! | alphas | 1 | opacity `a / 255` (stored after the sigmoid) |
//! | colours | 3 | SH DC `(c / 255 − 0.5) / 0.15` |
//! | scales | 3 | `exp(b / 16 − 10)` |
//! | rotations | v2: 3 (x, y, z as `b / 127.5 − 1`, w ≥ 0 derived); v3: 4 ("smallest three") | unit quaternion |
//! | SH rest | 3 per coefficient, coefficient-major, colour inner | `(b − 128) / 128` |
//!
//! Coordinates are taken as stored (Niantic's own `ply_to_spz` stores the PLY's axes as they
//! are). Version 4 (ZSTD streams) and version 1 (float16 positions) are refused by name, and
//! so is SH degree 4. Vendor extensions after the attributes (flag 0x2) are ignored; a file
//! trained with antialiasing (flag 0x1, mip-splatting) is read and said so in the log.

use std::io::Read;
use std::path::Path;

use glam::{Quat, Vec3};

use super::{checked, error};
use crate::error::Result;
use crate::gaussians::{check_budget, coefficients, Gaussians, MAX_SH_DEGREE};

/// `NGSP` as a little-endian u32.
pub const SPZ_MAGIC: u32 = 0x5053_474e;

/// Bytes of the (gzipped) header.
const HEADER_BYTES: usize = 16;

/// The DC colour scale of Niantic's `colorScale` (not SH_C0: it leaves room beyond [0, 1]).
const COLOR_SCALE: f32 = 0.15;

/// Deflate expands at most 1032:1; a header counting more bytes than that is a lie, found
/// before anything is inflated.
const MAX_DEFLATE_RATIO: u64 = 1032;

/// A `.spz` file's `bytes` (`path` names it in errors).
pub fn parse_spz(bytes: &[u8], path: &Path) -> Result<Gaussians> {
    let fail = |reason: String| error(path, reason);
    if bytes.starts_with(b"NGSP") {
        return Err(fail(
            "SPZ version 4 (ZSTD streams) is not read yet; save it as version 3 (gzip)".into(),
        ));
    }
    if !bytes.starts_with(&[0x1f, 0x8b]) {
        return Err(fail(
            "not an SPZ file: it is not gzip (versions 2 and 3 are gzip streams)".into(),
        ));
    }
    let mut stream = flate2::read::GzDecoder::new(bytes);
    let mut head = [0u8; HEADER_BYTES];
    stream.read_exact(&mut head).map_err(|e| {
        fail(format!(
            "the gzip stream ends before the 16-byte header ({e})"
        ))
    })?;
    let word = |at: usize| u32::from_le_bytes(head[at..at + 4].try_into().expect("4 bytes"));
    let (magic, version, n) = (word(0), word(4), word(8));
    let (degree, fractional_bits, flags) = (u32::from(head[12]), head[13], head[14]);
    if magic != SPZ_MAGIC {
        return Err(fail(format!(
            "wrong magic {magic:#010x}: not an SPZ file (its gzip stream starts with 'NGSP')"
        )));
    }
    match version {
        2 | 3 => {}
        1 => return Err(fail("SPZ version 1 (float16 positions) is not read".into())),
        4 => {
            return Err(fail(
                "SPZ version 4 (ZSTD streams) is not read yet; save it as version 3".into(),
            ))
        }
        v => return Err(fail(format!("SPZ version {v}: versions 2 and 3 are read"))),
    }
    if degree > MAX_SH_DEGREE {
        return Err(fail(format!(
            "SH degree {degree}: at most {MAX_SH_DEGREE} is read"
        )));
    }
    let rotation_bytes = if version >= 3 { 4 } else { 3 };
    let rest = coefficients(degree) - 1;
    let per_gaussian = (9 + 1 + 3 + 3 + rotation_bytes + 3 * rest) as u64;
    let payload = u64::from(n) * per_gaussian;
    let most = (bytes.len() as u64).saturating_mul(MAX_DEFLATE_RATIO);
    if payload > most {
        return Err(fail(format!(
            "the header's {n} Gaussians need {payload} bytes, more than {} compressed bytes \
             can hold",
            bytes.len()
        )));
    }
    check_budget(u64::from(n), degree, payload).map_err(|e| fail(e.to_string()))?;
    let mut data = Vec::new();
    stream
        .take(payload)
        .read_to_end(&mut data)
        .map_err(|e| fail(format!("gzip stream: {e}")))?;
    if (data.len() as u64) < payload {
        return Err(fail(format!(
            "truncated: the gzip stream holds {} of the {payload} bytes the header's {n} \
             Gaussians need",
            data.len()
        )));
    }
    if flags & 1 != 0 {
        log::warn!(
            "{}: trained with antialiasing (mip-splatting); drawn without its opacity \
             compensation",
            path.display()
        );
    }
    checked(
        decode(&data, n as usize, degree, fractional_bits, version),
        path,
    )
}

/// The attributes of `n` Gaussians, one array after another in `data`.
fn decode(data: &[u8], n: usize, degree: u32, fractional_bits: u8, version: u32) -> Gaussians {
    let (positions, data) = data.split_at(9 * n);
    let (alphas, data) = data.split_at(n);
    let (colors, data) = data.split_at(3 * n);
    let (scales, data) = data.split_at(3 * n);
    let rotation_bytes = if version >= 3 { 4 } else { 3 };
    let (rotations, sh) = data.split_at(rotation_bytes * n);
    let unit = 0.5f32.powi(i32::from(fractional_bits));
    let fixed = |b: &[u8]| {
        // 24-bit two's complement: shift into the top of an i32 and back.
        let v = (i32::from(b[0]) << 8 | i32::from(b[1]) << 16 | i32::from(b[2]) << 24) >> 8;
        v as f32 * unit
    };
    let k = coefficients(degree);
    let rest = k - 1;
    let mut g = Gaussians {
        positions: positions
            .chunks_exact(9)
            .map(|p| Vec3::new(fixed(&p[0..3]), fixed(&p[3..6]), fixed(&p[6..9])))
            .collect(),
        scales: scales
            .chunks_exact(3)
            .map(|s| {
                Vec3::from_array([s[0], s[1], s[2]].map(|b| (f32::from(b) / 16.0 - 10.0).exp()))
            })
            .collect(),
        rotations: rotations
            .chunks_exact(rotation_bytes)
            .map(|r| match version {
                2 => first_three(r),
                _ => smallest_three(r),
            })
            .collect(),
        opacities: alphas.iter().map(|&a| f32::from(a) / 255.0).collect(),
        sh_degree: degree,
        sh: Vec::with_capacity(n * k),
    };
    for (i, c) in colors.chunks_exact(3).enumerate() {
        g.sh.push([c[0], c[1], c[2]].map(|b| (f32::from(b) / 255.0 - 0.5) / COLOR_SCALE));
        let own = &sh[i * 3 * rest..(i + 1) * 3 * rest];
        g.sh.extend(
            own.chunks_exact(3)
                .map(|t| [t[0], t[1], t[2]].map(|b| (f32::from(b) - 128.0) / 128.0)),
        );
    }
    g
}

/// Version 2: x, y, z as `b / 127.5 − 1`, w = √(1 − |xyz|²) ≥ 0.
fn first_three(r: &[u8]) -> Quat {
    let xyz = Vec3::new(r[0].into(), r[1].into(), r[2].into()) / 127.5 - Vec3::ONE;
    let w = (1.0 - xyz.length_squared()).max(0.0).sqrt();
    Quat::from_xyzw(xyz.x, xyz.y, xyz.z, w).normalize()
}

/// Version 3: a little-endian u32 whose top 2 bits index the largest component (x, y, z, w
/// order), then the other three in that order, 10 bits each (a sign bit over a 9-bit
/// magnitude of `|q| / (1/√2)`), the last in the lowest bits; the largest is derived (≥ 0).
fn smallest_three(r: &[u8]) -> Quat {
    let mut bits = u32::from_le_bytes([r[0], r[1], r[2], r[3]]);
    let largest = (bits >> 30) as usize;
    let mut q = [0.0f32; 4];
    let mut sum = 0.0;
    for i in (0..4).rev().filter(|&i| i != largest) {
        let magnitude = (bits & 0x1ff) as f32 / 511.0 * std::f32::consts::FRAC_1_SQRT_2;
        q[i] = if bits & 0x200 != 0 {
            -magnitude
        } else {
            magnitude
        };
        sum += magnitude * magnitude;
        bits >>= 10;
    }
    q[largest] = (1.0 - sum).max(0.0).sqrt();
    let q = Quat::from_array(q);
    // Three stored magnitudes over 1 with a zero largest: still a rotation, normalised.
    q.normalize()
}
