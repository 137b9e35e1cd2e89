//! Views split into passes where a method draws at most so many views per pass (multiview's
//! layer limit, MRT's render targets).

use std::ops::Range;

/// `views` split into the fewest passes of at most `max` views, as equal as possible (the
/// first passes take the remainder).
pub fn batches(views: u32, max: u32) -> Vec<Range<u32>> {
    let max = max.max(1);
    let passes = views.div_ceil(max).max(1);
    let (base, extra) = (views / passes, views % passes);
    let mut start = 0;
    (0..passes)
        .map(|i| {
            let len = base + u32::from(i < extra);
            let range = start..start + len;
            start += len;
            range
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::batches;

    #[test]
    fn batches_are_few_and_even() {
        assert_eq!(batches(8, 6), vec![0..4, 4..8]);
        assert_eq!(
            batches(45, 8),
            vec![0..8, 8..16, 16..24, 24..31, 31..38, 38..45]
        );
        assert_eq!(batches(1, 8), vec![0..1]);
        assert_eq!(batches(6, 6), vec![0..6]);
        for views in 1..=64 {
            for max in 1..=9 {
                let b = batches(views, max);
                assert_eq!(b.len() as u32, views.div_ceil(max));
                assert!(b.iter().all(|r| r.len() as u32 <= max && !r.is_empty()));
                assert_eq!(b.last().unwrap().end, views);
            }
        }
    }
}
