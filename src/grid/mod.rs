//! Neighbour search by a uniform grid: the robots within a range of each robot, in ascending
//! index, at O(N) cost for a bounded density.
//!
//! Everything in the method that couples robots has a finite reach: a robot senses the robots
//! within `R_s` (eq. `eq_nonholo_controller_co_avoid` sums over the sensed set only), and the
//! safety metrics look at pairs closer than `2·r_ij`. A grid of square cells no smaller than
//! that reach puts every robot's neighbours in its own cell and the eight around it, so a step
//! looks at a bounded number of candidates per robot instead of all `N − 1`.
//!
//! The cells are hashed into a table of counting-sorted arrays (a start per bucket, robot
//! indices in bucket order), so a rebuild allocates nothing once the buffers have grown to the
//! swarm's size. The lists come out in ascending index (see [`Neighbours::build`] for
//! how, without a sort): the neighbours reach the controller in the same order as a scan of all
//! robots, so sums over them (the centroid of eq. `eq_tilde_p_o`) give the same bits.

use glam::DVec2;

/// Up to this many robots, [`Neighbours::build`] scans all pairs instead of building cells.
const SCAN_MAX: usize = 32;

/// Cells are this much wider than the reach, so that rounding in `x / cell` cannot put two
/// robots within reach more than one cell apart (see [`MAX_CELL_COORDINATE`]).
const CELL_MARGIN: f64 = 1e-6;

/// Cell coordinates stay below this: the rounding error of `x / cell` (about
/// `|x / cell|·2⁻⁵³ ≤ 1.2·10⁻⁷` cell widths) is then far below [`CELL_MARGIN`]. Scenario
/// coordinates are at most 10⁷ ([`crate::scenario::MAX_BOUNDS`]), so only a reach below 0.01
/// gets wider cells from this.
const MAX_CELL_COORDINATE: f64 = 1e9;

/// The robots within `reach` of each robot, as flat per-robot lists (compressed rows).
///
/// After [`Neighbours::build`], [`Neighbours::of`]`(i)` holds the indices `j ≠ i` with
/// `|p_j − p_i|² ≤ reach²`, ascending. The same predicate as a scan over all pairs, so the two
/// give the same sets.
///
/// The grid is unbounded: cell `(cx, cy)` goes to bucket `(cy·K + cx) mod B` of a table of
/// `B ≥ 2N` buckets (`K` a large odd constant), so memory and time stay O(N) however sparse the
/// swarm (a crowd on a circle leaves the disc inside empty). The three cells of a row of the
/// 3 × 3 block around a robot are three consecutive buckets, one range of robots; the rows land
/// far apart. Two cells that share a bucket only add candidates, which the distance test drops.
#[derive(Clone, Debug, Default)]
pub struct Neighbours {
    // The table: robot `i` lies in bucket `bucket_of[i]`; bucket `b` lists
    // `order[start[b]..start[b + 1]]`, in ascending robot index.
    bucket_of: Vec<u32>,
    start: Vec<u32>,
    order: Vec<u32>,
    // The lists: robot `i`'s neighbours are `list[first[i]..first[i + 1]]`. `hits` holds each
    // robot's neighbours of higher index in bucket order, robot `i`'s from `upper[i]`;
    // `cursor` is a fill position per row.
    first: Vec<u32>,
    list: Vec<u32>,
    hits: Vec<u32>,
    upper: Vec<u32>,
    cursor: Vec<u32>,
}

