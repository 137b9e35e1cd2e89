//! The built-in head: a contrast CT of a head and neck, modelled from signed distances so
//! that it reads as a real scan under the CT presets — skin with a face and ears, a skull with
//! orbits, sinuses and a jaw, teeth, the cervical spine, arteries filled with contrast, and a
//! brain with folded cortex, ventricles and cerebellum.
//!
//! Coordinates: p in [−1, 1]³ over the volume's physical extent (≈ 12 cm per unit); x to the
//! patient's left, y up, z forward (the face looks along +z, towards the default camera).
//! Densities follow the `ct-skin` preset's bands (src/volume/transfer.rs): air 0, fat 0.27,
//! soft tissue 0.3–0.33, CSF 0.37, white matter 0.42, grey matter 0.46, contrast-filled
//! arteries 0.75, cancellous bone 0.82, cortical bone 0.95, enamel 1.

/// Width of the smooth step at each boundary (units of p): about a voxel at the default
/// 96³, so surfaces shade smoothly without staircase contours.
const SOFT: f32 = 0.02;

type V = [f32; 3];

fn sub(a: V, b: V) -> V {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: V, b: V) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn len(a: V) -> f32 {
    dot(a, a).sqrt()
}

/// Approximate signed distance to an ellipsoid with centre c and semi-axes r.
fn ellipsoid(p: V, c: V, r: V) -> f32 {
    let q = [0, 1, 2].map(|i| (p[i] - c[i]) / r[i]);
    (len(q) - 1.0) * r[0].min(r[1]).min(r[2])
}

/// Approximate signed distance to a vertical elliptic cylinder (ellipse in x–z).
fn ellipse_xz(p: V, c: [f32; 2], r: [f32; 2]) -> f32 {
    let q = [(p[0] - c[0]) / r[0], (p[2] - c[1]) / r[1]];
    ((q[0] * q[0] + q[1] * q[1]).sqrt() - 1.0) * r[0].min(r[1])
}

/// Signed distance to a capsule from a to b whose radius goes from ra to rb.
fn capsule(p: V, a: V, b: V, ra: f32, rb: f32) -> f32 {
    let (pa, ba) = (sub(p, a), sub(b, a));
    let t = (dot(pa, ba) / dot(ba, ba)).clamp(0.0, 1.0);
    len(sub(pa, ba.map(|x| x * t))) - (ra + (rb - ra) * t)
}

/// Polynomial smooth minimum: unions that blend over `k` instead of creasing.
fn smooth_union(a: f32, b: f32, k: f32) -> f32 {
    let h = (0.5 + 0.5 * (b - a) / k).clamp(0.0, 1.0);
    b + (a - b) * h - k * h * (1.0 - h)
}

/// How much of a voxel at signed distance `d` is inside (1 deep inside, 0 outside).
fn cover(d: f32) -> f32 {
    let t = ((d + SOFT) / (2.0 * SOFT)).clamp(0.0, 1.0);
    1.0 - t * t * (3.0 - 2.0 * t)
}

fn mix(a: f32, b: f32, t: f32) -> f32 {
    a + (b - a) * t
}

/// Both sides of the face: the nearest of the primitive mirrored at x = 0.
fn mirrored(p: V, f: impl Fn(V) -> f32) -> f32 {
    f([p[0].abs(), p[1], p[2]])
}

/// The cranium's outer surface; the skull and the brain are offsets of it.
fn cranium(p: V) -> f32 {
    ellipsoid(p, [0.0, 0.25, -0.08], [0.6, 0.6, 0.74])
}

/// The outside of the body: cranium, face, jaw, nose, ears and neck, blended.
fn skin(p: V) -> f32 {
    let face = ellipsoid(p, [0.0, -0.2, 0.18], [0.46, 0.55, 0.5]);
    let jaw = ellipsoid(p, [0.0, -0.55, 0.2], [0.36, 0.3, 0.4]);
    let neck = capsule(p, [0.0, -1.3, -0.12], [0.0, -0.45, -0.1], 0.34, 0.34);
    let nose = capsule(p, [0.0, 0.05, 0.6], [0.0, -0.2, 0.76], 0.045, 0.075);
    let ears = mirrored(p, |q| ellipsoid(q, [0.6, 0.02, -0.08], [0.06, 0.15, 0.1]));
    let brow = ellipsoid(p, [0.0, 0.3, 0.5], [0.4, 0.14, 0.16]);
    let lips = ellipsoid(p, [0.0, -0.5, 0.58], [0.17, 0.08, 0.06]);
    let mut d = smooth_union(cranium(p), face, 0.12);
    for part in [jaw, neck, brow] {
        d = smooth_union(d, part, 0.1);
    }
    for part in [nose, ears, lips] {
        d = smooth_union(d, part, 0.04);
    }
    // The orbits sink the skin a little between brow and cheek.
    let sockets = mirrored(p, |q| ellipsoid(q, [0.22, 0.13, 0.66], [0.11, 0.07, 0.08]));
    d.max(-sockets + 0.02)
}

