//! The trail rings: a bounded history of every robot's poses, with the time and the smallest
//! pair distance of each sample, spanning the whole run however long (the samples thin out, the
//! memory stays fixed).
//!
//! Layout (flat, robots in scenario order): poses `[robots · capacity · 3]`, a ring of past
//! `x, y, θ` per robot, written at slot [`Trails::head`] (the next to write, shared by all
//! robots); robot `i` holds its last [`Trails::len_of`]`(i)` samples, the oldest at slot
//! `(head − len + capacity) % capacity`; sample `g` since the reset is in slot
//! `g % capacity` ([`Trails::recorded`]). The time and minimum pair distance of each slot are in
//! two rings of `capacity` ([`Trails::times`], [`Trails::min_pair`]), whose own length is
//! [`Trails::history_len`].

use super::POSE_STRIDE;
use crate::se2::Pose;

/// Trail samples kept in all robots' rings together: a robot keeps
/// `TRAIL_BUDGET / robots` samples, at most [`MAX_TRAIL_SAMPLES`]. 2¹⁸ samples are 6 MiB, and
/// bound what the page draws when it redraws every trail (about 0.1 s in Chromium without a
/// GPU, after a pan or zoom).
pub const TRAIL_BUDGET: usize = 1 << 18;
/// Samples kept per robot in the trail ring, for up to `TRAIL_BUDGET / 2,048` = 128 robots
/// (see [`Trails::samples_per_robot`]).
pub const MAX_TRAIL_SAMPLES: usize = 2_048;

/// The rings of one live simulation.
#[derive(Clone, Debug, Default)]
pub struct Trails {
    /// Samples per robot.
    capacity: usize,
    poses: Vec<f64>,
    lens: Vec<u32>,
    times: Vec<f64>,
    min_pair: Vec<f64>,
    head: usize,
    history_len: usize,
    /// Samples written since the reset (sample `g` is in slot `g % capacity`).
    recorded: usize,
}

impl Trails {
    /// Samples per robot in the rings for `n` robots: `TRAIL_BUDGET / n`, at most
    /// [`MAX_TRAIL_SAMPLES`] (2,048 up to 128 robots, 26 for 10,000). The rings span the whole
    /// run, so a crowd's trails are coarser, not shorter.
    #[must_use]
    pub fn samples_per_robot(n: usize) -> usize {
        (TRAIL_BUDGET / n.max(1)).clamp(2, MAX_TRAIL_SAMPLES)
    }

    /// Empty rings for `n` robots.
    #[must_use]
    pub fn new(n: usize) -> Self {
        let cap = Self::samples_per_robot(n);
        // Filled (NaN: not recorded yet) rather than zeroed: a zeroed allocation is committed
        // page by page as the ring fills, which would look like growth in a long run.
        Self {
            capacity: cap,
            poses: vec![f64::NAN; n * cap * POSE_STRIDE],
            lens: vec![0; n],
            times: vec![f64::NAN; cap],
            min_pair: vec![f64::NAN; cap],
            head: 0,
            history_len: 0,
            recorded: 0,
        }
    }

    /// Writes a sample of every robot (`poses`, in robot order) at `time`.
    pub fn record(&mut self, poses: impl Iterator<Item = Pose>, time: f64, min_pair: f64) {
        let h = self.head;
        let cap = self.capacity;
        for (i, pose) in poses.enumerate() {
            let o = (i * cap + h) * POSE_STRIDE;
            self.poses[o..o + POSE_STRIDE].copy_from_slice(&pose.to_array());
            self.lens[i] = (self.lens[i] + 1).min(cap as u32);
        }
        self.times[h] = time;
        self.min_pair[h] = min_pair;
        self.history_len = (self.history_len + 1).min(cap);
        self.head = (h + 1) % cap;
        self.recorded += 1;
    }

