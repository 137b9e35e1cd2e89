//! 3D Gaussian splat files: one scene written by this test as graphdeco PLY, antimatter15
//! `.splat` and Niantic `.spz` (versions 2 and 3, the spec's quantisation) loads to the same
//! Gaussians within each format's quantisation; malformed files are refused by name; a 3DGS
//! PLY given to the point-cloud or mesh loaders names `autostereo gaussians`.

use crate::common;

mod loading;
mod refusals;
mod rendering;

use std::io::{Read, Write};
use std::path::{Path, PathBuf};

use autostereo::formats::{self, DataKind, Format};
use autostereo::gaussians::load::{parse_ply, parse_splat, parse_spz};
use autostereo::gaussians::sh::SH_C0;
use autostereo::gaussians::{sigmoid, Gaussians};
use common::graphdeco::{write_ply, Lcg, Raw};
use glam::{Quat, Vec3};

/// Gaussians in the scene.
const N: usize = 50;

/// 50 Gaussians with SH degree 3, anisotropic scales and random rotations, from a fixed seed.
pub(crate) fn scene() -> Vec<Raw> {
    let mut r = Lcg(30);
    (0..N)
        .map(|_| {
            let position = [0; 3].map(|_| r.range(-1.0, 1.0));
            let log_scale = [
                r.range(-4.5, -1.0),
                r.range(-4.5, -1.0),
                r.range(-4.5, -1.0),
            ];
            let rotation = [0; 4].map(|_| r.range(-1.0, 1.0));
            let logit = r.range(-3.0, 4.0);
            let mut sh = [[0.0; 3]; 16];
            sh[0] = [0; 3].map(|_| r.range(-1.5, 1.5));
            for c in &mut sh[1..] {
                *c = [0; 3].map(|_| r.range(-0.5, 0.5));
            }
            Raw {
                position,
                log_scale,
                rotation,
                logit,
                sh,
            }
        })
        .collect()
}

/// What every format should load: the activated values, degree 3.
fn expected(raw: &[Raw]) -> Gaussians {
    Gaussians {
        positions: raw.iter().map(|g| Vec3::from(g.position)).collect(),
        scales: raw
            .iter()
            .map(|g| Vec3::from(g.log_scale.map(f32::exp)))
            .collect(),
        rotations: raw.iter().map(|g| quat(g.rotation).normalize()).collect(),
        opacities: raw.iter().map(|g| sigmoid(g.logit)).collect(),
        sh_degree: 3,
        sh: raw.iter().flat_map(|g| g.sh).collect(),
    }
}

fn quat([w, x, y, z]: [f32; 4]) -> Quat {
    Quat::from_xyzw(x, y, z, w)
}

/// antimatter15's `convert.py`: colour `0.5 + SH_C0·f_dc` and the sigmoid's opacity ×255,
/// clipped and truncated to u8; rotation `q/|q|·128 + 128`, clipped and truncated.
pub(crate) fn write_splat(raw: &[Raw]) -> Vec<u8> {
    let byte = |v: f32| v.clamp(0.0, 255.0) as u8;
    let mut bytes = Vec::new();
    for g in raw {
        for v in g.position.iter().chain(&g.log_scale.map(f32::exp)) {
            bytes.extend(v.to_le_bytes());
        }
        for c in g.sh[0] {
            bytes.push(byte((0.5 + SH_C0 * c) * 255.0));
        }
        bytes.push(byte(sigmoid(g.logit) * 255.0));
        let q = g.rotation;
        let length = q.iter().map(|v| v * v).sum::<f32>().sqrt();
        bytes.extend(q.map(|v| byte(v / length * 128.0 + 128.0)));
    }
    bytes
}

