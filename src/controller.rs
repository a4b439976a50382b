//! Controllers that turn the dynamic vector field into velocities (eqs. `eq_fully_controller`,
//! `eq_nonholo_controller`, `eq_nonholo_controller_ob_avoid`, `eq_nonholo_controller_co_avoid`).
//!
//! [`command`] is the one call a robot needs: its pose, its goal, the obstacles and the
//! neighbours it senses in, `(v, ω)` out.
//!
//! How the paper's three controllers combine (the paper gives them separately; Example 4 uses
//! both kinds of avoidance at once): with `S = Π ς_i` over the obstacles and `ς_c` for the
//! virtual obstacle (1 when there is none),
//!
//! ```text
//! Γ_P = S Γ̃_d + Σ (1 − ς_i) Γ_oi                       (eq. VF_all_V3)
//! Γ   = ς_c Γ_P + (1 − ς_c) Γ_ri⊥                        (eq. DVF_Gamma_Qi, with Γ_P for Γ̃_d)
//! v   = k_v ς_c Γ_Pᴮˣ + (1 − ς_c) v_c                     (eq. nonholo_controller_co_avoid)
//! ω   = −k_ω ς_c S θ̃ + k_a δ
//! δ   = fade(|Γ|)·atan(Γᴮʸ/Γᴮˣ)   when ς_c = 1             (eq. nonholo_controller_ob_avoid)
//!     = atan2(Γᴮʸ, Γᴮˣ)            when ς_c < 1             (eq. angle_delta_2)
//! ```
//!
//! Each reduces to the paper's controller in the paper's setting: no obstacle and no
//! neighbour gives eq. `eq_nonholo_controller`, obstacles only give
//! eq. `eq_nonholo_controller_ob_avoid`, neighbours only give
//! eq. `eq_nonholo_controller_co_avoid`.
//!
//! With `"avoidance": "exit"` (the default) an obstacle or neighbour farther than the goal is
//! let go: `ς` is raised to `1 − (1 − ς)(1 − g)` with `g` from
//! [`crate::obstacle::goal_first`] (and, for a neighbour at rest, by how far it stands aside of
//! the way); see [`crate::obstacle::blend`] and [`crate::swarm::cluster`]. A robot at its goal
//! lets go of every neighbour and moves its goal aside for those that press on it
//! ([`crate::swarm::make_room`]). The speed is then made safe by [`crate::safety::filter`] in
//! the simulator.

use crate::field::{goal_field_body, goal_field_body_turned};
use crate::obstacle::{blend, goal_first, transition, Obstacle};
use crate::params::{Avoidance, Params};
use crate::se2::{heading, unrotate, unrotate_by, Pose};
use crate::swarm::{
    cluster, make_room, pair_range, tangent_field, Approach, Neighbour, PRESSED, ROOM,
};
use glam::DVec2;

/// Velocity inputs of a unicycle (eq. `eq_kine_nonho`).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Command {
    /// Forward speed `v_x` along the heading (negative: backwards).
    pub v: f64,
    /// Angular velocity `ω` (rad/s, counter-clockwise positive).
    pub omega: f64,
}

/// Everything the controller computed on the way to a [`Command`], for drawing and testing.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Evaluation {
    /// The command, saturated when the parameters ask for it.
    pub command: Command,
    /// The blended field `Γ` in the world frame.
    pub field: DVec2,
    /// The obstacle-free goal field `Γ̃_d` in the world frame.
    pub goal_field: DVec2,
    /// `Π ς_i` over the obstacles (1: no obstacle influence).
    pub obstacle_keep: f64,
    /// `ς_c` of the virtual obstacle (1: not avoiding robots).
    pub robot_keep: f64,
    /// The virtual obstacle, when neighbours are within the avoidance range.
    pub virtual_obstacle: Option<DVec2>,
}

/// `atan(y/x)` with the limits the ratio takes: `±π/2` for `x = 0`, and 0 for a zero vector.
/// Range `[−π/2, π/2]`: the robot may drive backwards (docs/notes-on-the-paper.md §3).
#[inline]
#[must_use]
pub fn atan_ratio(y: f64, x: f64) -> f64 {
    if x == 0.0 {
        if y == 0.0 {
            0.0
        } else {
            std::f64::consts::FRAC_PI_2.copysign(y)
        }
    } else {
        crate::maths::atan(y / x)
    }
}

