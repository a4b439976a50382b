//! Collision avoidance among robots through a virtual obstacle (Section V, eqs.
//! `eq_tilde_p_o`, `eq_Gamma_r_co_avoid`, `eq_Gamma_r_perp_co_avoid`, `DVF_Gamma_Qi`).
//!
//! A robot that has neighbours closer than the avoidance range places a virtual obstacle and
//! circles it along `Γ_ri⊥`, the tangent whose projection on its own body Y axis is positive:
//! every robot turns left, so that the two robots of a pair circle their midpoint the same
//! way. With [`Avoidance::Paper`] the virtual obstacle is the centroid of the robot and all
//! those neighbours (the midpoint for two robots); with [`Avoidance::Exit`] it lies between
//! the robot and the one neighbour it is heading for, and the robot leaves the ring once its
//! motion or its field no longer leads to that neighbour ([`cluster`]).

use crate::params::Avoidance;
use crate::select::pick;
use glam::DVec2;

/// Speeds are compared with this floor added (m/s), so that two robots at rest share their
/// virtual obstacle half and half instead of dividing zero by zero.
pub const SPEED_FLOOR: f64 = 1e-3;

/// A sensed robot: where it is and how fast it moves (`|v|` of its last command).
///
/// Four `f64`, 32 bytes: a simulation's sensing loop copies one such record for every listed
/// robot (some sixteen per robot-step in a jam), and a record of 40 bytes (the slowest
/// neighbour as an `Option<f64>`) took the jam's step 0.7 % longer (README, Performance).
#[derive(Clone, Copy, Debug)]
pub struct Neighbour {
    /// Its position `p_j`.
    pub position: DVec2,
    /// Its speed `|v_j|` (m/s).
    pub speed: f64,
    /// The smallest speed of the robots within the avoidance range of this one (at another
    /// position, the sensing robot included: it is never at rest next to itself): `+∞` for
    /// none, [`SLOWEST_UNKNOWN`] (NaN) when the caller does not know it, and then [`cluster`]
    /// looks among the sensing robot's other neighbours (`in_a_parked_formation`: the same
    /// answer whenever they hold every robot within the range of this one). A simulation knows
    /// it, and its lists then reach half as far ([`cluster_reach`]).
    pub slowest_near: f64,
}

/// [`Neighbour::slowest_near`] when the caller does not know it: NaN, which no speed is.
pub const SLOWEST_UNKNOWN: f64 = f64::NAN;

impl Default for Neighbour {
    /// At the origin, at rest, its slowest neighbour unknown.
    fn default() -> Self {
        Self {
            position: DVec2::ZERO,
            speed: 0.0,
            slowest_near: SLOWEST_UNKNOWN,
        }
    }
}

/// The virtual obstacle a robot avoids, and the distance that drives its transition `ς`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cluster {
    /// `p̃_o`: the point the robot circles.
    pub center: DVec2,
    /// The distance fed to `ς` (eq. `eq_switch_func` with `R_c`): `|p_i − p̃_o|`. For
    /// [`Avoidance::Exit`] it is taken as `|p_j − p_i|·w_i/(w_i + w_j)`, the neighbour's
    /// distance times the share of the way at which `p̃_o` stands
    /// ([`virtual_obstacle_between`]): the same length up to rounding (within eight machine
    /// epsilons of the coordinates), from the distance the choice of the neighbour has
    /// measured, where `|p_i − p̃_o|` waits on `p̃_o` and then takes a square root of its own
    /// (a circling robot's command waits on it: README, Performance).
    pub distance: f64,
    /// [`Avoidance::Exit`]: how far the robot is from the avoided neighbour's safe disc,
    /// `d − 2·r_ij`. The controller lets the neighbour go, as it does an obstacle
    /// ([`crate::obstacle::goal_first`]), when the goal is nearer than that. `None` for the
    /// paper's avoidance.
    pub clearance: Option<f64>,
    /// [`Avoidance::Exit`]: how far a neighbour at rest stands aside of the robot's way
    /// (0: in the way, 1: clear); the controller lets it go by as much. 0 for the paper.
    pub aside: f64,
    /// [`Avoidance::Exit`]: how far the robot is squeezed among the robots of a parked
    /// formation (`squeezed`: 1 with one of them within `SQUEEZED·2r_ij`, 0 with none
    /// within `(SQUEEZED + ½)·2r_ij`); the controller lets the neighbour go by as much. 0 for
    /// the paper.
    pub squeezed: f64,
    /// [`Avoidance::Exit`]: the neighbour is at rest next to the robot (it moves at most a
    /// tenth as fast), so the robot goes round it on the side of its own field, as round an
    /// obstacle, rather than by the turn-left rule meant for two robots that both give way.
    pub at_rest: bool,
}

/// A neighbour moving at most this fraction of the robot's speed is at rest for
/// [`Cluster::at_rest`].
pub const AT_REST_RATIO: f64 = 0.1;

