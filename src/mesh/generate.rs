//! Meshes generated in code for tests, examples and the built-in scenes.

use std::f32::consts::TAU;

use glam::Vec3;

use super::Mesh;

impl Mesh {
    /// The built-in test scene: an orange torus facing +z with a blue sphere through its hole,
    /// reaching in front of and behind the ring, so that parallax has both signs.
    pub fn torus_scene() -> Self {
        let mut scene = Mesh::torus(1.0, 0.35, 64, 24, [0.95, 0.55, 0.15, 1.0]);
        scene.append(&Mesh::sphere(
            Vec3::new(0.0, 0.0, 0.3),
            0.5,
            24,
            32,
            [0.2, 0.45, 0.95, 1.0],
        ));
        scene
    }

    /// A torus around the z axis (facing a camera on +z): `major` ring radius, `minor` tube
    /// radius, `rings × sides` quads, one colour.
    pub fn torus(major: f32, minor: f32, rings: u32, sides: u32, color: [f32; 4]) -> Self {
        let (rings, sides) = (rings.max(3), sides.max(3));
        let mut mesh = Mesh::default();
        for i in 0..rings {
            let u = i as f32 / rings as f32 * TAU;
            let ring = Vec3::new(u.cos(), u.sin(), 0.0);
            for j in 0..sides {
                let v = j as f32 / sides as f32 * TAU;
                let normal = ring * v.cos() + Vec3::Z * v.sin();
                mesh.positions.push(ring * major + normal * minor);
                mesh.normals.push(normal);
                mesh.colors.push(color);
            }
        }
        for i in 0..rings {
            for j in 0..sides {
                let at = |a: u32, b: u32| (a % rings) * sides + (b % sides);
                let (p, q, r, s) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
                mesh.indices.extend_from_slice(&[p, q, r, p, r, s]);
            }
        }
        mesh
    }

    /// An axis-aligned rectangle in the plane z = `z`, facing +z, from `min` to `max` (x, y).
    pub fn rectangle(min: [f32; 2], max: [f32; 2], z: f32, color: [f32; 4]) -> Self {
        Mesh {
            positions: vec![
                Vec3::new(min[0], min[1], z),
                Vec3::new(max[0], min[1], z),
                Vec3::new(max[0], max[1], z),
                Vec3::new(min[0], max[1], z),
            ],
            normals: vec![Vec3::Z; 4],
            colors: vec![color; 4],
            indices: vec![0, 1, 2, 0, 2, 3],
            ..Mesh::default()
        }
    }

    /// A UV sphere of `radius` at `center`.
    pub fn sphere(center: Vec3, radius: f32, stacks: u32, slices: u32, color: [f32; 4]) -> Self {
        let (stacks, slices) = (stacks.max(2), slices.max(3));
        let mut mesh = Mesh::default();
        for i in 0..=stacks {
            let theta = i as f32 / stacks as f32 * std::f32::consts::PI;
            for j in 0..=slices {
                let phi = j as f32 / slices as f32 * TAU;
                let n = Vec3::new(
                    theta.sin() * phi.cos(),
                    theta.cos(),
                    theta.sin() * phi.sin(),
                );
                mesh.positions.push(center + n * radius);
                mesh.normals.push(n);
                mesh.colors.push(color);
            }
        }
        let row = slices + 1;
        for i in 0..stacks {
            for j in 0..slices {
                let (p, q) = (i * row + j, (i + 1) * row + j);
                mesh.indices
                    .extend_from_slice(&[p, q, q + 1, p, q + 1, p + 1]);
            }
        }
        mesh
    }
}
