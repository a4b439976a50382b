//! [`SafeRobot`]: one robot driven from the caller's own loop, one step at a time, by the DVF
//! controller made safe by the barrier: what [`crate::sim::Simulation`] does for each of its
//! robots, for a program that keeps its robots itself.

use super::{filter_facing, neighbour_reach, Constraints};
use crate::controller::{evaluate_facing, Command, Evaluation, Facing};
use crate::error::Error;
use crate::obstacle::Obstacle;
use crate::params::Params;
use crate::scenario::{RobotSpec, Scenario, MAX_DT};
use crate::se2::{continue_branch, heading, unrotate_by, wrap_angle, Pose};
use crate::swarm::Neighbour;
use crate::unicycle::integrate_along;
use glam::DVec2;

/// One robot under the DVF controller and the safety barrier, stepped by the caller.
///
/// Each [`SafeRobot::step`] takes what the robot senses (the other robots as [`Neighbour`]s,
/// with their positions and speeds `|v|`, and the obstacles), evaluates the controller, clamps
/// its speed by the barrier, and integrates the unicycle exactly over `dt`. It keeps what a
/// simulation keeps of a robot from step to step: its heading error on a continued branch
/// ([`continue_branch`]), its heading as the last step left it, and its own speed.
///
/// Stepped from the same snapshot with the neighbours in scenario order, a `SafeRobot` takes
/// the very steps (the same bits) that [`crate::sim::Simulation`] takes for its robot
/// (`tests/library.rs`).
///
/// ```
/// use dvf::swarm::Neighbour;
/// use dvf::{Params, Pose, SafeRobot};
/// use glam::DVec2;
///
/// let params = Params::default();
/// let (start, goal) = (Pose::new(0.0, 0.0, 0.0), Pose::new(10.0, 0.0, 0.0));
/// let mut robot = SafeRobot::new(&params, 0.01, start, goal)?;
/// // A robot at rest just outside the safe distance 2·r_ij = 2, in the way.
/// let other = Neighbour { position: DVec2::new(2.05, 0.0), speed: 0.0, ..Default::default() };
/// for _ in 0..100 {
///     robot.step(&[other], &[]);
///     assert!(robot.pose().p.distance(other.position) > 2.0 * params.safe_radius);
/// }
/// # Ok::<(), dvf::Error>(())
/// ```
#[derive(Clone, Debug)]
pub struct SafeRobot {
    params: Params,
    dt: f64,
    pose: Pose,
    goal: Pose,
    heading_error: f64,
    // `(cos θ, sin θ)` as the last step's motion left it, and the goal's.
    heading: DVec2,
    goal_heading: DVec2,
    // `|v|` of the last command: how fast the robot's neighbours see it move.
    speed: f64,
    last: Evaluation,
    // Buffers reused from step to step: the barrier's constraints, the robots and obstacles
    // sensed.
    constraints: Constraints,
    sensed: Vec<Neighbour>,
    near_obstacles: Vec<usize>,
}

impl SafeRobot {
    /// A robot at rest at `start` (heading wrapped into `(−π, π]`) bound for `goal`, under
    /// `params` with step `dt`.
    ///
    /// # Errors
    /// What a scenario of this one robot would be refused for, with the same message
    /// ([`Scenario::validate`]): `dt` out of range or too large for the gains, a parameter out
    /// of range, a pose that is not finite.
    pub fn new(params: &Params, dt: f64, start: Pose, goal: Pose) -> Result<Self, Error> {
        // A run of one step (of the largest step for a `dt` out of range, which the checks of
        // `dt` then name).
        let duration = if dt > 0.0 && dt <= MAX_DT { dt } else { MAX_DT };
        Scenario {
            params: *params,
            dt,
            duration,
            robots: vec![RobotSpec {
                start: start.to_array(),
                goal: goal.to_array(),
            }],
            ..Scenario::default()
        }
        .validate()?;
        let (pose, goal) = (start.wrapped(), goal.wrapped());
        Ok(Self {
            params: *params,
            dt,
            pose,
            goal,
            heading_error: wrap_angle(pose.theta - goal.theta),
            heading: heading(pose.theta),
            goal_heading: heading(goal.theta),
            speed: 0.0,
            last: Evaluation::default(),
            constraints: Constraints::new(),
            sensed: Vec::new(),
            near_obstacles: Vec::new(),
        })
    }

