//! The cell table under every spatial index here: points counting-sorted into square cells
//! hashed into a table of buckets, so that the points near any position are a few ranges of one
//! array. [`super::Neighbours`] makes per-robot lists from it, the playground's field view asks
//! it for the robots near each sample point, and [`super::ObstacleCells`] hashes its cells the
//! same way.
//!
//! The grid is unbounded: cell `(cx, cy)` goes to bucket `(cy·K + cx) mod B` of a table of
//! `B ≥ 2N` buckets (`K` a large odd constant), so memory and time stay O(N) however sparse the
//! points (a crowd on a circle leaves the disc inside empty). The three cells of a row of the
//! 3 × 3 block around a point are three consecutive buckets, one range of points; the rows land
//! far apart. Two cells that share a bucket only add candidates, which the caller's distance
//! test drops.

use glam::DVec2;

/// Cells are this much wider than the reach, so that rounding in `x / cell` cannot put two
/// points within reach more than one cell apart (see [`MAX_CELL_COORDINATE`]).
pub(super) const CELL_MARGIN: f64 = 1e-6;

/// Cell coordinates stay below this: the rounding error of `x / cell` (about
/// `|x / cell|·2⁻⁵³ ≤ 1.2·10⁻⁷` cell widths) is then far below [`CELL_MARGIN`]. Scenario
/// coordinates are at most 10⁷ ([`crate::scenario::MAX_BOUNDS`]), so only a reach below 0.01
/// gets wider cells from this.
pub(super) const MAX_CELL_COORDINATE: f64 = 1e9;

/// The bucket of cell `(cx, cy)` in a table of `mask + 1` buckets: row-major within a row, rows
/// scattered, so the three cells of a row of a 3 × 3 block are three consecutive buckets.
#[inline]
pub(super) fn bucket(cx: i64, cy: i64, mask: u64) -> usize {
    ((cy as u64)
        .wrapping_mul(0x9E37_79B9_7F4A_7C15)
        .wrapping_add(cx as u64)
        & mask) as usize
}

/// The side of the cells for a `reach` among points at most `far` from the origin.
pub(super) fn cell_side(reach: f64, far: f64) -> f64 {
    (reach * (1.0 + CELL_MARGIN))
        .max(far / MAX_CELL_COORDINATE)
        .max(f64::MIN_POSITIVE)
}

/// Points sorted into hashed cells at least a reach wide: after [`Cells::build`], the points
/// within reach of any position are among [`Cells::block`]'s ranges of [`Cells::order`].
#[derive(Clone, Debug, Default)]
pub struct Cells {
    cell: f64,
    buckets: usize,
    // Point `i` lies in bucket `bucket_of[i]`; bucket `b` lists `order[start[b]..start[b + 1]]`,
    // in ascending point index.
    bucket_of: Vec<u32>,
    start: Vec<u32>,
    order: Vec<u32>,
    cursor: Vec<u32>,
}

impl Cells {
    /// An empty table; its buffers grow on the first [`Cells::build`].
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// Sorts `points` into cells for `reach`, reusing the buffers.
    /// A non-finite position lands in some cell and is nobody's neighbour (its distance is
    /// not `≤ reach`).
    pub fn build(&mut self, points: &[DVec2], reach: f64) {
        let n = points.len();
        let far = points
            .iter()
            .filter(|p| p.is_finite())
            .fold(0.0_f64, |m, p| m.max(p.abs().max_element()));
        self.cell = cell_side(reach, far);
        // A power of two at least 2N: few cells share a bucket.
        let buckets = (2 * n.max(1)).next_power_of_two();
        self.buckets = buckets;
        // Counting sort into buckets, in ascending point index within each bucket.
        self.start.clear();
        self.start.resize(buckets + 1, 0);
        self.bucket_of.clear();
        for &p in points {
            let (cx, cy) = self.coords(p);
            let b = bucket(cx, cy, buckets as u64 - 1);
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
    }

    /// The capacities of the bucket starts and of the order (for a test of buffer reuse).
    #[cfg(test)]
    pub(super) fn capacities(&self) -> (usize, usize) {
        (self.start.capacity(), self.order.capacity())
    }

    /// The cell of `p`.
    #[inline]
    #[must_use]
    pub fn coords(&self, p: DVec2) -> (i64, i64) {
        (floor(p.x / self.cell), floor(p.y / self.cell))
    }

    /// The points in bucket order (see [`Cells::block`]).
    #[must_use]
    pub fn order(&self) -> &[u32] {
        &self.order
    }

    /// The ranges of [`Cells::order`] that hold the 3 × 3 block of cells around cell
    /// `(cx, cy)`, each bucket once: `(runs, count)`, the first `count` runs valid. Each bucket
    /// of a range is ascending in point index, not a range that spans several buckets, and the
    /// ranges are not ordered among themselves.
    #[must_use]
    pub fn block(&self, (cx, cy): (i64, i64)) -> ([(u32, u32); 6], usize) {
        let buckets = self.buckets;
        let mask = buckets as u64 - 1;
        // Bucket intervals [lo, hi] of the three rows, split where they wrap.
        let mut spans = [(0usize, 0usize); 6];
        let mut k = 0;
        for dy in -1..=1_i64 {
            let lo = bucket(cx.wrapping_sub(1), cy.wrapping_add(dy), mask);
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
        (runs, k)
    }

    /// Appends to `out` the points `j` (not `except`) with `|points[j] − p|² ≤ reach²`, in
    /// ascending index: the answer of a scan over all points. `reach` is at most the reach of
    /// the build.
    pub fn within(
        &self,
        points: &[DVec2],
        p: DVec2,
        reach: f64,
        except: usize,
        out: &mut Vec<u32>,
    ) {
        if self.order.is_empty() {
            return;
        }
        let from = out.len();
        let (runs, count) = self.block(self.coords(p));
        for &(lo, hi) in &runs[..count] {
            out.extend(
                self.order[lo as usize..hi as usize]
                    .iter()
                    .copied()
                    .filter(|&j| {
                        j as usize != except
                            && points[j as usize].distance_squared(p) <= reach * reach
                    }),
            );
        }
        // A few dozen entries, each bucket ascending already: an insertion sort, which runs
        // in one pass over entries that are nearly in order.
        let v = &mut out[from..];
        for i in 1..v.len() {
            let x = v[i];
            let mut j = i;
            while j > 0 && v[j - 1] > x {
                v[j] = v[j - 1];
                j -= 1;
            }
            v[j] = x;
        }
    }
}

/// `⌊x⌋` as an integer, saturating (NaN → 0, ±∞ → the extremes): every position gets a
/// cell. The same as `x.floor() as i64`, without the library call that `floor` is on a CPU
/// baseline without SSE4.1.
#[inline]
pub(super) fn floor(x: f64) -> i64 {
    let t = x as i64;
    // Exact below 2⁵³; above, `x` is an integer and `t as f64 == x` (or `t` saturated).
    if (t as f64) > x {
        t.saturating_sub(1)
    } else {
        t
    }
}