/// What a robot knows of itself when it picks the neighbours to avoid.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Approach {
    /// Its position `p_i`.
    pub position: DVec2,
    /// Its direction of motion under the goal field (heading times the sign of the speed).
    pub motion: DVec2,
    /// The field it would follow without robots to avoid (`Γ_P`, world frame).
    pub field: DVec2,
    /// Where its goal lies, as the translation of its error pose, `err.p = R(θ_d)ᵀ(p − p_d)`
    /// ([`crate::se2::Pose::error_to`], `p_d` moved by `make_room` at the goal) ...
    pub goal_error: DVec2,
    /// ... and the goal's attitude `θ_d` on the robot's branch, `θ − θ̃`: [`Approach::goal`]
    /// turns the two into the goal position, only where a neighbour at rest may stand in the
    /// way (in open space no robot needs it, and it costs a sine and a cosine).
    pub goal_attitude: f64,
    /// Its speed `|v_i|` (m/s).
    pub speed: f64,
}

impl Approach {
    /// Its goal position, `p − R(θ_d)·err.p`.
    ///
    /// Not inlined: inlined, its sine and cosine are intrinsics the compiler may take
    /// speculatively, and it took them before the loop of [`cluster`] over the neighbours, for
    /// every robot with a neighbour in range, at rest or not (0.9 per robot-step in the crowd
    /// of 1,000, where a neighbour at rest is rare). A call it cannot move.
    #[inline(never)]
    #[must_use]
    pub fn goal(&self) -> DVec2 {
        self.position - crate::se2::rotate(self.goal_attitude, self.goal_error)
    }
}

/// The virtual obstacle a robot avoids among its sensed `neighbours`, or `None`.
///
/// Only neighbours closer than `range` ([`pair_range`]) count.
///
/// [`Avoidance::Paper`]: the centroid of the robot and all of them (eq. `eq_tilde_p_o`).
///
/// [`Avoidance::Exit`]: one neighbour, the nearest of those that the robot's motion leads
/// towards (the case `θ_r < π/2` of eq. `eq_ob_avoid_VF` applied to each neighbour) that does
/// not stand at rest in a parked formation (`in_a_parked_formation`). A robot
/// moving away from a neighbour cannot collide with it by its own motion, and one that ignored
/// the rule would circle the virtual obstacle forever (docs/notes-on-the-paper.md §5). Its
/// [`Cluster::clearance`] lets a robot settle at a goal next to a parked neighbour.
///
/// The virtual obstacle then lies on the segment between the two robots, dividing it in the
/// ratio of their speeds ([`virtual_obstacle_between`]): the midpoint of eq. `eq_tilde_p_o`
/// for two robots moving alike, the neighbour itself for a neighbour at rest. A robot
/// circling the midpoint of a parked robot would run into it, since that circle passes
/// through the parked robot. Taking the nearest neighbour rather than a centroid keeps the
/// circling direction perpendicular to the closest robot, which the safety barrier guards, so
/// the field never points at it.
#[must_use]
pub fn cluster(
    me: Approach,
    neighbours: impl IntoIterator<Item = Neighbour, IntoIter: Clone>,
    range: f64,
    safe: f64,
    avoidance: Avoidance,
) -> Option<Cluster> {
    let p_i = me.position;
    let sensed = neighbours.into_iter();
    let (center, distance, clearance, at_rest, aside, squeezed) = match avoidance {
        Avoidance::Paper => {
            let center = virtual_obstacle(
                p_i,
                sensed
                    .filter(|n| within(n.position, p_i, range))
                    .map(|n| n.position),
            )?;
            (center, p_i.distance(center), None, false, 0.0, 0.0)
        }
        Avoidance::Exit => {
            // The nearest neighbour to circle, by squared distance and its place among the
            // sensed, and the nearest robot of a parked formation (`squeezed`): natively by a
            // first pass that takes every neighbour for one that moves, and again, out of line,
            // only where one of them turns out to be at rest (in the jam of the crowd of
            // 1,000, one in a thousand). The wasm build takes the second pass alone (the
            // module's budget).
            let moving = if cfg!(target_arch = "wasm32") {
                None
            } else {
                nearest_moving(me, sensed.clone(), range)
            };
            let (nearest2, at, parked) = match moving {
                Some((nearest2, at)) => (nearest2, at, f64::INFINITY),
                None => nearest_exit(me, sensed.clone(), range, safe),
            };
            // A candidate is in range, so its squared distance is finite: `+∞` left means
            // none.
            if nearest2 == f64::INFINITY {
                return None;
            }
            let nearest = sensed.clone().nth(at)?;
            // `nearest2` is its squared distance (a candidate's key): its root is the
            // distance, the same bits.
            let d = nearest2.sqrt();
            let share = share_of_the_way(me.speed, nearest);
            (
                p_i + (nearest.position - p_i) * share,
                d * share,
                Some(d - safe),
                self::at_rest(me, nearest),
                self::aside(me, nearest, safe),
                self::squeezed(parked, safe),
            )
        }
    };
    Some(Cluster {
        center,
        distance,
        clearance,
        at_rest,
        aside,
        squeezed,
    })
}

