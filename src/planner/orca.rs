//! `orca`: Optimal Reciprocal Collision Avoidance (van den Berg, Guy, Lin & Manocha,
//! *Reciprocal n-Body Collision Avoidance*, ISRR 2009) from the crate `dodgy_2d`, a port of
//! RVO2's `Agent.cc`, for unicycles as NH-ORCA practice drives them (Alonso-Mora, Breitenmoser,
//! Rufli, Beardsley & Siegwart, *Optimal Reciprocal Collision Avoidance for Multiple
//! Non-Holonomic Robots*, DARS 2010; the tracking of collvoid's
//! `collvoid_local_planner/src/ROSAgent.cpp`, `computeNewVelocity`, github.com/daenny/collvoid).
//!
//! Each step, for every robot:
//! - its agent is its look-ahead point `p + d·(cos θ, sin θ)`, a disc of radius `r_ij + d`
//!   (which holds the robot's own disc of radius `r_ij`), moving with the velocity the robot's
//!   last command gave that point, `v·h + d·ω·h⊥`. Its neighbours are the robots it senses
//!   (within `R_s`), the same discs;
//! - its preferred velocity is toward its goal, `p_d − p`, cut to `preferred_speed` (RVO2's
//!   examples: a unit vector, shorter within a metre of the goal);
//! - ORCA gives the velocity `v_H` nearest the preferred one outside every neighbour's
//!   velocity obstacle over `time_horizon`, and every obstacle's over
//!   `obstacle_time_horizon`, no faster than `max_speed` (and `v_max` when the robot has one);
//! - the robot tracks `v_H` as collvoid does: with `θ` the angle from its heading to `v_H`,
//!   speed `‖v_H‖·θ·sin θ/(2(1 − cos θ))` (the speed of the arc that turns the heading onto
//!   `v_H` in `T`, which is `‖v_H‖` for `θ = 0` and 0 for `θ = π`) and turn rate
//!   `sign(θ)·min(|θ|/T, ω_max)`, `T = time_to_holo`; while `|θ| > 3π/4` it keeps turning the
//!   way it turned last, so that a `v_H` near its back does not flip it from side to side.
//!
//! ORCA plans a position, not a heading: within `tol_position` of its goal a robot stops and
//! turns in place toward its goal heading at `sign(θ̃)·min(|θ̃|/T, ω_max)`, as collvoid's
//! planner hands a robot that has reached its goal position to a stop-and-rotate controller.
//!
//! Obstacles: each disc is given to ORCA as the regular polygon of [`SIDES`] sides
//! circumscribing it, counter-clockwise (`dodgy_2d` keeps agents out of the left of an edge),
//! with the margin `d`: the look-ahead point stays `d` out of the polygon, so the robot's centre
//! stays out of the disc, as the scene's obstacles ask.
//!
//! Where this departs from its sources:
//! - collvoid inflates a robot's radius by the tracking error it allows (`max_error_holo`,
//!   0.15 m) and adds constraints that keep `v_H` trackable within it; here the agent is the
//!   look-ahead point with its radius inflated by `d`, and `v_H` is not constrained further
//!   (`dodgy_2d` takes no extra constraints).
//! - collvoid commands the full speed `max_vel_x` when `|θ|` is below 0.001, whatever `‖v_H‖`;
//!   here the law's own limit there, `‖v_H‖`. For `v_H = 0` collvoid turns the robot toward
//!   the angle `atan2(0, 0) = 0`; here the robot stops.
//! - `dodgy_2d` computes in `f32`: every position is taken relative to the robot's own
//!   look-ahead point before it is rounded, and `v_H` is read back into `f64`.

use super::{gains, positive, Built, Entry, Planner, World};
use crate::controller::{Command, Evaluation};
use crate::error::Error;
use crate::maths::{atan2, from_angle, sin_cos};
use crate::se2::{heading, wrap_angle};
use dodgy_2d::{Agent, AvoidanceOptions, Obstacle as Polygon, Vec2};
use glam::DVec2;
use serde::Deserialize;
use std::borrow::Cow;
use std::f64::consts::{FRAC_PI_4, PI};