impl Neighbours {
    /// An empty search; its buffers grow on the first [`Neighbours::build`].
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// Rebuilds the lists for the `n` robots at `positions(0..n)` and a `reach` (scenario
    /// units). Reuses the buffers: after the first call with as many robots, it allocates only
    /// when the lists' total grows past its previous maximum.
    ///
    /// A non-finite position is nobody's neighbour (its distance is not `≤ reach`), as in a
    /// scan over all pairs.
    pub fn build(&mut self, positions: impl Fn(usize) -> DVec2, n: usize, reach: f64) {
        if n <= SCAN_MAX {
            // A few robots: the scan over all pairs costs less than the cells (the paper's
            // examples have ten), and it is the definition the lists meet.
            let reach2 = reach * reach;
            self.first.clear();
            self.list.clear();
            for i in 0..n {
                self.first.push(self.list.len() as u32);
                let p = positions(i);
                for j in 0..n {
                    if j != i && positions(j).distance_squared(p) <= reach2 {
                        self.list.push(j as u32);
                    }
                }
            }
            self.first.push(self.list.len() as u32);
            return;
        }
        let far = (0..n)
            .map(&positions)
            .filter(|p| p.is_finite())
            .fold(0.0_f64, |m, p| m.max(p.abs().max_element()));
        let cell = (reach * (1.0 + CELL_MARGIN))
            .max(far / MAX_CELL_COORDINATE)
            .max(f64::MIN_POSITIVE);
        // A power of two at least 2N: few cells share a bucket.
        let bits = (2 * n.max(1)).next_power_of_two().trailing_zeros();
        let buckets = 1usize << bits;
        let coords = |p: DVec2| -> (i64, i64) { (floor(p.x / cell), floor(p.y / cell)) };
        let mask = buckets as u64 - 1;
        // Row-major within a row, rows scattered: the three cells of a row of the 3 × 3 block
        // are three consecutive buckets.
        let bucket = |(cx, cy): (i64, i64)| -> usize {
            ((cy as u64)
                .wrapping_mul(0x9E37_79B9_7F4A_7C15)
                .wrapping_add(cx as u64)
                & mask) as usize
        };
        // Counting sort into buckets, in ascending robot index within each bucket.
        self.start.clear();
        self.start.resize(buckets + 1, 0);
        self.bucket_of.clear();
        for i in 0..n {
            let b = bucket(coords(positions(i)));
            self.bucket_of.push(b as u32);
            self.start[b + 1] += 1;
        }
        for b in 0..buckets {
            self.start[b + 1] += self.start[b];
        }
        self.order.clear();
        self.order.resize(n, 0);
        self.cursor.clear();
        self.cursor.extend_from_slice(&self.start[..buckets]);
        for (i, &b) in self.bucket_of.iter().enumerate() {
            let slot = &mut self.cursor[b as usize];
            self.order[*slot as usize] = i as u32;
            *slot += 1;
        }

        // The hits of each robot, in bucket order: the robots of higher index within reach
        // among the 3 × 3 cells around it (a robot within reach is at most one cell away along
        // each axis). "Within reach" is symmetric (the squared distance of a pair is the same
        // bits either way round), so each pair is tested once.
        let reach2 = reach * reach;
        self.upper.clear();
        // `hits[..count]` are the hits so far; the rest is room (kept from build to build), so
        // that a candidate is written before its test and kept by advancing `count`: no
        // branch to mispredict.
        let mut count = 0usize;
        for i in 0..n {
            self.upper.push(count as u32);
            let p = positions(i);
            let (cx, cy) = coords(p);
            // Bucket intervals [lo, hi] of the three rows, split where they wrap.
            let mut spans = [(0usize, 0usize); 6];
            let mut k = 0;
            for dy in -1..=1_i64 {
                let lo = bucket((cx.wrapping_sub(1), cy.wrapping_add(dy)));
                let hi = lo + 2;
                if hi < buckets {
                    spans[k] = (lo, hi);
                    k += 1;
                } else {
                    spans[k] = (lo, buckets - 1);
                    spans[k + 1] = (0, hi - buckets);
                    k += 2;
                }
            }
            let spans = &mut spans[..k];
            // Sort (at most six) and merge overlapping or touching intervals: a bucket once.
            for x in 1..spans.len() {
                let mut y = x;
                while y > 0 && spans[y - 1].0 > spans[y].0 {
                    spans.swap(y - 1, y);
                    y -= 1;
                }
            }
            let mut runs = [(0u32, 0u32); 6];
            let mut k = 0;
            let mut cur = spans[0];
            for &(lo, hi) in &spans[1..] {
                if lo <= cur.1 + 1 {
                    cur.1 = cur.1.max(hi);
                } else {
                    runs[k] = (self.start[cur.0], self.start[cur.1 + 1]);
                    k += 1;
                    cur = (lo, hi);
                }
            }
            runs[k] = (self.start[cur.0], self.start[cur.1 + 1]);
            k += 1;
            for &(from, to) in &runs[..k] {
                let candidates = &self.order[from as usize..to as usize];
                if self.hits.len() < count + candidates.len() {
                    self.hits.resize(2 * (count + candidates.len()), 0);
                }
                for &j in candidates {
                    self.hits[count] = j;
                    let hit =
                        (j as usize > i) & (positions(j as usize).distance_squared(p) <= reach2);
                    count += usize::from(hit);
                }
            }
        }
        self.upper.push(count as u32);

        // Ascending rows without a sort. Row `i` is its neighbours of lower index, then those
        // of higher index. (1) Lengths: robot `j`'s lower neighbours are the `i` whose hits
        // hold `j`. (2) Scattering each `i` into the rows of its hits, for `i` ascending, fills
        // every lower part in ascending order. (3) Scattering each `i` into the rows of its
        // lower neighbours, for `i` ascending, fills every upper part in ascending order.
        self.cursor.clear();
        self.cursor.resize(n, 0);
        for &j in &self.hits[..count] {
            self.cursor[j as usize] += 1;
        }
        self.first.clear();
        let mut total = 0u32;
        for i in 0..n {
            self.first.push(total);
            total += self.cursor[i] + (self.upper[i + 1] - self.upper[i]);
        }
        self.first.push(total);
        self.list.clear();
        self.list.resize(total as usize, 0);
        self.cursor.clear();
        self.cursor.extend_from_slice(&self.first[..n]);
        for i in 0..n {
            let (a, b) = (self.upper[i] as usize, self.upper[i + 1] as usize);
            for &j in &self.hits[a..b] {
                let slot = &mut self.cursor[j as usize];
                self.list[*slot as usize] = i as u32;
                *slot += 1;
            }
        }
        // `cursor[i]` is now where row `i`'s upper part starts, past its lower part.
        for i in 0..n {
            let lower_end = self.first[i + 1] - (self.upper[i + 1] - self.upper[i]);
            for k in self.first[i]..lower_end {
                let j = self.list[k as usize] as usize;
                let slot = &mut self.cursor[j];
                self.list[*slot as usize] = i as u32;
                *slot += 1;
            }
        }
    }

