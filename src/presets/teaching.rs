//! The teaching presets: small scenes whose robots drive at speeds a class can follow
//! (`teach-one-robot`, `teach-obstacle`, `teach-two-robots` in [`super::PRESETS`]).

use super::robot;
use crate::obstacle::Obstacle;
use crate::params::Params;
use crate::scenario::{RobotSpec, Scenario};
use glam::DVec2;
use std::f64::consts::{FRAC_PI_2, PI};

/// The teaching presets' speed limit `v_max` (m/s): a robot crosses their 60 m scenes in about
/// half a minute at 1×, which a class can follow (without a limit the field's speed grows with
/// the distance to the goal).
pub const TEACH_V_MAX: f64 = 2.0;
/// The teaching presets' turn-rate limit `ω_max` (rad/s).
pub const TEACH_OMEGA_MAX: f64 = 1.0;

/// A teaching scene: default gains but for the speed limits, dt = 0.01, T = 60 s.
fn teaching(
    name: &str,
    bounds: [f64; 4],
    robots: Vec<RobotSpec>,
    obstacles: Vec<Obstacle>,
) -> Scenario {
    Scenario {
        planner: crate::planner::Spec::default(),
        name: name.into(),
        bounds: Some(bounds),
        duration: 60.0,
        dt: 0.01,
        params: Params {
            v_max: Some(TEACH_V_MAX),
            omega_max: Some(TEACH_OMEGA_MAX),
            ..Params::default()
        },
        independent: false,
        robots,
        obstacles,
    }
}

/// One robot from `(−30, 25, π/2)` to `(0, 0, 0)`: the scene of the book's figures of the
/// paper's Fig. 1 and 2 (`docs/book/src/scenarios/field-one-robot.json`, bounds included), at
/// the teaching speeds.
pub(super) fn teach_one_robot() -> Scenario {
    teaching(
        "Teaching: one robot to the origin",
        [-40.0, -40.0, 40.0, 40.0],
        vec![robot([-30.0, 25.0, FRAC_PI_2], [0.0, 0.0, 0.0])],
        vec![],
    )
}

/// One robot from `(−30, 0, 0)` to `(30, 0, 0)` past an obstacle just off its straight path
/// (centre `(0, 1)`), so that it goes round one side.
pub(super) fn teach_obstacle() -> Scenario {
    teaching(
        "Teaching: round an obstacle",
        [-40.0, -30.0, 40.0, 30.0],
        vec![robot([-30.0, 0.0, 0.0], [30.0, 0.0, 0.0])],
        vec![Obstacle {
            center: DVec2::new(0.0, 1.0),
            radius: 4.0,
            influence: 8.0,
        }],
    )
}

/// Two robots on nearly the same line, facing each other, swap ends keeping their headings:
/// they meet in the middle and pass.
pub(super) fn teach_two_robots() -> Scenario {
    teaching(
        "Teaching: two robots pass each other",
        [-30.0, -20.0, 30.0, 20.0],
        vec![
            robot([-20.0, 0.0, 0.0], [20.0, 0.0, 0.0]),
            robot([20.0, 0.5, PI], [-20.0, 0.5, PI]),
        ],
        vec![],
    )
}
