//! `clf`: the Robotarium's unicycle pose controller from a control Lyapunov function,
//! `create_pose_controller_clf` in `rps/utilities/controllers.py` of
//! robotarium_python_simulator (<https://github.com/robotarium/robotarium_python_simulator>),
//! after Aicardi, Casalino, Bicchi & Balestrino, "Closed loop steering of unicycle-like
//! vehicles via Lyapunov techniques" (IEEE Robotics & Automation Magazine, 1995).
//!
//! In the goal's frame, `e` is the distance from the robot to its goal, `θ` the direction of
//! the goal seen from the robot and `α = θ − (φ − φ_d)` the bearing of the goal off the
//! robot's heading (wrapped to `(−π, π]`):
//!
//! ```text
//! v = γ e cos α,    ω = k α + γ cos α sinc α (α + h θ)
//! ```
//!
//! with `sinc α = sin α / α` (1 for `|α| < 1e-6`, as the source takes it). When a wheel of the
//! differential drive (radius `wheel_radius`, track `base_length`) would turn faster than
//! `wheel_velocity_limit`, `v` and `ω` are scaled together until the faster wheel is at the
//! limit. The gains default to the source's: γ = 1, k = 2.7, h = 1, and the GRITSbot's wheel
//! (10 rad/s, radius 0.016 m, track 0.105 m: at most 0.16 m/s). `wheel_velocity_limit: null`
//! leaves only the scene's `v_max`/`ω_max`. Each robot steers alone: it avoids nothing.

use super::{gains, positive, Alone, Built, Entry};
use crate::sim::Robot;
use crate::controller::{Command, Evaluation};
use crate::error::Error;
use crate::maths::{atan2, sin_cos};
use crate::se2::{wrap_angle, Pose};
use glam::DVec2;
use serde::Deserialize;
use serde_json::{Map, Value};

/// The distance to the goal, relative to the goal's distance from the origin plus 1 m, below
/// which the robot is at its goal position, `e = 0` and `θ = 0`: 1e-9, where the
/// round-off of the positions (1e-16 relative) turns the direction of the error by 1e-7 rad.
const AT_GOAL: f64 = 1e-9;

/// The planner's entry.
pub(super) const ENTRY: Entry = Entry {
    name: "clf",
    title: "Control-Lyapunov pose controller (Robotarium)",
    source: "Robotarium, create_pose_controller_clf (robotarium_python_simulator, \
             rps/utilities/controllers.py), after Aicardi et al., Closed loop steering of \
             unicycle-like vehicles via Lyapunov techniques, 1995",
    avoids: "nothing",
    build: |map| Ok(Built::Other(Box::new(Clf(Gains::read(map)?)))),
};

/// The CLF's gains and the wheel it scales its command to, with the source's defaults.
#[derive(Clone, Copy, Debug, PartialEq, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub(super) struct Gains {
    /// `γ`: the gain of the approach (`v = γ e cos α`). 1/s.
    pub(super) approach_angle_gain: f64,
    /// `k`: the gain of the bearing error `α`. 1/s.
    pub(super) desired_angle_gain: f64,
    /// `h`: the weight of the goal's direction `θ` in the turn.
    pub(super) rotation_error_gain: f64,
    /// The fastest a wheel turns (rad/s); `None`: no wheel limit.
    pub(super) wheel_velocity_limit: Option<f64>,
    /// The wheels' radius (m).
    pub(super) wheel_radius: f64,
    /// The distance between the wheels (m).
    pub(super) base_length: f64,
}

impl Default for Gains {
    /// The defaults of `create_pose_controller_clf`.
    fn default() -> Self {
        Self {
            approach_angle_gain: 1.0,
            desired_angle_gain: 2.7,
            rotation_error_gain: 1.0,
            wheel_velocity_limit: Some(10.0),
            wheel_radius: 0.016,
            base_length: 0.105,
        }
    }
}

impl Gains {
    /// The gains of a `planner` object, every one a finite number > 0 (the wheel limit may be
    /// `null`).
    pub(super) fn read(map: &Map<String, Value>) -> Result<Self, Error> {
        let g: Self = gains(map)?;
        g.check()?;
        Ok(g)
    }