    /// Rewrites robot `i`'s newest sample and the newest pair distance: an edit of the one
    /// sample at `t = 0`.
    pub fn rewrite_newest(&mut self, i: usize, pose: Pose, min_pair: f64) {
        let cap = self.capacity;
        let h = (self.head + cap - 1) % cap;
        let o = (i * cap + h) * POSE_STRIDE;
        self.poses[o..o + POSE_STRIDE].copy_from_slice(&pose.to_array());
        self.min_pair[h] = min_pair;
    }

    /// Rings for `n` robots: robots keep their index, removed ones drop off the end, added ones
    /// start empty; the rings move to the capacity for `n`, keeping the newest samples.
    pub fn resize(&mut self, n: usize) {
        let cap = self.capacity;
        self.poses.resize(n * cap * POSE_STRIDE, f64::NAN);
        self.lens.resize(n, 0);
        self.relayout(Self::samples_per_robot(n));
    }

    /// Moves the rings to `cap` samples per robot, keeping the newest samples (as many as
    /// fit) in time order from slot 0.
    fn relayout(&mut self, cap: usize) {
        let old = self.capacity;
        if cap == old {
            return;
        }
        let keep = self.history_len.min(cap);
        // Slot k of the new rings holds the sample of old slot `(head − keep + k) mod old`.
        let head = self.head;
        let slot = move |k: usize| (head + old - keep + k) % old;
        let n = self.lens.len();
        let mut poses = vec![f64::NAN; n * cap * POSE_STRIDE];
        for i in 0..n {
            for k in 0..keep {
                let src = (i * old + slot(k)) * POSE_STRIDE;
                let dst = (i * cap + k) * POSE_STRIDE;
                poses[dst..dst + POSE_STRIDE].copy_from_slice(&self.poses[src..src + POSE_STRIDE]);
            }
            self.lens[i] = self.lens[i].min(keep as u32);
        }
        let ring = |r: &[f64]| {
            let mut v = vec![f64::NAN; cap];
            for (k, x) in v.iter_mut().enumerate().take(keep) {
                *x = r[slot(k)];
            }
            v
        };
        self.times = ring(&self.times);
        self.min_pair = ring(&self.min_pair);
        self.poses = poses;
        self.capacity = cap;
        self.history_len = keep;
        self.head = keep % cap;
        self.recorded = keep;
    }

    /// Samples per robot in these rings (see [`Trails::samples_per_robot`]).
    #[must_use]
    pub fn capacity(&self) -> usize {
        self.capacity
    }
    /// `[robots · capacity · 3]` the rings of poses.
    #[must_use]
    pub fn poses(&self) -> &[f64] {
        &self.poses
    }
    /// `[robots]` valid samples in each robot's ring.
    #[must_use]
    pub fn lens(&self) -> &[u32] {
        &self.lens
    }
    /// Valid samples in robot `index`'s ring (0 for an index out of range).
    #[must_use]
    pub fn len_of(&self, index: usize) -> usize {
        self.lens.get(index).map_or(0, |&l| l as usize)
    }
    /// The slot the next sample is written to (shared by every ring).
    #[must_use]
    pub fn head(&self) -> usize {
        self.head
    }
    /// `[capacity]` ring of the times of the samples (s).
    #[must_use]
    pub fn times(&self) -> &[f64] {
        &self.times
    }
    /// `[capacity]` ring of the minimum pair distance at those times.
    #[must_use]
    pub fn min_pair(&self) -> &[f64] {
        &self.min_pair
    }
    /// Samples written since the last reset: sample `g` lies in slot `g % capacity`, so a
    /// reader that drew up to sample `g` draws only what follows (the page's trail layer). A
    /// change of the ring layout renumbers the kept samples from 0.
    #[must_use]
    pub fn recorded(&self) -> usize {
        self.recorded
    }
    /// Valid samples in the time and pair-distance rings.
    #[must_use]
    pub fn history_len(&self) -> usize {
        self.history_len
    }
}