/// Niantic's `packGaussians` + `serializePackedGaussians` + gzip, for version 2 or 3, SH
/// degree `degree`, 12 fractional bits and the default SH bits (5 for degree 1, 4 above).
pub(crate) fn write_spz(raw: &[Raw], version: u32, degree: u8) -> Vec<u8> {
    let to_u8 = |x: f32| x.round().clamp(0.0, 255.0) as u8;
    let quantize_sh = |x: f32, bucket: i32| {
        let q = (x * 128.0).round() as i32 + 128;
        ((q + bucket / 2) / bucket * bucket).clamp(0, 255) as u8
    };
    let n = raw.len() as u32;
    let mut data = Vec::new();
    data.extend(0x5053_474e_u32.to_le_bytes());
    data.extend(version.to_le_bytes());
    data.extend(n.to_le_bytes());
    data.extend([degree, 12, 0, 0]);
    for g in raw {
        for p in g.position {
            let fixed = (p * 4096.0).round() as i32;
            data.extend(&fixed.to_le_bytes()[..3]);
        }
    }
    data.extend(raw.iter().map(|g| to_u8(sigmoid(g.logit) * 255.0)));
    for g in raw {
        data.extend(g.sh[0].map(|c| to_u8(c * (0.15 * 255.0) + 0.5 * 255.0)));
    }
    for g in raw {
        data.extend(g.log_scale.map(|s| to_u8((s + 10.0) * 16.0)));
    }
    for g in raw {
        // SPZ's quaternions are (x, y, z, w).
        let q = quat(g.rotation).normalize().to_array();
        if version == 2 {
            let sign = if q[3] < 0.0 { -127.5 } else { 127.5 };
            data.extend([0, 1, 2].map(|i| to_u8(q[i] * sign + 127.5)));
        } else {
            let largest = (0..4)
                .max_by(|&a, &b| q[a].abs().total_cmp(&q[b].abs()))
                .unwrap();
            let negate = q[largest] < 0.0;
            let mut comp = largest as u32;
            for (i, v) in q.iter().enumerate() {
                if i != largest {
                    let negbit = ((*v < 0.0) ^ negate) as u32;
                    let mag = (511.0 * (v.abs() / std::f32::consts::FRAC_1_SQRT_2) + 0.5) as u32;
                    comp = (comp << 10) | (negbit << 9) | mag;
                }
            }
            data.extend(comp.to_le_bytes());
        }
    }
    let coefficients = (degree as usize + 1).pow(2);
    for g in raw {
        for (k, c) in g.sh[1..coefficients].iter().enumerate() {
            let bucket = if k < 3 { 1 << 3 } else { 1 << 4 };
            data.extend(c.map(|v| quantize_sh(v, bucket)));
        }
    }
    gzip(&data)
}

fn gzip(data: &[u8]) -> Vec<u8> {
    let mut e = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
    e.write_all(data).unwrap();
    e.finish().unwrap()
}

/// Per-attribute tolerances of a format (absolute, except scales: |Δ ln s|).
#[derive(Debug)]
struct Tolerance {
    position: f32,
    log_scale: f32,
    opacity: f32,
    /// Quaternion distance up to sign, where |w| ≥ 0.5 and elsewhere.
    rotation: [f32; 2],
    dc: f32,
    /// SH degree 1 and degrees 2–3.
    rest: [f32; 2],
}

/// `got` is `want` within `tol` (`want`'s degree may be higher: `got`'s coefficients are
/// compared).
fn assert_close(name: &str, got: &Gaussians, want: &Gaussians, tol: &Tolerance) {
    assert_eq!(got.len(), want.len(), "{name}: count");
    let k = got.coefficients();
    let mut worst = [0.0f32; 7];
    for i in 0..got.len() {
        let d = [
            (got.positions[i] - want.positions[i]).abs().max_element(),
            (got.scales[i].map(f32::ln) - want.scales[i].map(f32::ln))
                .abs()
                .max_element(),
            (got.opacities[i] - want.opacities[i]).abs(),
        ];
        let (q, p) = (got.rotations[i], want.rotations[i]);
        let rotation = (q - p).length().min((q + p).length());
        let w_large = p.w.abs() >= 0.5;
        let dc = (Vec3::from(got.sh_of(i)[0]) - Vec3::from(want.sh_of(i)[0]))
            .abs()
            .max_element();
        let rest = |range: std::ops::Range<usize>| {
            range
                .filter(|&j| j < k)
                .map(|j| {
                    (Vec3::from(got.sh_of(i)[j]) - Vec3::from(want.sh_of(i)[j]))
                        .abs()
                        .max_element()
                })
                .fold(0.0, f32::max)
        };
        let found = [d[0], d[1], d[2], rotation, dc, rest(1..4), rest(4..16)];
        let limits = [
            tol.position,
            tol.log_scale,
            tol.opacity,
            tol.rotation[usize::from(!w_large)],
            tol.dc,
            tol.rest[0],
            tol.rest[1],
        ];
        let what = [
            "position",
            "log scale",
            "opacity",
            "rotation",
            "DC",
            "SH 1",
            "SH 2-3",
        ];
        for j in 0..7 {
            assert!(
                found[j] <= limits[j],
                "{name}: Gaussian {i}'s {} is off by {} (tolerance {})",
                what[j],
                found[j],
                limits[j]
            );
            worst[j] = worst[j].max(found[j]);
        }
    }
    eprintln!("{name}: worst differences {worst:?} within {tol:?}");
}

fn dir() -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("gaussians_formats");
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn file(name: &str, bytes: &[u8]) -> PathBuf {
    let path = dir().join(name);
    std::fs::write(&path, bytes).unwrap();
    path
}