/// Sides of the polygon that stands for an obstacle disc. Its edges touch the disc and its
/// corners stand `r_o·(1/cos(π/16) − 1) < 0.02·r_o` beyond it: the robots keep at most 2 % of
/// the radius further off than the disc asks, where a robot passes a corner, for 16 edges in
/// ORCA's linear program (of which it keeps those that face the robot and are not covered by
/// a nearer one).
const SIDES: usize = 16;

/// ORCA for unicycles.
pub(super) const ENTRY: Entry = Entry {
    name: "orca",
    title: "ORCA on a look-ahead point, tracked by a unicycle",
    source: "van den Berg, Guy, Lin & Manocha, Reciprocal n-Body Collision Avoidance (ISRR \
             2009), through the crate dodgy_2d (a port of RVO2); tracked as in Alonso-Mora et \
             al., Optimal Reciprocal Collision Avoidance for Multiple Non-Holonomic Robots \
             (DARS 2010), by collvoid's ROSAgent::computeNewVelocity \
             (github.com/daenny/collvoid)",
    avoids: "robots and obstacles (each disc as a circumscribed 16-gon)",
    build: |map| {
        let g: Gains = gains(map)?;
        g.check()?;
        Ok(Built::Other(Box::new(Orca::new(g))))
    },
};

/// ORCA's settings (RVO2's `Circle` example: time horizons of 10 s, a speed of at most 2 m/s,
/// a preferred speed of 1 m/s) and the tracking's (collvoid's `time_to_holo`, 0.4 s; its
/// `max_error_holo`, 0.15 m, as the look-ahead distance).
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(default, deny_unknown_fields)]
struct Gains {
    /// `d`: how far ahead of the robot its agent is, and how much wider (m).
    lookahead: f64,
    /// How far ahead in time ORCA avoids other robots (s).
    time_horizon: f64,
    /// How far ahead in time ORCA avoids obstacles (s).
    obstacle_time_horizon: f64,
    /// ORCA's greatest speed (m/s), and `v_max` when the robot has a smaller one.
    max_speed: f64,
    /// The speed toward the goal a robot prefers (m/s), less within that many metres of it.
    preferred_speed: f64,
    /// `T`: the time in which the tracking turns the heading onto ORCA's velocity (s).
    time_to_holo: f64,
}

impl Default for Gains {
    fn default() -> Self {
        Self {
            lookahead: 0.15,
            time_horizon: 10.0,
            obstacle_time_horizon: 10.0,
            max_speed: 2.0,
            preferred_speed: 1.0,
            time_to_holo: 0.4,
        }
    }
}

impl Gains {
    fn check(&self) -> Result<(), Error> {
        if !(self.lookahead.is_finite() && self.lookahead >= 0.0) {
            return Err(Error::Invalid {
                field: "planner.lookahead".to_owned(),
                message: format!("must be a finite number ≥ 0, not {}", self.lookahead),
            });
        }
        positive("time_horizon", self.time_horizon)?;
        positive("obstacle_time_horizon", self.obstacle_time_horizon)?;
        positive("max_speed", self.max_speed)?;
        positive("preferred_speed", self.preferred_speed)?;
        positive("time_to_holo", self.time_to_holo)
    }
}

/// The speed factor of collvoid's tracking, `θ·sin θ/(2(1 − cos θ))` (`calcVstar`), written
/// `x·cos x/sin x` with `x = θ/2` so that it loses nothing near 0, where it is 1.
fn track_speed(theta: f64) -> f64 {
    let x = 0.5 * theta;
    if x == 0.0 {
        return 1.0;
    }
    let (s, c) = sin_cos(x);
    x * c / s
}

/// The turn rate of collvoid's tracking toward an angle `theta` off: `sign(θ)·min(|θ|/T,
/// ω_max)`.
fn track_turn(theta: f64, time_to_holo: f64, omega_max: f64) -> f64 {
    (theta.abs() / time_to_holo).min(omega_max).copysign(theta)
}