    /// Refuses a gain that is not a finite number > 0, naming it.
    pub(super) fn check(&self) -> Result<(), Error> {
        positive("approach_angle_gain", self.approach_angle_gain)?;
        positive("desired_angle_gain", self.desired_angle_gain)?;
        positive("rotation_error_gain", self.rotation_error_gain)?;
        if let Some(w) = self.wheel_velocity_limit {
            positive("wheel_velocity_limit", w)?;
        }
        positive("wheel_radius", self.wheel_radius)?;
        positive("base_length", self.base_length)
    }

    /// The command that steers a robot at `pose` to `goal`.
    #[must_use]
    pub(super) fn command(&self, pose: Pose, goal: Pose) -> Command {
        let (s, c) = sin_cos(-goal.theta);
        let d = goal.p - pose.p;
        let error = DVec2::new(c * d.x - s * d.y, s * d.x + c * d.y);
        // The goal's direction is undefined at the goal (the source takes atan2(0, 0) = 0, and
        // there v = 0). Within round-off of it, the direction of the error is the round-off's,
        // and turning to it would throw the heading off the goal's: there the robot is at its
        // goal, turning in place (`holds_its_pose_at_round_off_distance`).
        let e = error.length();
        let (e, theta) = if e <= AT_GOAL * (1.0 + goal.p.length()) {
            (0.0, 0.0)
        } else {
            (e, atan2(error.y, error.x))
        };
        let alpha = wrap_angle(theta - (pose.theta - goal.theta));
        let (sa, ca) = sin_cos(alpha);
        let sinc = if alpha.abs() < 1e-6 { 1.0 } else { sa / alpha };
        let gamma = self.approach_angle_gain;
        let mut command = Command {
            v: gamma * e * ca,
            omega: self.desired_angle_gain * alpha
                + gamma * (ca * sinc) * (alpha + self.rotation_error_gain * theta),
        };
        if let Some(limit) = self.wheel_velocity_limit {
            // The wheels turn at (v ∓ ω·L/2)/r; the faster one sets the scale.
            let fastest = (command.v.abs() + command.omega.abs() * self.base_length / 2.0)
                / self.wheel_radius;
            if fastest > limit {
                let scale = limit / fastest;
                command.v *= scale;
                command.omega *= scale;
            }
        }
        command
    }
}

/// The CLF on every robot.
#[derive(Clone, Debug)]
struct Clf(Gains);

