//! Empty-space skipping, exact: per voxel cell (the box between 2 × 2 × 2 voxel centres, over
//! which trilinear interpolation reads the same 8 voxels) the range of pre-integration table
//! entries any sample inside it can read; per transfer function, each cell's Chebyshev distance
//! (in cells) to the nearest cell where a segment could be seen.
//!
//! A cell is *transparent* when every table entry its scalars can reach is zero (no opacity,
//! premultiplied colour 0). If cell c has distance D, every cell within D − 1 of it is
//! transparent, and face-adjacent cells share four voxels, so the entry ranges of that cube of
//! cells overlap into one run of zero entries: a segment between any two samples in the cube
//! adds exactly zero. So a ray at a sample in cell c may jump as far as it moves at most D − 1
//! voxels along every axis and resume on the same sample planes (wgsl/volume/shared/march.wgsl):
//! the image is the one without skipping, bit for bit (tests/volumes/volume.rs). Unlike fixed bricks, a
//! ray in air next to a surface still skips all but the voxel or two before it, and one look-up
//! crosses up to 254 voxels of open space.
//!
//! Memory: the ranges take 2 bytes per cell for the scene's lifetime (the distances are
//! rebuilt from them when the transfer function changes); building them holds 2 more per voxel
//! at a time; the distance texture takes 1 byte per cell on the GPU.

use half::f16;

use super::preintegration::TABLE_SIZE;
use super::transfer::TransferFunction;
use super::Volume;

/// Largest distance stored (one byte per cell).
pub const MAX_DISTANCE: u8 = u8::MAX;

/// Per voxel cell of one volume, the table entries its samples can read.
#[derive(Clone, Debug, PartialEq)]
pub struct CellRanges {
    /// Cells along x, y, z (`dims − 1`, at least 1).
    pub grid: [u32; 3],
    /// Per cell (x fastest), the first and last pre-integration table entry (front or back
    /// index) a filtered look-up at any scalar inside the cell reads.
    entries: Vec<[u8; 2]>,
}

impl CellRanges {
    /// Entry ranges of `volume` (validated: see [`Volume::validate`]), reduced one axis at a
    /// time. Cell c along an axis spans voxels c and c + 1 (the last voxel where the axis has
    /// one): a sample there, and one the sampler clamps at the box's faces, interpolates only
    /// those.
    pub(crate) fn new(volume: &Volume) -> Self {
        let dims = volume.dims.map(|d| d as usize);
        let grid = volume.dims.map(|d| d.saturating_sub(1).max(1));
        let g = grid.map(|d| d as usize);
        let widen = |r: [u8; 2], s: [u8; 2]| [r[0].min(s[0]), r[1].max(s[1])];
        let pair = |c: usize, n: usize| [c, (c + 1).min(n - 1)];
        // Along x: per (cell x, y, z). The GPU holds the scalars as f16.
        // Each voxel's entries once (a row at a time), then widened over the cell's pair.
        let mut along_x = vec![[0u8; 2]; g[0] * dims[1] * dims[2]];
        let mut row_entries = vec![[0u8; 2]; dims[0]];
        for (row, out) in volume
            .data
            .chunks_exact(dims[0])
            .zip(along_x.chunks_exact_mut(g[0]))
        {
            for (e, &v) in row_entries.iter_mut().zip(row) {
                *e = entries_of(v);
            }
            for (cx, range) in out.iter_mut().enumerate() {
                let [a, b] = pair(cx, dims[0]).map(|x| row_entries[x]);
                *range = widen(a, b);
            }
        }
        // Along y: per (cell x, cell y, z).
        let mut along_y = vec![[0u8; 2]; g[0] * g[1] * dims[2]];
        for z in 0..dims[2] {
            for cy in 0..g[1] {
                let [y0, y1] = pair(cy, dims[1]);
                for cx in 0..g[0] {
                    let at = |y: usize| along_x[(z * dims[1] + y) * g[0] + cx];
                    along_y[(z * g[1] + cy) * g[0] + cx] = widen(at(y0), at(y1));
                }
            }
        }
        drop(along_x);
        // Along z: per cell.
        let layer = g[0] * g[1];
        let mut entries = vec![[0u8; 2]; layer * g[2]];
        for cz in 0..g[2] {
            let [z0, z1] = pair(cz, dims[2]);
            for i in 0..layer {
                entries[cz * layer + i] = widen(along_y[z0 * layer + i], along_y[z1 * layer + i]);
            }
        }
        Self { grid, entries }
    }

