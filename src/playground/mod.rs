//! The playground's live model: a [`Simulation`] that a person edits while it runs, with the
//! buffers the page draws from. Pure Rust: `src/wasm/` only hands these buffers to JavaScript.
//!
//! - `mod.rs`: the model, its clock and the per-robot buffers;
//! - [`edits`]: what an edit means, and each kind of edit validated for what it touches;
//! - [`trails`]: the bounded history rings; [`prediction`]: the paths run ahead;
//! - [`field_view`]: the field sampled around a robot, and integral curves.
//!
//! # Editing while the clock runs
//! - At `t = 0` every edit is an edit of the scenario: moving a robot moves its start.
//! - At `t > 0` goals, obstacles and parameters apply at once and the robots continue from
//!   where they are now; moving a robot moves its current pose, not its start (so
//!   [`Live::reset`] brings back the scenario's starts). A robot added at `t > 0` appears at
//!   its start. After an edit the heading error restarts on its principal branch (the
//!   continued branch of [`crate::se2::continue_branch`] belongs to the path before the edit).
//! - Every edit recomputes the predicted paths: a copy of the simulation run from the current
//!   state towards the scenario's end (within [`PREDICTION_WORK`], or the shorter
//!   [`DRAG_PREDICTION_WORK`] while a drag is under way), so that the prediction is exactly
//!   what playing will show.
//!
//! # Buffers (all flat `f64`, robots in scenario order)
//! - poses `[robots · 3]`: `x, y, θ` now;
//! - status `[robots · 6]`: `v, ω, Π ς_i, ς_c, vo_x, vo_y` (the virtual obstacle, NaN when
//!   none);
//! - the trail rings ([`trails`]), the predicted paths ([`prediction`]), the field samples and
//!   integral curves ([`field_view`]), each laid out as its module says.
//!
//! A missing pair distance (fewer than two interacting robots) is NaN.
//!
//! The tests of the parts together (the prediction against playing, the trails across edits
//! and crowd sizes, the field view against a scan) are in `tests.rs`.

pub mod edits;
pub mod field_view;
pub mod prediction;
pub mod trails;

pub use field_view::{CURVE_POINTS, CURVE_STRIDE, FIELD_STRIDE, MAX_CURVE_SIDE, MAX_GRID_SIDE};
pub use prediction::{
    Prediction, DRAG_PREDICTION_WORK, MAX_PREDICTED_ROBOTS, MAX_PREDICTION_STEPS,
    PREDICTION_SAMPLES, PREDICTION_WORK,
};
pub use trails::{Trails, MAX_TRAIL_SAMPLES, TRAIL_BUDGET};

use crate::error::Error;
use crate::grid::{min_pair_distance, Cells, Neighbours};
use crate::scenario::Scenario;
use crate::sim::{Robot, Simulation};
use crate::swarm::Neighbour;
use glam::DVec2;

/// At most this many robots in the playground: the scenario format's own limit. A step, a
/// trail sample, a pair distance and a field sample all cost O(robots) (grid neighbour search),
/// so a crowd of 10,000 plays live; only the predicted paths stop at
/// [`MAX_PREDICTED_ROBOTS`].
pub const MAX_LIVE_ROBOTS: usize = crate::scenario::MAX_ROBOTS;
/// At most this many steps (`duration / dt`) in a live scenario: the trails are bounded, so
/// a long run costs time, not memory.
pub const MAX_LIVE_STEPS: usize = 1_000_000;
/// Values per pose: `x, y, θ`.
pub const POSE_STRIDE: usize = 3;
/// Values per robot status: `v, ω, Π ς_i, ς_c, vo_x, vo_y`.
pub const STATUS_STRIDE: usize = 6;
/// The names of a status record's values, in order (the page's names for them).
pub const STATUS_FIELDS: [&str; STATUS_STRIDE] = [
    "v",
    "omega",
    "obstacleKeep",
    "robotKeep",
    "virtualX",
    "virtualY",
];

