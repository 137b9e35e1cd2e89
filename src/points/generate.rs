//! Generated clouds with exact normals: test scenes and the CLI's default.

use glam::Vec3;

use super::PointCloud;

/// Colour varying with position, so that images have structure to compare.
fn hue(p: Vec3, scale: f32) -> [f32; 3] {
    let q = p / scale.max(1e-12);
    [
        0.55 + 0.4 * (2.1 * q.x).sin(),
        0.55 + 0.4 * (1.7 * q.y + 1.0).sin(),
        0.55 + 0.4 * (2.3 * q.z + 2.0).sin(),
    ]
}

impl PointCloud {
    /// `n` points evenly spread over a sphere (Fibonacci lattice), outward normals, radii
    /// `radius_factor` × the mean spacing (`None`: left to estimation).
    pub fn sphere(n: u32, centre: Vec3, radius: f32, radius_factor: Option<f32>) -> Self {
        let n = n.max(1);
        let golden = std::f32::consts::PI * (3.0 - 5f32.sqrt());
        let mut cloud = Self::default();
        for i in 0..n {
            let y = 1.0 - 2.0 * (i as f32 + 0.5) / n as f32;
            let ring = (1.0 - y * y).max(0.0).sqrt();
            let phi = golden * i as f32;
            let normal = Vec3::new(ring * phi.cos(), y, ring * phi.sin());
            cloud.positions.push(centre + radius * normal);
            cloud.normals.get_or_insert_with(Vec::new).push(normal);
            cloud
                .colors
                .get_or_insert_with(Vec::new)
                .push(hue(normal, 1.0));
        }
        let spacing = radius * (4.0 * std::f32::consts::PI / n as f32).sqrt();
        cloud.radii = radius_factor.map(|f| vec![f * spacing; n as usize]);
        cloud
    }

    /// A torus around the y axis sampled on a `rings × sides` grid, outward normals, radii
    /// `radius_factor` × the larger grid spacing (`None`: left to estimation).
    pub fn torus(
        major: f32,
        minor: f32,
        rings: u32,
        sides: u32,
        radius_factor: Option<f32>,
    ) -> Self {
        let (rings, sides) = (rings.max(3), sides.max(3));
        let tau = std::f32::consts::TAU;
        let mut cloud = Self::default();
        for i in 0..rings {
            let u = tau * i as f32 / rings as f32;
            let axis = Vec3::new(u.cos(), 0.0, u.sin());
            for j in 0..sides {
                let v = tau * j as f32 / sides as f32;
                let normal = axis * v.cos() + Vec3::Y * v.sin();
                let p = axis * major + normal * minor;
                cloud.positions.push(p);
                cloud.normals.get_or_insert_with(Vec::new).push(normal);
                cloud
                    .colors
                    .get_or_insert_with(Vec::new)
                    .push(hue(p, major));
            }
        }
        let spacing = (tau * (major + minor) / rings as f32).max(tau * minor / sides as f32);
        cloud.radii = radius_factor.map(|f| vec![f * spacing; cloud.positions.len()]);
        cloud
    }

    /// The CLI's default scene: a torus around a sphere, tilted towards the viewer.
    pub fn torus_scene() -> Self {
        let mut scene = Self::torus(1.0, 0.3, 240, 72, Some(0.75));
        let sphere = Self::sphere(20_000, Vec3::ZERO, 0.55, Some(0.75));
        scene.append(&sphere);
        let tilt = glam::Quat::from_rotation_x(0.6);
        for p in &mut scene.positions {
            *p = tilt * *p;
        }
        for n in scene.normals.iter_mut().flatten() {
            *n = tilt * *n;
        }
        scene
    }

    /// Append `other` (attributes kept only where both have them).
    pub fn append(&mut self, other: &PointCloud) {
        fn join<T: Clone>(a: &mut Option<Vec<T>>, b: &Option<Vec<T>>) {
            match b {
                Some(b) => {
                    if let Some(a) = a {
                        a.extend_from_slice(b);
                    }
                }
                None => *a = None,
            }
        }
        join(&mut self.normals, &other.normals);
        join(&mut self.colors, &other.colors);
        join(&mut self.radii, &other.radii);
        self.positions.extend_from_slice(&other.positions);
    }
}