/// The fade `n²/(n² + g²)` of the alignment term for a field of magnitude `n ≥ g`, and 0
/// below `g` (docs/notes-on-the-paper.md §3). 1 far from the goal, 0 once the field is
/// smaller than `g`: there the robot only turns, `ω = −k_ω θ̃`, to its goal heading.
///
/// The step from ½ to 0 at `n = g` is deliberate. A fade that went smoothly to 0 would pass
/// through `2k_ω|θ̃|/(k_a·π)` for every heading error, and where it does a robot whose field is
/// perpendicular to its heading (so `v = 0`) balances `k_ω θ̃` against `k_a·fade·π/2`: it sits
/// on its goal position with its heading off (in formations, a robot that reaches its slot
/// after circling others with its heading error unattended would stay a few hundredths of a
/// radian off). With the step no such balance exists while `k_a > 4k_ω` (the defaults: 10 and 1).
/// `n = g` lies far inside `tol_position`, where the field is a tiny correction.
#[inline]
#[must_use]
pub fn alignment_fade(n: f64, g: f64) -> f64 {
    let n2 = n * n;
    if n2 == 0.0 || n < g {
        0.0
    } else {
        n2 / (n2 + g * g)
    }
}

/// The fully actuated controller of eq. `eq_fully_controller`: body velocities
/// `(v_x, v_y) = k_v Γ̃_dᴮ` and `ω = −k_ω θ̃` for the error pose `err`.
#[inline]
#[must_use]
pub fn fully_actuated(params: &Params, err: Pose) -> (DVec2, f64) {
    (
        params.k_v * goal_field_body(err),
        -params.k_omega * err.theta,
    )
}

/// The command of a unicycle at `pose` with goal `goal`, sensing `obstacles` and the
/// positions of its `neighbours` (what it senses: the caller applies the sensing radius).
/// The heading error is taken on the principal branch.
///
/// ```
/// use dvf::{command, Params, Pose};
/// let cmd = command(&Params::default(), Pose::new(0.0, 0.0, 0.0), Pose::new(0.0, 40.0, 0.0), &[], &[]);
/// assert!(cmd.omega > 0.0); // the goal is to the left: turn left
/// ```
#[must_use]
pub fn command(
    params: &Params,
    pose: Pose,
    goal: Pose,
    obstacles: &[Obstacle],
    neighbours: &[DVec2],
) -> Command {
    let err = pose.error_to(goal);
    // Without speeds every robot counts as moving alike: the paper's midpoint.
    let sensed = neighbours.iter().map(|&position| Neighbour {
        position,
        speed: 0.0,
        slowest_near: crate::swarm::SLOWEST_UNKNOWN,
    });
    evaluate(params, pose, err, 0.0, obstacles, sensed).command
}

/// The controller with the heading error `err.theta` on a branch of the caller's choice
/// (see [`crate::se2::continue_branch`]); `err` is `pose.error_to(goal)` otherwise. `speed`
/// is the robot's own `|v|` (its last command) and each neighbour carries its own: they place
/// the virtual obstacle ([`crate::swarm::cluster`]).
#[must_use]
pub fn evaluate<'a, I>(
    params: &Params,
    pose: Pose,
    err: Pose,
    speed: f64,
    obstacles: I,
    neighbours: impl IntoIterator<Item = Neighbour, IntoIter: Clone>,
) -> Evaluation
where
    I: IntoIterator<Item = &'a Obstacle>,
    I::IntoIter: Clone,
{
    evaluate_facing(
        params,
        pose,
        Facing::of(pose.theta, err.theta),
        err,
        speed,
        obstacles,
        neighbours,
    )
}

/// A robot's heading and heading error as unit vectors: what the controller takes of its
/// attitude `θ` besides the angles themselves, given once so that a step, which has them at
/// hand, takes no sine or cosine for them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Facing {
    /// The heading `h = (cos θ, sin θ)` ([`heading`]), which rotates the body frame into the
    /// world's.
    pub heading: DVec2,
    /// `(cos θ̃, sin θ̃)` of the heading error, from which the log map takes `α(θ̃)`
    /// ([`crate::se2::alpha_turned`]).
    pub error: DVec2,
}

impl Facing {
    /// The vectors of heading `theta` and heading error `error` (rad), by their sines and
    /// cosines.
    #[must_use]
    pub fn of(theta: f64, error: f64) -> Self {
        Self {
            heading: heading(theta),
            error: heading(error),
        }
    }
}