    /// [`Neighbours::build`] for a slice of positions (one instance of the generic build for
    /// every caller with a slice: the wasm module stays smaller).
    pub fn build_points(&mut self, points: &[DVec2], reach: f64) {
        self.build(|i| points[i], points.len(), reach);
    }

    /// Makes room for `factor` times as many neighbours in all as the last build found, so
    /// that rebuilds allocate nothing while the total stays below that.
    pub fn reserve(&mut self, factor: f64) {
        let want = (self.list.len() as f64 * factor) as usize;
        self.list.reserve(want.saturating_sub(self.list.len()));
        // The hits hold half the pairs, plus room for one range of candidates (at most all).
        let room = want / 2 + self.order.len() + 1;
        if self.hits.len() < room {
            self.hits.resize(room, 0);
        }
    }

    /// Robot `i`'s neighbours, ascending (empty before the first build or for `i` out of range).
    #[must_use]
    pub fn of(&self, i: usize) -> &[u32] {
        match (self.first.get(i), self.first.get(i + 1)) {
            (Some(&a), Some(&b)) => &self.list[a as usize..b as usize],
            _ => &[],
        }
    }
}

/// Up to this many obstacles, [`ObstacleCells`] lists them all for every point.
pub const FEW_OBSTACLES: usize = 8;

/// An obstacle whose grown disc would cover more cells than this is listed for every point
/// instead ([`ObstacleCells`]): a few huge obstacles cost a check per robot, not memory.
const MAX_OBSTACLE_CELLS: i64 = 1_024;

/// The obstacles near any point, for the sensing of eq. `eq_nonholo_controller_co_avoid` and
/// the obstacle metrics at O(1) per robot: square cells as wide as a reach, each listing (in
/// ascending index) the obstacles whose disc grown by the reach meets the cell.
///
/// [`ObstacleCells::near`]`(p)` holds every obstacle whose surface is within the reach of
/// `p` (and some farther ones, which the caller's own distance test drops), ascending. Built
/// once per scenario: obstacles do not move. As in [`Neighbours`], cells are hashed into a
/// table of counting-sorted lists, so the grid is unbounded and its memory is O(cells covered).
#[derive(Clone, Debug, Default)]
pub struct ObstacleCells {
    cell: f64,
    mask: u64,
    // Bucket `b` lists `items[start[b]..start[b + 1]]`, ascending.
    start: Vec<u32>,
    items: Vec<u32>,
    // Obstacles listed for every point: too large for cells, or all of them (the reference).
    everywhere: Vec<u32>,
}

