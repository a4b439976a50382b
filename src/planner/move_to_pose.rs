//! `move-to-pose`: the polar pose controller of PythonRobotics
//! (`PathTracking/move_to_pose/move_to_pose.py`, github.com/AtsushiSakai/PythonRobotics, after
//! Corke, *Robotics, Vision and Control*, Springer 2017), each robot on its own.
//!
//! With `ρ` the distance to the goal, `α` the bearing of the goal from the heading and
//! `β = θ_d − θ − α`, both wrapped to `[−π, π)` as the file's `angle_mod` does:
//! `v = K_ρ·ρ`, `ω = K_α·α − K_β·β`. When the goal lies behind the robot (`|α| > π/2`) the
//! robot reverses: `α` is taken from the bearing of `−(p_d − p)`, `β` again from it, and
//! `v = −K_ρ·ρ`. Then `|v| ≤ 15` and `|ω| ≤ 7` (the file's `MAX_LINEAR_SPEED`,
//! `MAX_ANGULAR_SPEED`), clipped one at a time. The file's example loop stops once
//! `ρ ≤ 0.001`; so does the robot here (`stop_distance`): nearer the goal the bearing is
//! round-off, and the law left running turns the robot away from its goal heading.
//!
//! It avoids nothing: robots and obstacles are left to the shared safety barrier (or to
//! nothing, with `barrier_rate: null`).

use super::{gains, positive, Alone, Built, Entry};
use crate::sim::Robot;
use crate::controller::{Command, Evaluation};
use crate::error::Error;
use crate::maths::atan2;
use serde::Deserialize;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// PythonRobotics' polar law.
pub(super) const ENTRY: Entry = Entry {
    name: "move-to-pose",
    title: "Polar pose controller (move to pose)",
    source: "PythonRobotics, PathTracking/move_to_pose/move_to_pose.py \
             (github.com/AtsushiSakai/PythonRobotics), after Corke, Robotics, Vision and \
             Control (Springer, 2017)",
    avoids: "nothing",
    build: |map| {
        let g: Gains = gains(map)?;
        g.check()?;
        Ok(Built::Other(Box::new(MoveToPose { g })))
    },
};

/// The law's gains and limits, with the file's values (`PathFinderController(9, 15, 3)`,
/// `MAX_LINEAR_SPEED`, `MAX_ANGULAR_SPEED`, the loop's `rho > 0.001`).
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(default, deny_unknown_fields)]
struct Gains {
    /// `K_ρ`: the speed per metre of distance to the goal (1/s).
    kp_rho: f64,
    /// `K_α`: the turn rate per radian of bearing error (1/s).
    kp_alpha: f64,
    /// `K_β`: the turn rate per radian of `β` (1/s), subtracted.
    kp_beta: f64,
    /// `|v|` at most this (m/s).
    max_linear_speed: f64,
    /// `|ω|` at most this (rad/s).
    max_angular_speed: f64,
    /// Within this distance of its goal (m) the robot stops.
    stop_distance: f64,
}

impl Default for Gains {
    fn default() -> Self {
        Self {
            kp_rho: 9.0,
            kp_alpha: 15.0,
            kp_beta: 3.0,
            max_linear_speed: 15.0,
            max_angular_speed: 7.0,
            stop_distance: 0.001,
        }
    }
}

impl Gains {
    fn check(&self) -> Result<(), Error> {
        positive("kp_rho", self.kp_rho)?;
        positive("kp_alpha", self.kp_alpha)?;
        positive("kp_beta", self.kp_beta)?;
        positive("max_linear_speed", self.max_linear_speed)?;
        positive("max_angular_speed", self.max_angular_speed)?;
        positive("stop_distance", self.stop_distance)
    }

    /// The command of a robot at `(x, y, θ)` whose goal lies at `(x_diff, y_diff)` from it,
    /// with goal heading `θ_d`: `calc_control_command` of the file and the loop's clipping.
    fn command(&self, x_diff: f64, y_diff: f64, theta: f64, theta_goal: f64) -> Command {
        let rho = libm::hypot(x_diff, y_diff);
        if rho <= self.stop_distance {
            return Command::default();
        }
        let mut v = self.kp_rho * rho;
        let mut alpha = angle_mod(atan2(y_diff, x_diff) - theta);
        let mut beta = angle_mod(theta_goal - theta - alpha);
        if !(-FRAC_PI_2..=FRAC_PI_2).contains(&alpha) {
            alpha = angle_mod(atan2(-y_diff, -x_diff) - theta);
            beta = angle_mod(theta_goal - theta - alpha);
            v = -v;
        }
        let w = self.kp_alpha * alpha - self.kp_beta * beta;
        Command {
            v: clip(v, self.max_linear_speed),
            omega: clip(w, self.max_angular_speed),
        }
    }
}

/// `x` with its magnitude cut to `max`, as the file does (`np.sign(x)·max`).
fn clip(x: f64, max: f64) -> f64 {
    if x.abs() > max {
        max.copysign(x)
    } else {
        x
    }
}

/// The file's `angle_mod`: `(x + π) mod 2π − π`, in `[−π, π)`, the modulo floored as
/// Python's `%` is.
fn angle_mod(x: f64) -> f64 {
    (x + PI).rem_euclid(TAU) - PI
}

/// PythonRobotics' polar law for every robot.
#[derive(Clone, Debug)]
struct MoveToPose {
    g: Gains,
}

impl Alone for MoveToPose {
    fn evaluate(&self, r: &Robot) -> Evaluation {
        let d = r.goal.p - r.pose.p;
        Evaluation {
            command: self.g.command(d.x, d.y, r.pose.theta, r.goal.theta),
            ..Evaluation::default()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{assert_close, test};

    /// The file's first command from the start (5, 5, 0) to the goal (1, 4, 0) of
    /// PythonRobotics' `tests/test_move_to_pose.py::test_stability`, by hand: the goal lies
    /// behind (`α = atan2(−1, −4) = −2.897`), so the robot reverses with
    /// `α = atan2(1, 4) = 0.24498`, `β = −α`, `ω = 15α + 3α = 4.40962` and
    /// `v = −9·√17 = −37.1`, clipped to −15. Within 1e-12: a few operations' round-off.
    #[test]
    fn the_first_command_reverses_towards_a_goal_behind() {
        let c = Gains::default().command(-4.0, -1.0, 0.0, 0.0);
        assert_eq!(c.v, -15.0);
        assert_close!(c.omega, 18.0 * 0.25_f64.atan(), 1e-12);
        assert_close!(c.omega, 4.409_615_936_283_556, 1e-12);
    }

    /// The clipping keeps the sign, `angle_mod` is Python's (−π maps to −π, π to −π), and a
    /// robot within `stop_distance` stops.
    #[test]
    fn the_clip_the_wrap_and_the_stop_follow_the_file() {
        assert_eq!(clip(-20.0, 7.0), -7.0);
        assert_eq!(clip(3.0, 7.0), 3.0);
        assert_eq!(angle_mod(PI), -PI);
        assert_eq!(angle_mod(-PI), -PI);
        assert_close!(angle_mod(-4.0), 2.283_185_307_179_586, 1e-15);
        assert_eq!(
            Gains::default().command(0.0005, 0.0, 1.0, 0.0),
            Command::default()
        );
    }
}
