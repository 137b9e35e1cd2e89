//! Splat groups for ε-z deferred compositing (Zhang & Pajarola 2006): splats are split into K
//! groups in which no two splats overlap (their bounding spheres are disjoint), by greedy
//! colouring over a spatial grid. Each group is rendered into its own target with a plain
//! z-test, so a splat can only hide splats of other surfaces, never its overlapping neighbours.

use super::grid::Grid;
use super::Splats;

/// Groups the automatic colouring may open; beyond, splats join the least-conflicting group.
pub const MAX_AUTO_GROUPS: u32 = 64;

/// How many groups to make.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GroupCount {
    /// As many as the greedy colouring needs (≤ [`MAX_AUTO_GROUPS`]): no overlap in a group.
    Auto,
    /// Exactly this many (≥ 1); overlaps inside a group are counted as conflicts.
    Fixed(u32),
}

/// The group of every splat.
#[derive(Clone, Debug, PartialEq)]
pub struct Grouping {
    /// Group index per splat.
    pub group_of: Vec<u32>,
    /// Number of groups K.
    pub groups: u32,
    /// Overlapping pairs that share a group (0 for [`GroupCount::Auto`] unless capped). Exact
    /// unless `truncated` > 0; then a lower bound.
    pub conflicts: u64,
    /// Splats whose neighbour scan stopped at [`MAX_CANDIDATES`] (dense clusters: a splat with
    /// thousands of overlapping neighbours); their group is the best among those seen.
    pub truncated: u32,
    /// Candidate pairs examined: the work done, at most [`MAX_CANDIDATES`] per splat.
    pub checks: u64,
}

impl Grouping {
    /// Splats per group.
    pub fn sizes(&self) -> Vec<u32> {
        let mut sizes = vec![0u32; self.groups as usize];
        for &g in &self.group_of {
            sizes[g as usize] += 1;
        }
        sizes
    }
}

/// Splats larger than this × the typical radius are placed last, on a grid of their own, so
/// that one huge splat does not turn the grid into one cell.
const LARGE_PER_MEDIAN: f32 = 8.0;

/// Most candidates a splat's placement examines. Ordinary clouds have a few dozen overlapping
/// neighbours; a dense cluster (identical points, a far outlier cluster collapsed by f32
/// rounding) can have all n, which made grouping quadratic. Past this bound the splat takes the
/// best group among the candidates seen: bounded work, at the price of possible (counted as
/// `truncated`) overlaps inside a group, in clouds that have no distinct surface there anyway.
pub const MAX_CANDIDATES: usize = 4096;

/// Greedy colouring of `splats`: each splat takes the first group none of its overlapping,
/// already placed neighbours is in. `Fixed(k)` must be ≥ 1 and is bounded by the caller.
/// Work is at most [`MAX_CANDIDATES`] candidates per splat, plus sorting into grids.
pub fn assign(splats: &Splats, count: GroupCount) -> Grouping {
    let n = splats.positions.len();
    let limit = match count {
        GroupCount::Auto => MAX_AUTO_GROUPS,
        GroupCount::Fixed(k) => k.max(1),
    };
    // Zero-radius splats overlap nothing: they neither set the typical radius nor the reach.
    let cap = LARGE_PER_MEDIAN * typical_radius(&splats.radii);
    let (normal, large): (Vec<usize>, Vec<usize>) = (0..n).partition(|&i| splats.radii[i] <= cap);
    // Normal splats find every normal neighbour within r_i + r_j ≤ r_i + reach on the grid.
    let reach = normal.iter().fold(0.0f32, |m, &i| m.max(splats.radii[i]));
    const UNASSIGNED: u32 = u32::MAX;
    let mut state = Placement {
        splats,
        group_of: vec![UNASSIGNED; n],
        clashes: vec![0u32; limit as usize],
        groups: 0,
        conflicts: 0,
        truncated: 0,
        checks: 0,
    };
    if reach > 0.0 {
        let grid = Grid::new(&splats.positions, 2.0 * reach);
        for &i in &normal {
            let (p, r) = (splats.positions[i], splats.radii[i]);
            state.place(i, grid.near(p, r + reach));
        }
    } else {
        // Every normal splat has radius 0: no overlaps among them.
        normal.iter().for_each(|&i| state.group_of[i] = 0);
        state.groups = state.groups.max(1);
    }
    // Large splats (outliers, usually few) on a grid sized for the largest.
    if !large.is_empty() {
        let largest = large.iter().fold(0.0f32, |m, &i| m.max(splats.radii[i]));
        let grid = Grid::new(&splats.positions, 2.0 * largest);
        for &i in &large {
            let (p, r) = (splats.positions[i], splats.radii[i]);
            state.place(i, grid.near(p, r + largest));
        }
    }
    let mut groups = state.groups;
    if let GroupCount::Fixed(k) = count {
        groups = k.max(1);
    }
    Grouping {
        group_of: state.group_of,
        groups: groups.max(1),
        conflicts: state.conflicts,
        truncated: state.truncated,
        checks: state.checks,
    }
}

/// The median of the positive radii (0 when none is positive).
fn typical_radius(radii: &[f32]) -> f32 {
    let mut positive: Vec<f32> = radii.iter().copied().filter(|&r| r > 0.0).collect();
    if positive.is_empty() {
        return 0.0;
    }
    let mid = positive.len() / 2;
    *positive.select_nth_unstable_by(mid, f32::total_cmp).1
}

/// The colouring's state while splats are placed one by one.
struct Placement<'a> {
    splats: &'a Splats,
    group_of: Vec<u32>,
    /// Per group: placed, overlapping candidates of the splat being placed.
    clashes: Vec<u32>,
    groups: u32,
    conflicts: u64,
    truncated: u32,
    checks: u64,
}

