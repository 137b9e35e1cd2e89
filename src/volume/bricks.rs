//! Empty-space skipping, exact: per brick of [`BRICK`]³ voxels, the range of scalars any sample
//! inside the brick can take; per transfer function, which bricks no segment can be seen in.
//!
//! A ray-marched segment between two samples inside one transparent brick adds exactly zero
//! (its pre-integration entries are all 0: no opacity, premultiplied colour 0), so the ray
//! caster jumps over such bricks and resumes on the same sample planes: the image is the one
//! without skipping, bit for bit (tests/volume.rs).

use half::f16;

use super::transfer::{TransferFunction, TABLE_SIZE};
use super::Volume;

/// Brick edge, voxels.
pub const BRICK: u32 = 8;

/// Scalar ranges of the bricks of one volume.
#[derive(Clone, Debug, PartialEq)]
pub struct BrickRanges {
    /// Bricks along x, y, z (`⌈dims / BRICK⌉`).
    pub grid: [u32; 3],
    /// Per brick (x fastest), the smallest and largest scalar that trilinear interpolation can
    /// give anywhere within half a voxel of the brick's box.
    pub(crate) ranges: Vec<[f32; 2]>,
}

impl BrickRanges {
    /// Ranges of `volume` (one visit per voxel and brick it touches, ≈ 2× the voxels).
    pub fn new(volume: &Volume) -> Self {
        let grid = volume.dims.map(|d| d.div_ceil(BRICK));
        let mut ranges = Vec::with_capacity(grid.iter().map(|&g| g as usize).product());
        // A sample at texel-space position p (voxel centres at i + ½) interpolates voxels
        // ⌊p − ½⌋ and ⌊p − ½⌋ + 1, so positions within half a voxel of brick b's box
        // [b·B, (b + 1)·B] read voxels b·B − 1 ..= (b + 1)·B.
        let span = |b: u32, n: u32| {
            let lo = (i64::from(b) * i64::from(BRICK) - 1).max(0);
            let hi = ((i64::from(b) + 1) * i64::from(BRICK)).min(i64::from(n) - 1);
            lo..=hi
        };
        for bz in 0..grid[2] {
            for by in 0..grid[1] {
                for bx in 0..grid[0] {
                    let mut range = [f32::INFINITY, f32::NEG_INFINITY];
                    for z in span(bz, volume.dims[2]) {
                        for y in span(by, volume.dims[1]) {
                            for x in span(bx, volume.dims[0]) {
                                // The GPU holds the scalar as f16.
                                let s = f16::from_f32(volume.at(x, y, z)).to_f32();
                                range = [range[0].min(s), range[1].max(s)];
                            }
                        }
                    }
                    ranges.push(range);
                }
            }
        }
        Self { grid, ranges }
    }

    /// Per brick (x fastest), 1 where every segment between two samples inside it is
    /// transparent under `tf`, else 0.
    pub fn transparent(&self, tf: &TransferFunction) -> Vec<u8> {
        let table = TransparentEntries::new(tf);
        self.ranges
            .iter()
            .map(|&[lo, hi]| u8::from(table.all_transparent(lo, hi)))
            .collect()
    }

    /// Share of the bricks that are transparent under `tf` (0..1).
    pub fn transparent_share(&self, tf: &TransferFunction) -> f64 {
        let flags = self.transparent(tf);
        flags.iter().filter(|&&f| f == 1).count() as f64 / flags.len().max(1) as f64
    }
}

/// Which pre-integration table entries are exactly zero. The table (transfer.rs) integrates the
/// transfer function's extinction on a grid 4× finer than its entries; entry (f, b) is zero
/// exactly when the opacity is zero at every fine point between 4f and 4b.
struct TransparentEntries {
    /// Fine points with non-zero opacity before each fine index (prefix count).
    opaque_before: Vec<u32>,
}

/// Fine grid points per table entry (as in `PreintegrationTable::new`).
const FINE_PER_ENTRY: usize = 4;

impl TransparentEntries {
    fn new(tf: &TransferFunction) -> Self {
        let fine = FINE_PER_ENTRY * (TABLE_SIZE - 1);
        let mut opaque_before = Vec::with_capacity(fine + 2);
        opaque_before.push(0);
        for i in 0..=fine {
            let opaque = tf.eval(i as f32 / fine as f32)[3] > 0.0;
            opaque_before.push(opaque_before[i] + u32::from(opaque));
        }
        Self { opaque_before }
    }

