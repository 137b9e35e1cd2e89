//! A generated scene of 3D Gaussians shaped like a capture (the bench's and the built-in
//! scene): flat, oriented Gaussians tiling a torus and a ground disc — surfaces as trainers
//! leave them — with view-dependent colour (SH degree 3) and a fixed seed.

use glam::{Quat, Vec3};

use super::Gaussians;

/// A small deterministic generator (no rand dependency): uniform in [0, 1).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> f32 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 40) as f32) / (1u64 << 24) as f32
    }

    fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.next()
    }
}

impl Gaussians {
    /// `count` (≥ 1) Gaussians: three quarters on a torus (radii 1 and 0.35), the rest on a
    /// ground disc below it, each a flat ellipse in its surface (σ about half the spacing of
    /// the means, so that neighbours overlap), opacity 0.5–1, SH degree 3 (a hue around the torus, a sheen that turns with
    /// the view direction).
    pub fn generated(count: usize) -> Gaussians {
        let count = count.max(1);
        let mut r = Lcg(0x5eed);
        let mut g = Gaussians {
            sh_degree: 3,
            ..Default::default()
        };
        let on_torus = count * 3 / 4;
        // Mean spacing of the points on each surface: the Gaussians' in-surface size.
        let torus_area = 4.0 * std::f32::consts::PI.powi(2) * 1.0 * 0.35;
        let disc_area = std::f32::consts::PI * 1.8f32.powi(2);
        let spacing = |area: f32, n: usize| (area / n.max(1) as f32).sqrt();
        for i in 0..count {
            let (position, normal, hue, size) = if i < on_torus {
                let (u, v) = (
                    r.range(0.0, std::f32::consts::TAU),
                    r.range(0.0, std::f32::consts::TAU),
                );
                let ring = Vec3::new(u.cos(), 0.0, u.sin());
                let normal = ring * v.cos() + Vec3::Y * v.sin();
                let size = spacing(torus_area, on_torus);
                (
                    ring + normal * 0.35,
                    normal,
                    u / std::f32::consts::TAU,
                    size,
                )
            } else {
                let (a, d) = (r.range(0.0, std::f32::consts::TAU), 1.8 * r.next().sqrt());
                let p = Vec3::new(a.cos() * d, -0.6, a.sin() * d);
                let size = spacing(disc_area, count - on_torus);
                (p, Vec3::Y, 0.1 + 0.05 * (d * 3.0).sin(), size)
            };
            g.positions.push(position);
            g.scales.push(Vec3::new(
                size * r.range(0.3, 0.7),
                size * r.range(0.3, 0.7),
                size * 0.03,
            ));
            // The Gaussian's z axis along the normal, turned at random about it.
            let align = Quat::from_rotation_arc(Vec3::Z, normal);
            let spin = Quat::from_rotation_z(r.range(0.0, std::f32::consts::TAU));
            g.rotations.push((align * spin).normalize());
            g.opacities.push(r.range(0.5, 1.0));
            let base = hue_rgb(hue);
            g.sh.push(base.map(super::sh::dc_from_color));
            for k in 1..16 {
                let sheen = if k < 4 { 0.25 } else { 0.08 };
                g.sh.push([
                    r.range(-sheen, sheen),
                    r.range(-sheen, sheen),
                    r.range(-sheen, sheen),
                ]);
            }
        }
        g
    }
}

/// A saturated colour for `hue` in [0, 1).
fn hue_rgb(hue: f32) -> [f32; 3] {
    let h = hue.rem_euclid(1.0) * 6.0;
    let x = 1.0 - (h % 2.0 - 1.0).abs();
    let (r, g, b) = match h as u32 {
        0 => (1.0, x, 0.0),
        1 => (x, 1.0, 0.0),
        2 => (0.0, 1.0, x),
        3 => (0.0, x, 1.0),
        4 => (x, 0.0, 1.0),
        _ => (1.0, 0.0, x),
    };
    [0.15 + 0.7 * r, 0.15 + 0.7 * g, 0.15 + 0.7 * b]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_generated_scene_is_valid_and_fixed() {
        let a = Gaussians::generated(1000);
        a.validate().unwrap();
        assert_eq!(a.len(), 1000);
        assert_eq!(a, Gaussians::generated(1000));
        let b = a.bounds().unwrap();
        assert!(b.radius() > 1.0 && b.radius() < 3.0, "{b:?}");
    }
}
