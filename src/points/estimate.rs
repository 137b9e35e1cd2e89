//! Missing splat attributes from the k nearest neighbours: normals by PCA (the direction of
//! least variance of the neighbourhood) and radii from the local point spacing.

use glam::{Mat3, Vec3};

use super::grid::Grid;

/// Neighbours per point (the point itself excluded).
pub const NEIGHBOURS: usize = 8;
/// Radius = this × distance to the k-th neighbour. On a hexagonal surface sampling of spacing h
/// the 8th neighbour is √3 h away (radius ≈ 1.04 h), on a square one √2 h (≈ 0.85 h):
/// neighbouring disks overlap and close the surface without blurring it.
pub const RADIUS_PER_KTH_DISTANCE: f32 = 0.6;
/// Estimated radii are capped at this × their median: an isolated outlier (its 8th neighbour
/// far away) must not become a disk over the whole scene.
pub const MAX_RADIUS_PER_MEDIAN: f32 = 8.0;
/// Shells searched on the grid before a point's neighbours are found by brute force (outliers).
const MAX_SHELLS: i32 = 8;

/// Normals (unit, unoriented) and radii of `points` from their neighbourhoods.
pub(crate) fn normals_and_radii(points: &[Vec3]) -> (Vec<Vec3>, Vec<f32>) {
    if points.is_empty() {
        return (Vec::new(), Vec::new());
    }
    let grid = adaptive_grid(points);
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let chunk = points.len().div_ceil(threads);
    let mut normals = vec![Vec3::Z; points.len()];
    let mut radii = vec![0.0f32; points.len()];
    std::thread::scope(|s| {
        for ((normals, radii), start) in normals
            .chunks_mut(chunk)
            .zip(radii.chunks_mut(chunk))
            .zip((0..).step_by(chunk))
        {
            let grid = &grid;
            s.spawn(move || {
                let mut near = Vec::with_capacity(NEIGHBOURS + 1);
                for (k, (n, r)) in normals.iter_mut().zip(radii.iter_mut()).enumerate() {
                    let i = start + k;
                    nearest(grid, points, i, &mut near);
                    *n = pca_normal(points[i], near.iter().map(|&(_, j)| points[j as usize]));
                    *r = near.last().map_or(0.0, |&(d2, _)| d2.sqrt()) * RADIUS_PER_KTH_DISTANCE;
                }
            });
        }
    });
    let mut sorted = radii.clone();
    let mid = sorted.len() / 2;
    let median = *sorted.select_nth_unstable_by(mid, f32::total_cmp).1;
    if median > 0.0 {
        let cap = MAX_RADIUS_PER_MEDIAN * median;
        radii.iter_mut().for_each(|r| *r = r.min(cap));
    }
    (normals, radii)
}

/// A grid whose occupied cells hold a few points each, whatever the cloud's dimension (a
/// surface sampling wants cells of ≈ the spacing, a volume sampling larger ones).
fn adaptive_grid(points: &[Vec3]) -> Grid {
    let (lo, hi) = points.iter().fold(
        (Vec3::splat(f32::MAX), Vec3::splat(f32::MIN)),
        |(lo, hi), p| (lo.min(*p), hi.max(*p)),
    );
    // Surface guess: spacing ≈ diagonal / √n.
    let mut cell = 2.0 * (hi - lo).length() / (points.len() as f32).sqrt();
    let mut grid = Grid::new(points, cell);
    for _ in 0..6 {
        let occupancy = grid.mean_occupancy();
        if occupancy < 2.0 {
            cell = grid.cell_size() * 2.0;
        } else if occupancy > 16.0 {
            cell = grid.cell_size() * 0.5;
        } else {
            break;
        }
        grid = Grid::new(points, cell);
    }
    grid
}

/// The `NEIGHBOURS` nearest points to point i as (squared distance, index), nearest first.
/// A cell holding more than [`crate::points::groups::MAX_CANDIDATES`] points (a dense cluster,
/// identical points) is sampled, not scanned whole: the neighbours are then the nearest among
/// those seen, and the work per point stays bounded.
fn nearest(grid: &Grid, points: &[Vec3], i: usize, near: &mut Vec<(f32, u32)>) {
    near.clear();
    let p = points[i];
    let home = grid.cell_of(p);
    let budget = crate::points::groups::MAX_CANDIDATES;
    let consider = |near: &mut Vec<(f32, u32)>, j: u32| {
        if j as usize == i {
            return;
        }
        let d2 = p.distance_squared(points[j as usize]);
        if near.len() < NEIGHBOURS {
            near.push((d2, j));
            near.sort_by(|a, b| a.0.total_cmp(&b.0));
        } else if d2 < near[NEIGHBOURS - 1].0 {
            near[NEIGHBOURS - 1] = (d2, j);
            near.sort_by(|a, b| a.0.total_cmp(&b.0));
        }
    };
    for shell in 0..=grid.max_shell() {
        if shell > MAX_SHELLS {
            // An outlier: its neighbours are far; one pass over all points is cheaper.
            near.clear();
            (0..points.len() as u32).for_each(|j| consider(near, j));
            return;
        }
        let mut seen = 0usize;
        for cell in grid.shell(home, shell) {
            let here = grid.points_in(cell);
            let take = here.len().min(budget.saturating_sub(seen));
            here[..take].iter().for_each(|&j| consider(near, j));
            seen += take;
            if seen >= budget {
                return;
            }
        }
        // Points in later shells are at least shell · cell away.
        let bound = shell as f32 * grid.cell_size();
        if near.len() == NEIGHBOURS && near[NEIGHBOURS - 1].0 <= bound * bound {
            break;
        }
    }
}

