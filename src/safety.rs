//! The safety barrier: a limit on each robot's forward speed that keeps every pair of robots
//! at least `2·r_ij` apart and every robot out of every obstacle disc, whatever the field
//! asks for. Not in the paper (README, "Notes on the paper"): the paper's field alone only
//! keeps robots apart in continuous time and for the cases its proofs cover.
//!
//! It is a discrete-time barrier on distances. Over one step of `dt` robot `i` moves by the
//! chord `Δp_i = v_i·dt·c_i` of its arc (`c_i = sinc(ω_i dt/2)·(cos, sin)(θ_i + ω_i dt/2)`,
//! see [`crate::unicycle::chord`]). For a pair at distance `d` along the unit vector
//! `u = (p_i − p_j)/d`,
//!
//! ```text
//! |p_i' − p_j'|² = d² + 2d·u·(Δp_i − Δp_j) + |Δp_i − Δp_j|² ≥ d² + 2d·u·(Δp_i − Δp_j).
//! ```
//!
//! If each robot takes half of the budget, `u·Δp_i ≥ −(a/2)(d − d_s)` and
//! `−u·Δp_j ≥ −(a/2)(d − d_s)`, then `|p_i' − p_j'|² ≥ d² − 2a·d(d − d_s)`, which is at least
//! `d_s²` whenever `d ≥ d_s` and `a ≤ 1/2` (it factors as `(d − d_s)(d + d_s − 2ad) ≥ 0`).
//! So a pair that starts at least `d_s` apart stays so at every step, exactly and not only in
//! the limit `dt → 0`. An obstacle does not move: the robot takes the whole budget,
//! `u·Δp_i ≥ −a(c − r_o)` with `c` the distance to the centre. `a = α·dt`, with `α` the
//! barrier rate ([`crate::params::Params::barrier_rate`]).
//!
//! Every constraint bounds the speed along one direction and holds for `v = 0`, so the set of
//! allowed speeds is an interval that contains 0: the filter clamps the field's speed into it
//! and never needs to search. Steering is left to the field; the barrier only brakes.

use crate::controller::Command;
use crate::obstacle::Obstacle;
use crate::params::Params;
use crate::se2::{heading, Pose};
use crate::unicycle::{motion, Motion};
use glam::DVec2;
use std::f64::consts::FRAC_PI_2;

/// The barrier holds distances a relative `1e-9` beyond the limits, so that the round-off of
/// computing distances (a few ulps) cannot show a robot that slides along a limit as one
/// `1e-15` inside it.
pub const MARGIN: f64 = 1e-9;