    /// Whether every table entry the GPU can read for scalars in `lo..=hi` is zero. The
    /// filtered lookup at scalar s reads entries ⌊255·s⌋ and ⌊255·s⌋ + 1; a margin of 1 % of an
    /// entry absorbs rounding of s.
    fn all_transparent(&self, lo: f32, hi: f32) -> bool {
        let last = (TABLE_SIZE - 1) as f32;
        let first_entry = (lo * last - 0.01).floor().clamp(0.0, last) as usize;
        let last_entry = ((hi * last + 0.01).floor() + 1.0).clamp(0.0, last) as usize;
        let (a, b) = (
            FINE_PER_ENTRY * first_entry,
            FINE_PER_ENTRY * last_entry + 1,
        );
        self.opaque_before[b] == self.opaque_before[a]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::volume::{phantom, PreintegrationTable};

    /// Trilinear interpolation of the f16 scalars at texel-space `p`, clamped at the edges as
    /// the GPU sampler does.
    fn trilinear(v: &Volume, p: [f32; 3]) -> f32 {
        let q = p.map(|c| c - 0.5);
        let i = q.map(|c| c.floor());
        let f = [q[0] - i[0], q[1] - i[1], q[2] - i[2]];
        let mut s = 0.0;
        for corner in 0..8 {
            let d = [corner & 1, (corner >> 1) & 1, corner >> 2];
            let w: f32 = (0..3)
                .map(|a| if d[a] == 1 { f[a] } else { 1.0 - f[a] })
                .product();
            let at = |a: usize| i[a] as i64 + d[a] as i64;
            s += w * f16::from_f32(v.at(at(0), at(1), at(2))).to_f32();
        }
        s
    }

    #[test]
    fn ranges_hold_every_sample_within_half_a_voxel_of_a_brick() {
        let v = phantom::ct_head(21).unwrap(); // partial bricks on every axis
        let bricks = BrickRanges::new(&v);
        assert_eq!(bricks.grid, [3, 3, 3]);
        let mut state = 12345u32;
        let mut next = || {
            state = state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            (state >> 8) as f32 / (1 << 24) as f32
        };
        for _ in 0..20_000 {
            let b = [0, 1, 2].map(|a| (next() * bricks.grid[a] as f32) as u32);
            let p = [0, 1, 2].map(|a| {
                let lo = (b[a] * BRICK) as f32 - 0.5;
                let hi = (((b[a] + 1) * BRICK).min(v.dims[a])) as f32 + 0.5;
                lo + next() * (hi - lo)
            });
            let [lo, hi] = bricks.ranges[((b[2] * 3 + b[1]) * 3 + b[0]) as usize];
            let s = trilinear(&v, p);
            assert!(s >= lo - 1e-6 && s <= hi + 1e-6, "{s} outside {lo}..{hi}");
        }
    }

    #[test]
    fn transparent_bricks_have_only_zero_table_entries() {
        let v = phantom::ct_head(48).unwrap();
        let bricks = BrickRanges::new(&v);
        for name in crate::volume::transfer::PRESETS {
            let tf = TransferFunction::preset(name).unwrap();
            let table = PreintegrationTable::new(&tf, 0.5).unwrap();
            let flags = bricks.transparent(&tf);
            for (flag, &[lo, hi]) in flags.iter().zip(&bricks.ranges) {
                if *flag == 0 {
                    continue;
                }
                let entry = |s: f32| (s * 255.0).floor() as usize;
                for f in entry(lo)..=(entry(hi) + 1).min(255) {
                    for b in entry(lo)..=(entry(hi) + 1).min(255) {
                        assert_eq!(table.rgba[f * TABLE_SIZE + b], [0.0; 4], "{name}");
                    }
                }
            }
        }
        // The head in air under ct-skin: a good share of the box is skippable, but not all.
        let share = bricks.transparent_share(&TransferFunction::preset("ct-skin").unwrap());
        assert!(share > 0.2 && share < 0.9, "{share}");
    }

    #[test]
    fn an_opaque_or_constant_transfer_function() {
        let v = phantom::ct_head(16).unwrap();
        let bricks = BrickRanges::new(&v);
        let opaque = TransferFunction::new(vec![(0.0, [1.0, 1.0, 1.0, 0.01])]).unwrap();
        assert_eq!(bricks.transparent_share(&opaque), 0.0);
        let clear = TransferFunction::new(vec![(0.0, [1.0, 1.0, 1.0, 0.0])]).unwrap();
        assert_eq!(bricks.transparent_share(&clear), 1.0);
    }
}