/// The eyeballs' centres and radius.
const EYE: (V, f32) = ([0.22, 0.12, 0.5], 0.11);

/// Skull, facial bones, jaw and spine as (signed distance, density): the calvaria has dense
/// outer and inner tables around a cancellous layer.
fn bone(p: V) -> (f32, f32) {
    let outer = cranium(p) + 0.045;
    let shell = outer.max(-(outer + 0.075));
    let tables = outer
        .max(-(outer + 0.02))
        .min((outer + 0.055).max(-(outer + 0.075)));
    // The skull base is open below the brain; the face has its own bones.
    let calvaria = shell.max(-p[1] - 0.1 + 0.3 * p[2].max(0.0));
    let orbits = mirrored(p, |q| ellipsoid(q, [0.22, 0.12, 0.5], [0.14, 0.14, 0.2]));
    // Upper jaw: the front of a bowl around the upper teeth, open at the nose.
    let maxilla = {
        let f = ellipsoid(p, [0.0, -0.26, 0.24], [0.28, 0.26, 0.3]);
        let aperture = ellipsoid(p, [0.0, -0.12, 0.5], [0.07, 0.12, 0.2]);
        f.max(-(f + 0.06))
            .max(p[1] + 0.02)
            .max(-p[1] - 0.5)
            .max(0.4 - p[2])
            .max(-aperture)
    };
    // Lower jaw: a U of bone open at the back, with the rami rising to the skull.
    let mandible = {
        let f = ellipse_xz(p, [0.0, 0.14], [0.3, 0.38]);
        let body = f
            .max(-(f + 0.06))
            .max(-p[1] - 0.78)
            .max(p[1] + 0.56)
            .max(-0.02 - p[2]);
        let ramus = mirrored(p, |q| {
            capsule(q, [0.29, -0.66, 0.0], [0.35, -0.22, -0.08], 0.05, 0.035)
        });
        body.min(ramus)
    };
    let cheekbones = mirrored(p, |q| {
        capsule(q, [0.16, -0.2, 0.46], [0.34, -0.1, 0.34], 0.04, 0.035).min(capsule(
            q,
            [0.34, -0.1, 0.34],
            [0.5, -0.06, 0.0],
            0.035,
            0.03,
        ))
    });
    let nasal = capsule(p, [0.0, 0.12, 0.6], [0.0, -0.05, 0.68], 0.025, 0.02);
    let face = maxilla
        .min(mandible)
        .min(cheekbones)
        .min(nasal)
        .max(-orbits);
    let mut spine = f32::MAX;
    for i in 0..7 {
        let y = -0.52 - 0.13 * i as f32;
        let body = capsule(p, [0.0, y, -0.15], [0.0, y - 0.07, -0.15], 0.09, 0.09);
        let arch = capsule(p, [0.0, y - 0.03, -0.2], [0.0, y - 0.06, -0.4], 0.04, 0.03);
        spine = spine.min(body.min(arch));
    }
    let d = calvaria.max(-orbits).min(face).min(spine);
    let dense = tables.max(-orbits).min(face).min(spine);
    (d, if dense < 0.0 { 0.95 } else { 0.82 })
}

/// Air inside the head: nasal cavity, sinuses, mouth and airway.
fn air(p: V) -> f32 {
    let nasal = ellipsoid(p, [0.0, -0.08, 0.48], [0.07, 0.16, 0.2]);
    let maxillary = mirrored(p, |q| ellipsoid(q, [0.18, -0.14, 0.36], [0.1, 0.1, 0.12]));
    let frontal = ellipsoid(p, [0.0, 0.42, 0.5], [0.12, 0.06, 0.05]);
    let airway = capsule(p, [0.0, -1.3, 0.05], [0.0, -0.3, 0.12], 0.06, 0.07);
    nasal.min(maxillary).min(frontal).min(airway)
}

/// Teeth: two arches of crowns along a parabola.
fn teeth(p: V) -> f32 {
    let mut d = f32::MAX;
    for (row, y) in [(0, -0.47f32), (1, -0.56)] {
        for i in 0..8 {
            let a = (i as f32 + 0.5) / 8.0; // front (0) to back (1)
            let x = 0.05 + 0.22 * a;
            let z = 0.5 - 0.36 * a * a;
            let dy = if row == 0 { -0.05 } else { 0.05 };
            let tooth = mirrored(p, |q| capsule(q, [x, y, z], [x, y + dy, z], 0.022, 0.018));
            d = d.min(tooth);
        }
    }
    d
}

