//! The obstacles near any point, for the sensing of eq. `eq_nonholo_controller_co_avoid` and the
//! obstacle metrics at O(1) per robot.

use super::cells::{bucket, cell_side, floor, CELL_MARGIN};
use super::FEW_OBSTACLES;
use glam::DVec2;

/// An obstacle whose grown disc would cover more cells than this is listed for every point
/// instead ([`ObstacleCells`]): a few huge obstacles cost a check per robot, not memory.
const MAX_OBSTACLE_CELLS: i64 = 1_024;

/// The obstacles near any point, for the sensing of eq. `eq_nonholo_controller_co_avoid` and
/// the obstacle metrics at O(1) per robot: square cells as wide as a reach, each listing (in
/// ascending index) the obstacles whose disc grown by the reach meets the cell.
///
/// [`ObstacleCells::near`]`(p)` holds every obstacle whose surface is within the reach of
/// `p` (and some farther ones, which the caller's own distance test drops), ascending. Built
/// once per scenario: obstacles do not move. As in [`super::Neighbours`], cells are hashed into a
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
        let cell = cell_side(reach, far);
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
        bucket(cx, cy, self.mask)
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
