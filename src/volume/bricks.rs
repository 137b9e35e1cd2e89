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
pub const BRICK: u32 = 4;

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
    /// Ranges of `volume` (validated: see [`Volume::validate`]), reduced one axis at a time
    /// (≈ 1.5 visits per voxel).
    pub(crate) fn new(volume: &Volume) -> Self {
        let dims = volume.dims.map(|d| d as usize);
        let grid = volume.dims.map(|d| d.div_ceil(BRICK));
        let g = grid.map(|d| d as usize);
        // A sample at texel-space position p (voxel centres at i + ½) interpolates voxels
        // ⌊p − ½⌋ and ⌊p − ½⌋ + 1, so positions within half a voxel of brick b's box
        // [b·B, (b + 1)·B] read voxels b·B − 1 ..= (b + 1)·B along each axis.
        let span = |b: usize, n: usize| {
            let brick = BRICK as usize;
            (b * brick).saturating_sub(1)..((b + 1) * brick + 1).min(n)
        };
        let widen = |r: [f32; 2], s: [f32; 2]| [r[0].min(s[0]), r[1].max(s[1])];
        const EMPTY: [f32; 2] = [f32::INFINITY, f32::NEG_INFINITY];
        // Along x: per (brick x, y, z). The GPU holds the scalars as f16.
        let mut along_x = vec![EMPTY; g[0] * dims[1] * dims[2]];
        for (row, out) in volume
            .data
            .chunks_exact(dims[0])
            .zip(along_x.chunks_exact_mut(g[0]))
        {
            for (bx, range) in out.iter_mut().enumerate() {
                for &v in &row[span(bx, dims[0])] {
                    let s = f16::from_f32(v).to_f32();
                    *range = widen(*range, [s, s]);
                }
            }
        }
        // Along y: per (brick x, brick y, z).
        let mut along_y = vec![EMPTY; g[0] * g[1] * dims[2]];
        for z in 0..dims[2] {
            for by in 0..g[1] {
                for y in span(by, dims[1]) {
                    for bx in 0..g[0] {
                        let out = &mut along_y[(z * g[1] + by) * g[0] + bx];
                        *out = widen(*out, along_x[(z * dims[1] + y) * g[0] + bx]);
                    }
                }
            }
        }
        // Along z: per brick.
        let mut ranges = vec![EMPTY; g[0] * g[1] * g[2]];
        for bz in 0..g[2] {
            for z in span(bz, dims[2]) {
                for i in 0..g[0] * g[1] {
                    let out = &mut ranges[bz * g[0] * g[1] + i];
                    *out = widen(*out, along_y[z * g[0] * g[1] + i]);
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
        assert_eq!(bricks.grid, [6, 6, 5]);
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
            let [gx, gy, _] = bricks.grid;
            let [lo, hi] = bricks.ranges[((b[2] * gy + b[1]) * gx + b[0]) as usize];
            let s = trilinear(&v, p);
            assert!(s >= lo - 1e-6 && s <= hi + 1e-6, "{s} outside {lo}..{hi}");
        }
    }

    #[test]
    fn separable_ranges_equal_the_direct_definition() {
        let v = phantom::ct_head(23).unwrap();
        let bricks = BrickRanges::new(&v);
        let b = BRICK as i64;
        let mut i = 0;
        for bz in 0..bricks.grid[2] as i64 {
            for by in 0..bricks.grid[1] as i64 {
                for bx in 0..bricks.grid[0] as i64 {
                    let mut range = [f32::INFINITY, f32::NEG_INFINITY];
                    for z in (bz * b - 1).max(0)..=((bz + 1) * b).min(v.dims[2] as i64 - 1) {
                        for y in (by * b - 1).max(0)..=((by + 1) * b).min(v.dims[1] as i64 - 1) {
                            for x in (bx * b - 1).max(0)..=((bx + 1) * b).min(v.dims[0] as i64 - 1)
                            {
                                let s = f16::from_f32(v.at(x, y, z)).to_f32();
                                range = [range[0].min(s), range[1].max(s)];
                            }
                        }
                    }
                    assert_eq!(bricks.ranges[i], range, "brick {bx},{by},{bz}");
                    i += 1;
                }
            }
        }
        assert_eq!(i, bricks.ranges.len());
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
