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
    /// Overlapping pairs that share a group (0 for [`GroupCount::Auto`] unless capped).
    pub conflicts: u64,
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

/// Splats larger than this × the median radius are placed last, by brute force, so that one huge
/// splat does not turn the grid into one cell.
const LARGE_PER_MEDIAN: f32 = 8.0;

/// Greedy colouring of `splats`: each splat takes the first group none of its overlapping,
/// already placed neighbours is in. `Fixed(k)` must be ≥ 1 and is bounded by the caller.
pub fn assign(splats: &Splats, count: GroupCount) -> Grouping {
    let n = splats.positions.len();
    let limit = match count {
        GroupCount::Auto => MAX_AUTO_GROUPS,
        GroupCount::Fixed(k) => k.max(1),
    };
    let cap = LARGE_PER_MEDIAN * splats.median_radius();
    let (normal, large): (Vec<usize>, Vec<usize>) = (0..n).partition(|&i| splats.radii[i] <= cap);
    // Normal splats find every normal neighbour within r_i + r_j ≤ r_i + reach on the grid.
    let reach = normal.iter().fold(0.0f32, |m, &i| m.max(splats.radii[i]));
    let grid = Grid::new(&splats.positions, 2.0 * reach);
    const UNASSIGNED: u32 = u32::MAX;
    let mut group_of = vec![UNASSIGNED; n];
    let mut clashes = vec![0u32; limit as usize];
    let mut groups = 0u32;
    let mut conflicts = 0u64;
    let mut place =
        |i: usize, candidates: &mut dyn Iterator<Item = u32>, group_of: &mut Vec<u32>| {
            let (p, r) = (splats.positions[i], splats.radii[i]);
            clashes.iter_mut().for_each(|c| *c = 0);
            for j in candidates {
                let g = group_of[j as usize];
                if g != UNASSIGNED
                    && p.distance(splats.positions[j as usize]) < r + splats.radii[j as usize]
                {
                    clashes[g as usize] += 1;
                }
            }
            let group = match clashes.iter().position(|&c| c == 0) {
                Some(free) => free as u32,
                None => {
                    let (least, c) = clashes
                        .iter()
                        .enumerate()
                        .min_by_key(|(_, c)| **c)
                        .expect("at least one group");
                    conflicts += *c as u64;
                    least as u32
                }
            };
            group_of[i] = group;
            groups = groups.max(group + 1);
        };
    for &i in &normal {
        place(
            i,
            &mut grid.near(splats.positions[i], splats.radii[i] + reach),
            &mut group_of,
        );
    }
    // Large splats (outliers, usually few) check every placed splat.
    for &i in &large {
        place(i, &mut (0..n as u32), &mut group_of);
    }
    if let GroupCount::Fixed(k) = count {
        groups = k.max(1);
    }
    Grouping {
        group_of,
        groups: groups.max(1),
        conflicts,
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

    #[test]
    fn coincident_and_zero_radius_splats() {
        let mut s = row(3, 0.0, 0.0);
        assert_eq!(assign(&s, GroupCount::Auto).groups, 1);
        s.radii = vec![0.1; 3];
        let g = assign(&s, GroupCount::Auto);
        assert_eq!((g.groups, g.conflicts), (3, 0));
    }
}
