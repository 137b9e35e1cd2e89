//! A uniform grid over points (counting sort by cell): the neighbour queries behind normal and
//! radius estimation and splat grouping.

use glam::{IVec3, Vec3};

/// Most cells a grid allocates per point (bounds memory when the cell size is tiny).
const MAX_CELLS_PER_POINT: f32 = 4.0;

pub(crate) struct Grid {
    origin: Vec3,
    cell: f32,
    dims: IVec3,
    /// `order[starts[c]..starts[c + 1]]` are the points of cell c.
    starts: Vec<u32>,
    order: Vec<u32>,
}

impl Grid {
    /// Bin `points` into cells of (at least) `cell` size; larger when the box would need more
    /// than a few cells per point.
    pub fn new(points: &[Vec3], cell: f32) -> Self {
        let (lo, hi) = points.iter().fold(
            (Vec3::splat(f32::MAX), Vec3::splat(f32::MIN)),
            |(lo, hi), p| (lo.min(*p), hi.max(*p)),
        );
        let extent = (hi - lo).max(Vec3::splat(1e-30));
        let budget = (points.len() as f32 * MAX_CELLS_PER_POINT).max(1.0);
        let min_cell = (extent.x * extent.y * extent.z / budget).cbrt();
        let cell = if cell.is_finite() && cell > 0.0 {
            cell.max(min_cell)
        } else {
            min_cell
        };
        let mut cell = cell.max(extent.max_element() * 1e-6).max(f32::MIN_POSITIVE);
        // Flat or linear clouds: the volume estimate says nothing, so grow until in budget.
        let dims_for = |cell: f32| ((extent / cell).floor() + 1.0).max(Vec3::ONE);
        while dims_for(cell).element_product() > 2.0 * budget + 1024.0 {
            cell *= 1.25;
        }
        let dims = dims_for(cell).as_ivec3();
        let mut grid = Self {
            origin: lo,
            cell,
            dims,
            starts: Vec::new(),
            order: Vec::new(),
        };
        let cells = (dims.x as usize) * (dims.y as usize) * (dims.z as usize);
        let mut counts = vec![0u32; cells + 1];
        let index: Vec<u32> = points
            .iter()
            .map(|p| grid.cell_index(grid.cell_of(*p)))
            .collect();
        for &c in &index {
            counts[c as usize + 1] += 1;
        }
        for c in 1..counts.len() {
            counts[c] += counts[c - 1];
        }
        let mut fill = counts.clone();
        let mut order = vec![0u32; points.len()];
        for (i, &c) in index.iter().enumerate() {
            order[fill[c as usize] as usize] = i as u32;
            fill[c as usize] += 1;
        }
        grid.starts = counts;
        grid.order = order;
        grid
    }

    pub fn cell_size(&self) -> f32 {
        self.cell
    }

    /// Mean number of points per non-empty cell.
    pub fn mean_occupancy(&self) -> f32 {
        let occupied = self.starts.windows(2).filter(|w| w[1] > w[0]).count();
        self.order.len() as f32 / occupied.max(1) as f32
    }

    pub fn cell_of(&self, p: Vec3) -> IVec3 {
        ((p - self.origin) / self.cell)
            .floor()
            .as_ivec3()
            .clamp(IVec3::ZERO, self.dims - 1)
    }

    fn cell_index(&self, c: IVec3) -> u32 {
        (c.x + self.dims.x * (c.y + self.dims.y * c.z)) as u32
    }

    /// Points of cell `c` (empty outside the grid).
    pub fn points_in(&self, c: IVec3) -> &[u32] {
        if c.cmplt(IVec3::ZERO).any() || c.cmpge(self.dims).any() {
            return &[];
        }
        let i = self.cell_index(c) as usize;
        &self.order[self.starts[i] as usize..self.starts[i + 1] as usize]
    }

    /// Cells whose Chebyshev distance from `centre` is exactly `shell`, clipped to the grid.
    pub fn shell(&self, centre: IVec3, shell: i32) -> impl Iterator<Item = IVec3> + '_ {
        let lo = (centre - shell).max(IVec3::ZERO);
        let hi = (centre + shell).min(self.dims - 1);
        (lo.z..=hi.z).flat_map(move |z| {
            (lo.y..=hi.y).flat_map(move |y| {
                (lo.x..=hi.x).filter_map(move |x| {
                    let c = IVec3::new(x, y, z);
                    ((c - centre).abs().max_element() == shell).then_some(c)
                })
            })
        })
    }

    /// Largest shell that can still hold points.
    pub fn max_shell(&self) -> i32 {
        self.dims.max_element()
    }

    /// Every point within the box `p ± reach`, plus some nearby.
    pub fn near(&self, p: Vec3, reach: f32) -> impl Iterator<Item = u32> + '_ {
        let lo = self.cell_of(p - Vec3::splat(reach));
        let hi = self.cell_of(p + Vec3::splat(reach));
        (lo.z..=hi.z).flat_map(move |z| {
            (lo.y..=hi.y).flat_map(move |y| {
                (lo.x..=hi.x).flat_map(move |x| self.points_in(IVec3::new(x, y, z)).iter().copied())
            })
        })
    }
}