/// A live, editable simulation and the buffers drawn from it.
#[derive(Clone, Debug)]
pub struct Live {
    scenario: Scenario,
    sim: Simulation,
    /// Time and steps before the current `sim` started (it restarts at 0 after each edit).
    base_time: f64,
    base_steps: usize,
    /// History is recorded every this many steps, so the rings span the whole run.
    record_every: usize,
    poses: Vec<f64>,
    status: Vec<f64>,
    trails: Trails,
    prediction: Prediction,
    /// The robot-steps a prediction may run: [`PREDICTION_WORK`], or
    /// [`DRAG_PREDICTION_WORK`] during a drag ([`Live::set_dragging`]).
    prediction_work: usize,
    /// The prediction shown ran within [`DRAG_PREDICTION_WORK`] only.
    prediction_short: bool,
    field: Vec<f64>,
    curves: Vec<f64>,
    /// Scratch kept from call to call: the pair distance, the field view's cells and lists.
    pairs: PairDistance,
    field_cells: Cells,
    field_points: Vec<DVec2>,
    near: Vec<u32>,
    neighbours: Vec<Neighbour>,
    sensed_obstacles: Vec<u32>,
}

impl Live {
    /// A live simulation of `scenario` at `t = 0` (validated here), with its prediction.
    ///
    /// # Errors
    /// The scenario's first invalid field (more than [`MAX_LIVE_ROBOTS`] robots included), or
    /// more than [`MAX_LIVE_STEPS`] steps.
    pub fn new(scenario: Scenario) -> Result<Self, Error> {
        edits::check(&scenario)?;
        let sim = Simulation::of_valid(&scenario, crate::sim::Neighbourhood::Grid);
        let mut live = Self {
            record_every: 1,
            scenario,
            sim,
            base_time: 0.0,
            base_steps: 0,
            poses: Vec::new(),
            status: Vec::new(),
            trails: Trails::default(),
            prediction: Prediction::default(),
            prediction_work: PREDICTION_WORK,
            prediction_short: false,
            field: Vec::new(),
            curves: Vec::new(),
            pairs: PairDistance::default(),
            field_cells: Cells::new(),
            field_points: Vec::new(),
            near: Vec::new(),
            neighbours: Vec::new(),
            sensed_obstacles: Vec::new(),
        };
        live.start();
        Ok(live)
    }

    /// The scenario (starts are where [`reset`](Self::reset) puts the robots).
    #[must_use]
    pub fn scenario(&self) -> &Scenario {
        &self.scenario
    }

    /// The simulation as it is now.
    #[must_use]
    pub fn simulation(&self) -> &Simulation {
        &self.sim
    }

    /// Simulated time now (s).
    #[must_use]
    pub fn time(&self) -> f64 {
        self.base_time + self.sim.time()
    }

    /// Steps taken since `t = 0`.
    #[must_use]
    pub fn steps(&self) -> usize {
        self.base_steps + self.sim.steps()
    }

    /// Whether the clock has reached the scenario's duration.
    #[must_use]
    pub fn finished(&self) -> bool {
        self.steps() >= self.scenario.steps()
    }

    /// Back to `t = 0` at the scenario's starts; clears the trails.
    pub fn reset(&mut self) {
        self.sim = Simulation::of_valid(&self.scenario, crate::sim::Neighbourhood::Grid);
        self.start();
    }

    /// The rest of a start at `t = 0` once `sim` is new: the clock, the trails, the prediction.
    fn start(&mut self) {
        self.base_time = 0.0;
        self.base_steps = 0;
        self.trails = Trails::new(self.scenario.robots.len());
        self.record_every = record_every(&self.scenario, self.trails.capacity());
        self.record();
        self.refresh();
        self.predict();
    }

    /// Advances up to `n` steps, stopping at the scenario's end; returns the steps taken.
    pub fn step(&mut self, n: usize) -> usize {
        let left = self.scenario.steps().saturating_sub(self.steps());
        let n = n.min(left);
        for _ in 0..n {
            self.sim.step();
            if self.steps().is_multiple_of(self.record_every) || self.finished() {
                self.record();
            }
        }
        if n > 0 {
            self.refresh();
        }
        n
    }

