//! A sparse uniform grid over points (points sorted by cell, a hash map from cell to its run):
//! the neighbour queries behind normal and radius estimation and splat grouping. Sparse, so a
//! far outlier costs one cell, not a bounding box full of empty ones.

use std::collections::HashMap;

use glam::{IVec3, Vec3};

/// Largest cell coordinate magnitude (keeps `IVec3` arithmetic far from overflow).
const MAX_COORD: f32 = (1 << 28) as f32;

pub(crate) struct Grid {
    origin: Vec3,
    cell: f32,
    /// Cell → range of `order`.
    cells: HashMap<IVec3, (u32, u32)>,
    order: Vec<u32>,
    /// Largest Chebyshev distance between occupied cells (bounds shell searches).
    span: i32,
}

impl Grid {
    /// Bin `points` into cells of size `cell` (grown if the cloud would need cell coordinates
    /// beyond ±2²⁸; any non-positive or non-finite `cell` means "one cell per cloud extent").
    pub fn new(points: &[Vec3], cell: f32) -> Self {
        let (lo, hi) = points.iter().fold(
            (Vec3::splat(f32::MAX), Vec3::splat(f32::MIN)),
            |(lo, hi), p| (lo.min(*p), hi.max(*p)),
        );
        let extent = if points.is_empty() {
            1.0
        } else {
            (hi - lo).max_element()
        };
        let min_cell = (extent / MAX_COORD).max(f32::MIN_POSITIVE);
        let cell = if cell.is_finite() && cell > 0.0 {
            cell.max(min_cell)
        } else {
            extent.max(min_cell)
        };
        let origin = if points.is_empty() { Vec3::ZERO } else { lo };
        let key = |p: Vec3| ((p - origin) / cell).floor().as_ivec3();
        let mut keyed: Vec<(IVec3, u32)> = points
            .iter()
            .enumerate()
            .map(|(i, p)| (key(*p), i as u32))
            .collect();
        keyed.sort_unstable_by_key(|(c, _)| (c.z, c.y, c.x));
        let mut cells = HashMap::new();
        let mut start = 0usize;
        let (mut cmin, mut cmax) = (IVec3::MAX, IVec3::MIN);
        for i in 1..=keyed.len() {
            if i == keyed.len() || keyed[i].0 != keyed[start].0 {
                let c = keyed[start].0;
                cells.insert(c, (start as u32, i as u32));
                cmin = cmin.min(c);
                cmax = cmax.max(c);
                start = i;
            }
        }
        Self {
            origin,
            cell,
            cells,
            order: keyed.into_iter().map(|(_, i)| i).collect(),
            span: if points.is_empty() {
                0
            } else {
                (cmax - cmin).max_element()
            },
        }
    }

    pub fn cell_size(&self) -> f32 {
        self.cell
    }

    /// Mean number of points per non-empty cell.
    pub fn mean_occupancy(&self) -> f32 {
        self.order.len() as f32 / self.cells.len().max(1) as f32
    }

    pub fn cell_of(&self, p: Vec3) -> IVec3 {
        ((p - self.origin) / self.cell)
            .floor()
            .clamp(Vec3::splat(-MAX_COORD), Vec3::splat(MAX_COORD))
            .as_ivec3()
    }

    /// Points of cell `c` (empty when unoccupied).
    pub fn points_in(&self, c: IVec3) -> &[u32] {
        match self.cells.get(&c) {
            Some(&(a, b)) => &self.order[a as usize..b as usize],
            None => &[],
        }
    }

    /// Cells whose Chebyshev distance from `centre` is exactly `shell`.
    pub fn shell(&self, centre: IVec3, shell: i32) -> impl Iterator<Item = IVec3> + '_ {
        let (lo, hi) = (centre - shell, centre + shell);
        (lo.z..=hi.z).flat_map(move |z| {
            (lo.y..=hi.y).flat_map(move |y| {
                // Interior rows of the shell only touch its two x faces.
                let face = z == lo.z || z == hi.z || y == lo.y || y == hi.y;
                let step = if face { 1 } else { (2 * shell).max(1) as usize };
                (lo.x..=hi.x)
                    .step_by(step)
                    .map(move |x| IVec3::new(x, y, z))
            })
        })
    }

    /// Largest shell that can still reach an occupied cell.
    pub fn max_shell(&self) -> i32 {
        self.span
    }

    /// Every point whose cell intersects the box `p ± reach` (a superset of those within
    /// `reach`). Visits occupied cells only when the box spans more cells than there are.
    pub fn near(&self, p: Vec3, reach: f32) -> Box<dyn Iterator<Item = u32> + '_> {
        let lo = self.cell_of(p - Vec3::splat(reach));
        let hi = self.cell_of(p + Vec3::splat(reach));
        let span = (hi - lo + 1).as_vec3();
        if span.x * span.y * span.z > self.cells.len() as f32 {
            return Box::new(
                self.cells
                    .iter()
                    .filter(move |(c, _)| c.cmpge(lo).all() && c.cmple(hi).all())
                    .flat_map(|(_, &(a, b))| self.order[a as usize..b as usize].iter().copied()),
            );
        }
        Box::new((lo.z..=hi.z).flat_map(move |z| {
            (lo.y..=hi.y).flat_map(move |y| {
                (lo.x..=hi.x).flat_map(move |x| self.points_in(IVec3::new(x, y, z)).iter().copied())
            })
        }))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shells_partition_the_cube() {
        let grid = Grid::new(&[Vec3::ZERO], 1.0);
        let mut seen = std::collections::HashSet::new();
        for s in 0..4 {
            for c in grid.shell(IVec3::ZERO, s) {
                assert_eq!(c.abs().max_element(), s);
                assert!(seen.insert(c), "{c} twice");
            }
        }
        assert_eq!(seen.len(), 7 * 7 * 7);
    }

    #[test]
    fn a_far_outlier_costs_one_cell() {
        let mut points: Vec<Vec3> = (0..1000)
            .map(|i| Vec3::new(i as f32 * 0.01, 0.0, 0.0))
            .collect();
        points.push(Vec3::splat(1e7));
        let grid = Grid::new(&points, 0.02);
        assert!(grid.mean_occupancy() >= 1.9, "{}", grid.mean_occupancy());
        let near: Vec<u32> = grid.near(Vec3::ZERO, 0.015).collect();
        assert!(near.contains(&0) && near.contains(&1) && !near.contains(&1000));
    }
}