/// ORCA and each robot's tracking state.
#[derive(Clone, Debug)]
struct Orca {
    g: Gains,
    /// The corners of [`SIDES`]-gon circumscribing the unit circle, counter-clockwise.
    unit: [DVec2; SIDES],
    /// Per robot, the turn rate it last took while `|θ| > 3π/4` (0: it was not).
    last_turn: Vec<f64>,
    /// Each robot's look-ahead point and that point's velocity.
    points: Vec<(DVec2, DVec2)>,
    neighbours: Vec<Cow<'static, Agent>>,
    polygons: Vec<Cow<'static, Polygon>>,
}

impl Orca {
    fn new(g: Gains) -> Self {
        let corner = 1.0 / sin_cos(PI / SIDES as f64).1;
        Self {
            g,
            unit: std::array::from_fn(|k| corner * from_angle(2.0 * PI * k as f64 / SIDES as f64)),
            last_turn: Vec::new(),
            points: Vec::new(),
            neighbours: Vec::new(),
            polygons: Vec::new(),
        }
    }

    /// Robot `i`'s command to track `vh` from heading `theta`.
    fn track(&mut self, i: usize, vh: DVec2, theta: f64, omega_max: f64) -> Command {
        if vh == DVec2::ZERO {
            self.last_turn[i] = 0.0;
            return Command::default();
        }
        let off = wrap_angle(atan2(vh.y, vh.x) - theta);
        let mut omega = track_turn(off, self.g.time_to_holo, omega_max);
        if off.abs() > 3.0 * FRAC_PI_4 {
            let last = self.last_turn[i];
            if last != 0.0 {
                omega = omega.abs().copysign(last);
            }
            self.last_turn[i] = omega;
        } else {
            self.last_turn[i] = 0.0;
        }
        Command {
            v: vh.length() * track_speed(off),
            omega,
        }
    }
}

/// `v` in `dodgy_2d`'s `f32`.
fn single(v: DVec2) -> Vec2 {
    Vec2::new(v.x as f32, v.y as f32)
}

impl Planner for Orca {
    fn plan(&mut self, world: &World<'_>, out: &mut [Evaluation]) {
        let p = world.params;
        let d = self.g.lookahead;
        self.last_turn.resize(world.robots.len(), 0.0);
        self.points.clear();
        self.points.extend(world.robots.iter().map(|r| {
            let h = heading(r.pose.theta);
            let c = r.last.command;
            (r.pose.p + d * h, c.v * h + d * c.omega * h.perp())
        }));
        let radius = (p.safe_radius + d) as f32;
        let max_speed = p.v_max.map_or(self.g.max_speed, |m| m.min(self.g.max_speed));
        let preferred = self.g.preferred_speed.min(max_speed);
        let omega_max = p.omega_max.unwrap_or(f64::INFINITY);
        // `dodgy_2d` asserts a positive step: a step below `f32`'s smallest normal (which
        // rounds to 0) is taken as that.
        let step = (world.dt as f32).max(f32::MIN_POSITIVE);
        let options = AvoidanceOptions {
            obstacle_margin: d as f32,
            time_horizon: self.g.time_horizon as f32,
            obstacle_time_horizon: self.g.obstacle_time_horizon as f32,
        };
        for (i, (r, e)) in world.robots.iter().zip(out.iter_mut()).enumerate() {
            let to_goal = r.goal.p - r.pose.p;
            if to_goal.length() <= p.tol_position {
                let off = wrap_angle(r.goal.theta - r.pose.theta);
                self.last_turn[i] = 0.0;
                *e = Evaluation {
                    command: Command {
                        v: 0.0,
                        omega: track_turn(off, self.g.time_to_holo, omega_max),
                    },
                    ..Evaluation::default()
                };
                continue;
            }
            let (at, velocity) = self.points[i];
            let agent = Agent {
                position: Vec2::ZERO,
                velocity: single(velocity),
                radius,
                avoidance_responsibility: 1.0,
            };
            self.neighbours.clear();
            self.neighbours.extend(world.sensed(i).map(|j| {
                let (q, u) = self.points[j];
                Cow::Owned(Agent {
                    position: single(q - at),
                    velocity: single(u),
                    radius,
                    avoidance_responsibility: 1.0,
                })
            }));
            self.polygons.clear();
            for o in world.sensed_obstacles(i) {
                let centre = o.center - at;
                self.polygons.push(Cow::Owned(Polygon::Closed {
                    vertices: self
                        .unit
                        .iter()
                        .map(|&u| single(centre + o.radius * u))
                        .collect(),
                }));
            }
            let vh = agent.compute_avoiding_velocity(
                &self.neighbours,
                &self.polygons,
                single(to_goal.clamp_length_max(preferred)),
                max_speed as f32,
                step,
                &options,
            );
            let vh = DVec2::new(f64::from(vh.x), f64::from(vh.y));
            *e = Evaluation {
                command: self.track(i, vh, r.pose.theta, omega_max),
                field: vh,
                ..Evaluation::default()
            };
        }
    }

