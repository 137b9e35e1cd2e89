//! Spatial ordering of triangles along a Morton (Z-order) curve of their centroids.
//!
//! Consecutive triangles then lie close together, which the single-pass renderer relies on
//! when several triangles share one covering rectangle, and which helps every cache.

use glam::Vec3;

use super::Mesh;

/// Spread the low 10 bits of `v` to every third bit.
fn spread_bits(v: u32) -> u32 {
    let mut x = v & 0x3ff;
    x = (x | (x << 16)) & 0x0300_00ff;
    x = (x | (x << 8)) & 0x0300_f00f;
    x = (x | (x << 4)) & 0x030c_30c3;
    x = (x | (x << 2)) & 0x0924_9249;
    x
}

/// 30-bit Morton code of `p` inside the box `min..min + extent`.
fn morton(p: Vec3, min: Vec3, inv_extent: Vec3) -> u32 {
    let q = ((p - min) * inv_extent * 1023.0).clamp(Vec3::ZERO, Vec3::splat(1023.0));
    spread_bits(q.x as u32) | (spread_bits(q.y as u32) << 1) | (spread_bits(q.z as u32) << 2)
}

impl Mesh {
    /// Reorder the triangles (not the vertices) along a Morton curve of their centroids.
    /// Ties keep the original order, so the result is deterministic.
    pub fn sort_triangles_spatially(&mut self) {
        let Some(bounds) = self.bounds() else { return };
        let extent = (bounds.max - bounds.min).max(Vec3::splat(f32::MIN_POSITIVE));
        let inv_extent = extent.recip();
        let mut keyed: Vec<(u32, u32)> = self
            .indices
            .chunks_exact(3)
            .enumerate()
            .map(|(i, t)| {
                let c = (self.positions[t[0] as usize]
                    + self.positions[t[1] as usize]
                    + self.positions[t[2] as usize])
                    / 3.0;
                (morton(c, bounds.min, inv_extent), i as u32)
            })
            .collect();
        keyed.sort_unstable();
        self.indices = keyed
            .iter()
            .flat_map(|&(_, i)| {
                let i = i as usize * 3;
                [self.indices[i], self.indices[i + 1], self.indices[i + 2]]
            })
            .collect();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn morton_interleaves_axes() {
        assert_eq!(spread_bits(0b11), 0b1001);
        let m = morton(Vec3::new(1.0, 0.0, 0.0), Vec3::ZERO, Vec3::ONE);
        assert_eq!(m, spread_bits(1023));
    }

    #[test]
    fn sorting_keeps_the_triangle_set() {
        let mut mesh = Mesh::torus(1.0, 0.3, 16, 8, [1.0; 4]);
        let mut before: Vec<[u32; 3]> =
            mesh.indices.chunks(3).map(|t| [t[0], t[1], t[2]]).collect();
        mesh.sort_triangles_spatially();
        let mut after: Vec<[u32; 3]> = mesh.indices.chunks(3).map(|t| [t[0], t[1], t[2]]).collect();
        assert_ne!(before, after);
        before.sort();
        after.sort();
        assert_eq!(before, after);
    }
}