    /// Writes the current state into the history rings.
    fn record(&mut self) {
        let min_pair = self.pairs.of(&self.sim);
        let poses = self.sim.robots().iter().map(|r| r.pose);
        self.trails.record(poses, self.time(), min_pair);
    }

    /// Copies poses and controller states into their flat buffers.
    fn refresh(&mut self) {
        self.poses.clear();
        self.status.clear();
        for r in self.sim.robots() {
            self.poses.extend_from_slice(&r.pose.to_array());
            let e = r.last;
            let vo = e.virtual_obstacle.unwrap_or(DVec2::NAN);
            self.status.extend_from_slice(&[
                e.command.v,
                e.command.omega,
                e.obstacle_keep,
                e.robot_keep,
                vo.x,
                vo.y,
            ]);
        }
    }

    /// Runs a copy of the simulation towards the scenario's end (see [`Prediction::run`]).
    pub fn predict(&mut self) {
        let left = self.scenario.steps().saturating_sub(self.steps());
        let work = self.prediction_work;
        self.prediction
            .run(&self.sim, left, self.base_time, &mut self.pairs, work);
        self.prediction_short = work < PREDICTION_WORK;
    }

    /// Says whether a drag is under way. During one, each edit predicts within
    /// [`DRAG_PREDICTION_WORK`] robot-steps (a shorter look ahead in a scene of many robots,
    /// so that a pointer move stays within a frame); at its end, a prediction made that way is
    /// made again within [`PREDICTION_WORK`], and a drag that edited nothing predicts nothing.
    pub fn set_dragging(&mut self, dragging: bool) {
        self.prediction_work = if dragging {
            DRAG_PREDICTION_WORK
        } else {
            PREDICTION_WORK
        };
        if !dragging && self.prediction_short {
            self.predict();
        }
    }

    fn robot(&self, index: usize) -> Result<&Robot, Error> {
        let count = self.sim.robots().len();
        self.sim
            .robots()
            .get(index)
            .ok_or(Error::RobotIndex { index, count })
    }

    /// `[robots · 3]` poses now.
    #[must_use]
    pub fn poses(&self) -> &[f64] {
        &self.poses
    }
    /// `[robots · 6]` controller states now (see the module doc).
    #[must_use]
    pub fn status(&self) -> &[f64] {
        &self.status
    }
    /// The trail rings.
    #[must_use]
    pub fn trails(&self) -> &Trails {
        &self.trails
    }
    /// The predicted paths.
    #[must_use]
    pub fn prediction(&self) -> &Prediction {
        &self.prediction
    }
}

/// Steps between two trail samples, so that a ring of `cap` samples spans the whole run.
fn record_every(s: &Scenario, cap: usize) -> usize {
    s.steps().div_ceil(cap - 1).max(1)
}

/// The smallest distance between two interacting robots of a simulation (NaN when there is no
/// pair): from the simulation's own neighbour lists when they hold a pair
/// ([`Simulation::min_listed_pair_distance`]), else through [`min_pair_distance`] (a scan below
/// [`crate::grid::FEW_ROBOTS`], the grid above), with its buffers kept from call to call.
#[derive(Clone, Debug, Default)]
pub struct PairDistance {
    positions: Vec<DVec2>,
    search: Neighbours,
}

impl PairDistance {
    /// The smallest pair distance in `sim` now (NaN for independent robots or fewer than two).
    // Not inlined: one copy for its callers keeps the wasm module small.
    #[inline(never)]
    pub fn of(&mut self, sim: &Simulation) -> f64 {
        let r = sim.robots();
        if sim.independent() || r.len() < 2 {
            return f64::NAN;
        }
        if let Some(m) = sim.min_listed_pair_distance() {
            return m;
        }
        self.positions.clear();
        self.positions.extend(r.iter().map(|r| r.pose.p));
        min_pair_distance(&self.positions, sim.params().sense_radius, &mut self.search)
    }
}

#[cfg(test)]
mod tests;