    fn clone_box(&self) -> Box<dyn Planner> {
        Box::new(self.clone())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{assert_close, test};
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_3};

    /// collvoid's speed factor by hand: `θ = π/3` gives `(π/3)(√3/2)/(2·½) = π√3/6`,
    /// `θ = π/2` gives `(π/2)·1/(2·1) = π/4`, and `θ = ±π` gives 0 (to round-off: `cos(π/2)`
    /// is 6e-17 in `f64`). Within 1e-15: a sine, a cosine and two products.
    #[test]
    fn the_tracking_speed_is_collvoids() {
        assert_eq!(track_speed(0.0), 1.0);
        assert_close!(track_speed(FRAC_PI_3), PI * 3f64.sqrt() / 6.0, 1e-15);
        assert_close!(track_speed(-FRAC_PI_3), PI * 3f64.sqrt() / 6.0, 1e-15);
        assert_close!(track_speed(FRAC_PI_2), PI / 4.0, 1e-15);
        assert_close!(track_speed(PI), 0.0, 1e-15);
        // Near 0 the factor is 1 − θ²/12 (the next term, θ⁴/720, is 1.4e-19 here), to an ulp
        // or two: nothing cancels.
        assert_close!(track_speed(1e-4), 1.0 - 1e-8 / 12.0, 3e-16);
        assert_eq!(track_turn(-1.0, 0.4, f64::INFINITY), -2.5);
        assert_eq!(track_turn(1.0, 0.4, 2.0), 2.0);
    }

    /// Beyond 3π/4 the turn keeps its last direction, as collvoid's `last_twist_ang_` does: a
    /// velocity just past the robot's back on the left, then just past it on the right, turns
    /// the robot the same way both times; back within 3π/4 it turns toward the velocity.
    #[test]
    fn behind_the_robot_the_turn_keeps_its_direction() {
        let mut orca = Orca::new(Gains::default());
        orca.last_turn = vec![0.0];
        let left = orca.track(0, from_angle(0.9 * PI), 0.0, f64::INFINITY);
        assert!(left.omega > 0.0);
        let right = orca.track(0, from_angle(-0.9 * PI), 0.0, f64::INFINITY);
        assert_eq!(right.omega, left.omega);
        let ahead = orca.track(0, from_angle(-0.5 * PI), 0.0, f64::INFINITY);
        assert!(ahead.omega < 0.0);
        assert_eq!(orca.last_turn[0], 0.0);
        assert_eq!(orca.track(0, DVec2::ZERO, 0.0, 1.0), Command::default());
    }

    /// The polygon circumscribes the unit circle: its corners at `1/cos(π/16)`, the middles of
    /// its edges at 1 (to 1e-15), counter-clockwise.
    #[test]
    fn the_polygon_circumscribes_the_disc() {
        let orca = Orca::new(Gains::default());
        for k in 0..SIDES {
            let (a, b) = (orca.unit[k], orca.unit[(k + 1) % SIDES]);
            assert_close!(a.length(), 1.0 / (PI / 16.0).cos(), 1e-15);
            assert_close!((0.5 * (a + b)).length(), 1.0, 1e-15);
            assert!(a.perp_dot(b) > 0.0);
        }
    }
}