/// [`evaluate`] with the robot's heading and heading error as unit vectors (`facing`) taken
/// by the caller: a step keeps the heading from step to step and needs it again for the
/// safety barrier ([`crate::safety::filter_facing`]), and has the heading error's by rotating
/// it back by the goal's heading.
#[must_use]
pub fn evaluate_facing<'a, I>(
    params: &Params,
    pose: Pose,
    facing: Facing,
    err: Pose,
    speed: f64,
    obstacles: I,
    neighbours: impl IntoIterator<Item = Neighbour, IntoIter: Clone>,
) -> Evaluation
where
    I: IntoIterator<Item = &'a Obstacle>,
    I::IntoIter: Clone,
{
    let theta = pose.theta;
    let eps = params.transition_width;
    let neighbours = neighbours.into_iter();
    // A robot at its goal (within r_ij, let go smoothly by 2·r_ij) makes room for the
    // neighbours that press on it (`make_room`, Exit only): its goal moves by `room`, so that
    // err.p = R(θ_d)ᵀ(p − p_d − room) with θ_d = θ − θ̃.
    // Away from its goal (`at_goal` = 0) the shift is exactly zero: skipped.
    let r = params.safe_radius;
    let at_goal = 1.0 - transition(err.p.length(), r, r);
    let err = if params.avoidance == Avoidance::Exit && at_goal > 0.0 {
        let room = at_goal * make_room(pose.p, neighbours.clone(), 2.0 * r, PRESSED * r, ROOM * r);
        Pose {
            p: err.p - unrotate(theta - err.theta, room),
            ..err
        }
    } else {
        err
    };
    let h = facing.heading;
    let goal_body = goal_field_body_turned(err, facing.error);
    let goal_world = h.rotate(goal_body);

    // Direction of motion under the goal field: the heading, reversed when the robot would
    // drive backwards (θ_r is measured against the motion, docs/notes-on-the-paper.md §4).
    let motion = if goal_body.x < 0.0 { -h } else { h };
    let to_goal = err.p.length();
    let exits = (params.avoidance == Avoidance::Exit).then_some(to_goal);
    let (gp, keep_o, on_surface) = blend(pose.p, motion, goal_world, obstacles, eps, exits);

    let range = pair_range(params.avoid_radius, eps);
    let me = Approach {
        position: pose.p,
        // With a bounded turn rate the heading lags the field by up to π/ω_max seconds, and
        // where it points is no guide to where the robot goes: the exit asks where the field
        // leads (docs/notes-on-the-paper.md §10).
        motion: if params.omega_max.is_some() {
            gp
        } else {
            motion
        },
        field: gp,
        // err.p = R(θ_d)ᵀ(p − p_d) with θ_d = θ − θ̃.
        goal_error: err.p,
        goal_attitude: theta - err.theta,
        // On an obstacle's surface the barrier, not the robot, may hold it still: its speed
        // then counts as at least the circling speed `avoid_speed`, so that it still tells a
        // parked neighbour from one that moves (by its speed alone, every neighbour would move
        // as fast as it does).
        speed: if on_surface {
            speed.max(params.avoid_speed)
        } else {
            speed
        },
    };
    let vo = cluster(
        me,
        neighbours,
        range,
        2.0 * params.safe_radius,
        params.avoidance,
    );
    // The virtual obstacle and its ς_c, while it has any influence (ς_c < 1).
    let avoiding = vo
        .map(|c| {
            let s = transition(c.distance, params.avoid_radius, eps);
            // Let go of a neighbour whose safe disc is farther than the goal (Exit only).
            let go = c.clearance.map_or(0.0, |cl| goal_first(cl, to_goal, eps));
            // A robot at its goal (within ½·r_ij, let go smoothly by r_ij) circles no
            // neighbour (Exit only): it leaves the avoidance to the neighbour, the barrier and
            // `make_room`.
            // Circling a point next to its slot with a vanishing goal field makes its ω jump
            // by the tangent's whole angle whenever the cluster changes, and robots at their
            // goals in a tight grid then turn one way and the other from step to step.
            let half = 0.5 * params.safe_radius;
            let arrived = match params.avoidance {
                Avoidance::Exit => 1.0 - transition(to_goal, half, half),
                Avoidance::Paper => 0.0,
            };
            // Squeezed among parked robots, a robot circles no neighbour either (Exit only,
            // `swarm::squeezed`).
            let go = 1.0 - (1.0 - go) * (1.0 - c.aside) * (1.0 - c.squeezed) * (1.0 - arrived);
            let side = c.at_rest.then_some(gp);
            (c.center, 1.0 - (1.0 - s) * (1.0 - go), side)
        })
        .filter(|&(_, s, _)| s < 1.0);

    let gp_body = unrotate_by(h, gp);
    let (field, v, delta, keep_c) = match avoiding {
        Some((o, keep_c, side)) => {
            let t = tangent_field(pose.p, h, o, side);
            let field = keep_c * gp + (1.0 - keep_c) * t;
            let fb = unrotate_by(h, field);
            let v = params.k_v * keep_c * gp_body.x + (1.0 - keep_c) * params.avoid_speed;
            (field, v, crate::maths::atan2(fb.y, fb.x), keep_c)
        }
        None => {
            let fade = alignment_fade(gp_body.length(), params.align_fade);
            let delta = fade * atan_ratio(gp_body.y, gp_body.x);
            (gp, params.k_v * gp_body.x, delta, 1.0)
        }
    };
    let omega = -params.k_omega * keep_c * keep_o * err.theta + params.k_a * delta;

    Evaluation {
        command: saturate(params, Command { v, omega }),
        field,
        goal_field: goal_world,
        obstacle_keep: keep_o,
        robot_keep: keep_c,
        virtual_obstacle: avoiding.map(|(o, _, _)| o),
    }
}