    /// Takes one step of `dt` and returns the command held over it.
    ///
    /// The robot senses the `neighbours` and the `obstacles` within the sensing radius `R_s`
    /// (`params.sense_radius`; those farther are left out here). A neighbour's `speed` is its
    /// `|v|` ([`SafeRobot::speed`] of another one) and places the virtual obstacle between the
    /// two; its `slowest_near` may stay unknown (`..Default::default()`). The command keeps
    /// the robot at least `2·r_ij` from every neighbour given and out of every obstacle disc,
    /// as long as the neighbours keep their side of the barrier too.
    pub fn step(&mut self, neighbours: &[Neighbour], obstacles: &[Obstacle]) -> Command {
        let (params, dt, p, h) = (&self.params, self.dt, self.pose.p, self.heading);
        let rs = params.sense_radius;
        self.sensed.clear();
        self.sensed.extend(
            neighbours
                .iter()
                .filter(|n| n.position.distance_squared(p) <= rs * rs),
        );
        self.near_obstacles.clear();
        self.near_obstacles.extend(
            obstacles
                .iter()
                .enumerate()
                .filter(|(_, o)| o.clearance(p) <= rs)
                .map(|(k, _)| k),
        );
        let sensed_obstacles = || self.near_obstacles.iter().map(|&k| &obstacles[k]);
        let err = Pose {
            p: unrotate_by(self.goal_heading, p - self.goal.p),
            theta: self.heading_error,
        };
        let facing = Facing {
            heading: h,
            error: unrotate_by(self.goal_heading, h),
        };
        let mut e = evaluate_facing(
            params,
            self.pose,
            facing,
            err,
            self.speed,
            sensed_obstacles(),
            self.sensed.iter().copied(),
        );
        let binding = neighbour_reach(params, e.command.v);
        let motion;
        (e.command, motion) = filter_facing(
            &mut self.constraints,
            params,
            dt,
            p,
            h,
            e.command,
            e.field,
            self.sensed
                .iter()
                .map(|n| n.position)
                .filter(|q| q.distance_squared(p) <= binding * binding),
            sensed_obstacles(),
        );
        self.pose = integrate_along(self.pose, e.command, dt, motion.chord);
        // As a simulation's step: back on the principal branch while the robot circles robots,
        // continued while it follows its goal field (`Simulation::step`).
        self.heading_error = if e.robot_keep < 1.0 {
            wrap_angle(self.pose.theta - self.goal.theta)
        } else {
            continue_branch(self.heading_error, self.pose.theta, self.goal.theta)
        };
        self.heading = motion.heading;
        self.speed = e.command.v.abs();
        self.last = e;
        e.command
    }

    /// Where the robot is now.
    #[must_use]
    pub fn pose(&self) -> Pose {
        self.pose
    }
    /// Its goal pose.
    #[must_use]
    pub fn goal(&self) -> Pose {
        self.goal
    }
    /// `|v|` of its last command (0 before the first step): the speed its neighbours sense.
    #[must_use]
    pub fn speed(&self) -> f64 {
        self.speed
    }
    /// The robot as its neighbours sense it: its position and speed.
    #[must_use]
    pub fn as_neighbour(&self) -> Neighbour {
        Neighbour {
            position: self.pose.p,
            speed: self.speed,
            ..Neighbour::default()
        }
    }
    /// What the controller computed for the last step (its field, its virtual obstacle, …),
    /// with the command the barrier made safe.
    #[must_use]
    pub fn last(&self) -> &Evaluation {
        &self.last
    }
}