/// A step whose direction `c` (a chord, `|c| ≤ 1`) has `|u·c|` below this slides along a
/// limit: it is not bounded by it. A robot held exactly on a limit (budget 0) whose field is
/// tangent to it has a heading a few ulps off the tangent, `u·c ≈ −1e-16`, and without this
/// the bound `0/1e-16` would stop it there forever (seen on an obstacle's surface with the goal
/// behind the disc, the field along the surface, `v = 0` for minutes).
///
/// Still safe: the squared distance after a step `s·c` is `d² + 2d·s(u·c) + s²|c|²`, which
/// can only shrink while `s < 2d·1e-12/|c|²`, and then by less than `s·1e-12 < 1e-23·d`; the
/// barrier holds every distance `MARGIN` = `1e-9` (relative) beyond its limit, so even 10⁶ such
/// steps in a row stay outside the limit itself.
pub const ALONG_ROUND_OFF: f64 = 1e-12;

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
        self.keep_bound(along, -(budget / along), dt);
    }

    /// [`Self::keep`] with its bound `−(budget / along)` taken (`limits_of_two` takes two
    /// at once).
    #[inline]
    fn keep_bound(&mut self, along: f64, bound: f64, dt: f64) {
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

/// The distance beyond which a neighbour never changes what [`filter`] returns for a command
/// of speed `|v| ≤ speed`: a neighbour farther than this may be left out of the barrier, with
/// the same bits. Zero without a barrier (nothing binds). This is what bounds a step's cost in
/// a dense crowd (README, Performance): a slow robot in a jam constrains itself against its
/// immediate neighbours only.
///
/// Why: a neighbour at distance `d` along `u` bounds the speed along a direction `c`
/// (`|c| ≤ 1`: a chord, `sinc ≤ 1`) by `½·a(d − d_s)/(|u·c|·dt) ≥ ½·α(d − d_s)` on one side
/// (`a = α·dt`). The filter reads its limits twice: whether the speed `min(k_v|Γ|, v_c) ≤ v_c`
/// along the field is cut (a bound at or above it cuts nothing), and the clamp of `v` (a bound
/// beyond `|v|` on either side clamps nothing). Both are a minimum or a maximum over the
/// neighbours, exact in floating point, so a neighbour whose bound is at least
/// `max(|v|, v_c)` changes neither: `d ≥ d_s + 2·max(|v|, v_c)/α`, widened by a relative
/// [`REACH_MARGIN`] for the round-off of the bounds (a few ulps).
#[must_use]
pub fn neighbour_reach(params: &Params, speed: f64) -> f64 {
    let Some(rate) = params.barrier_rate else {
        return 0.0;
    };
    let fastest = speed.abs().max(params.avoid_speed);
    let reach = 2.0 * params.safe_radius * (1.0 + MARGIN) + 2.0 * fastest / rate;
    widened(reach)
}

/// The relative widening of [`neighbour_reach`] (and of the avoidance range where the
/// simulation lists neighbours): far above the few ulps of round-off it covers, far below any
/// distance that matters.
pub const REACH_MARGIN: f64 = 1e-6;

/// A reach `d` widened by [`REACH_MARGIN`], relatively and absolutely:
/// `d·(1 + REACH_MARGIN) + REACH_MARGIN`.
#[inline]
#[must_use]
pub fn widened(d: f64) -> f64 {
    d * (1.0 + REACH_MARGIN) + REACH_MARGIN
}

/// The command `c` of a robot at `pose` whose field is `field` (world frame), made safe: its
/// speed clamped by the barrier (see [`speed_limits`]), with `a = barrier_rate·dt` and the
/// safe distance `2·r_ij` of `params`. The barrier's constraints are derived once into
/// `constraints` (a buffer reused from robot to robot) for the two directions it asks about. Without a barrier rate the command is returned as it is.
///
/// Returned with the chord of its step, `chord(pose.theta, ω, dt)`, which the barrier computes
/// anyway and [`crate::unicycle::integrate_along`] takes: a step computes it once.
///
/// A robot whose field leads into a barrier also turns left (counter-clockwise) by
/// `k_a·h·π/2`, where `h ∈ [0, 1]` is the part of the speed `min(k_v|Γ|, v_c)` that the
/// barrier would take away from a motion straight along the field: its heading settles up to
/// a right angle left of the blocked field, the way the paper turns every robot left around a
/// virtual obstacle, and it slides round what blocks it. Without it, a robot circling one
/// neighbour whose path is blocked by another stands still with its field pointing at the
/// blocker, and the two wait for each other forever. A field that is not blocked adds no
/// turn, so a robot merely facing a blocker turns to its field as usual. The speed is clamped
/// again for the final turn rate, so the returned command keeps the barrier exactly.
#[must_use]
#[allow(clippy::too_many_arguments)]
pub fn filter<'a>(
    constraints: &mut Constraints,
    params: &Params,
    dt: f64,
    pose: Pose,
    c: Command,
    field: DVec2,
    neighbours: impl IntoIterator<Item = DVec2>,
    obstacles: impl IntoIterator<Item = &'a Obstacle>,
) -> (Command, DVec2) {
    let h = heading(pose.theta);
    let (c, step) = filter_facing(
        constraints,
        params,
        dt,
        pose.p,
        h,
        c,
        field,
        neighbours,
        obstacles,
    );
    (c, step.chord)
}