impl ObstacleCells {
    /// The cells for `obstacles` and a `reach` (scenario units). Up to [`FEW_OBSTACLES`]
    /// obstacles are all listed everywhere: testing them costs less than finding a cell.
    #[must_use]
    pub fn build(obstacles: &[crate::Obstacle], reach: f64) -> Self {
        if obstacles.len() <= FEW_OBSTACLES {
            return Self::all(obstacles.len());
        }
        let far = obstacles
            .iter()
            .map(|o| o.center.abs().max_element() + o.radius)
            .filter(|v| v.is_finite())
            .fold(0.0_f64, f64::max);
        let cell = (reach * (1.0 + CELL_MARGIN))
            .max(far / MAX_CELL_COORDINATE)
            .max(f64::MIN_POSITIVE);
        // The cells met by obstacle `k`'s disc grown by the reach (its bounding box, padded
        // against round-off in the distance a caller computes), or None for "everywhere".
        let span = |o: &crate::Obstacle| -> Option<[i64; 4]> {
            let grow = (o.radius + reach) * (1.0 + CELL_MARGIN) + far * 1e-12;
            let lo = (o.center - grow) / cell;
            let hi = (o.center + grow) / cell;
            let b = [floor(lo.x), floor(lo.y), floor(hi.x), floor(hi.y)];
            let count = (b[2] - b[0] + 1).saturating_mul(b[3] - b[1] + 1);
            (grow.is_finite() && (1..=MAX_OBSTACLE_CELLS).contains(&count)).then_some(b)
        };
        let spans: Vec<Option<[i64; 4]>> = obstacles.iter().map(span).collect();
        let entries: i64 = spans
            .iter()
            .flatten()
            .map(|b| (b[2] - b[0] + 1) * (b[3] - b[1] + 1))
            .sum();
        let buckets = (2 * entries.max(1) as usize).next_power_of_two();
        let mask = buckets as u64 - 1;
        let mut out = Self {
            cell,
            mask,
            start: vec![0; buckets + 1],
            items: Vec::new(),
            everywhere: Vec::new(),
        };
        // Counting sort, obstacles in ascending index; an obstacle once per bucket even where
        // two of its cells share one.
        let mut last = vec![u32::MAX; buckets];
        for pass in 0..2 {
            if pass == 1 {
                for b in 0..buckets {
                    out.start[b + 1] += out.start[b];
                }
                out.items = vec![0; out.start[buckets] as usize];
                last.fill(u32::MAX);
            }
            let mut fill = out.start.clone();
            for (k, b) in spans.iter().enumerate() {
                let Some([x0, y0, x1, y1]) = *b else {
                    if pass == 0 {
                        out.everywhere.push(k as u32);
                    }
                    continue;
                };
                for cy in y0..=y1 {
                    for cx in x0..=x1 {
                        let bucket = out.bucket(cx, cy);
                        if last[bucket] == k as u32 {
                            continue;
                        }
                        last[bucket] = k as u32;
                        if pass == 0 {
                            out.start[bucket + 1] += 1;
                        } else {
                            out.items[fill[bucket] as usize] = k as u32;
                            fill[bucket] += 1;
                        }
                    }
                }
            }
        }
        out
    }

    /// Every one of `m` obstacles listed for every point: the reference that the cells are
    /// tested against (and the same code path for [`crate::Neighbourhood::AllPairs`]).
    #[must_use]
    pub fn all(m: usize) -> Self {
        Self {
            cell: 1.0,
            mask: 0,
            start: vec![0, 0],
            items: Vec::new(),
            everywhere: (0..m as u32).collect(),
        }
    }

    fn bucket(&self, cx: i64, cy: i64) -> usize {
        ((cy as u64)
            .wrapping_mul(0x9E37_79B9_7F4A_7C15)
            .wrapping_add(cx as u64)
            & self.mask) as usize
    }

    /// The obstacles that may be within the reach of `p`, ascending.
    #[must_use]
    pub fn near(&self, p: DVec2) -> Candidates<'_> {
        if self.items.is_empty() {
            return Candidates {
                cells: &[],
                everywhere: &self.everywhere,
            };
        }
        let b = self.bucket(floor(p.x / self.cell), floor(p.y / self.cell));
        Candidates {
            cells: &self.items[self.start[b] as usize..self.start[b + 1] as usize],
            everywhere: &self.everywhere,
        }
    }
}