/// Unit normal of the plane through `p` and `neighbours` (least-variance direction); +z when
/// the neighbourhood has no distinct plane (fewer than 2 neighbours, all coincident).
pub(crate) fn pca_normal(p: Vec3, neighbours: impl Iterator<Item = Vec3>) -> Vec3 {
    let pts: Vec<Vec3> = std::iter::once(p).chain(neighbours).collect();
    let mean = pts.iter().copied().sum::<Vec3>() / pts.len() as f32;
    let mut c = Mat3::ZERO;
    for q in &pts {
        let d = *q - mean;
        c += Mat3::from_cols(d * d.x, d * d.y, d * d.z);
    }
    smallest_eigenvector(c).unwrap_or(Vec3::Z)
}

/// Eigenvector of the smallest eigenvalue of symmetric `c` (closed-form eigenvalues, then the
/// largest cross product of two rows of c − λI); `None` when it is not determined.
fn smallest_eigenvector(c: Mat3) -> Option<Vec3> {
    let scale = c.to_cols_array().iter().fold(0.0f32, |m, v| m.max(v.abs()));
    if !(scale > 0.0 && scale.is_finite()) {
        return None;
    }
    let c = c * (1.0 / scale);
    // Eigenvalues of a symmetric 3×3 matrix (trigonometric form).
    let (a, b) = (c.x_axis, c.y_axis);
    let cz = c.z_axis;
    let p1 = a.y * a.y + a.z * a.z + b.z * b.z;
    let q = (a.x + b.y + cz.z) / 3.0;
    let p2 = (a.x - q).powi(2) + (b.y - q).powi(2) + (cz.z - q).powi(2) + 2.0 * p1;
    let p = (p2 / 6.0).sqrt();
    let lambda = if p < 1e-12 {
        q // all eigenvalues equal: no preferred direction
    } else {
        let bm = (c - Mat3::from_diagonal(Vec3::splat(q))) * (1.0 / p);
        let r = (bm.determinant() / 2.0).clamp(-1.0, 1.0);
        let phi = r.acos() / 3.0;
        q + 2.0 * p * (phi + 2.0 * std::f32::consts::PI / 3.0).cos()
    };
    let m = c - Mat3::from_diagonal(Vec3::splat(lambda));
    let rows = [m.row(0), m.row(1), m.row(2)];
    let candidates = [
        rows[0].cross(rows[1]),
        rows[0].cross(rows[2]),
        rows[1].cross(rows[2]),
    ];
    let best = candidates
        .into_iter()
        .max_by(|x, y| x.length_squared().total_cmp(&y.length_squared()))?;
    (best.length_squared() > 1e-20).then(|| best.normalize())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plane_normal_and_spacing() {
        // A 20 × 20 grid of spacing 0.1 in a tilted plane.
        let tilt = glam::Quat::from_rotation_x(0.7);
        let points: Vec<Vec3> = (0..400)
            .map(|i| tilt * Vec3::new((i % 20) as f32 * 0.1, (i / 20) as f32 * 0.1, 0.0))
            .collect();
        let (normals, radii) = normals_and_radii(&points);
        let expected = tilt * Vec3::Z;
        for n in &normals {
            assert!(n.dot(expected).abs() > 0.9999, "{n} vs {expected}");
        }
        // Interior points: 8th neighbour at √2·0.1 (4 at 0.1, 4 at 0.141).
        let r = radii[10 * 20 + 10];
        assert!((r - 0.6 * 0.1 * 2f32.sqrt()).abs() < 1e-4, "{r}");
    }

    #[test]
    fn degenerate_neighbourhoods_give_finite_normals() {
        let same = vec![Vec3::ONE; 5];
        let (normals, radii) = normals_and_radii(&same);
        assert!(normals
            .iter()
            .all(|n| n.is_finite() && (n.length() - 1.0).abs() < 1e-5));
        assert!(radii.iter().all(|r| *r == 0.0));
        let line: Vec<Vec3> = (0..10).map(|i| Vec3::X * i as f32).collect();
        let (normals, _) = normals_and_radii(&line);
        assert!(normals
            .iter()
            .all(|n| n.is_finite() && n.dot(Vec3::X).abs() < 1e-3));
        assert_eq!(normals_and_radii(&[Vec3::ZERO]).1, vec![0.0]);
    }

    #[test]
    fn outliers_get_capped_radii_and_do_not_stall_the_search() {
        let mut points: Vec<Vec3> = (0..2500)
            .map(|i| Vec3::new((i % 50) as f32 * 0.01, (i / 50) as f32 * 0.01, 0.0))
            .collect();
        points.push(Vec3::splat(1e6));
        let (normals, radii) = normals_and_radii(&points);
        let typical = radii[1275];
        assert!(
            radii[2500] <= MAX_RADIUS_PER_MEDIAN * typical * 1.01,
            "{}",
            radii[2500]
        );
        assert!(normals.iter().all(|n| n.is_finite()));
    }
}