/// [`filter`] of a robot at `p` with the heading `h = (cos θ, sin θ)` its controller has taken
/// already ([`crate::controller::evaluate_facing`]): the same command, and no sine or cosine
/// of its own. Returned with the step's whole [`Motion`]: its chord, and the heading at its
/// end, which a simulation keeps for the next step.
#[must_use]
#[allow(clippy::too_many_arguments)]
pub fn filter_facing<'a>(
    constraints: &mut Constraints,
    params: &Params,
    dt: f64,
    p: DVec2,
    h: DVec2,
    c: Command,
    field: DVec2,
    neighbours: impl IntoIterator<Item = DVec2>,
    obstacles: impl IntoIterator<Item = &'a Obstacle>,
) -> (Command, Motion) {
    let Some(rate) = params.barrier_rate else {
        return (c, motion(h, c.omega, dt));
    };
    // The step's motion if the field is not held, taken before the constraints, on which it
    // does not depend: its series then runs while the constraints' divisions do.
    let free = turn_rate(params, c.omega, 0.0);
    let free_step = motion(h, free, dt);
    let safe = 2.0 * params.safe_radius;
    constraints.derive(p, rate * dt, safe, neighbours, obstacles);
    steer(
        params,
        dt,
        h,
        c,
        field,
        (free, free_step),
        |direction| constraints.limits(direction, dt),
        |a, b| constraints.limits_of_two(a, b, dt),
    )
}

/// The turn rate `ω + k_a·held·π/2` of a command whose field the barrier holds by `held`,
/// within `ω_max` (see [`filter`]).
#[inline]
fn turn_rate(params: &Params, omega: f64, held: f64) -> f64 {
    let turned = omega + params.k_a * held * FRAC_PI_2;
    params.omega_max.map_or(turned, |m| turned.clamp(-m, m))
}

/// The barrier's constraints on one robot: for each neighbour and obstacle, the unit vector
/// `u` away from it and the approach `budget` allowed per step, as [`speed_limits`] derives
/// them. They do not depend on the direction of the step, so [`filter`] derives them once.
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

    /// [`Self::limits`] along `a` and along `b`: the same bits as two calls.
    ///
    /// Natively two calls, two passes over the constraints: the barrier asks for the field's
    /// direction `a`, known early, and the step's chord `b`, which waits on the turn rate, and
    /// the processor runs the first pass while the turn rate is still being found (the crowd of
    /// 1,000 on one thread: open space 1.7 % faster, the jam 1.1 %, than in one pass). The wasm
    /// build takes one pass that divides pairs of bounds, with one 128-bit division (1.3 %
    /// faster in Node than two passes, and 31 bytes smaller; README, Performance).
    #[must_use]
    pub fn limits_of_two(&self, a: DVec2, b: DVec2, dt: f64) -> (SpeedLimits, SpeedLimits) {
        #[cfg(not(target_arch = "wasm32"))]
        {
            (self.limits(a, dt), self.limits(b, dt))
        }
        #[cfg(target_arch = "wasm32")]
        {
            let (mut along_a, mut along_b) = (SpeedLimits::FREE, SpeedLimits::FREE);
            for &(u, budget) in &self.items {
                // Both bounds in one division of pairs (the same IEEE division in each lane,
                // so the same bits as `keep`'s).
                let along = DVec2::new(u.dot(a) * dt, u.dot(b) * dt);
                let bound = -(DVec2::splat(budget) / along);
                along_a.keep_bound(along.x, bound.x, dt);
                along_b.keep_bound(along.y, bound.y, dt);
            }
            (along_a, along_b)
        }
    }
}

