//! Parked formations: the robots at rest that a robot does not circle (a robot of a parked
//! formation, one that stands aside of its way), how far a robot is squeezed among them, and
//! how a robot at its goal steps aside for the neighbours that press on it ([`make_room`]).

use super::{segment_distance, Approach, Neighbour, AT_REST_RATIO, SPEED_FLOOR};
use glam::DVec2;

/// A neighbour at rest is avoided only if it stands within this many safe distances of the
/// straight way to the goal: one beside the way is no obstacle, and circling it would keep a
/// robot from a goal that lies between parked neighbours (a slot in a crowded formation).
pub const BLOCKING: f64 = 1.5;

/// Whether `n` is at rest and has another neighbour at rest within `range` of it (among the
/// robot's `sensed` neighbours): a robot of a parked formation. Such a neighbour is not
/// circled: circling one robot of a grid of parked robots leads into the next, and a robot
/// between two of them flips from one to the other (each circled on its own side) and stays
/// there. The robot follows its field past them instead, and the safety barrier, with its
/// turn to the left where the field leads into it, takes it round one that stands in the way.
/// A lone parked robot is still circled.
fn in_a_parked_formation(
    me: Approach,
    n: Neighbour,
    sensed: impl Iterator<Item = Neighbour>,
    range: f64,
) -> bool {
    at_rest(me, n)
        && if n.slowest_near.is_nan() {
            sensed.into_iter().any(|m| {
                m.position != n.position
                    && at_rest(me, m)
                    && m.position.distance_squared(n.position) <= range * range
            })
        } else {
            at_rest_at(me, n.slowest_near)
        }
}

/// [`super::cluster`]'s look at a neighbour `n` at rest beside the robot `me`: whether it stands in a
/// parked formation ([`in_a_parked_formation`]), and whether the robot may circle it (not in
/// one, and in the way: [`aside`] below 1).
// Out of line, so that `cluster`'s loop keeps its values in registers.
#[inline(never)]
pub(super) fn at_rest_neighbour(
    me: Approach,
    n: Neighbour,
    sensed: impl Iterator<Item = Neighbour>,
    range: f64,
    safe: f64,
) -> (bool, bool) {
    let in_formation = in_a_parked_formation(me, n, sensed, range);
    (in_formation, !in_formation & (aside(me, n, safe) < 1.0))
}

/// A robot closer than this many safe distances `2·r_ij` to a robot of a parked formation
/// circles no neighbour (let go smoothly over another half safe distance, `squeezed`).
pub const SQUEEZED: f64 = 2.0;

/// How far a robot is squeezed among parked robots, from 0 (no robot of a parked formation,
/// `in_a_parked_formation`, within `(SQUEEZED + ½)·safe` of it) to 1 (one within
/// `SQUEEZED·safe`), by the transition ς of eq. `eq_switch_func` over the nearest one's
/// distance (`nearest_parked2` its square, `+∞` for none).
///
/// Among the robots of a parked formation a robot cannot circle anything: the circle of its
/// virtual obstacle runs through parked robots, the barrier stops it on the way, and the
/// neighbour it circles changes from step to step (another robot that passes, one that makes
/// room, none), each time turning its field round: in grids of slots `3·r_ij` apart, robots
/// would spin on the spot between parked ones (`v` up to the circling speed, `ω` of tens of
/// rad/s) and pairs of them circle each other across the grid. Squeezed, the robot
/// follows its goal field, as it does past the parked robots themselves; the barrier, with its
/// turn to the left, and the parked robots that make room ([`make_room`]) take it through.
pub(super) fn squeezed(nearest_parked2: f64, safe: f64) -> f64 {
    1.0 - crate::obstacle::transition(nearest_parked2.sqrt(), SQUEEZED * safe, 0.5 * safe)
}

