//! The outcome of a run: per robot, where it ended and since when it has been at its goal; over
//! the run, the smallest distances, the violation events (`sim/metrics.rs` keeps them) and the
//! smoothness of the commands ([`super::smoothness`]).

use super::smoothness::{Smoothness, Tally};
use serde::Serialize;

/// Per-robot outcome in a [`Report`].
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RobotReport {
    /// `[x, y, θ]` at the end.
    #[serde(rename = "final")]
    pub final_pose: [f64; 3],
    /// Distance to the goal position at the end.
    pub position_error: f64,
    /// `|wrap(θ − θ_d)|` at the end (rad).
    pub heading_error: f64,
    /// The time after which the robot stayed within `tol_position` and `tol_heading` to the
    /// end of the run; `None` if it was outside at the end.
    pub converged_at: Option<f64>,
    /// How smooth its turn rate was, over the run and after it reached its goal position.
    pub smoothness: Tally,
}

/// The outcome of a run (the JSON that `dvf simulate` prints).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Report {
    /// The scenario's name.
    pub name: String,
    /// The planner, when it is not `dvf` (the scenario's `planner`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub planner: Option<String>,
    /// Simulated time at the end (s).
    pub time: f64,
    /// Steps taken.
    pub steps: usize,
    /// One entry per robot, in scenario order.
    pub robots: Vec<RobotReport>,
    /// Smallest distance between two robots at any sampled time (`None`: fewer than two
    /// interacting robots).
    pub min_pair_distance: Option<f64>,
    /// Smallest distance from a robot to the surface of an obstacle it senses (within
    /// `max(R_s, 2·r_ij)`) at any sampled time (negative: inside). `None` when no robot ever
    /// came that close to an obstacle (or there are none). Obstacles farther away play no part
    /// in the method, and leaving them out keeps a step O(N) among many obstacles.
    pub min_obstacle_clearance: Option<f64>,
    /// Violation events: each time a pair of robots comes closer than `2·safe_radius`, and
    /// each time a robot enters an obstacle disc, counts once (a violation that lasts several
    /// steps is one event).
    pub violations: usize,
    /// How smooth the robots' turn rates were, over all robots.
    pub smoothness: Smoothness,
}
