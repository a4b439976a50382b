//! The barrier's speed limits: each neighbour and obstacle bounds the speed along a step's
//! direction ([`SpeedLimits`]), from constraints that do not depend on that direction
//! ([`Constraints`], derived once per robot and read for each direction the filter asks about).

use super::{ALONG_ROUND_OFF, MARGIN};
use crate::obstacle::Obstacle;
use glam::DVec2;

/// The interval of forward speeds `[lo, hi]` (with `lo ≤ 0 ≤ hi`) under which a robot at `p`
/// moving along `chord` keeps its share of every barrier.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpeedLimits {
    /// Least speed (≤ 0).
    pub lo: f64,
    /// Greatest speed (≥ 0).
    pub hi: f64,
}

impl SpeedLimits {
    /// No limit.
    pub const FREE: Self = Self {
        lo: f64::NEG_INFINITY,
        hi: f64::INFINITY,
    };

    /// Adds the constraint `s·(u·c) ≥ −budget` on the displacement `s = v·dt` along `c`:
    /// `u` is the unit vector away from what is avoided, `budget ≥ 0` the allowed approach.
    #[inline]
    fn keep(&mut self, u: DVec2, c: DVec2, dt: f64, budget: f64) {
        // d(u·Δp)/dv.
        let along = u.dot(c) * dt;
        // The bound `budget / −along` on one side and `−budget / along` on the other are both
        // `−(budget / along)`, bit for bit (a division rounds its magnitude alike whatever the
        // signs).
        let bound = -(budget / along);
        let tol = ALONG_ROUND_OFF * dt;
        // The bound taken either way and kept by selects, without a branch to mispredict
        // (which side a neighbour bounds is a coin toss in a crowd); selects rather than
        // `f64::min`/`max`, which are calls in wasm (to `fmin`/`fmax`, for their rule on NaN):
        // the same bits, since a bound kept is never NaN and each side has zeros of one sign
        // only (`hi` from `+0` budgets over positive divisors, `lo` from their negation).
        self.hi = if (along < -tol) & (bound < self.hi) {
            bound
        } else {
            self.hi
        };
        self.lo = if (along > tol) & (bound > self.lo) {
            bound
        } else {
            self.lo
        };
    }

    /// `v` clamped into the limits.
    #[inline]
    #[must_use]
    pub fn clamp(self, v: f64) -> f64 {
        v.clamp(self.lo, self.hi)
    }
}

/// The barrier's speed limits for a robot at `p` whose step goes along `chord`, among robots
/// at `neighbours` (kept `safe_distance` apart, half the budget each) and `obstacles` (kept
/// out of the disc, the whole budget), with `a = α·dt ≤ 1/2`.
///
/// A neighbour or obstacle already closer than its limit (a scenario that starts that way)
/// gets a zero budget: the robot may not approach it further, but may leave.
#[must_use]
pub fn speed_limits<'a>(
    p: DVec2,
    chord: DVec2,
    dt: f64,
    a: f64,
    safe_distance: f64,
    neighbours: impl IntoIterator<Item = DVec2>,
    obstacles: impl IntoIterator<Item = &'a Obstacle>,
) -> SpeedLimits {
    let mut limits = SpeedLimits::FREE;
    constraints(p, a, safe_distance, neighbours, obstacles, |u, budget| {
        limits.keep(u, chord, dt, budget);
    });
    limits
}

/// The barrier's constraints on a robot at `p`, in order (neighbours, then obstacles): for
/// each, the unit vector `u` away from it and the approach `budget` allowed per step, passed
/// to `each`. They do not depend on the direction of the step; [`speed_limits`] and
/// [`Constraints::derive`] both take them from here.
fn constraints<'a>(
    p: DVec2,
    a: f64,
    safe_distance: f64,
    neighbours: impl IntoIterator<Item = DVec2>,
    obstacles: impl IntoIterator<Item = &'a Obstacle>,
    mut each: impl FnMut(DVec2, f64),
) {
    // `u` is the difference over its length, a unit vector to within an ulp or two: the
    // barrier's `MARGIN` (relative 1e-9) covers that. A neighbour at the robot's very position
    // (`d = 0`) gives no direction and is left out.
    let safe_distance = safe_distance * (1.0 + MARGIN);
    // By `for_each`, which a chain of runs (a simulation's two) folds run by run, without a
    // test of which run each neighbour comes from.
    neighbours.into_iter().for_each(|q| {
        let d = p.distance(q);
        if d > 0.0 {
            each((p - q) / d, 0.5 * a * (d - safe_distance).max(0.0));
        }
    });
    for o in obstacles {
        let c = p.distance(o.center);
        if c > 0.0 {
            each(
                (p - o.center) / c,
                a * (c - o.radius * (1.0 + MARGIN)).max(0.0),
            );
        }
    }
}

/// The barrier's constraints on one robot: for each neighbour and obstacle, the unit vector
/// `u` away from it and the approach `budget` allowed per step, as [`speed_limits`] derives
/// them. They do not depend on the direction of the step, so [`super::filter`] derives them once.
#[derive(Clone, Debug, Default)]
pub struct Constraints {
    items: Vec<(DVec2, f64)>,
}

impl Constraints {
    /// An empty set; its buffer grows to the most constraints a robot has had.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// Replaces the constraints with those of a robot at `p` (see [`speed_limits`]).
    pub fn derive<'a>(
        &mut self,
        p: DVec2,
        a: f64,
        safe_distance: f64,
        neighbours: impl IntoIterator<Item = DVec2>,
        obstacles: impl IntoIterator<Item = &'a Obstacle>,
    ) {
        self.items.clear();
        let items = &mut self.items;
        constraints(p, a, safe_distance, neighbours, obstacles, |u, budget| {
            items.push((u, budget));
        });
    }

    /// Makes room for `n` constraints, so that deriving up to that many allocates nothing.
    pub fn reserve(&mut self, n: usize) {
        self.items.reserve(n.saturating_sub(self.items.len()));
    }

    /// The speed limits of a step along `chord` (see [`speed_limits`]).
    #[must_use]
    pub fn limits(&self, chord: DVec2, dt: f64) -> SpeedLimits {
        let mut limits = SpeedLimits::FREE;
        for &(u, budget) in &self.items {
            limits.keep(u, chord, dt, budget);
        }
        limits
    }

    /// [`Self::limits`] along `a` and along `b`, in two passes over the constraints: the
    /// barrier asks for the field's direction `a`, known early, and the step's chord `b`,
    /// which waits on the turn rate, so that the processor runs the first pass while the turn
    /// rate is still being found.
    #[must_use]
    pub fn limits_of_two(&self, a: DVec2, b: DVec2, dt: f64) -> (SpeedLimits, SpeedLimits) {
        (self.limits(a, dt), self.limits(b, dt))
    }
}
