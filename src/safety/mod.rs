//! The safety barrier: a limit on each robot's forward speed that keeps every pair of robots
//! at least `2·r_ij` apart and every robot out of every obstacle disc, whatever the field
//! asks for. Not in the paper (docs/notes-on-the-paper.md): the paper's field alone only
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

mod limits;
mod robot;

pub use limits::{speed_limits, Constraints, SpeedLimits};
pub use robot::SafeRobot;

/// The barrier holds distances a relative `1e-9` beyond the limits, so that the round-off of
/// computing distances (a few ulps) cannot show a robot that slides along a limit as one
/// `1e-15` inside it.
pub const MARGIN: f64 = 1e-9;

/// A step whose direction `c` (a chord, `|c| ≤ 1`) has `|u·c|` below this slides along a
/// limit: it is not bounded by it. A robot held exactly on a limit (budget 0) whose field is
/// tangent to it has a heading a few ulps off the tangent, `u·c ≈ −1e-16`, and without this
/// the bound `0/1e-16` would stop it there forever (on an obstacle's surface with the goal
/// behind the disc, the field along the surface: `v = 0` for good).
///
/// Still safe: the squared distance after a step `s·c` is `d² + 2d·s(u·c) + s²|c|²`, which
/// can only shrink while `s < 2d·1e-12/|c|²`, and then by less than `s·1e-12 < 1e-23·d`; the
/// barrier holds every distance `MARGIN` = `1e-9` (relative) beyond its limit, so even 10⁶ such
/// steps in a row stay outside the limit itself.
pub const ALONG_ROUND_OFF: f64 = 1e-12;

/// The distance beyond which a neighbour never changes what [`filter`] returns for a command
/// of speed `|v| ≤ speed`: a neighbour farther than this may be left out of the barrier, with
/// the same bits. Zero without a barrier (nothing binds). This is what bounds a step's cost in
/// a dense crowd: a slow robot in a jam constrains itself against its
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
    let turned = c.omega + params.k_a * held * FRAC_PI_2;
    let omega = turn_rate(params, c.omega, held);
    // A left turn that `ω_max` cuts slows the robot by the same factor, so that it keeps the
    // turning radius the turn asks for (`controller::saturate`, docs/notes-on-the-paper.md §10).
    let v = if omega == turned {
        c.v
    } else {
        c.v * (omega / turned).abs()
    };
    let step = motion(h, omega, dt);
    let v = limits(step.chord).clamp(v);
    (Command { v, omega }, step)
}

#[cfg(test)]
mod tests;