impl Alone for Clf {
    fn evaluate(&self, r: &Robot) -> Evaluation {
        Evaluation {
            command: self.0.command(r.pose, r.goal),
            ..Evaluation::default()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::planner::Spec;
    use crate::scenario::Scenario;
    use crate::testing::{assert_close, test};


    /// The Robotarium's own numbers: `create_pose_controller_clf()` with its defaults, called
    /// on these five states and goals (robotarium_python_simulator at commit b23069e, numpy
    /// 2.4), printed to 17 digits. The first three bind the wheel limit, the last two do not;
    /// the last is at its goal's position, turning in place. Tolerance 1e-12: the two take
    /// the same arithmetic with sines and arctangents from different libraries (each within
    /// an ulp), times gains below 10.
    #[test]
    fn gives_the_robotariums_commands() {
        let cases = [
            (Pose::new(0.0, 0.0, 0.0), Pose::new(1.0, 0.5, 0.7), (0.148_696_544_415_550_16, 0.215_303_915_894_282_58)),
            (Pose::new(0.5, -0.2, 2.0), Pose::new(0.0, 0.3, -1.5), (0.148_929_812_226_237_4, -0.210_860_719_500_240_02)),
            (Pose::new(-0.3, 0.4, -1.0), Pose::new(0.2, -0.1, 0.5), (0.154_609_742_083_714_34, -0.102_671_579_357_822_3)),
            (Pose::new(1.0, 1.0, 3.0), Pose::new(1.05, 1.02, 3.1), (-0.020_090_444_839_683_51, -2.664_943_907_815_552_6)),
            (Pose::new(0.0, 0.0, 0.2), Pose::new(0.0, 0.0, 0.0), (0.0, -0.734_709_171_154_325_3)),
        ];
        let g = Gains::default();
        for (at, goal, (v, omega)) in cases {
            let c = g.command(at, goal);
            assert_close!(c.v, v, 1e-12);
            assert_close!(c.omega, omega, 1e-12);
        }
    }

    /// Without the wheel limit the command is the law itself: straight behind its goal and
    /// facing it, a robot 2 m away drives at γ·e = 2 m/s and does not turn.
    #[test]
    fn without_a_wheel_limit_the_law_is_unscaled() {
        let g = Gains {
            wheel_velocity_limit: None,
            ..Gains::default()
        };
        let c = g.command(Pose::new(-2.0, 0.0, 0.0), Pose::new(0.0, 0.0, 0.0));
        assert_eq!((c.v, c.omega), (2.0, 0.0));
    }

    /// At round-off distance from its goal (1e-14 m off, on either side) a robot turns in
    /// place to its goal heading as it does at the goal itself: the direction of a round-off
    /// error does not steer it. 0.3 rad off, it turns at (k + γ sinc α cos α)·0.3.
    #[test]
    fn holds_its_pose_at_round_off_distance() {
        let g = Gains::default();
        let goal = Pose::new(1.0, 0.7, 1.5);
        let at = g.command(Pose::new(1.0, 0.7, 1.2), goal);
        for off in [DVec2::new(1e-14, 0.0), DVec2::new(0.0, -1e-14)] {
            let c = g.command(Pose::new(1.0 + off.x, 0.7 + off.y, 1.2), goal);
            assert_eq!((c.v, c.omega), (at.v, at.omega));
        }
        let a: f64 = 0.3;
        assert_close!(at.omega, 2.7 * a + a.sin() * a.cos(), 1e-12);
    }

    fn run(json: &str) -> crate::Report {
        crate::run(&Scenario::from_json(json).unwrap()).unwrap()
    }

    /// The CLF brings a robot to its pose: from 1.2 m away, facing 1.4 rad off its goal
    /// heading, at the GRITSbot's wheel limit and the source's step of 0.033 s, it is within
    /// the scene's tolerances (5 cm and 0.02 rad) by 20 s, as the source's own loop is
    /// (`create_pose_controller_clf` stepped by Euler), and stays there to the end of 60 s.
    #[test]
    fn brings_a_robot_to_its_pose() {
        let report = run(r#"{"duration": 60, "dt": 0.033, "planner": "clf",
            "params": {"safe_radius": 0.075},
            "robots": [{"start": [0, 0, 3.0], "goal": [1, 0.7, 1.5707963267948966]}]}"#);
        let r = &report.robots[0];
        assert!(r.converged_at.is_some_and(|t| t < 20.0), "{r:?}");
        assert!(r.position_error <= 0.05 && r.heading_error <= 0.02, "{r:?}");
        assert_eq!(report.planner.as_deref(), Some("clf"));
    }

    /// A scene of the random sweep family (4 robots, 2 obstacles, 100 m across, no wheel limit)
    /// runs with the CLF and the shared barrier to its end with finite poses.
    #[test]
    fn runs_a_sweep_scene_without_nan() {
        let recipe = crate::sweep::Recipe {
            robots: 4..=4,
            obstacles: 2..=2,
            duration: 30.0,
            ..crate::sweep::Recipe::default()
        };
        let mut s = crate::sweep::scenario(&recipe, 3).unwrap();
        s.planner = serde_json::from_str(r#"{"name": "clf", "wheel_velocity_limit": null}"#)
            .unwrap();
        let report = crate::run(&s).unwrap();
        assert_eq!(report.robots.len(), 4);
        for r in &report.robots {
            assert!(r.final_pose.iter().all(|x| x.is_finite()), "{r:?}");
        }
    }

    /// A gain that is not a positive number, or one the CLF does not have, is refused naming
    /// the field.
    #[test]
    fn refuses_bad_gains_naming_the_field() {
        for (json, field) in [
            (r#"{"name": "clf", "desired_angle_gain": -1}"#, "planner.desired_angle_gain"),
            (r#"{"name": "clf", "wheel_velocity_limit": 0}"#, "planner.wheel_velocity_limit"),
            (r#"{"name": "clf", "wheel_radius": "big"}"#, "planner.wheel_radius"),
            (r#"{"name": "clf", "k": 2}"#, "planner.k"),
        ] {
            let spec: Spec = serde_json::from_str(json).unwrap();
            let e = spec.build().unwrap_err().to_string();
            assert!(e.starts_with(&format!("{field}:")), "{json}: {e}");
        }
    }
}