/// The nearest neighbour to circle among the `sensed` within `range` of the robot `me`: the
/// nearest of those its motion and its field lead towards that `clear` (which sees every
/// neighbour in range, with its squared distance) lets it circle, as its squared distance
/// (`+∞` for none) and its place among the sensed; the first of equally near ones, as `min_by`
/// keeps. [`cluster`]'s two passes ([`nearest_moving`], [`nearest_exit`]).
///
/// By selects, without a branch to mispredict: whether a neighbour is ahead is a coin toss in a
/// crowd, and so is whether it is the nearest so far. The compiler turns a select of one `f64`
/// into a branch unless its condition is a comparison of floats: the condition is made one, by
/// giving a neighbour that is no candidate a key that no comparison takes (its exponent's bits
/// all set: `+∞` or NaN). Measured in the jam of the crowd of 1,000: 6 % less time a step
/// (README, Performance). The nearest one is kept by its place, not as a neighbour: a select
/// of an integer and a minimum, where its speed kept alongside took a branch.
#[inline(always)]
fn nearest_in_range(
    me: Approach,
    sensed: impl Iterator<Item = Neighbour>,
    range: f64,
    mut clear: impl FnMut(Neighbour, f64) -> bool,
) -> (f64, usize) {
    let p_i = me.position;
    let (mut nearest2, mut at) = (f64::INFINITY, 0);
    for (k, n) in sensed.enumerate() {
        if !within(n.position, p_i, range) {
            continue;
        }
        let to = n.position - p_i;
        let d2 = n.position.distance_squared(p_i);
        let candidate = (me.motion.dot(to) > 0.0) & (me.field.dot(to) > 0.0) & clear(n, d2);
        let key = f64::from_bits(
            d2.to_bits() | (u64::from(!candidate).wrapping_neg() & f64::INFINITY.to_bits()),
        );
        let take = key < nearest2;
        nearest2 = pick(take, key, nearest2);
        at = std::hint::select_unpredictable(take, k, at);
    }
    (nearest2, at)
}

/// [`cluster`]'s pass for [`Avoidance::Exit`] where no neighbour within `range` is at rest:
/// [`nearest_in_range`] with every neighbour clear; `None` where some neighbour in range is at
/// rest ([`nearest_exit`] then looks again). The same answer as `nearest_exit` otherwise: a
/// neighbour that moves is neither in a parked formation nor aside.
///
/// Without a call in the loop its values stay in registers (`nearest_exit`'s call, though
/// never taken, put them on the stack: in the jam of the crowd of 1,000, 8 % fewer
/// instructions a step and 3–5 % less time).
fn nearest_moving(
    me: Approach,
    sensed: impl Iterator<Item = Neighbour>,
    range: f64,
) -> Option<(f64, usize)> {
    let mut any_at_rest = false;
    let nearest = nearest_in_range(me, sensed, range, |n, _| {
        any_at_rest |= at_rest(me, n);
        true
    });
    (!any_at_rest).then_some(nearest)
}

/// [`cluster`]'s pass for [`Avoidance::Exit`] where a neighbour within `range` is at rest:
/// [`nearest_in_range`] among those not in a parked formation and in the way (`aside` below
/// 1), and the squared distance of the nearest robot of a parked formation (`+∞` for none). A
/// neighbour at rest is looked at out of line, behind a branch (`at_rest_neighbour`), which in
/// a crowd on its way is predicted.
#[cfg_attr(not(target_arch = "wasm32"), inline(never))]
fn nearest_exit(
    me: Approach,
    sensed: impl Iterator<Item = Neighbour> + Clone,
    range: f64,
    safe: f64,
) -> (f64, usize, f64) {
    let mut parked = f64::INFINITY;
    let (nearest2, at) = nearest_in_range(me, sensed.clone(), range, |n, d2| {
        // Whether it stands in a parked formation, and whether it may be circled (not in one,
        // and in the way: `aside` below 1); a neighbour that moves is neither in a parked
        // formation nor aside.
        let (in_formation, clear) = if at_rest(me, n) {
            at_rest_neighbour(me, n, sensed.clone(), range, safe)
        } else {
            (false, true)
        };
        parked = if in_formation & (d2 < parked) {
            d2
        } else {
            parked
        };
        clear
    });
    (nearest2, at, parked)
}

/// `q.distance(p) <= r`, bit for bit, with a square root only within a relative 1e-9 of the
/// border: below `r²(1 − 1e-9)` (rounded twice, still below `r²`) the distance is below `r`,
/// and above `r²(1 + 1e-9)` it exceeds `r` by far more than the half ulp of its rounding.
#[inline]
fn within(q: DVec2, p: DVec2, r: f64) -> bool {
    let (d2, r2) = (q.distance_squared(p), r * r);
    if d2 <= r2 * (1.0 - 1e-9) {
        true
    } else if d2 > r2 * (1.0 + 1e-9) {
        false
    } else {
        d2.sqrt() <= r
    }
}

/// A neighbour at rest is avoided only if it stands within this many safe distances of the
/// straight way to the goal: one beside the way is no obstacle, and circling it would keep a
/// robot from a goal that lies between parked neighbours (a slot in a crowded formation).
pub const BLOCKING: f64 = 1.5;