impl Placement<'_> {
    /// Put splat `i` in the first group none of its placed, overlapping `candidates` is in (or
    /// the least clashing when all are), looking at no more than [`MAX_CANDIDATES`].
    fn place(&mut self, i: usize, candidates: impl Iterator<Item = u32>) {
        let s = self.splats;
        let (p, r) = (s.positions[i], s.radii[i]);
        self.clashes.iter_mut().for_each(|c| *c = 0);
        let mut seen = 0usize;
        for j in candidates {
            if seen == MAX_CANDIDATES {
                self.truncated += 1;
                break;
            }
            seen += 1;
            let g = self.group_of[j as usize];
            if g != u32::MAX && p.distance(s.positions[j as usize]) < r + s.radii[j as usize] {
                self.clashes[g as usize] += 1;
            }
        }
        self.checks += seen as u64;
        let group = match self.clashes.iter().position(|&c| c == 0) {
            Some(free) => free as u32,
            None => {
                let (least, c) = self
                    .clashes
                    .iter()
                    .enumerate()
                    .min_by_key(|(_, c)| **c)
                    .expect("at least one group");
                self.conflicts += *c as u64;
                least as u32
            }
        };
        self.group_of[i] = group;
        self.groups = self.groups.max(group + 1);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    fn row(n: usize, spacing: f32, radius: f32) -> Splats {
        Splats {
            positions: (0..n).map(|i| Vec3::X * i as f32 * spacing).collect(),
            normals: vec![Vec3::Z; n],
            colors: vec![[1.0; 3]; n],
            radii: vec![radius; n],
        }
    }

    fn overlapping_pairs_in_groups(s: &Splats, g: &Grouping) -> u64 {
        let mut count = 0;
        for i in 0..s.positions.len() {
            for j in 0..i {
                if g.group_of[i] == g.group_of[j]
                    && s.positions[i].distance(s.positions[j]) < s.radii[i] + s.radii[j]
                {
                    count += 1;
                }
            }
        }
        count
    }

    #[test]
    fn auto_groups_have_no_overlap() {
        // Radius 1, spacing 0.5: each splat overlaps 3 neighbours per side → 4 groups.
        let s = row(40, 0.5, 1.0);
        let g = assign(&s, GroupCount::Auto);
        assert_eq!(g.groups, 4);
        assert_eq!(g.conflicts, 0);
        assert_eq!(overlapping_pairs_in_groups(&s, &g), 0);
    }

    #[test]
    fn fixed_groups_count_their_conflicts() {
        let s = row(40, 0.5, 1.0);
        let g = assign(&s, GroupCount::Fixed(2));
        assert_eq!(g.groups, 2);
        assert!(g.group_of.iter().all(|&k| k < 2));
        assert_eq!(g.conflicts, overlapping_pairs_in_groups(&s, &g));
        assert!(g.conflicts > 0);
    }

    #[test]
    fn a_huge_splat_is_placed_apart_without_overlap() {
        let mut s = row(40, 0.5, 1.0);
        s.positions.push(Vec3::new(10.0, 0.0, 0.0));
        s.normals.push(Vec3::Z);
        s.colors.push([1.0; 3]);
        s.radii.push(1000.0);
        let g = assign(&s, GroupCount::Auto);
        assert_eq!(g.conflicts, 0);
        assert_eq!(overlapping_pairs_in_groups(&s, &g), 0);
        assert_eq!(
            g.groups, 5,
            "the huge splat overlaps all: a group of its own"
        );
    }

    /// The worst clouds the hostile tests found (identical points, mostly zero radii, two tight
    /// clusters far apart, one huge splat among many): work grows linearly with n.
    #[test]
    fn degenerate_clouds_cost_linear_work() {
        let cloud = |kind: &str, n: usize| -> Splats {
            let mut s = row(n, 0.01, 0.05);
            match kind {
                "identical" => s.positions.iter_mut().for_each(|p| *p = Vec3::ONE),
                "zero radii" => s
                    .radii
                    .iter_mut()
                    .skip(1)
                    .step_by(10)
                    .for_each(|r| *r = 0.0),
                "mostly zero radii" => {
                    for (i, r) in s.radii.iter_mut().enumerate() {
                        *r = if i % 10 == 0 { 0.05 } else { 0.0 };
                    }
                }
                "clusters" => {
                    for (i, p) in s.positions.iter_mut().enumerate() {
                        *p = Vec3::splat((i % 2) as f32 * 1.0e6) + Vec3::X * (i as f32 * 1e-9);
                    }
                }
                "half huge" => s.radii.iter_mut().step_by(2).for_each(|r| *r = 50.0),
                _ => {}
            }
            s
        };
        for kind in [
            "identical",
            "zero radii",
            "mostly zero radii",
            "clusters",
            "half huge",
        ] {
            let small = assign(&cloud(kind, 10_000), GroupCount::Auto);
            let big = assign(&cloud(kind, 20_000), GroupCount::Auto);
            assert!(big.checks <= (MAX_CANDIDATES * 20_000) as u64, "{kind}");
            assert!(
                big.checks as f64 <= 2.2 * small.checks.max(1) as f64,
                "{kind}: {} checks for 10k splats, {} for 20k",
                small.checks,
                big.checks
            );
        }
    }

    #[test]
    fn coincident_and_zero_radius_splats() {
        let mut s = row(3, 0.0, 0.0);
        assert_eq!(assign(&s, GroupCount::Auto).groups, 1);
        s.radii = vec![0.1; 3];
        let g = assign(&s, GroupCount::Auto);
        assert_eq!((g.groups, g.conflicts), (3, 0));
    }
}
