//! What of a volume its classification shows ([`Volume::visible_bounds`]): the framing's box
//! for `--fit visible`, so a skull-stripped brain or a CT inside its padding fills the frame
//! instead of the scan's whole box.

use glam::{Mat3, Vec3};

use super::{ClipPlane, Projection, TransferFunction, Volume};
use crate::camera::Bounds;

/// Entries of the visibility table over the normalised scalar.
const TABLE: usize = 4096;

/// For each of [`TABLE`] equal scalar intervals: whether `transfer` gives any opacity in it
/// (at either end or at a control point inside — it is piecewise linear, so nowhere else).
fn opaque_intervals(transfer: &TransferFunction) -> Vec<bool> {
    let at = |i: usize| i as f32 / TABLE as f32;
    let mut table: Vec<bool> = (0..TABLE)
        .map(|i| transfer.eval(at(i))[3] > 0.0 || transfer.eval(at(i + 1))[3] > 0.0)
        .collect();
    for &(s, c) in &transfer.points {
        if c[3] > 0.0 {
            table[((s.clamp(0.0, 1.0) * TABLE as f32) as usize).min(TABLE - 1)] = true;
        }
    }
    table
}

impl Volume {
    /// The box around the voxels that `projection` shows under `transfer` (`isovalue`: the
    /// isosurface's normalised value), kept by `clip`, in the frame of [`Volume::bounds`] (its
    /// axes, centred); grown by one voxel each way, since rays interpolate into the
    /// neighbours. Compositing shows the voxels the transfer function gives any opacity; an
    /// isosurface those at or above its value; the projections (MIP, MinIP, mean) are opaque
    /// over the whole box, so their box is the volume's. `None` where nothing is shown.
    pub fn visible_bounds(
        &self,
        transfer: &TransferFunction,
        projection: Projection,
        isovalue: f32,
        clip: &[ClipPlane],
    ) -> Option<Bounds> {
        let table = opaque_intervals(transfer);
        let shows = |s: f32| match projection {
            // The table rules out most scalars at once; the rest are evaluated.
            Projection::Composite => {
                table[((s.clamp(0.0, 1.0) * TABLE as f32) as usize).min(TABLE - 1)]
                    && transfer.eval(s)[3] > 0.0
            }
            Projection::Isosurface => s >= isovalue,
            _ => true,
        };
        let spacing = Vec3::from(self.spacing);
        let kept = |v: [u32; 3]| {
            let p = (Vec3::new(v[0] as f32, v[1] as f32, v[2] as f32) + 0.5) * spacing;
            clip.iter().all(|c| c.normal.dot(p) <= c.offset)
        };
        let [nx, ny, nz] = self.dims.map(|d| d as usize);
        let (mut lo, mut hi) = ([u32::MAX; 3], [0u32; 3]);
        for z in 0..nz {
            for y in 0..ny {
                let row = &self.data[(z * ny + y) * nx..][..nx];
                for (x, &s) in row.iter().enumerate() {
                    let v = [x as u32, y as u32, z as u32];
                    if shows(s) && kept(v) {
                        for a in 0..3 {
                            lo[a] = lo[a].min(v[a]);
                            hi[a] = hi[a].max(v[a]);
                        }
                    }
                }
            }
        }
        if lo[0] == u32::MAX {
            return None;
        }
        // Voxel i spans i … i + 1 (in spacing units from the corner); one voxel more each way.
        let corner = |v: [u32; 3], grow: i64| {
            Vec3::from_array([0, 1, 2].map(|a| {
                (v[a] as i64 + grow).clamp(0, self.dims[a] as i64) as f32 * self.spacing[a]
            }))
        };
        let (min, max) = (corner(lo, -1), corner(hi, 2));
        let centre = self.extent() * 0.5;
        Some(placed(self.axes, min - centre, max - centre))
    }
}

/// The box `min … max` in voxel-axis coordinates as `axes` turn it, bounded again.
fn placed(axes: Mat3, min: Vec3, max: Vec3) -> Bounds {
    let corners = (0..8).map(|i| {
        axes * Vec3::new(
            if i & 1 == 0 { min.x } else { max.x },
            if i & 2 == 0 { min.y } else { max.y },
            if i & 4 == 0 { min.z } else { max.z },
        )
    });
    Bounds::of_points(corners).expect("finite corners")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 20³ volume of 0 with a block of 1 at voxels 4…7 along x, 10…14 along y and z.
    fn block() -> Volume {
        let n = 20;
        let mut data = vec![0.0; n * n * n];
        for z in 10..15 {
            for y in 10..15 {
                for x in 4..8 {
                    data[(z * n + y) * n + x] = 1.0;
                }
            }
        }
        Volume::new([n as u32; 3], [1.0, 2.0, 1.0], data).unwrap()
    }

    #[test]
    fn the_visible_box_is_the_shown_voxels_grown_by_one() {
        let v = block();
        let tf =
            TransferFunction::new(vec![(0.0, [0.0; 4]), (0.5, [0.0; 4]), (1.0, [1.0; 4])]).unwrap();
        let b = v
            .visible_bounds(&tf, Projection::Composite, 0.5, &[])
            .unwrap();
        // x: voxels 3 … 8 (spans 3 … 9), centred on 10; y (spacing 2): 9 … 15 → 18 … 32, on 20.
        assert_eq!(b.min, Vec3::new(-7.0, -2.0, -1.0));
        assert_eq!(b.max, Vec3::new(-1.0, 12.0, 6.0));
        let iso = v
            .visible_bounds(&tf, Projection::Isosurface, 0.9, &[])
            .unwrap();
        assert_eq!(iso, b);
        let mip = v
            .visible_bounds(&tf, Projection::Maximum, 0.5, &[])
            .unwrap();
        assert_eq!(mip, v.bounds());
        // A plane keeping x ≤ 6 (mm from the corner) drops the block's voxels 6 and 7.
        let cut = [ClipPlane::new(Vec3::X, 6.0)];
        let clipped = v
            .visible_bounds(&tf, Projection::Composite, 0.5, &cut)
            .unwrap();
        assert_eq!(clipped.max.x, -3.0);
        let clear =
            TransferFunction::new(vec![(0.0, [0.0; 4]), (1.0, [1.0, 1.0, 1.0, 0.0])]).unwrap();
        assert_eq!(
            v.visible_bounds(&clear, Projection::Composite, 0.5, &[]),
            None
        );
    }

    #[test]
    fn the_visible_box_turns_with_the_voxel_axes() {
        let v = block()
            .with_axes(Mat3::from_rotation_z(std::f32::consts::FRAC_PI_2))
            .unwrap();
        let tf = TransferFunction::new(vec![(0.0, [0.0; 4]), (1.0, [1.0; 4])]).unwrap();
        let b = v
            .visible_bounds(&tf, Projection::Composite, 0.5, &[])
            .unwrap();
        // Voxel x now points along world y, voxel y along −x.
        assert!(
            (b.min - Vec3::new(-12.0, -7.0, -1.0)).abs().max_element() < 1e-5,
            "{b:?}"
        );
        assert!(
            (b.max - Vec3::new(2.0, -1.0, 6.0)).abs().max_element() < 1e-5,
            "{b:?}"
        );
    }
}
