//! Pair queries over a set of points through [`Neighbours`]: the first pair closer than a limit
//! (scenario validation, the playground's edits) and the smallest pair distance (the
//! playground's trails and plots).

use super::Neighbours;
use glam::DVec2;

/// The pair `(i, j, distance)` with `i < j` of `points` closer than `limit` with the smallest
/// `j` (then `i`), or `None` if every pair is at least `limit` apart: the answer of the scan
/// over all pairs (`for j { for i < j }`), at O(N) cost for a bounded density. Scenario
/// validation and the playground's edits use it on up to 10,000 robots.
#[must_use]
pub fn closest_pair_below(points: &[DVec2], limit: f64) -> Option<(usize, usize, f64)> {
    if limit.is_nan() || limit <= 0.0 {
        return None;
    }
    let mut g = Neighbours::new();
    g.build(points, limit);
    // Each list is ascending, so its first `i < j` within the limit is the scan's.
    (0..points.len()).find_map(|j| {
        g.of(j)
            .iter()
            .map(|&i| i as usize)
            .take_while(|&i| i < j)
            .map(|i| (i, j, points[i].distance(points[j])))
            .find(|&(_, _, d)| d < limit)
    })
}

/// The smallest distance between two of `points` (NaN for fewer than two finite points).
///
/// The grid `search` is built with reach `reach`, then four times that, until some pair is
/// within reach: the nearest pair is then among the lists. For `N` points spread over a box
/// the nearest pair is about `side/√N` apart, so the search stops while cells hold a bounded
/// number of points: O(N) per try for the swarms of the playground. `search` keeps its
/// buffers from call to call.
pub fn min_pair_distance(points: &[DVec2], reach: f64, search: &mut Neighbours) -> f64 {
    let finite = points.iter().filter(|p| p.is_finite()).count();
    if finite < 2 {
        return f64::NAN;
    }
    let mut reach = if reach.is_finite() && reach > 0.0 {
        reach
    } else {
        1.0
    };
    loop {
        search.build(points, reach);
        let mut m = f64::INFINITY;
        for (i, p) in points.iter().enumerate() {
            for &j in search.of(i) {
                if (j as usize) > i {
                    m = m.min(p.distance(points[j as usize]));
                }
            }
        }
        // Two finite points are within reach once it passes their distance (finite, as
        // positions are at most 10⁷ from the origin): the loop ends.
        if m.is_finite() {
            return m;
        }
        reach *= 4.0;
    }
}