/// The arteries, filled with contrast: carotids and vertebrals up the neck, the circle of
/// Willis and the cerebral arteries spreading out from it.
fn arteries(p: V) -> f32 {
    let r = 0.022;
    let side =
        mirrored(p, |q| {
            let carotid = capsule(q, [0.16, -1.3, 0.02], [0.15, -0.4, 0.04], r, r).min(capsule(
                q,
                [0.15, -0.4, 0.04],
                [0.1, -0.08, 0.02],
                r,
                r,
            ));
            let vertebral = capsule(q, [0.1, -1.3, -0.18], [0.03, -0.3, -0.16], 0.016, 0.016);
            let middle = capsule(q, [0.1, -0.08, 0.02], [0.32, -0.02, 0.05], r, 0.016)
                .min(capsule(
                    q,
                    [0.32, -0.02, 0.05],
                    [0.45, 0.2, 0.1],
                    0.016,
                    0.012,
                ))
                .min(capsule(
                    q,
                    [0.32, -0.02, 0.05],
                    [0.48, 0.05, -0.25],
                    0.016,
                    0.012,
                ));
            let anterior = capsule(q, [0.1, -0.08, 0.02], [0.03, 0.0, 0.3], 0.016, 0.014).min(
                capsule(q, [0.03, 0.0, 0.3], [0.02, 0.45, 0.15], 0.014, 0.011),
            );
            let posterior = capsule(q, [0.02, -0.12, -0.12], [0.2, -0.05, -0.5], 0.014, 0.011);
            carotid
                .min(vertebral)
                .min(middle)
                .min(anterior)
                .min(posterior)
        });
    let basilar = capsule(p, [0.0, -0.3, -0.16], [0.0, -0.12, -0.12], 0.018, 0.018);
    side.min(basilar)
}

/// A smooth pseudo-random field in about [−1, 1], used to fold the cortex.
fn folds(p: V) -> f32 {
    let w = [
        p[0] + 0.3 * (3.1 * p[1] + 1.7).sin(),
        p[1] + 0.3 * (2.7 * p[2] + 0.4).sin(),
        p[2] + 0.3 * (2.9 * p[0] + 2.3).sin(),
    ];
    ((11.0 * w[0]).sin() * (9.0 * w[1]).cos()
        + (10.0 * w[1]).sin() * (12.0 * w[2]).cos()
        + (13.0 * w[2]).sin() * (8.0 * w[0]).cos())
        / 3.0
}

/// The brain's density inside the skull (None where p is outside the brain).
fn brain(p: V) -> Option<f32> {
    let cerebrum = cranium(p) + 0.135;
    let cerebellum = ellipsoid(p, [0.0, -0.2, -0.42], [0.38, 0.18, 0.24]);
    let stem = capsule(p, [0.0, 0.05, -0.12], [0.0, -0.5, -0.2], 0.07, 0.06);
    let outline = cerebrum
        .max(-p[1] - 0.05 + 0.6 * (p[2] + 0.3).min(0.0))
        .min(cerebellum)
        .min(stem);
    if outline > SOFT {
        return None;
    }
    let depth = -outline;
    // Grey matter near the surface, white matter inside; sulci of CSF cut into the cortex
    // and the fissure between the hemispheres.
    let sulcus: f32 = if depth < 0.09 && folds(p).abs() < 0.12 {
        1.0
    } else {
        0.0
    };
    let fissure = (1.0 - (p[0].abs() / 0.012)).max(0.0) * (p[1] > -0.05) as u8 as f32;
    let folia = if cerebellum < 0.0 && (55.0 * p[1] + 8.0 * p[2]).sin() > 0.6 {
        1.0
    } else {
        0.0
    };
    let tissue = mix(0.42, 0.46, cover(0.06 - depth));
    let mut d = mix(tissue, 0.37, sulcus.max(fissure).max(folia * 0.7));
    let ventricles = mirrored(p, |q| {
        capsule(q, [0.08, 0.22, 0.22], [0.1, 0.3, -0.1], 0.035, 0.045).min(capsule(
            q,
            [0.1, 0.3, -0.1],
            [0.2, 0.05, -0.25],
            0.045,
            0.03,
        ))
    });
    let third = capsule(p, [0.0, 0.05, 0.1], [0.0, 0.1, -0.1], 0.012, 0.012);
    d = mix(d, 0.37, cover(ventricles.min(third)));
    // A calcified pineal gland, as most adult scans show.
    d = mix(d, 0.85, cover(len(sub(p, [0.0, 0.1, -0.16])) - 0.02));
    Some(mix(0.37, d, cover(outline)))
}

/// The density at p.
pub fn density(p: V) -> f32 {
    let outside = skin(p);
    if outside > SOFT {
        return 0.0; // exactly empty, so empty-space skipping sees the air as transparent
    }
    // Soft tissue: a fat layer under the skin, muscle beneath.
    let mut d = mix(0.32, 0.27, cover(outside + 0.03) - cover(outside + 0.06));
    if let Some(b) = brain(p) {
        d = mix(d, b, cover(cranium(p) + 0.12));
    }
    let (eye, r) = EYE;
    let eyes = mirrored(p, |q| len(sub(q, eye)) - r);
    let lens = mirrored(p, |q| ellipsoid(q, [0.22, 0.12, 0.6], [0.04, 0.04, 0.015]));
    d = mix(d, 0.33, cover(eyes));
    d = mix(d, 0.5, cover(lens));
    d = mix(d, 0.0, cover(air(p)));
    let (bones, value) = bone(p);
    d = mix(d, value, cover(bones));
    d = mix(d, 1.0, cover(teeth(p)));
    d = mix(d, 0.75, cover(arteries(p)));
    d * cover(outside)
}