/// The rest of [`filter`] once the barrier's limits can be had for any direction (`limits`),
/// or for two at once (`limits_of_two`).
///
/// The step's direction depends on how far the field is held, which the limits along the field
/// tell; but a field that is not held (the usual case) turns the robot by nothing, and the
/// step's direction is then known before: the limits along the field and along that step are
/// taken together ([`Constraints::limits_of_two`]), and a held field takes another pass for its
/// own step. The same bits either way. The motion of the step without a hold (`free`: its turn
/// rate and motion) comes from the caller, which takes it before the constraints.
#[allow(clippy::too_many_arguments)]
fn steer(
    params: &Params,
    dt: f64,
    h: DVec2,
    c: Command,
    field: DVec2,
    (free, free_step): (f64, Motion),
    limits: impl Fn(DVec2) -> SpeedLimits,
    limits_of_two: impl Fn(DVec2, DVec2) -> (SpeedLimits, SpeedLimits),
) -> (Command, Motion) {
    let wanted = (params.k_v * field.length()).min(params.avoid_speed);
    let (held, free_limits) = match field.try_normalize() {
        Some(along) if wanted > 0.0 => {
            let (on_field, on_step) = limits_of_two(along, free_step.chord);
            // Not held when the limit is at least the speed wanted (then `hi / wanted ≥ 1`
            // and the expression below is 0): the usual case, known without waiting on the
            // division.
            let held = if on_field.hi >= wanted {
                0.0
            } else {
                (1.0 - on_field.hi / wanted).max(0.0)
            };
            (held, on_step)
        }
        _ => (0.0, limits(free_step.chord)),
    };
    if held == 0.0 {
        return (
            Command {
                v: free_limits.clamp(c.v),
                omega: free,
            },
            free_step,
        );
    }
    let omega = turn_rate(params, c.omega, held);
    let step = motion(h, omega, dt);
    let v = limits(step.chord).clamp(c.v);
    (Command { v, omega }, step)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::se2::heading;
    use crate::testing::{assert_close, test, XorShift};
    use crate::unicycle::{chord, integrate};

    /// The constraints derived once give the same bits as deriving them for each direction
    /// ([`speed_limits`], the definition).
    #[test]
    fn constraints_derived_once_equal_the_limits_of_each_direction() {
        let mut rng = XorShift(0x2545_F491_4F6C_DD1D_u64);
        let mut next = move || rng.unit() * 2.0 - 1.0;
        let (dt, a, safe) = (0.01, 0.05, 2.0);
        let mut constraints = Constraints::new();
        for _ in 0..500 {
            let p = DVec2::new(next() * 5.0, next() * 5.0);
            let neighbours: Vec<DVec2> = (0..4)
                .map(|_| DVec2::new(next() * 8.0, next() * 8.0))
                .collect();
            let obstacles = [Obstacle {
                center: DVec2::new(next() * 8.0, next() * 8.0),
                radius: 1.0,
                influence: 2.0,
            }];
            constraints.derive(p, a, safe, neighbours.iter().copied(), &obstacles);
            for _ in 0..2 {
                let direction = chord(next() * 3.0, next() * 5.0, dt);
                let once = constraints.limits(direction, dt);
                let each = speed_limits(
                    p,
                    direction,
                    dt,
                    a,
                    safe,
                    neighbours.iter().copied(),
                    &obstacles,
                );
                assert_eq!(once.lo.to_bits(), each.lo.to_bits());
                assert_eq!(once.hi.to_bits(), each.hi.to_bits());
            }
        }
    }

    /// A robot on an obstacle's surface (budget 0) whose step is tangent to it up to round-off
    /// keeps its speed and slides along the surface, never inside the disc. Before
    /// `ALONG_ROUND_OFF`, an inward component of 1e-16 bounded its speed by 0.
    #[test]
    fn a_step_along_a_limit_is_not_stopped_by_round_off() {
        let disc = Obstacle {
            center: DVec2::ZERO,
            radius: 4.0,
            influence: 5.0,
        };
        let (dt, a) = (0.01, 0.05);
        let on = disc.radius * (1.0 + MARGIN);
        // At (−on, 0) the tangent is ±Y; the chord leans inward (+X) by 1e-15.
        let p = DVec2::new(-on, 0.0);
        let chord = DVec2::new(1e-15, -1.0).normalize();
        let limits = speed_limits(p, chord, dt, a, 2.0, [], [&disc]);
        assert!(limits.hi.is_infinite(), "{limits:?}");
        // Driven along its heading tangent at 4 m/s, turning as a circle of the same radius
        // would, it stays outside the disc at every step.
        let params = Params {
            barrier_rate: Some(a / dt),
            ..Params::default()
        };
        let mut r = Pose::new(-on, 0.0, -std::f64::consts::FRAC_PI_2);
        let c = Command {
            v: 4.0,
            omega: 4.0 / on,
        };
        let mut travelled = 0.0;
        for _ in 0..2000 {
            let (c, _) = filter(
                &mut Constraints::new(),
                &params,
                dt,
                r,
                c,
                heading(r.theta),
                [],
                [&disc],
            );
            let next = integrate(r, c, dt);
            travelled += next.p.distance(r.p);
            r = next;
            assert!(disc.clearance(r.p) >= 0.0, "{}", disc.clearance(r.p));
        }
        // It went round (at the barrier's stop it would have travelled nothing).
        assert!(travelled > 70.0, "{travelled}");
    }

    /// Two robots driven straight at each other stop outside the safe distance at every step
    /// and give way to the left, and a robot driven into a disc stops at its surface.
    #[test]
    fn head_on_robots_never_come_closer_than_the_safe_distance() {
        let (dt, a, ds) = (0.1, 0.5, 2.0);
        let p = Params {
            barrier_rate: Some(a / dt),
            safe_radius: ds / 2.0,
            ..Params::default()
        };
        let mut pi = Pose::new(-5.0, 0.0, 0.0);
        let mut pj = Pose::new(5.0, 0.0, std::f64::consts::PI);
        let wild = Command {
            v: 10.0,
            omega: 0.0,
        };
        let mut closest = f64::INFINITY;
        for _ in 0..200 {
            // Both commands from the same snapshot, as in the simulator.
            let (ci, _) = filter(
                &mut Constraints::new(),
                &p,
                dt,
                pi,
                wild,
                heading(pi.theta),
                [pj.p],
                [],
            );
            let (cj, _) = filter(
                &mut Constraints::new(),
                &p,
                dt,
                pj,
                wild,
                heading(pj.theta),
                [pi.p],
                [],
            );
            pi = integrate(pi, ci, dt);
            pj = integrate(pj, cj, dt);
            closest = closest.min(pi.p.distance(pj.p));
            assert!(pi.p.distance(pj.p) >= ds, "{}", pi.p.distance(pj.p));
        }
        // The barrier brakes, it does not freeze: each robot, held, turned left
        // (counter-clockwise) and drove off, the two on mirrored paths.
        assert!(pi.p.y > 10.0 && pj.p.y < -10.0, "{pi:?} {pj:?}");
        assert_close!((pi.p + pj.p).length(), 0.0, 1e-9);
        assert!(closest < 2.0 * ds, "{closest}");

        let disc = Obstacle {
            center: DVec2::new(3.0, 0.0),
            radius: 1.0,
            influence: 2.0,
        };
        let mut r = Pose::new(-5.0, 0.0, 0.0);
        let mut closest = f64::INFINITY;
        for _ in 0..200 {
            let (c, _) = filter(
                &mut Constraints::new(),
                &p,
                dt,
                r,
                wild,
                heading(r.theta),
                [],
                [&disc],
            );
            r = integrate(r, c, dt);
            closest = closest.min(disc.clearance(r.p));
            assert!(disc.clearance(r.p) >= 0.0);
        }
        assert!(closest < 1.0 && r.p.y > 10.0, "{closest} {r:?}");
    }

    /// Random pairs, random speeds and turn rates: every step keeps the pair apart, including
    /// when both reverse and turn fast, and zero speed is always allowed.
    #[test]
    fn any_commands_keep_any_pair_apart() {
        let mut rng = XorShift(0x2545_f491_4f6c_dd1d_u64);
        let mut next = move || rng.unit();
        let (dt, a, ds) = (0.02, 0.5, 2.0);
        let p = Params {
            barrier_rate: Some(a / dt),
            safe_radius: ds / 2.0,
            ..Params::default()
        };
        for _ in 0..2000 {
            let d0 = ds + 3.0 * next();
            let mut pi = Pose::new(0.0, 0.0, 7.0 * next());
            let mut pj = Pose::new(d0, 0.0, 7.0 * next());
            for _ in 0..20 {
                let ci = Command {
                    v: 400.0 * (next() - 0.5),
                    omega: 100.0 * (next() - 0.5),
                };
                let cj = Command {
                    v: 400.0 * (next() - 0.5),
                    omega: 100.0 * (next() - 0.5),
                };
                let li = speed_limits(pi.p, chord(pi.theta, ci.omega, dt), dt, a, ds, [pj.p], []);
                assert!(li.lo <= 0.0 && li.hi >= 0.0);
                let (fi, fj) = (
                    filter(
                        &mut Constraints::new(),
                        &p,
                        dt,
                        pi,
                        ci,
                        DVec2::ZERO,
                        [pj.p],
                        [],
                    )
                    .0,
                    filter(
                        &mut Constraints::new(),
                        &p,
                        dt,
                        pj,
                        cj,
                        DVec2::ZERO,
                        [pi.p],
                        [],
                    )
                    .0,
                );
                pi = integrate(pi, fi, dt);
                pj = integrate(pj, fj, dt);
                assert!(pi.p.distance(pj.p) >= ds);
            }
        }
    }

    /// A neighbour beyond [`neighbour_reach`] of the command's speed changes nothing: random
    /// robots, commands and fields among neighbours up to 30 m away (the default `α` = 5 1/s,
    /// speeds up to 30 m/s so that the reach varies from 2.8 m to 14 m), filtered with every
    /// neighbour and with those within the reach only, give the same bits, command and chord.
    #[test]
    fn neighbours_beyond_the_reach_change_nothing() {
        let mut rng = XorShift(0x9E37_79B9_7F4A_7C15_u64);
        let mut next = move || rng.unit() * 2.0 - 1.0;
        let p = Params::default();
        let dt = 0.01;
        let (mut all, mut near) = (Constraints::new(), Constraints::new());
        let mut left_out = 0;
        for _ in 0..3000 {
            let pose = Pose::new(0.0, 0.0, 4.0 * next());
            let c = Command {
                v: 30.0 * next(),
                omega: 20.0 * next(),
            };
            let field = DVec2::new(next(), next()) * 3.0;
            let neighbours: Vec<DVec2> = (0..8)
                .map(|_| DVec2::new(next(), next()) * 30.0)
                .filter(|q| q.length() > 2.0 * p.safe_radius)
                .collect();
            let reach = neighbour_reach(&p, c.v);
            let within = || neighbours.iter().copied().filter(|q| q.length() <= reach);
            left_out += neighbours.len() - within().count();
            let a = filter(
                &mut all,
                &p,
                dt,
                pose,
                c,
                field,
                neighbours.iter().copied(),
                [],
            );
            let b = filter(&mut near, &p, dt, pose, c, field, within(), []);
            assert_eq!(a.0.v.to_bits(), b.0.v.to_bits(), "{pose:?} {c:?}");
            assert_eq!(a.0.omega.to_bits(), b.0.omega.to_bits(), "{pose:?} {c:?}");
            assert_eq!(a.1, b.1);
        }
        assert!(
            left_out > 5000,
            "the reach left out only {left_out} neighbours"
        );
        assert_eq!(
            neighbour_reach(
                &Params {
                    barrier_rate: None,
                    ..p
                },
                10.0
            ),
            0.0
        );
    }
}
