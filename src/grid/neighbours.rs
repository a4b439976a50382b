//! The robots within a reach of each robot, as flat per-robot lists in ascending index, at O(N)
//! cost for a bounded density (the sensed sets of a step and the pairs of the metrics).

use super::cells::Cells;
use super::FEW_ROBOTS;
use glam::DVec2;

/// The robots within `reach` of each robot, as flat per-robot lists (compressed rows).
///
/// After [`Neighbours::build`], [`Neighbours::of`]`(i)` holds the indices `j ≠ i` with
/// `|p_j − p_i|² ≤ reach²`, ascending. The same predicate as a scan over all pairs, so the two
/// give the same sets. Up to [`FEW_ROBOTS`] robots the lists come from that scan; above, from a
/// [`Cells`] table of cells as wide as the reach.
#[derive(Clone, Debug, Default)]
pub struct Neighbours {
    cells: Cells,
    // The lists: robot `i`'s neighbours are `list[first[i]..first[i + 1]]`. `hits` holds each
    // robot's neighbours of higher index in bucket order, robot `i`'s from `upper[i]`;
    // `cursor` is a fill position per row.
    first: Vec<u32>,
    list: Vec<u32>,
    hits: Vec<u32>,
    upper: Vec<u32>,
    cursor: Vec<u32>,
    // The hits and their starts of each chunk of robots, when they are found on threads
    // ([`Neighbours::build_on_threads`]; native only).
    #[cfg(not(target_arch = "wasm32"))]
    chunks: Vec<(Vec<u32>, Vec<u32>)>,
}

impl Neighbours {
    /// An empty search; its buffers grow on the first [`Neighbours::build`].
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// Rebuilds the lists for the robots at `points` and a `reach` (scenario
    /// units). Reuses the buffers: after the first call with as many robots, it allocates only
    /// when the lists' total grows past its previous maximum.
    ///
    /// A non-finite position is nobody's neighbour (its distance is not `≤ reach`), as in a
    /// scan over all pairs.
    pub fn build(&mut self, points: &[DVec2], reach: f64) {
        let n = points.len();
        if n <= FEW_ROBOTS {
            // A few robots: the scan over all pairs costs less than the cells (the paper's
            // examples have ten), and it is the definition the lists meet.
            let reach2 = reach * reach;
            self.first.clear();
            self.list.clear();
            for (i, &p) in points.iter().enumerate() {
                self.first.push(self.list.len() as u32);
                for (j, q) in points.iter().enumerate() {
                    if j != i && q.distance_squared(p) <= reach2 {
                        self.list.push(j as u32);
                    }
                }
            }
            self.first.push(self.list.len() as u32);
            return;
        }
        self.cells.build(points, reach);
        self.upper.clear();
        let count = hits(
            &self.cells,
            points,
            reach,
            0..n,
            &mut self.hits,
            &mut self.upper,
        );
        self.upper.push(count as u32);
        self.rows(n, count);
    }

    /// [`Neighbours::build`] with the robots' hits found in chunks on rayon's threads: the same
    /// lists (each chunk's hits are those the serial loop finds for its robots, in the same
    /// order, and are joined in chunk order).
    #[cfg(not(target_arch = "wasm32"))]
    pub fn build_on_threads(&mut self, points: &[DVec2], reach: f64) {
        use rayon::prelude::*;
        let n = points.len();
        if n <= FEW_ROBOTS || rayon::current_num_threads() < 2 {
            return self.build(points, reach);
        }
        self.cells.build(points, reach);
        // A few chunks per thread, so that one dense chunk does not hold the others up.
        let chunks = 4 * rayon::current_num_threads();
        let size = n.div_ceil(chunks);
        self.chunks.resize_with(chunks, Default::default);
        let cells = &self.cells;
        self.chunks
            .par_iter_mut()
            .enumerate()
            .for_each(|(k, (hits_k, upper_k))| {
                upper_k.clear();
                let rows = (k * size).min(n)..((k + 1) * size).min(n);
                let count = hits(cells, points, reach, rows, hits_k, upper_k);
                upper_k.push(count as u32);
            });
        self.upper.clear();
        let mut count = 0usize;
        for (hits_k, upper_k) in &self.chunks {
            let found = *upper_k.last().unwrap_or(&0) as usize;
            let (_, starts) = upper_k.split_last().unwrap_or((&0, &[]));
            self.upper.extend(starts.iter().map(|&u| u + count as u32));
            if self.hits.len() < count + found {
                self.hits.resize(2 * (count + found), 0);
            }
            self.hits[count..count + found].copy_from_slice(&hits_k[..found]);
            count += found;
        }
        self.upper.push(count as u32);
        self.rows(n, count);
    }

