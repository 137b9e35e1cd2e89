//! One scene in every format loads to the same Gaussians within each format's quantisation;
//! degree-0 colours.

use super::*;

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
