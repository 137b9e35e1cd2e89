//! Precomputed gradients (paper §3.5.1): the 3D Sobel operator, in world units.

use super::Volume;

impl Volume {
    /// Per voxel `[gx, gy, gz, scalar]`: the Sobel gradient (∂/∂x … in scalar units per world
    /// unit, so anisotropic spacing shades correctly) and the scalar itself.
    pub fn gradients(&self) -> Vec<[f32; 4]> {
        let [nx, ny, nz] = self.dims.map(|d| d as i64);
        let smooth = [1.0f32, 2.0, 1.0];
        // Sobel: central difference along the axis, (1, 2, 1) smoothing across it; the weights
        // on one side sum to 16 and the two sides are 2 voxels apart.
        let scale = [0, 1, 2].map(|a| 1.0 / (32.0 * self.spacing[a]));
        let mut out = Vec::with_capacity(self.data.len());
        for z in 0..nz {
            for y in 0..ny {
                for x in 0..nx {
                    let mut g = [0.0f32; 3];
                    for dz in -1..=1i64 {
                        for dy in -1..=1i64 {
                            for dx in -1..=1i64 {
                                let v = self.at(x + dx, y + dy, z + dz);
                                let w = |a: i64, b: i64| {
                                    smooth[(a + 1) as usize] * smooth[(b + 1) as usize]
                                };
                                g[0] += dx as f32 * w(dy, dz) * v;
                                g[1] += dy as f32 * w(dx, dz) * v;
                                g[2] += dz as f32 * w(dx, dy) * v;
                            }
                        }
                    }
                    out.push([
                        g[0] * scale[0],
                        g[1] * scale[1],
                        g[2] * scale[2],
                        self.at(x, y, z),
                    ]);
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sobel_of_a_linear_ramp_is_its_slope_in_world_units() {
        let dims = [6, 5, 4];
        let spacing = [0.5, 1.0, 2.0];
        let mut data = Vec::new();
        for z in 0..4 {
            for y in 0..5 {
                for x in 0..6 {
                    data.push(0.01 * x as f32 + 0.02 * y as f32 + 0.03 * z as f32);
                }
            }
        }
        let v = Volume::new(dims, spacing, data).unwrap();
        let g = v.gradients();
        let inner = (2 * 5 + 2) * 6 + 2; // voxel (2, 2, 2)
        let expect = [0.01 / 0.5, 0.02 / 1.0, 0.03 / 2.0];
        for a in 0..3 {
            assert!(
                (g[inner][a] - expect[a]).abs() < 1e-6,
                "{a}: {:?}",
                g[inner]
            );
        }
    }
}