    /// The lists from the hits (`hits[..count]`, robot `i`'s from `upper[i]`).
    fn rows(&mut self, n: usize, count: usize) {
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

    /// Makes room for `factor` times as many neighbours in all as the last build found, so
    /// that rebuilds allocate nothing while the total stays below that.
    pub fn reserve(&mut self, factor: f64) {
        let want = (self.list.len() as f64 * factor) as usize;
        self.list.reserve(want.saturating_sub(self.list.len()));
        // The hits hold half the pairs, plus room for one range of candidates (at most all).
        let room = want / 2 + self.cells.order().len() + 1;
        if self.hits.len() < room {
            self.hits.resize(room, 0);
        }
    }

    /// Whether the lists, last built at `was` for a reach `built`, list every robot that is
    /// now within `reach` of robot `j`, the robots being now at `now(i)`. Robot `j` may have
    /// moved any distance; every other robot `i` must be less than `built − reach` from
    /// `was[i]`, for it is looked for among the cells around robot `j`'s position now, which
    /// hold the robots within `built` of there as they were. `false` for lists that came from
    /// the scan over all pairs (a few robots), which keeps no cells.
    ///
    /// A robot is listed exactly when the build's own test holds (`|p_j − p_i|² ≤ built²` at
    /// `was`), which is taken again here with the same bits.
    #[must_use]
    pub fn list_all_near(
        &self,
        was: &[DVec2],
        now: impl Fn(usize) -> DVec2,
        j: usize,
        reach: f64,
        built: f64,
    ) -> bool {
        if was.len() <= FEW_ROBOTS {
            return false;
        }
        let (reach2, built2) = (reach * reach, built * built);
        let (p, p_was) = (now(j), was[j]);
        let (runs, k) = self.cells.block(self.cells.coords(p));
        runs[..k].iter().all(|&(from, to)| {
            self.cells.order()[from as usize..to as usize]
                .iter()
                .all(|&i| {
                    // Tested on the old positions first, which lie packed together: a robot
                    // more than `built` from robot `j`'s position now was, and is still, beyond
                    // `reach` of it; a robot listed is listed. Only the others are looked up
                    // where they are now.
                    let i = i as usize;
                    i == j
                        || was[i].distance_squared(p) > built2
                        || was[i].distance_squared(p_was) <= built2
                        || now(i).distance_squared(p) > reach2
                })
        })
    }

    /// Robot `i`'s neighbours, ascending (empty before the first build or for `i` out of range).
    #[must_use]
    pub fn of(&self, i: usize) -> &[u32] {
        match (self.first.get(i), self.first.get(i + 1)) {
            (Some(&a), Some(&b)) => &self.list[a as usize..b as usize],
            _ => &[],
        }
    }

    /// The capacities of the cell table's bucket starts and order, of the lists, and the
    /// lists' address: a test checks that a rebuild reuses them.
    #[cfg(test)]
    pub(super) fn buffers(&self) -> (usize, usize, usize, *const u32) {
        let (start, order) = self.cells.capacities();
        (start, order, self.list.capacity(), self.list.as_ptr())
    }
}

/// The hits of the robots `rows`, in bucket order, into `hits` from position 0, with each
/// robot's start pushed to `upper`; returns their count. A robot's hits are the robots of
/// higher index within `reach` among the 3 × 3 cells around it (a robot within reach is at most
/// one cell away along each axis). "Within reach" is symmetric (the squared distance of a pair
/// is the same bits either way round), so each pair is tested once.
fn hits(
    cells: &Cells,
    points: &[DVec2],
    reach: f64,
    rows: std::ops::Range<usize>,
    hits: &mut Vec<u32>,
    upper: &mut Vec<u32>,
) -> usize {
    let reach2 = reach * reach;
    // `hits[..count]` are the hits so far; the rest is room (kept from build to build), so
    // that a candidate is written before its test and kept by advancing `count`: no branch to
    // mispredict.
    let mut count = 0usize;
    for i in rows {
        upper.push(count as u32);
        let p = points[i];
        let (runs, k) = cells.block(cells.coords(p));
        for &(from, to) in &runs[..k] {
            let candidates = &cells.order()[from as usize..to as usize];
            if hits.len() < count + candidates.len() {
                hits.resize(2 * (count + candidates.len()), 0);
            }
            for &j in candidates {
                hits[count] = j;
                let hit = (j as usize > i) & (points[j as usize].distance_squared(p) <= reach2);
                count += usize::from(hit);
            }
        }
    }
    count
}
