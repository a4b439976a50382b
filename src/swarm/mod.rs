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

mod parked;

pub use parked::{at_rest_beside, make_room, BLOCKING, PRESSED, ROOM, SQUEEZED};

use crate::params::Avoidance;
use crate::select::pick;
use glam::DVec2;
use parked::{aside, at_rest, at_rest_neighbour, squeezed};

/// Speeds are compared with this floor added (m/s), so that two robots at rest share their
/// virtual obstacle half and half instead of dividing zero by zero.
pub const SPEED_FLOOR: f64 = 1e-3;

/// A sensed robot: where it is and how fast it moves (`|v|` of its last command).
///
/// Four `f64`, 32 bytes: a simulation's sensing loop copies one such record for every listed
/// robot (some sixteen per robot-step in a jam), so the slowest neighbour is a plain `f64`
/// with a NaN for "unknown" rather than an `Option<f64>` of 16 bytes.
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
    /// taken already, where `|p_i − p̃_o|` would wait on `p̃_o` and then take a square root
    /// of its own (a circling robot's command waits on this distance).
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
    /// Its direction of motion under the goal field (heading times the sign of the speed);
    /// for a robot with a bounded turn rate, its field `Γ_P`, where it goes once it has turned
    /// (docs/notes-on-the-paper.md §10).
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
    /// Not inlined: inlined, its sine and cosine are intrinsics the compiler may hoist and
    /// take speculatively before the loop of [`cluster`] over the neighbours, for every robot
    /// with a neighbour in range, where only one beside a neighbour at rest (rare in a crowd)
    /// needs them. A call is not moved.
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
            // sensed, and the nearest robot of a parked formation (`squeezed`): by a first
            // pass that takes every neighbour for one that moves, and again, out of line, only
            // where one of them turns out to be at rest (rare even in a jam).
            let (nearest2, at, parked) = match nearest_moving(me, sensed.clone(), range) {
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
/// all set: `+∞` or NaN). The nearest one is kept by its place, not as a neighbour: a select
/// of an integer and a minimum, where a neighbour's speed kept alongside would be compiled
/// into a branch.
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
/// Without a call in the loop its values stay in registers: a call in it, even one never
/// taken, as `nearest_exit`'s, puts them on the stack.
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
#[inline(never)]
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
mod tests;
