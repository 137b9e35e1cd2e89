//! Picking rows out of a run's results (one scene, display and size; a method kind; the best
//! exact single pass): what every report section reads the measurements by.

use super::scenes::Kind;
use super::{Results, Row};

pub(super) const PAPER_DISPLAY: &str = "hubner8";

/// Rows of one scene, display and size.
pub(super) fn rows_of<'a>(
    r: &'a Results,
    scene: &str,
    display: &str,
    size: [u32; 2],
) -> Vec<&'a Row> {
    r.rows
        .iter()
        .filter(|x| x.scene == scene && x.display == display && x.size == size)
        .collect()
}

/// The best *exact* single-pass row (not the paper's approximations), if any.
pub(super) fn best_single_pass<'a>(rows: &[&'a Row]) -> Option<&'a Row> {
    rows.iter()
        .copied()
        .filter(|x| {
            x.kind == Kind::SinglePass && !x.method.contains("paper") && !x.method.contains("fast")
        })
        .min_by(|a, b| a.ms.total_cmp(&b.ms))
}

pub(super) fn find<'a>(rows: &[&'a Row], kind: Kind) -> Option<&'a Row> {
    rows.iter().copied().find(|x| x.kind == kind)
}

pub(super) fn base_size(r: &Results) -> [u32; 2] {
    r.size
}