/// The command `c` within the robot's limits `|ω| ≤ ω_max` and `|v| ≤ v_max`, when they are
/// set (docs/notes-on-the-paper.md §10).
///
/// A turn rate beyond `ω_max` scales the whole command by `s = ω_max/|ω|`: `(s·v, s·ω)` has the
/// curvature `ω/v` the field prescribes, so the robot keeps to the path of the unlimited
/// controller and only takes longer along it (for one robot among static obstacles, the same
/// integral curve in time rescaled by `s`). The speed is then clamped into `v_max` with the
/// turn rate kept: the heading loop `ω` is the paper's, and a slower robot only turns more per
/// metre than the field asks, never less. Without `ω_max` this is the clamp of `v` alone, and
/// without either the command itself.
#[inline]
#[must_use]
pub fn saturate(params: &Params, c: Command) -> Command {
    let (v, omega) = match params.omega_max {
        Some(m) if c.omega.abs() > m => (c.v * (m / c.omega.abs()), c.omega.clamp(-m, m)),
        _ => (c.v, c.omega),
    };
    Command {
        v: params.v_max.map_or(v, |m| v.clamp(-m, m)),
        omega,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::se2::log;
    use crate::testing::test;
    use std::f64::consts::{FRAC_PI_2, PI};

    #[test]
    fn atan_ratio_limits() {
        assert_eq!(atan_ratio(1.0, 0.0), FRAC_PI_2);
        assert_eq!(atan_ratio(-1.0, 0.0), -FRAC_PI_2);
        assert_eq!(atan_ratio(0.0, 0.0), 0.0);
        // Backwards: the angle of the line, not of the ray.
        assert!((atan_ratio(1.0, -1.0) + PI / 4.0).abs() < 1e-15);
    }

    #[test]
    fn fade_is_one_far_and_zero_at_the_goal() {
        assert_eq!(alignment_fade(0.0, 1e-3), 0.0);
        assert!(alignment_fade(1.0, 1e-3) > 1.0 - 1e-6);
        assert!((alignment_fade(1e-3, 1e-3) - 0.5).abs() < 1e-15);
        // Below g the robot only turns.
        assert_eq!(alignment_fade(0.999e-3, 1e-3), 0.0);
    }

    /// The fully actuated loop (eq. `eq_fully_controller`) makes the Lyapunov function
    /// Φ = ½⟨Υ̃, Υ̃⟩ decrease at every step (proof of Theorem 1), from poses on both sides of
    /// ±π and with unequal gains.
    #[test]
    fn lyapunov_decreases_under_the_fully_actuated_loop() {
        for params in [
            Params::default(),
            Params {
                k_v: 1.0,
                k_omega: 1.0,
                ..Params::default()
            },
        ] {
            for start in [
                Pose::new(0.0, 40.0, 0.0),
                Pose::new(-30.0, 10.0, 3.0),
                Pose::new(12.0, -7.0, -3.1),
            ] {
                let goal = Pose::new(2.0, 1.0, 0.5);
                let mut h = start;
                let initial = log(h.error_to(goal)).lyapunov();
                let mut prev = initial;
                let dt = 1e-3;
                for _ in 0..20_000 {
                    let err = h.error_to(goal);
                    let (vb, w) = fully_actuated(&params, err);
                    // Exact integration of a constant body twist over dt: h ← h·exp(dt·η).
                    h = h.compose(crate::se2::exp(crate::se2::Twist {
                        phi: dt * vb,
                        theta: dt * w,
                    }));
                    let now = log(h.error_to(goal)).lyapunov();
                    assert!(now <= prev, "Φ rose from {prev} to {now}");
                    prev = now;
                }
                // Φ decays at least like e^{−2·min(k_v, k_ω)·t}: after 20 s at k_v = 0.5 that
                // is e^{−20} ≈ 2e-9 of the start; 1e-6 leaves room for the transient.
                assert!(prev < 1e-6 * initial, "Φ ended at {prev} from {initial}");
            }
        }
    }

    #[test]
    fn saturation_clamps_when_set() {
        let p = Params {
            v_max: Some(2.0),
            omega_max: Some(0.5),
            ..Params::default()
        };
        let c = saturate(
            &p,
            Command {
                v: -7.0,
                omega: 3.0,
            },
        );
        // The turn rate 3 is six times ω_max: the speed drops by the same factor to −7/6,
        // within v_max, and keeps the curvature ω/v (to the round-off of one division).
        assert_eq!(c.omega, 0.5);
        crate::testing::assert_close!(c.v, -7.0 / 6.0, 1e-15);
        crate::testing::assert_close!(c.omega / c.v, 3.0 / -7.0, 1e-15);
        let c = saturate(
            &p,
            Command {
                v: -70.0,
                omega: 3.0,
            },
        );
        assert_eq!(
            c,
            Command {
                v: -2.0,
                omega: 0.5
            }
        );
        let c = saturate(
            &Params::default(),
            Command {
                v: -7.0,
                omega: 3.0,
            },
        );
        assert_eq!(
            c,
            Command {
                v: -7.0,
                omega: 3.0
            }
        );
    }

    /// Inside the avoidance ring the robot drives at v_c and steers along Γ_ri⊥.
    #[test]
    fn inside_the_ring_the_speed_is_common() {
        let p = Params::default();
        let pose = Pose::new(0.0, 0.0, 0.0);
        let goal = Pose::new(50.0, 0.0, 0.0);
        let n = Neighbour {
            position: DVec2::new(1.0, 0.0),
            speed: 2.0,
            slowest_near: crate::swarm::SLOWEST_UNKNOWN,
        };
        let e = evaluate(&p, pose, pose.error_to(goal), 2.0, [], [n]);
        assert_eq!(e.robot_keep, 0.0);
        assert_eq!(e.command.v, p.avoid_speed);
        assert_eq!(e.virtual_obstacle, Some(DVec2::new(0.5, 0.0)));
        // Heading straight at the neighbour: turn left (positive ω).
        assert!(e.command.omega > 0.0);
    }

    /// A robot that the barrier holds still on an obstacle's surface counts as moving at the
    /// circling speed, so a neighbour at rest next to it is at rest: it is circled as itself,
    /// not at the midpoint between the two (which puts the circle through the parked robot).
    /// Off the surface, a robot at rest next to a robot at rest counts both as moving alike.
    #[test]
    fn held_on_a_surface_a_parked_neighbour_is_at_rest() {
        let p = Params::default();
        let o = Obstacle {
            center: DVec2::ZERO,
            radius: 5.0,
            influence: 10.0,
        };
        let goal = Pose::new(-30.0, -30.0, 0.0);
        let vo = |y: f64| {
            let pose = Pose::new(0.0, y, PI);
            let n = Neighbour {
                position: DVec2::new(2.0, y + 1.6),
                speed: 0.0,
                slowest_near: crate::swarm::SLOWEST_UNKNOWN,
            };
            let e = evaluate(&p, pose, pose.error_to(goal), 0.0, [&o], [n]);
            (e.virtual_obstacle, n.position, pose.p)
        };
        // On the surface (within `SURFACE·ε` of it): the neighbour itself, within the weight
        // `SPEED_FLOOR / (v_c + 2·SPEED_FLOOR)` of the segment (about 1.3e-3 here).
        let (c, n, _) = vo(5.0 * (1.0 + 1e-9));
        let c = c.expect("the neighbour is circled");
        assert!(c.distance(n) < 2e-3, "{c:?}, neighbour at {n:?}");
        // Two robots at rest off the surface: the midpoint.
        let (c, n, me) = vo(7.0);
        let c = c.expect("the neighbour is circled");
        assert!(c.distance(0.5 * (n + me)) < 1e-12, "{c:?}");
    }
}