/// The obstacle indices of [`ObstacleCells::near`]: two ascending lists merged.
#[derive(Clone, Debug)]
pub struct Candidates<'a> {
    cells: &'a [u32],
    everywhere: &'a [u32],
}

impl Iterator for Candidates<'_> {
    type Item = usize;

    fn next(&mut self) -> Option<usize> {
        if self.cells.is_empty() {
            let (&k, rest) = self.everywhere.split_first()?;
            self.everywhere = rest;
            return Some(k as usize);
        }
        let (a, b) = (self.cells.first(), self.everywhere.first());
        let take_cells = match (a, b) {
            (Some(x), Some(y)) => x < y,
            (Some(_), None) => true,
            (None, Some(_)) => false,
            (None, None) => return None,
        };
        let list = if take_cells {
            &mut self.cells
        } else {
            &mut self.everywhere
        };
        let (&k, rest) = list.split_first()?;
        *list = rest;
        Some(k as usize)
    }
}

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
    g.build_points(points, limit);
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
        search.build_points(points, reach);
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

/// `⌊x⌋` as an integer, saturating (NaN → 0, ±∞ → the extremes): every position gets a
/// cell. The same as `x.floor() as i64`, without the library call that `floor` is on a CPU
/// baseline without SSE4.1.
#[inline]
fn floor(x: f64) -> i64 {
    let t = x as i64;
    // Exact below 2⁵³; above, `x` is an integer and `t as f64 == x` (or `t` saturated).
    if (t as f64) > x {
        t.saturating_sub(1)
    } else {
        t
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::XorShift;
    use crate::testing::test;

    /// Every list equals the scan over all robots, in the same (ascending) order.
    fn check(points: &[DVec2], reach: f64) {
        let mut g = Neighbours::new();
        g.build(|i| points[i], points.len(), reach);
        for (i, p) in points.iter().enumerate() {
            let scan: Vec<u32> = (0..points.len())
                .filter(|&j| j != i && points[j].distance_squared(*p) <= reach * reach)
                .map(|j| j as u32)
                .collect();
            assert_eq!(g.of(i), &scan[..], "robot {i} at {p:?}");
        }
    }

    #[test]
    fn lists_equal_the_scan_over_all_pairs() {
        let mut rng = XorShift(0x9E37_79B9_7F4A_7C15_u64);
        let mut next = move || rng.unit();
        for (n, side, reach) in [
            (300, 100.0, 7.0),
            (50, 1e6, 3.0),
            (80, 5.0, 20.0),
            (400, 1e7, 1e-3),
            (200, 50.0, 0.5),
        ] {
            let points: Vec<DVec2> = (0..n)
                .map(|_| DVec2::new(next() * side, next() * side))
                .collect();
            check(&points, reach);
        }
        // Points exactly at the reach, on cell borders, coincident, and non-finite.
        let mut points: Vec<DVec2> = (0..10).map(|k| DVec2::new(2.0 * k as f64, 0.0)).collect();
        points.push(DVec2::new(4.0, 0.0));
        points.push(DVec2::new(f64::NAN, 1.0));
        points.push(DVec2::new(f64::INFINITY, 1.0));
        check(&points, 2.0);
        check(&points, 0.0);
        check(&[], 1.0);
        check(&[DVec2::ZERO], 1.0);
        // The same cases in rows far apart: more robots than the scan takes, so the cells.
        let rows: Vec<DVec2> = (0..4)
            .flat_map(|r| {
                points
                    .iter()
                    .map(move |p| *p + DVec2::new(0.0, 100.0 * r as f64))
            })
            .collect();
        assert!(rows.len() > SCAN_MAX);
        check(&rows, 2.0);
        check(&rows, 0.0);
    }

    /// The closest pair below a limit and the smallest distance are those of the scan over
    /// all pairs (same pair, same bits), on random points of several densities.
    #[test]
    fn pair_queries_equal_the_scan() {
        let mut rng = XorShift(0x2545_F491_4F6C_DD1D_u64);
        let mut next = move || rng.unit();
        let mut search = Neighbours::new();
        for (n, side) in [(2, 10.0), (40, 10.0), (300, 100.0), (500, 1e5), (60, 1e7)] {
            let points: Vec<DVec2> = (0..n)
                .map(|_| DVec2::new(next() * side, next() * side))
                .collect();
            let mut scan = f64::INFINITY;
            for j in 0..n {
                for i in 0..j {
                    scan = scan.min(points[i].distance(points[j]));
                }
            }
            assert_eq!(
                min_pair_distance(&points, 1.0, &mut search),
                scan,
                "{n} in {side}"
            );
            for limit in [0.5 * scan, scan, 1.5 * scan, side / 10.0, 2.0 * side] {
                let brute = points.iter().enumerate().find_map(|(j, b)| {
                    points[..j].iter().enumerate().find_map(|(i, a)| {
                        let d = a.distance(*b);
                        (d < limit).then_some((i, j, d))
                    })
                });
                assert_eq!(
                    closest_pair_below(&points, limit),
                    brute,
                    "{n} in {side}, {limit}"
                );
            }
        }
        assert!(min_pair_distance(&[DVec2::ONE], 1.0, &mut search).is_nan());
        assert!(min_pair_distance(&[DVec2::ONE, DVec2::NAN], 1.0, &mut search).is_nan());
        assert_eq!(closest_pair_below(&[DVec2::ONE, DVec2::ONE], 0.0), None);
    }

    /// The obstacle cells list, for any point, every obstacle whose surface is within the
    /// reach, in ascending order, with no repeats; the same set as a scan, after the caller's
    /// distance test.
    #[test]
    fn obstacle_cells_cover_the_reach() {
        use crate::Obstacle;
        let mut rng = XorShift(0x1234_5678_9ABC_DEF1_u64);
        let mut next = move || rng.unit();
        for (m, side, reach, rmax) in [
            (40, 200.0, 20.0, 8.0),
            (200, 1_000.0, 5.0, 3.0),
            (10, 100.0, 0.5, 60.0),
            (30, 1e6, 20.0, 1e4),
        ] {
            let obstacles: Vec<Obstacle> = (0..m)
                .map(|_| {
                    let radius = 0.1 + next() * rmax;
                    Obstacle {
                        center: DVec2::new(next() * side, next() * side),
                        radius,
                        influence: 2.0 * radius,
                    }
                })
                .collect();
            let cells = ObstacleCells::build(&obstacles, reach);
            for _ in 0..2_000 {
                let p = DVec2::new(next() * side * 1.1 - 0.05 * side, next() * side);
                let near: Vec<usize> = cells.near(p).collect();
                assert!(near.windows(2).all(|w| w[0] < w[1]), "{near:?}");
                let got: Vec<usize> = near
                    .into_iter()
                    .filter(|&k| obstacles[k].clearance(p) <= reach)
                    .collect();
                let scan: Vec<usize> = (0..m)
                    .filter(|&k| obstacles[k].clearance(p) <= reach)
                    .collect();
                assert_eq!(got, scan, "{p:?}, reach {reach}");
            }
        }
        let all = ObstacleCells::all(3);
        assert_eq!(
            all.near(DVec2::new(1e7, -1e7)).collect::<Vec<_>>(),
            [0, 1, 2]
        );
        assert_eq!(ObstacleCells::build(&[], 5.0).near(DVec2::ZERO).count(), 0);
    }

    #[test]
    fn floor_is_the_library_floor() {
        for x in [
            0.0,
            -0.0,
            0.5,
            -0.5,
            1.0,
            -1.0,
            -1e-300,
            2.5e15,
            -2.5e15 - 0.5,
            9.3e18,
            -9.3e18,
            f64::MAX,
            f64::MIN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ] {
            assert_eq!(floor(x), x.floor() as i64, "{x}");
        }
    }

    #[test]
    fn a_rebuild_reuses_the_buffers() {
        let points: Vec<DVec2> = (0..100)
            .map(|k| DVec2::new((k % 10) as f64, (k / 10) as f64))
            .collect();
        let mut g = Neighbours::new();
        g.build(|i| points[i], points.len(), 1.5);
        let caps = (g.start.capacity(), g.order.capacity(), g.list.capacity());
        let ptr = g.list.as_ptr();
        g.build(|i| points[i] * 0.999, points.len(), 1.5);
        assert_eq!(caps.1, g.order.capacity());
        assert_eq!(caps.2, g.list.capacity());
        assert_eq!(ptr, g.list.as_ptr());
        assert!(g.start.capacity() >= caps.0);
    }
}
