//! Test data for 3D Gaussian splats, once for every test binary: a deterministic generator
//! and graphdeco's binary PLY as the trainer writes it (`x y z nx ny nz f_dc_* f_rest_*
//! opacity scale_* rot_*`, `f_rest_*` channel-major, log scales, opacity logits, unnormalised
//! (w, x, y, z) rotations).

/// A tiny LCG (Knuth's MMIX constants; no rand crate): the same numbers on every machine.
pub struct Lcg(pub u64);

impl Lcg {
    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f32 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 40) as f32) / (1u64 << 24) as f32
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.unit()
    }
}

/// A trainer's raw parameters of one Gaussian, as a graphdeco PLY stores them.
#[derive(Clone, Copy, Debug)]
pub struct Raw {
    pub position: [f32; 3],
    pub log_scale: [f32; 3],
    /// (w, x, y, z), unnormalised.
    pub rotation: [f32; 4],
    pub logit: f32,
    /// 16 RGB coefficients, DC first (a lower degree uses the first (degree + 1)²).
    pub sh: [[f32; 3]; 16],
}

/// graphdeco's PLY of `raw` with `rest` `f_rest_*` properties (3 × ((degree + 1)² − 1)).
pub fn write_ply(raw: &[Raw], rest: usize) -> Vec<u8> {
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
    let mut header = format!(
        "ply\nformat binary_little_endian 1.0\nelement vertex {}\n",
        raw.len()
    );
    for n in &names {
        header += &format!("property float {n}\n");
    }
    header += "end_header\n";
    let mut bytes = header.into_bytes();
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