    /// Per cell (x fastest), the Chebyshev distance in cells to the nearest cell that is not
    /// transparent under `tf` (0: this one is not), at most [`MAX_DISTANCE`]. Cells outside
    /// the grid count as transparent: rays are clipped to the box.
    pub fn distances(&self, tf: &TransferFunction) -> Vec<u8> {
        let table = TransparentEntries::new(tf);
        let mut distance: Vec<u8> = self
            .entries
            .iter()
            .map(|&[first, last]| {
                if table.all_zero(first, last) {
                    MAX_DISTANCE
                } else {
                    0
                }
            })
            .collect();
        chessboard_distances(&mut distance, self.grid);
        distance
    }

    /// Make every cell read only the table entries of scalar 0 (air): a test that the ray
    /// caster really skips what the distances call empty.
    #[cfg(test)]
    pub(crate) fn falsify_for_tests(&mut self) {
        self.entries.fill(entries_of(0.0));
    }

    /// Share of the cells that are transparent under `tf` (0..1).
    pub fn transparent_share(&self, tf: &TransferFunction) -> f64 {
        let table = TransparentEntries::new(tf);
        let clear = self
            .entries
            .iter()
            .filter(|&&[first, last]| table.all_zero(first, last))
            .count();
        clear as f64 / self.entries.len().max(1) as f64
    }
}

/// The table entries a filtered look-up at scalar `s` (as f16, like the GPU's) reads: entries
/// ⌊255·s⌋ and ⌊255·s⌋ + 1, with 1 % of an entry either side for rounding of s.
fn entries_of(s: f32) -> [u8; 2] {
    let s = f16::from_f32(s).to_f32();
    let last = (TABLE_SIZE - 1) as f32;
    let first = (s * last - 0.01).floor().clamp(0.0, last);
    let after = ((s * last + 0.01).floor() + 1.0).clamp(0.0, last);
    [first as u8, after as u8]
}

/// Two-pass chamfer with every one of the 26 neighbours at distance 1: exact for the
/// Chebyshev (chessboard) distance (Rosenfeld & Pfaltz 1966). `distance` holds 0 at the
/// obstacles and [`MAX_DISTANCE`] elsewhere; distances saturate there. The backward pass is
/// the forward pass on the reversed array (reversing x-fastest order mirrors all three axes).
fn chessboard_distances(distance: &mut [u8], grid: [u32; 3]) {
    forward_chamfer(distance, grid);
    distance.reverse();
    forward_chamfer(distance, grid);
    distance.reverse();
}