/// How far from the robot [`cluster`] looks: its `range`, and with [`Avoidance::Exit`] when
/// its neighbours' [`Neighbour::slowest_near`] is not known (`slowest_known` false) the range
/// again around each neighbour within it (`in_a_parked_formation` then looks for another
/// parked robot near the neighbour among the robot's own). A sensed robot farther than this
/// changes no cluster.
#[must_use]
pub fn cluster_reach(range: f64, avoidance: Avoidance, slowest_known: bool) -> f64 {
    match avoidance {
        Avoidance::Exit if !slowest_known => 2.0 * range,
        _ => range,
    }
}

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

/// [`cluster`]'s look at a neighbour `n` at rest beside the robot `me`: whether it stands in a
/// parked formation ([`in_a_parked_formation`]), and whether the robot may circle it (not in
/// one, and in the way: [`aside`] below 1).
// Out of line natively, so that `cluster`'s loop keeps its values in registers (the crowd of
// 1,000 in its jam, one thread: 2 % less time a step); inlined in the wasm module, smaller.
#[cfg_attr(not(target_arch = "wasm32"), inline(never))]
#[cfg_attr(target_arch = "wasm32", inline)]
fn at_rest_neighbour(
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
/// room, none), each time turning its field round. Seen in grids of slots `3·r_ij` apart: robots
/// spinning on the spot between parked ones for minutes (`v` up to the circling speed, `ω`
/// 15–34 rad/s) and pairs of them circling each other across the grid. Squeezed, the robot
/// follows its goal field, as it does past the parked robots themselves; the barrier, with its
/// turn to the left, and the parked robots that make room ([`make_room`]) take it through.
fn squeezed(nearest_parked2: f64, safe: f64) -> f64 {
    1.0 - crate::obstacle::transition(nearest_parked2.sqrt(), SQUEEZED * safe, 0.5 * safe)
}

/// How far a robot at its goal steps aside for the neighbours that press on it
/// ([`make_room`]), in safe radii `r_ij`.
///
/// One `r_ij` (the gap that slots `3·r_ij` apart leave between two safe discs, so that two
/// robots parting by it each would open a lane) was not enough once a robot squeezed among
/// parked ones stopped circling ([`SQUEEZED`]): the robot that presses comes at the gap
/// obliquely, closer to one of the two than to the other, and only the nearer one steps aside.
/// Seen at spacing 3–3.5: a robot held on the safe disc of a parked robot that had stepped its
/// whole `r_ij`, with the other robot of the gap just out of reach of its pressing, the lane
/// between them 0.04·r_ij short, and the barrier's left turn balancing the turn to the field.
/// Two `r_ij` open the lane at slots `3·r_ij` apart by one robot's step alone; `1.5·r_ij` left
/// the narrowest grids (spacing 3 to 3.2) below 99 % (README, Notes on the paper, formations).
pub const ROOM: f64 = 2.0;

/// A neighbour closer than this many safe radii `r_ij` presses on a robot at its goal
/// ([`make_room`]); one on the safe distance `2·r_ij` presses it its whole [`ROOM`].
/// Starting half the step beyond the safe distance, as the step of one `r_ij` did
/// (`2.75·r_ij` for a step of `1.5·r_ij`), took as many robots into the formations and left
/// more of the dense random scenes outside their slots.
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

/// Whether `n` is at rest next to the robot `me` (see [`Cluster::at_rest`]).
fn at_rest(me: Approach, n: Neighbour) -> bool {
    at_rest_at(me, n.speed)
}

/// Whether a robot moving at `speed` is at rest next to the robot `me`.
fn at_rest_at(me: Approach, speed: f64) -> bool {
    at_rest_beside(speed, me.speed)
}

/// Whether a robot moving at `speed` is at rest next to one moving at `beside` (its
/// [`Approach::speed`]). Monotone in `beside` (floating-point sums and products are), so a
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
fn aside(me: Approach, n: Neighbour, safe: f64) -> f64 {
    if !at_rest(me, n) {
        return 0.0;
    }
    aside_at_rest(me, n, safe)
}

/// [`aside`] of a neighbour at rest.
#[inline(never)]
fn aside_at_rest(me: Approach, n: Neighbour, safe: f64) -> f64 {
    let way = segment_distance(n.position, me.position, me.goal());
    crate::obstacle::transition(way, safe, (BLOCKING - 1.0) * safe)
}

/// Distance from `q` to the segment from `a` to `b`.
#[must_use]
pub fn segment_distance(q: DVec2, a: DVec2, b: DVec2) -> f64 {
    let ab = b - a;
    let t = if ab == DVec2::ZERO {
        0.0
    } else {
        ((q - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0)
    };
    q.distance(a + t * ab)
}

/// The point that robot `i` at `p_i` moving at `speed` and the neighbour `n` circle together:
/// on the segment between them, `p_i + (p_j − p_i)·w_i/(w_i + w_j)` with `w = |v| + SPEED_FLOOR`.
/// Robots circling it at the same angular rate keep their distance (eq. `eq_dot_f_ij` for the
/// midpoint), whatever their speeds.
#[inline]
#[must_use]
pub fn virtual_obstacle_between(p_i: DVec2, speed: f64, n: Neighbour) -> DVec2 {
    p_i + (n.position - p_i) * share_of_the_way(speed, n)
}

/// How far along the segment from a robot moving at `speed` to its neighbour `n` their
/// virtual obstacle stands: `w_i/(w_i + w_j)` ([`virtual_obstacle_between`]).
#[inline]
fn share_of_the_way(speed: f64, n: Neighbour) -> f64 {
    let w_i = speed.abs() + SPEED_FLOOR;
    let w_j = n.speed.abs() + SPEED_FLOOR;
    w_i / (w_i + w_j)
}

/// The virtual obstacle `p̃_o` of robot `i` at `p_i`: the centroid of `p_i` and of the
/// neighbours' positions `others` (eq. `eq_tilde_p_o` for two robots, its convex-combination
/// generalisation for more). `None` without neighbours.
#[must_use]
pub fn virtual_obstacle(p_i: DVec2, others: impl IntoIterator<Item = DVec2>) -> Option<DVec2> {
    let mut sum = p_i;
    let mut n = 1usize;
    for q in others {
        sum += q;
        n += 1;
    }
    (n > 1).then(|| sum / n as f64)
}

/// The avoidance range on the distance between two robots: the transition of the virtual
/// obstacle field starts at `|p_i − p̃_o| = R_c + ε`, which for a pair is
/// `d_ij = 2(R_c + ε)`. Neighbours farther than this never influence a robot.
#[inline]
#[must_use]
pub fn pair_range(avoid_radius: f64, eps: f64) -> f64 {
    2.0 * (avoid_radius + eps)
}

/// `Γ_ri⊥` of eq. `eq_Gamma_r_perp_co_avoid` for a robot at `p_i` with attitude `θ`, given as
/// its heading `e = (cos θ, sin θ)` ([`crate::se2::heading`], which the controller has taken
/// already), circling the virtual obstacle `p_o`: perpendicular to `Γ_ri = p_i − p̃_o`
/// (eq. `eq_Gamma_r_co_avoid`), of the same length, with a positive projection on the body Y
/// axis `R(π/2)e`.
///
/// The paper leaves the case of a zero projection open (the robot's heading already tangent);
/// here the robot then keeps the tangent along its heading.
///
/// With `side = Some(Γ)` the tangent with a positive projection on `Γ` is taken instead (the
/// rule of the obstacle field, for a neighbour at rest), the paper's rule on a tie.
#[inline]
#[must_use]
pub fn tangent_field(p_i: DVec2, e: DVec2, p_o: DVec2, side: Option<DVec2>) -> DVec2 {
    let gamma_r = p_i - p_o;
    let ccw = gamma_r.perp(); // R(π/2)Γ_ri
    if let Some(toward) = side {
        let s = ccw.dot(toward);
        if s != 0.0 {
            return s.signum() * ccw;
        }
    }
    // ⟨σ R(π/2)Γ, R(π/2)e⟩ = σ⟨Γ, e⟩.
    let s = gamma_r.dot(e);
    if s > 0.0 || (s == 0.0 && ccw.dot(e) >= 0.0) {
        ccw
    } else {
        -ccw
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::se2::heading;
    use crate::testing::assert_close;
    use crate::testing::{test, XorShift};
    use std::f64::consts::{FRAC_PI_2, PI};

    fn at(x: f64, y: f64) -> Neighbour {
        Neighbour {
            position: DVec2::new(x, y),
            speed: 1.0,
            slowest_near: SLOWEST_UNKNOWN,
        }
    }

    /// `within` answers as the distance does, at random and on points a few ulps from the
    /// border (where the squared comparison alone would err).
    #[test]
    fn within_is_the_distance_compared() {
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15);
        let mut disagree_squared = 0;
        for k in 0..20_000 {
            let p = DVec2::new(rng.unit() * 100.0 - 50.0, rng.unit() * 100.0 - 50.0);
            let r = 0.5 + rng.unit() * 20.0;
            let angle = rng.unit() * 2.0 * PI;
            let mut q = p + r * crate::maths::from_angle(angle);
            if k % 2 == 0 {
                // Anywhere in a disc of twice the radius.
                q = p + (rng.unit() * 2.0) * (q - p);
            } else {
                // A few ulps off the border, either way.
                let nudge = (k % 7) as i64 - 3;
                q.x = f64::from_bits((q.x.to_bits() as i64 + nudge) as u64);
            }
            assert_eq!(within(q, p, r), q.distance(p) <= r, "q {q}, p {p}, r {r}");
            disagree_squared +=
                usize::from((q.distance_squared(p) <= r * r) != (q.distance(p) <= r));
        }
        // The border cases are real: the plain squared comparison gets some of them wrong.
        assert!(disagree_squared > 0);
    }

    #[test]
    fn exit_avoids_the_nearest_neighbour_ahead_only() {
        let ahead = at(2.0, 0.0);
        let behind = [at(-7.0, 0.5), at(-7.0, -0.5)];
        let all = [at(3.0, 1.0), ahead, behind[0], behind[1]];
        let me = Approach {
            position: DVec2::ZERO,
            motion: DVec2::X,
            field: DVec2::X,
            goal_error: DVec2::new(-20.0, 0.0),
            goal_attitude: 0.0,
            speed: 1.0,
        };
        // Paper: the centroid of all five, behind the robot.
        let c = cluster(me, all, 8.0, 1.0, Avoidance::Paper).unwrap();
        assert_close!(c.center.x, -1.8, 1e-15);
        assert_close!(c.center.y, 0.2, 1e-15);
        assert_close!(c.distance, c.center.length(), 1e-15);
        // Exit: only the nearest neighbour ahead, at the midpoint (same speeds).
        let c = cluster(me, all, 8.0, 1.0, Avoidance::Exit).unwrap();
        assert_eq!(c.center, DVec2::new(1.0, 0.0));
        assert_eq!(c.distance, 1.0);
        // Moving away from everyone: nothing to avoid.
        assert_eq!(cluster(me, behind, 8.0, 1.0, Avoidance::Exit), None);
        // Out of range.
        assert_eq!(
            cluster(me, [at(9.0, 0.0)], 8.0, 1.0, Avoidance::Paper),
            None
        );
        // The clearance to the neighbour's safe disc (2 − 1) lets a settling robot go.
        assert_eq!(c.clearance, Some(1.0));
        let c = cluster(me, all, 8.0, 1.0, Avoidance::Paper).unwrap();
        assert_eq!(c.clearance, None);
    }

    /// `cluster`'s first pass for neighbours that move gives the answer of its pass over all
    /// (the nearest to circle, by place and squared distance, no parked robot), and leaves the
    /// answer to it where a neighbour in range is at rest: random crowds around a robot, with
    /// equally near neighbours, neighbours on the range's border and robots at rest among them.
    #[test]
    fn the_pass_for_neighbours_that_move_is_the_pass_over_all() {
        let mut rng = crate::testing::XorShift(0x2545_F491_4F6C_DD1D);
        let (range, safe) = (8.0, 2.0);
        let (mut agreed, mut left) = (0, 0);
        for k in 0..5_000 {
            let me = Approach {
                motion: crate::maths::from_angle(rng.unit() * 2.0 * PI),
                field: crate::maths::from_angle(rng.unit() * 2.0 * PI),
                ..eastbound()
            };
            let count = 1 + (rng.next_u64() % 12) as usize;
            let mut neighbours: Vec<Neighbour> = (0..count)
                .map(|_| Neighbour {
                    // On a coarse lattice, so that some are equally near; some on the border.
                    position: if rng.unit() < 0.1 {
                        range * crate::maths::from_angle(rng.unit() * 2.0 * PI)
                    } else {
                        DVec2::new(
                            (rng.unit() * 20.0 - 10.0).round(),
                            (rng.unit() * 20.0 - 10.0).round(),
                        )
                    },
                    speed: 1.0 + rng.unit(),
                    slowest_near: SLOWEST_UNKNOWN,
                })
                .collect();
            if k % 3 == 0 {
                let j = (rng.next_u64() as usize) % count;
                neighbours[j].speed = 0.0;
            }
            let exit = nearest_exit(me, neighbours.iter().copied(), range, safe);
            match nearest_moving(me, neighbours.iter().copied(), range) {
                Some((nearest2, at)) => {
                    agreed += 1;
                    assert_eq!(nearest2.to_bits(), exit.0.to_bits(), "{neighbours:?}");
                    if nearest2.is_finite() {
                        assert_eq!(at, exit.1, "{neighbours:?}");
                    }
                    assert_eq!(exit.2, f64::INFINITY);
                }
                None => {
                    left += 1;
                    assert!(neighbours
                        .iter()
                        .any(|n| n.speed == 0.0 && within(n.position, me.position, range)));
                }
            }
        }
        // Both cases seen often.
        assert!(agreed > 1_000 && left > 500, "{agreed} {left}");
    }

    /// A robot at the origin heading east at 2 m/s to a goal 10 m ahead.
    fn eastbound() -> Approach {
        Approach {
            position: DVec2::ZERO,
            motion: DVec2::X,
            field: DVec2::X,
            goal_error: DVec2::new(-10.0, 0.0),
            goal_attitude: 0.0,
            speed: 2.0,
        }
    }

    /// A neighbour at rest beside the straight way to the goal is let go (a slot between
    /// parked robots can be reached); one in the way is not; a moving one never is.
    #[test]
    fn a_parked_neighbour_aside_of_the_way_is_let_go() {
        let me = eastbound();
        let parked = |y: f64| Neighbour {
            position: DVec2::new(5.0, y),
            speed: 0.0,
            slowest_near: SLOWEST_UNKNOWN,
        };
        let safe = 2.0;
        let c = |y| cluster(me, [parked(y)], 8.0, safe, Avoidance::Exit).unwrap();
        assert_eq!(c(0.5).aside, 0.0); // in the way
        assert_eq!(c(2.0).aside, 0.0); // exactly the safe distance from the way
        assert!(c(2.5).aside > 0.0 && c(2.5).aside < 1.0); // the smooth band
        assert!(cluster(me, [parked(3.0)], 8.0, safe, Avoidance::Exit).is_none()); // clear
        let moving = Neighbour {
            speed: 2.0,
            slowest_near: SLOWEST_UNKNOWN,
            ..parked(3.0)
        };
        assert_eq!(
            cluster(me, [moving], 8.0, safe, Avoidance::Exit)
                .unwrap()
                .aside,
            0.0
        );
        assert_close!(
            segment_distance(DVec2::new(5.0, 3.0), DVec2::ZERO, me.goal()),
            3.0,
            0.0
        );
        assert_close!(
            segment_distance(DVec2::new(13.0, 4.0), DVec2::ZERO, me.goal()),
            5.0,
            0.0
        );
        assert_close!(
            segment_distance(DVec2::new(1.0, 1.0), DVec2::ZERO, DVec2::ZERO),
            2f64.sqrt(),
            0.0
        );
    }

    /// A parked neighbour in the way is circled when it stands alone and passed when another
    /// parked robot stands within the range of it (a parked formation); a moving one is always
    /// circled.
    #[test]
    fn parked_formations_are_passed() {
        let me = eastbound();
        let parked = |x: f64, y: f64| Neighbour {
            position: DVec2::new(x, y),
            speed: 0.0,
            slowest_near: SLOWEST_UNKNOWN,
        };
        let c = |ns: &[Neighbour]| cluster(me, ns.iter().copied(), 8.0, 2.0, Avoidance::Exit);
        assert!(c(&[parked(4.0, 0.5)]).is_some());
        assert!(c(&[parked(4.0, 0.5), parked(4.0, 5.5)]).is_none());
        // Another parked robot beyond the range of it: alone again.
        assert!(c(&[parked(4.0, 0.5), parked(4.0, 9.0)]).is_some());
        let moving = Neighbour {
            speed: 2.0,
            slowest_near: SLOWEST_UNKNOWN,
            ..parked(4.0, 0.5)
        };
        assert!(c(&[moving, parked(4.0, 5.5)]).is_some());
    }

    /// A robot near a robot of a parked formation lets go of the moving neighbour it would
    /// circle: wholly within `SQUEEZED` safe distances of it, not at all beyond another half;
    /// a lone parked robot, or robots that move, squeeze nothing.
    #[test]
    fn squeezed_among_parked_robots_a_robot_circles_no_one() {
        let me = eastbound();
        let safe = 2.0;
        let moving = Neighbour {
            speed: 2.0,
            ..at(4.0, 0.5)
        };
        // A parked robot behind the robot (never circled itself), `d` away, with another
        // parked robot 3 m beyond it.
        let parked = |d: f64, speed: f64| {
            [-d, -d - 3.0].map(|x| Neighbour {
                position: DVec2::new(x, 0.0),
                speed,
                slowest_near: SLOWEST_UNKNOWN,
            })
        };
        let squeezed = |d: f64, speed: f64, avoidance| {
            let [a, b] = parked(d, speed);
            cluster(me, [moving, a, b], 8.0, safe, avoidance)
                .unwrap()
                .squeezed
        };
        assert_eq!(squeezed(0.9 * SQUEEZED * safe, 0.0, Avoidance::Exit), 1.0);
        assert_eq!(squeezed(SQUEEZED * safe, 0.0, Avoidance::Exit), 1.0);
        let band = squeezed((SQUEEZED + 0.25) * safe, 0.0, Avoidance::Exit);
        assert!(band > 0.0 && band < 1.0, "{band}");
        assert_eq!(squeezed((SQUEEZED + 0.6) * safe, 0.0, Avoidance::Exit), 0.0);
        // Parked robots that move (as fast as the robot) are no formation.
        assert_eq!(squeezed(SQUEEZED * safe, 2.0, Avoidance::Exit), 0.0);
        // A lone parked robot.
        let [lone, _] = parked(SQUEEZED * safe, 0.0);
        let c = cluster(me, [moving, lone], 8.0, safe, Avoidance::Exit).unwrap();
        assert_eq!(c.squeezed, 0.0);
        // The paper's avoidance has no such rule.
        assert_eq!(squeezed(SQUEEZED * safe, 0.0, Avoidance::Paper), 0.0);
    }

    /// A robot steps away from a neighbour that presses on it, by at most the step in all,
    /// and leaves alone the neighbours `reach` away or more.
    #[test]
    fn a_robot_makes_room_for_a_neighbour_that_presses_on_it() {
        let (safe, reach, step) = (2.0, PRESSED, ROOM);
        let room = |ns: &[Neighbour]| make_room(DVec2::ZERO, ns.iter().copied(), safe, reach, step);
        assert_eq!(room(&[at(-2.0, 0.0)]), DVec2::new(ROOM, 0.0));
        assert_eq!(room(&[at(0.0, PRESSED)]), DVec2::ZERO);
        assert_eq!(room(&[at(3.0, 0.0), at(0.0, -9.0)]), DVec2::ZERO);
        let between = room(&[at(2.3, 0.0)]);
        assert!(between.x < 0.0 && between.x > -ROOM && between.y == 0.0);
        // Pressed from two sides at once: still at most one step.
        let both = room(&[at(-2.0, 0.0), at(0.0, -2.0)]);
        // One rounding of the length of (step/√2, step/√2).
        assert_close!(both.length(), ROOM, 1e-15);
        assert_close!(both.x, both.y, 1e-15);
    }

    /// A neighbour at rest is circled about itself, one moving alike about the midpoint.
    #[test]
    fn the_virtual_obstacle_divides_the_gap_by_speed() {
        let p = DVec2::ZERO;
        let parked = Neighbour {
            position: DVec2::new(4.0, 0.0),
            speed: 0.0,
            slowest_near: SLOWEST_UNKNOWN,
        };
        let o = virtual_obstacle_between(p, 2.0, parked);
        assert_close!(o.x, 4.0 * 2.001 / 2.002, 1e-12);
        let alike = Neighbour {
            speed: 2.0,
            slowest_near: SLOWEST_UNKNOWN,
            ..parked
        };
        assert_eq!(
            virtual_obstacle_between(p, 2.0, alike),
            DVec2::new(2.0, 0.0)
        );
        // Both at rest: the midpoint, not 0/0.
        assert_eq!(
            virtual_obstacle_between(p, 0.0, parked),
            DVec2::new(2.0, 0.0)
        );
    }

    /// [`Cluster::distance`] with [`Avoidance::Exit`], taken as the neighbour's distance times
    /// the share of the way, is the distance from the robot to the virtual obstacle, within
    /// the rounding of the latter: `|p_i − p̃_o|` rounds the positions (about an ulp of the
    /// largest coordinate, twice, for `p̃_o` and for the difference) where the product rounds
    /// only lengths of the order of `d` (three or four half-ulps of `d`). Eight machine
    /// epsilons of the coordinates and of `d` cover both, with room.
    #[test]
    fn the_distance_to_the_virtual_obstacle_is_a_share_of_the_neighbours() {
        let mut rng = XorShift(0x2545_F491_4F6C_DD1D);
        for _ in 0..10_000 {
            let scale = [1.0, 100.0, 10_000.0][(rng.unit() * 3.0) as usize];
            let p = DVec2::new(rng.range(-scale, scale), rng.range(-scale, scale));
            let d = rng.range(0.05, 7.95);
            let to = heading(rng.heading());
            // Both moving (a neighbour at rest aside of the way could be let go), the robot
            // heading for it: it is the one circled.
            let speed = rng.range(0.0, 20.0);
            let n = Neighbour {
                position: p + d * to,
                speed: speed * rng.range(0.2, 2.2),
                slowest_near: f64::INFINITY,
            };
            let me = Approach {
                position: p,
                motion: to,
                field: to,
                goal_error: DVec2::new(-1000.0, 0.0),
                goal_attitude: 0.0,
                speed,
            };
            let c = cluster(me, [n], 8.0, 2.0, Avoidance::Exit).expect("the neighbour is ahead");
            let tol =
                8.0 * f64::EPSILON * (p.abs().max_element() + n.position.abs().max_element() + d);
            assert_close!(c.distance, p.distance(c.center), tol);
        }
    }

    #[test]
    fn virtual_obstacle_is_the_midpoint_and_the_centroid() {
        let a = DVec2::new(0.0, 0.0);
        let b = DVec2::new(4.0, 2.0);
        assert_eq!(virtual_obstacle(a, [b]), Some(DVec2::new(2.0, 1.0)));
        let c = DVec2::new(-1.0, 7.0);
        assert_eq!(virtual_obstacle(a, [b, c]), Some(DVec2::new(1.0, 3.0)));
        assert_eq!(virtual_obstacle(a, []), None);
    }

    /// Two robots heading at each other both turn left and circle their midpoint the same
    /// way, so their distance is constant along the field (eq. `eq_dot_f_ij`).
    #[test]
    fn head_on_pair_circles_the_same_way() {
        let pi = DVec2::new(-2.0, 0.0);
        let pj = DVec2::new(2.0, 0.0);
        let o = virtual_obstacle(pi, [pj]).unwrap();
        let gi = tangent_field(pi, heading(0.0), o, None);
        let gj = tangent_field(pj, heading(PI), o, None);
        // Positive projection on each body Y axis.
        assert!(gi.dot(heading(FRAC_PI_2)) > 0.0);
        assert!(gj.dot(heading(PI + FRAC_PI_2)) > 0.0);
        // d/dt |p_i − p_j|² = 2(p_i − p_j)ᵀ(Γ_i − Γ_j) = 0.
        assert_close!((pi - pj).dot(gi - gj), 0.0, 1e-12);
        assert_close!(gi.length(), 2.0, 1e-15);
    }

    #[test]
    fn tangent_is_perpendicular_to_the_radius() {
        for k in 0..24 {
            let t = k as f64 * 0.27;
            let p = DVec2::new(1.0, 2.0);
            let g = tangent_field(p, heading(t), DVec2::new(-0.5, 0.3), None);
            assert_close!(g.dot(p - DVec2::new(-0.5, 0.3)), 0.0, 1e-12);
            assert!(g.dot(heading(t + FRAC_PI_2)) >= 0.0);
        }
    }
}