/// How far a robot at its goal steps aside for the neighbours that press on it
/// ([`make_room`]), in safe radii `r_ij`.
///
/// Two `r_ij`, so that one robot's step alone opens a lane between slots `3·r_ij` apart: the
/// robot that presses comes at the gap between two parked robots obliquely, closer to one of
/// them than to the other, and only the nearer one steps aside. The gap between two safe
/// discs is one `r_ij` there, and a robot squeezed among parked ones follows its field rather
/// than circling ([`SQUEEZED`]), so the nearer robot's step must open the whole lane. The
/// formation presets in the narrowest grids (spacing 3 to 3.2) depend on it
/// (docs/notes-on-the-paper.md, formations; `tests/formation.rs`).
pub const ROOM: f64 = 2.0;

/// A neighbour closer than this many safe radii `r_ij` presses on a robot at its goal
/// ([`make_room`]); one on the safe distance `2·r_ij` presses it its whole [`ROOM`]. The
/// pressing starts `0.6·r_ij` beyond the safe distance: a robot at its goal steps aside
/// shortly before a passing robot reaches its safe disc, and neighbours parked `2.6·r_ij`
/// apart or more leave each other alone (`tests/formation.rs`).
pub const PRESSED: f64 = 2.6;

/// Where a robot at its goal moves its goal to make room for the neighbours that press on it:
/// away from each neighbour closer than `reach`, by the transition ς of eq. `eq_switch_func`
/// (1 at `safe`, 0 at `reach`), at most `step` in all. The robot steps aside while a
/// neighbour presses on it and returns to its slot and heading once the neighbour has gone:
/// slots closer together than a robot can pass between (`3·r_ij`: the gap between two safe
/// discs is one `r_ij`) open up, the robot that presses is let through, and neighbours parked
/// `reach` apart or more leave each other alone. Decentralised: the positions the robot
/// senses are all it needs.
#[must_use]
pub fn make_room(
    p_i: DVec2,
    neighbours: impl IntoIterator<Item = Neighbour>,
    safe: f64,
    reach: f64,
    step: f64,
) -> DVec2 {
    let push: DVec2 = neighbours
        .into_iter()
        .map(|n| {
            let away = (p_i - n.position).normalize_or_zero();
            let d = p_i.distance(n.position);
            (1.0 - crate::obstacle::transition(d, safe, reach - safe)) * away
        })
        .sum();
    step * push.clamp_length_max(1.0)
}

/// Whether `n` is at rest next to the robot `me` (see [`super::Cluster::at_rest`]).
pub(super) fn at_rest(me: Approach, n: Neighbour) -> bool {
    at_rest_at(me, n.speed)
}

/// Whether a robot moving at `speed` is at rest next to the robot `me`.
fn at_rest_at(me: Approach, speed: f64) -> bool {
    at_rest_beside(speed, me.speed)
}

/// Whether a robot moving at `speed` is at rest next to one moving at `beside` (its
/// [`super::Approach::speed`]). Monotone in `beside` (floating-point sums and products are), so a
/// robot that is not at rest beside the fastest is at rest beside none.
#[inline]
#[must_use]
pub fn at_rest_beside(speed: f64, beside: f64) -> bool {
    speed + SPEED_FLOOR <= AT_REST_RATIO * (beside + SPEED_FLOOR)
}

/// How far a neighbour at rest stands aside of the straight way to the goal, as a transition
/// from 0 (within `safe` of the segment from the robot to its goal: in the way) to 1 (beyond
/// `BLOCKING·safe`: clear). Always 0 for a neighbour that moves. Smooth, so that a robot near
/// the border does not chatter between circling and not circling.
// The test inline; the rest, for a neighbour at rest only, is a call (its goal position and
// transition would otherwise grow `cluster`, which takes it for its nearest neighbour).
#[inline]
pub(super) fn aside(me: Approach, n: Neighbour, safe: f64) -> f64 {
    if !at_rest(me, n) {
        return 0.0;
    }
    aside_at_rest(me, n, safe)
}

/// [`aside`] of a neighbour at rest.
#[inline(never)]
pub(super) fn aside_at_rest(me: Approach, n: Neighbour, safe: f64) -> f64 {
    let way = segment_distance(n.position, me.position, me.goal());
    crate::obstacle::transition(way, safe, (BLOCKING - 1.0) * safe)
}
