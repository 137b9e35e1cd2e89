//! 3D Gaussian splat files: one scene written by this test as graphdeco PLY, antimatter15
//! `.splat` and Niantic `.spz` (versions 2 and 3, the spec's quantisation) loads to the same
//! Gaussians within each format's quantisation; malformed files are refused by name; a 3DGS
//! PLY given to the point-cloud or mesh loaders names `autostereo gaussians`.

mod common;

use std::io::{Read, Write};
use std::path::{Path, PathBuf};

use autostereo::formats::{self, DataKind, Format};
use autostereo::gaussians::load::{parse_ply, parse_splat, parse_spz};
use autostereo::gaussians::sh::SH_C0;
use autostereo::gaussians::{sigmoid, Gaussians};
use glam::{Quat, Vec3};

/// Gaussians in the scene.
const N: usize = 50;

/// A trainer's raw parameters, as a graphdeco PLY stores them.
struct Raw {
    position: [f32; 3],
    log_scale: [f32; 3],
    /// (w, x, y, z), unnormalised.
    rotation: [f32; 4],
    logit: f32,
    /// 16 RGB coefficients, DC first.
    sh: [[f32; 3]; 16],
}

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

/// 50 Gaussians with SH degree 3, anisotropic scales and random rotations, from a fixed seed.
fn scene() -> Vec<Raw> {
    let mut r = Lcg(30);
    (0..N)
        .map(|_| {
            let position = [0; 3].map(|_| r.next(-1.0, 1.0));
            let log_scale = [r.next(-4.5, -1.0), r.next(-4.5, -1.0), r.next(-4.5, -1.0)];
            let rotation = [0; 4].map(|_| r.next(-1.0, 1.0));
            let logit = r.next(-3.0, 4.0);
            let mut sh = [[0.0; 3]; 16];
            sh[0] = [0; 3].map(|_| r.next(-1.5, 1.5));
            for c in &mut sh[1..] {
                *c = [0; 3].map(|_| r.next(-0.5, 0.5));
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

/// graphdeco's PLY: properties in the trainer's order, `f_rest_*` channel-major.
fn write_ply(raw: &[Raw], rest: usize) -> Vec<u8> {
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
    let mut bytes = format!(
        "ply\nformat binary_little_endian 1.0\nelement vertex {}\n",
        raw.len()
    );
    for n in &names {
        bytes += &format!("property float {n}\n");
    }
    bytes += "end_header\n";
    let mut bytes = bytes.into_bytes();
    let per_channel = rest / 3;
    for g in raw {
        let mut values: Vec<f32> = g.position.to_vec();
        values.extend([0.0; 3]);
        values.extend(g.sh[0]);
        for c in 0..3 {
            values.extend((1..=per_channel).map(|k| g.sh[k][c]));
        }
        values.push(g.logit);
        values.extend(g.log_scale);
        values.extend(g.rotation);
        for v in values {
            bytes.extend(v.to_le_bytes());
        }
    }
    bytes
}

/// antimatter15's `convert.py`: colour `0.5 + SH_C0·f_dc` and the sigmoid's opacity ×255,
/// clipped and truncated to u8; rotation `q/|q|·128 + 128`, clipped and truncated.
fn write_splat(raw: &[Raw]) -> Vec<u8> {
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
fn write_spz(raw: &[Raw], version: u32, degree: u8) -> Vec<u8> {
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

#[test]
fn one_scene_in_every_format_loads_alike() {
    let raw = scene();
    let want = expected(&raw);
    want.validate().unwrap();
    let exact = Tolerance {
        position: 0.0,
        log_scale: 1e-6,
        opacity: 0.0,
        rotation: [1e-6; 2],
        dc: 0.0,
        rest: [0.0; 2],
    };

    // PLY: f32 as written; the loader's sigmoid, exp and normalisation are the test's.
    let ply = Gaussians::load(&file("scene.ply", &write_ply(&raw, 45))).unwrap();
    assert_eq!(ply.sh_degree, 3);
    assert_close("PLY", &ply, &want, &exact);
    assert_eq!(
        formats::kind(&dir().join("scene.ply")).unwrap(),
        (Format::Ply, DataKind::Gaussians)
    );
    // Lower degrees from the f_rest count: the first coefficients of the same scene.
    for (rest, degree) in [(0, 0), (9, 1), (24, 2)] {
        let g = parse_ply(&write_ply(&raw, rest), Path::new("low.ply")).unwrap();
        assert_eq!(g.sh_degree, degree);
        assert_eq!(g.sh.len(), N * (degree as usize + 1).pow(2));
        assert_close(&format!("PLY degree {degree}"), &g, &want, &exact);
    }

    // .splat: positions and scales f32; colour and opacity truncated to 1/255 (the DC to
    // 1/(255·SH_C0)); each quaternion component truncated to 1/128 before normalising, so
    // the unit quaternion moves by at most 2·(2/128).
    let splat = Gaussians::load(&file("scene.splat", &write_splat(&raw))).unwrap();
    assert_eq!(splat.sh_degree, 0);
    let splat_tolerance = Tolerance {
        position: 0.0,
        log_scale: 1e-6,
        opacity: 1.0 / 255.0 + 1e-6,
        rotation: [4.0 / 128.0; 2],
        dc: 1.0 / (255.0 * SH_C0) + 1e-5,
        rest: [0.0; 2],
    };
    assert_close(".splat", &splat, &want, &splat_tolerance);

    // .spz: positions to 2^-12 (half of it by rounding); log scales to 1/16 (half: 1/32);
    // opacity and colour rounded to 1/255 (the DC: 0.5/(255·0.15)); SH rounded to 1/128 then
    // to buckets of 8 (degree 1) and 16 (above) steps: half a bucket and half a step.
    // Rotations: version 3's smallest three have 9-bit magnitudes over 1/√2 (0.0007 per
    // component, the largest derived from them); version 2 stores x, y, z to 1/127.5 and
    // derives w = √(1 − |xyz|²), which loses precision as w → 0.
    for (version, rotation) in [(2, [0.03, 0.2]), (3, [0.005, 0.005])] {
        let name = format!("scene.v{version}.spz");
        let spz = Gaussians::load(&file(&name, &write_spz(&raw, version, 3))).unwrap();
        assert_eq!(spz.sh_degree, 3);
        let tolerance = Tolerance {
            position: 0.5 / 4096.0 + 1e-6,
            log_scale: 1.0 / 32.0 + 1e-5,
            opacity: 0.5 / 255.0 + 1e-6,
            rotation,
            dc: 0.5 / (255.0 * 0.15) + 1e-5,
            rest: [4.5 / 128.0 + 1e-6, 8.5 / 128.0 + 1e-6],
        };
        assert_close(&format!(".spz v{version}"), &spz, &want, &tolerance);
    }
    let spz = parse_spz(&write_spz(&raw, 3, 1), Path::new("degree1.spz")).unwrap();
    assert_eq!(spz.sh_degree, 1);
    assert_eq!(spz.sh.len(), N * 4);
}

/// A `.splat`'s RGBA is the colour itself: the DC it loads to renders that colour at degree 0
/// (`SH_C0·dc + 0.5`); an `.spz`'s colour bytes are the DC scaled by 0.15, not a colour.
#[test]
fn degree_zero_colours() {
    let mut one = Vec::new();
    for v in [0.0f32, 0.0, 0.0, 1.0, 1.0, 1.0] {
        one.extend(v.to_le_bytes());
    }
    one.extend([255, 0, 51, 204, 255, 128, 128, 128]);
    let g = parse_splat(&one, Path::new("one.splat")).unwrap();
    let color = autostereo::gaussians::sh::eval(0, g.sh_of(0), Vec3::Z) + Vec3::splat(0.5);
    assert!(
        (color - Vec3::new(1.0, 0.0, 0.2)).abs().max_element() < 1e-6,
        "{color}"
    );
    assert!((g.opacities[0] - 0.8).abs() < 1e-6);
    assert_eq!(g.rotations[0], Quat::from_xyzw(0.0, 0.0, 0.0, 1.0));

    let mut data = Vec::new();
    data.extend(0x5053_474e_u32.to_le_bytes());
    data.extend(2u32.to_le_bytes());
    data.extend(1u32.to_le_bytes());
    data.extend([0, 12, 0, 0]);
    data.extend([0u8; 9]); // position
    data.push(255); // alpha
    data.extend([0, 128, 255]); // colour
    data.extend([160; 3]); // scales: exp(0)
    data.extend([128, 128, 128]); // rotation x, y, z ≈ 0
    let g = parse_spz(&gzip(&data), Path::new("one.spz")).unwrap();
    let dc = Vec3::from(g.sh[0]);
    let want = Vec3::new(-0.5, 128.0 / 255.0 - 0.5, 0.5) / 0.15;
    assert!((dc - want).abs().max_element() < 1e-5, "{dc} vs {want}");
    assert_eq!(g.opacities[0], 1.0);
    assert_eq!(g.scales[0], Vec3::ONE);
}

fn refused(result: autostereo::Result<Gaussians>, name: &str, expected: &str) {
    let e = result.expect_err(expected).to_string();
    assert!(e.contains(name), "names the file: {e}");
    assert!(e.contains(expected), "'{e}' lacks '{expected}'");
}

#[test]
fn malformed_files_are_refused_by_name() {
    let raw = scene();
    let ply = write_ply(&raw, 45);
    let p = Path::new("bad.ply");
    refused(parse_ply(&ply[..ply.len() - 5], p), "bad.ply", "truncated");
    let text = |from: &str, to: &str| {
        let end = ply.windows(10).position(|w| w == b"end_header").unwrap();
        let head = String::from_utf8_lossy(&ply[..end]).replace(from, to);
        [head.as_bytes(), &ply[end..]].concat()
    };
    refused(
        parse_ply(&text("vertex 50", "vertex 5000000"), p),
        "bad.ply",
        "truncated: the header declares 5000000 Gaussians",
    );
    refused(
        parse_ply(&text("property float f_rest_44\n", ""), p),
        "bad.ply",
        "44 f_rest properties: SH degree 0, 1, 2 or 3 has 0, 9, 24 or 45",
    );
    refused(
        parse_ply(&text("f_rest_44", "f_rest_45"), p),
        "bad.ply",
        "f_rest_44 is missing",
    );
    refused(
        parse_ply(&text("float opacity", "float alpha"), p),
        "bad.ply",
        "lacks opacity",
    );
    refused(
        parse_ply(&text("float opacity", "double opacity"), p),
        "bad.ply",
        "'opacity' is not float",
    );
    refused(
        parse_ply(&text("binary_little_endian", "binary_big_endian"), p),
        "bad.ply",
        "binary_little_endian",
    );
    let mut zero = raw;
    zero[3].rotation = [0.0; 4];
    refused(
        parse_ply(&write_ply(&zero, 45), p),
        "bad.ply",
        "Gaussian 3 has a zero or non-finite rotation",
    );
    zero[3].rotation = [1.0, 0.0, 0.0, 0.0];
    zero[7].log_scale[1] = 100.0;
    refused(
        parse_ply(&write_ply(&zero, 45), p),
        "bad.ply",
        "Gaussian 7 has a negative or non-finite scale",
    );

    let raw = scene();
    let splat = write_splat(&raw);
    let s = Path::new("bad.splat");
    refused(
        parse_splat(&splat[..splat.len() - 1], s),
        "bad.splat",
        "not a whole number of 32-byte splats",
    );
    let mut zero = splat.clone();
    zero[32 * 2 + 28..32 * 3].copy_from_slice(&[128; 4]);
    refused(parse_splat(&zero, s), "bad.splat", "Gaussian 2 has a zero");
    refused(parse_splat(&[], s), "bad.splat", "no Gaussians");

    let z = Path::new("bad.spz");
    let spz = write_spz(&raw, 3, 3);
    refused(parse_spz(&splat, z), "bad.spz", "not gzip");
    refused(
        parse_spz(b"NGSP\x04\0\0\0", z),
        "bad.spz",
        "version 4 (ZSTD",
    );
    let mut plain = Vec::new();
    flate2::read::GzDecoder::new(&spz[..])
        .read_to_end(&mut plain)
        .unwrap();
    let patched = |at: usize, bytes: &[u8]| {
        let mut p = plain.clone();
        p[at..at + bytes.len()].copy_from_slice(bytes);
        gzip(&p)
    };
    refused(
        parse_spz(&patched(0, b"NGSQ"), z),
        "bad.spz",
        "wrong magic 0x5153474e",
    );
    refused(parse_spz(&patched(4, &[1]), z), "bad.spz", "version 1");
    refused(parse_spz(&patched(12, &[4]), z), "bad.spz", "SH degree 4");
    refused(
        parse_spz(&patched(8, &1_000_000_000u32.to_le_bytes()), z),
        "bad.spz",
        "compressed bytes can hold",
    );
    refused(
        parse_spz(&patched(8, &60u32.to_le_bytes()), z),
        "bad.spz",
        "truncated",
    );
    refused(
        parse_spz(&gzip(&plain[..plain.len() - 1]), z),
        "bad.spz",
        "truncated",
    );
    refused(
        parse_spz(&gzip(&plain[..10]), z),
        "bad.spz",
        "16-byte header",
    );
    refused(parse_spz(&spz[..spz.len() / 2], z), "bad.spz", "gzip");
}

#[test]
fn a_3dgs_ply_given_to_points_or_meshes_names_gaussians() {
    let raw = scene();
    let path = file("splats.ply", &write_ply(&raw[..2], 45));
    for e in [
        autostereo::points::PointCloud::load(&path).unwrap_err(),
        autostereo::mesh::Mesh::load(&path).unwrap_err(),
    ] {
        let e = e.to_string();
        assert!(e.contains("3D Gaussian splats"), "{e}");
        assert!(e.contains("use `autostereo gaussians "), "{e}");
    }
    // And a point cloud's PLY, or another kind's file, given to the Gaussians loader.
    let cloud = file(
        "cloud.ply",
        b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n",
    );
    let e = Gaussians::load(&cloud).unwrap_err().to_string();
    assert!(
        e.contains("this is a point cloud (PLY, vertices only"),
        "{e}"
    );
    assert!(e.contains("`autostereo points "), "{e}");
    let e = autostereo::points::PointCloud::load(&file("scene.spz", &write_spz(&raw, 3, 0)))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("this is 3D Gaussian splats (SPZ), not a point cloud"),
        "{e}"
    );
    assert_eq!(
        formats::kind(&dir().join("scene.spz")).unwrap(),
        (Format::Spz, DataKind::Gaussians)
    );
    assert!(formats::supported().contains("Gaussian splats .ply .splat .spz"));
}

/// The same scene from each file renders alike: the single pass of each against the PLY's
/// (degree 0, which every format holds), within what each format's quantisation moves.
#[test]
fn the_formats_render_alike() {
    use autostereo::gaussians::{GaussianOptions, GaussianScene, GaussianSplatter};
    use autostereo::render::Method;
    let raw = scene();
    let files = [
        ("PLY", file("render.ply", &write_ply(&raw, 0))),
        (".splat", file("render.splat", &write_splat(&raw))),
        (".spz v2", file("render.v2.spz", &write_spz(&raw, 2, 0))),
        (".spz v3", file("render.v3.spz", &write_spz(&raw, 3, 0))),
    ];
    let mut images = Vec::new();
    for (name, path) in &files {
        let g = Gaussians::load(path).unwrap();
        let frame = common::frame(g.bounds().unwrap(), "hubner8", 0.08, 1.0, [96, 64]);
        let (scene, mut splatter) = {
            let ctx = common::gpu();
            let scene = GaussianScene::new(&ctx.device, &g).unwrap();
            let splatter =
                GaussianSplatter::new(&ctx.device, Method::SinglePass, GaussianOptions::default())
                    .unwrap();
            (scene, splatter)
        };
        images.push((*name, common::render(&mut splatter, &scene, &frame)));
    }
    let (_, ply) = &images[0];
    let lit = ply.data.iter().filter(|&&v| v > 40).count();
    assert!(
        lit > ply.data.len() / 20,
        "the scene is in view: {lit} lit subpixels"
    );
    // Measured: .splat 54.5 dB (rotations to 1/128, colour and opacity truncated), .spz v2
    // 54.0, v3 54.8 dB (positions to 2^-12, log scales to 1/16); at most 5/255 off.
    for ((name, image), min_db) in images.iter().zip([1000.0, 45.0, 45.0, 45.0]).skip(1) {
        let diff = autostereo::image_io::compare(image, ply).unwrap();
        eprintln!("{name} against the PLY: {diff:?}");
        assert!(diff.psnr_db >= min_db, "{name}: {diff:?}");
    }
}