/// The forward pass: each cell takes the least of itself and one more than its 13 neighbours
/// before it (the 3 × 3 block in the layer below, the 3 cells in the row before, the cell
/// before), which hold their final forward values. The block's minimum is filtered once per
/// layer (x, then y), so a cell costs a few operations whatever its neighbourhood.
fn forward_chamfer(distance: &mut [u8], grid: [u32; 3]) {
    let [nx, ny, nz] = grid.map(|n| n as usize);
    let layer = nx * ny;
    // Least of each cell's 3-wide neighbourhood along x within a row.
    let min3 = |row: &[u8], out: &mut [u8]| {
        for (x, o) in out.iter_mut().enumerate() {
            *o = row[x.saturating_sub(1)..(x + 2).min(row.len())]
                .iter()
                .copied()
                .min()
                .unwrap_or(MAX_DISTANCE);
        }
    };
    let mut below_x = vec![MAX_DISTANCE; layer];
    let mut below = vec![MAX_DISTANCE; layer];
    let mut row_before = vec![MAX_DISTANCE; nx];
    for z in 0..nz {
        let (done, rest) = distance.split_at_mut(z * layer);
        let current = &mut rest[..layer];
        if z > 0 {
            let previous = &done[(z - 1) * layer..];
            for (row, out) in previous.chunks_exact(nx).zip(below_x.chunks_exact_mut(nx)) {
                min3(row, out);
            }
            for y in 0..ny {
                for x in 0..nx {
                    let column =
                        (y.saturating_sub(1)..(y + 2).min(ny)).map(|b| below_x[b * nx + x]);
                    below[y * nx + x] = column.min().unwrap_or(MAX_DISTANCE);
                }
            }
        }
        for y in 0..ny {
            if y > 0 {
                min3(&current[(y - 1) * nx..y * nx], &mut row_before);
            }
            let row = &mut current[y * nx..(y + 1) * nx];
            for x in 0..nx {
                let mut near = MAX_DISTANCE;
                if z > 0 {
                    near = near.min(below[y * nx + x]);
                }
                if y > 0 {
                    near = near.min(row_before[x]);
                }
                if x > 0 {
                    near = near.min(row[x - 1]);
                }
                row[x] = row[x].min(near.saturating_add(1));
            }
        }
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

    /// Whether every table entry (f, b) with f and b in `first..=last` is zero.
    fn all_zero(&self, first: u8, last: u8) -> bool {
        let (a, b) = (
            FINE_PER_ENTRY * first as usize,
            FINE_PER_ENTRY * last as usize + 1,
        );
        self.opaque_before[b] == self.opaque_before[a]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::volume::{generate, PreintegrationTable};

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

    /// The cell the GPU looks up for texel-space position `p`.
    fn cell_of(cells: &CellRanges, p: [f32; 3]) -> usize {
        let c = [0, 1, 2].map(|a| ((p[a] - 0.5).floor().max(0.0) as u32).min(cells.grid[a] - 1));
        ((c[2] * cells.grid[1] + c[1]) * cells.grid[0] + c[0]) as usize
    }

    #[test]
    fn every_sample_reads_only_its_cells_entries() {
        let v = generate::ct_head(21).unwrap();
        let cells = CellRanges::new(&v);
        assert_eq!(cells.grid, [20, 20, 16]);
        let mut state = 12345u32;
        let mut next = || {
            state = state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            (state >> 8) as f32 / (1 << 24) as f32
        };
        for _ in 0..20_000 {
            // Anywhere in the box, the clamped margins included.
            let p = [0, 1, 2].map(|a| next() * v.dims[a] as f32);
            let [first, last] = cells.entries[cell_of(&cells, p)];
            let [lo, hi] = entries_of(trilinear(&v, p));
            assert!(
                lo >= first && hi <= last,
                "{lo}..{hi} outside {first}..{last}"
            );
        }
    }

    /// Brute force: the distance to the nearest non-transparent cell, all of them tried.
    #[test]
    fn the_chamfer_gives_the_chebyshev_distance() {
        let grid = [9u32, 7, 6];
        let n = (grid[0] * grid[1] * grid[2]) as usize;
        let coords = |i: usize| {
            let (x, y, z) = (i % 9, (i / 9) % 7, i / 63);
            [x as i64, y as i64, z as i64]
        };
        for seed in [1u32, 7, 99] {
            let mut state = seed;
            let obstacles: Vec<bool> = (0..n)
                .map(|_| {
                    state = state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
                    state >> 28 == 0 // 1 in 16
                })
                .collect();
            let mut distance: Vec<u8> = obstacles
                .iter()
                .map(|&o| if o { 0 } else { MAX_DISTANCE })
                .collect();
            chessboard_distances(&mut distance, grid);
            for (i, &d) in distance.iter().enumerate() {
                let c = coords(i);
                let want = (0..n)
                    .filter(|&j| obstacles[j])
                    .map(|j| {
                        let o = coords(j);
                        (0..3).map(|a| (c[a] - o[a]).abs()).max().unwrap()
                    })
                    .min()
                    .map_or(MAX_DISTANCE, |d| d.min(MAX_DISTANCE as i64) as u8);
                assert_eq!(d, want, "cell {c:?}, seed {seed}");
            }
        }
    }

    #[test]
    fn transparent_cells_have_only_zero_table_entries() {
        let v = generate::ct_head(48).unwrap();
        let cells = CellRanges::new(&v);
        for name in crate::volume::transfer::PRESETS {
            let tf = TransferFunction::preset(name).unwrap();
            let table = PreintegrationTable::new(&tf, 0.5).unwrap();
            let distance = cells.distances(&tf);
            for (&d, &[first, last]) in distance.iter().zip(&cells.entries) {
                if d == 0 {
                    continue;
                }
                for f in first as usize..=last as usize {
                    for b in first as usize..=last as usize {
                        assert_eq!(table.rgba[f * TABLE_SIZE + b], [0.0; 4], "{name}");
                    }
                }
            }
        }
        // The head in air under ct-skin: a good share of the box is skippable, but not all.
        let share = cells.transparent_share(&TransferFunction::preset("ct-skin").unwrap());
        assert!(share > 0.2 && share < 0.9, "{share}");
    }

    #[test]
    fn an_opaque_or_constant_transfer_function() {
        let v = generate::ct_head(16).unwrap();
        let cells = CellRanges::new(&v);
        let opaque = TransferFunction::new(vec![(0.0, [1.0, 1.0, 1.0, 0.01])]).unwrap();
        assert!(cells.distances(&opaque).iter().all(|&d| d == 0));
        let clear = TransferFunction::new(vec![(0.0, [1.0, 1.0, 1.0, 0.0])]).unwrap();
        assert!(cells.distances(&clear).iter().all(|&d| d == MAX_DISTANCE));
    }

    #[test]
    fn a_volume_one_voxel_thin_has_one_cell_across() {
        let v = Volume {
            dims: [1, 3, 2],
            spacing: [1.0; 3],
            data: vec![0.0; 6],
            axes: glam::Mat3::IDENTITY,
            values: Default::default(),
        };
        assert_eq!(CellRanges::new(&v).grid, [1, 2, 1]);
    }
}
