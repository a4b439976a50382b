//! Neighbour search by a uniform grid: the robots within a range of each robot, in ascending
//! index, at O(N) cost for a bounded density.
//!
//! Everything in the method that couples robots has a finite reach: a robot senses the robots
//! within `R_s` (eq. `eq_nonholo_controller_co_avoid` sums over the sensed set only), and the
//! safety metrics look at pairs closer than `2·r_ij`. A grid of square cells no smaller than
//! that reach puts every robot's neighbours in its own cell and the eight around it, so a step
//! looks at a bounded number of candidates per robot instead of all `N − 1`.
//!
//! The cells are counting-sorted arrays (a start per cell, robot indices in cell order), so a
//! rebuild allocates nothing once the buffers have grown to the swarm's size. Each cell lists its
//! robots in ascending index, and a robot's candidates are merged from its (at most nine) cells
//! in ascending index: the neighbours reach the controller in the same order as a scan of all
//! robots, so sums over them (the centroid of eq. `eq_tilde_p_o`) give the same bits.

use glam::DVec2;

/// At most this many cells per robot: a swarm spread far apart compared with the reach gets
/// larger cells rather than a grid of mostly empty ones (memory stays O(N)).
const CELLS_PER_ROBOT: usize = 4;

/// The robots within `reach` of each robot, as flat per-robot lists (compressed rows).
///
/// After [`Neighbours::build`], [`Neighbours::of`]`(i)` holds the indices `j ≠ i` with
/// `|p_j − p_i|² ≤ reach²`, ascending. The same predicate as a scan over all pairs, so the two
/// give the same sets.
#[derive(Clone, Debug, Default)]
pub struct Neighbours {
    // The grid: robot `i` lies in cell `cell_of[i]`; cell `c` lists `order[start[c]..start[c + 1]]`.
    cell_of: Vec<u32>,
    start: Vec<u32>,
    order: Vec<u32>,
    // The lists: robot `i`'s neighbours are `list[first[i]..first[i + 1]]`.
    first: Vec<u32>,
    list: Vec<u32>,
}

impl Neighbours {
    /// An empty search; its buffers grow on the first [`Neighbours::build`].
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// Rebuilds the lists for robots at `positions` and a `reach > 0` (scenario units).
    /// Reuses the buffers: after the first call with as many robots, it allocates only when a
    /// list total grows past its previous maximum.
    ///
    /// Non-finite positions all land in one cell and are never anybody's neighbour (their
    /// distance is not `≤ reach`), as in a scan over all pairs.
    pub fn build(&mut self, positions: impl Fn(usize) -> DVec2, n: usize, reach: f64) {
        let (lo, hi) = extent((0..n).map(&positions));
        let span = hi - lo;
        // Cells no smaller than the reach (so the 3×3 block around a robot holds every robot
        // within reach), and no more than CELLS_PER_ROBOT per robot.
        let cap = (CELLS_PER_ROBOT * n).max(1) as f64;
        let mut cell = reach.max(f64::MIN_POSITIVE);
        if (span.x / cell + 1.0) * (span.y / cell + 1.0) > cap {
            cell = cell
                .max((span.x * span.y / cap).sqrt())
                .max(span.x.max(span.y) / cap);
        }
        let cols = dim(span.x / cell);
        let rows = dim(span.y / cell);
        let index = |p: DVec2| -> (usize, usize) {
            let d = (p - lo) / cell;
            // `as` saturates (NaN → 0): a non-finite position gets a valid cell.
            ((d.x as usize).min(cols - 1), (d.y as usize).min(rows - 1))
        };

        // Counting sort into cells, in ascending robot index within each cell.
        let cells = cols * rows;
        self.start.clear();
        self.start.resize(cells + 1, 0);
        self.cell_of.clear();
        for i in 0..n {
            let (cx, cy) = index(positions(i));
            let c = cy * cols + cx;
            self.cell_of.push(c as u32);
            self.start[c + 1] += 1;
        }
        for c in 0..cells {
            self.start[c + 1] += self.start[c];
        }
        self.order.clear();
        self.order.resize(n, 0);
        // `first` serves as the fill cursor of each cell before it takes its own meaning.
        self.first.clear();
        self.first.extend_from_slice(&self.start[..cells]);
        for (i, &c) in self.cell_of.iter().enumerate() {
            let slot = &mut self.first[c as usize];
            self.order[*slot as usize] = i as u32;
            *slot += 1;
        }

        // Each robot's list: a merge of the ascending lists of the cells around it.
        let reach2 = reach * reach;
        self.first.clear();
        self.list.clear();
        for i in 0..n {
            self.first.push(self.list.len() as u32);
            let p = positions(i);
            let c = self.cell_of[i] as usize;
            let (cx, cy) = (c % cols, c / cols);
            let mut runs = [(0u32, 0u32); 9];
            let mut k = 0;
            for y in cy.saturating_sub(1)..=(cy + 1).min(rows - 1) {
                for x in cx.saturating_sub(1)..=(cx + 1).min(cols - 1) {
                    let c = y * cols + x;
                    if self.start[c] < self.start[c + 1] {
                        runs[k] = (self.start[c], self.start[c + 1]);
                        k += 1;
                    }
                }
            }
            let runs = &mut runs[..k];
            loop {
                // The smallest head among the runs (at most nine: a linear scan).
                let mut best: Option<(usize, u32)> = None;
                for (r, &(at, end)) in runs.iter().enumerate() {
                    if at < end {
                        let j = self.order[at as usize];
                        if best.map_or(true, |(_, b)| j < b) {
                            best = Some((r, j));
                        }
                    }
                }
                let Some((r, j)) = best else { break };
                runs[r].0 += 1;
                if j as usize != i && positions(j as usize).distance_squared(p) <= reach2 {
                    self.list.push(j);
                }
            }
        }
        self.first.push(self.list.len() as u32);
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

/// The bounding box of the finite points (`(0, 0)` twice when there are none).
fn extent(points: impl Iterator<Item = DVec2>) -> (DVec2, DVec2) {
    let mut lo = DVec2::splat(f64::INFINITY);
    let mut hi = DVec2::splat(f64::NEG_INFINITY);
    for p in points.filter(|p| p.is_finite()) {
        lo = lo.min(p);
        hi = hi.max(p);
    }
    if lo.x > hi.x {
        (DVec2::ZERO, DVec2::ZERO)
    } else {
        (lo, hi)
    }
}

/// Cells along a side of `span_cells` cell widths (at least one).
fn dim(span_cells: f64) -> usize {
    // Saturating `as`; bounded by CELLS_PER_ROBOT·N through the cell size.
    (span_cells as usize).saturating_add(1).max(1)
}

#[cfg(test)]
mod tests {
    use super::*;
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

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
        // xorshift64*: enough for a test that needs no statistics.
        let mut s = 0x9E37_79B9_7F4A_7C15_u64;
        let mut next = || {
            s ^= s >> 12;
            s ^= s << 25;
            s ^= s >> 27;
            (s.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
        };
        for (n, side, reach) in [(300, 100.0, 7.0), (50, 1e6, 3.0), (80, 5.0, 20.0)] {
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
