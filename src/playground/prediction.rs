//! The predicted paths: a copy of the simulation run ahead from the current state, so that what
//! the page draws after an edit is exactly what playing will show.
//!
//! Layout (flat, robots in scenario order): poses `[robots · samples · 3]` (`x, y, θ`), sample 0
//! the current state; times and the smallest pair distance `[samples]`. No samples above
//! [`MAX_PREDICTED_ROBOTS`] robots.

use super::{PairDistance, POSE_STRIDE};
use crate::sim::Simulation;

/// Predicted paths are computed for at most this many robots. Above, an edit would have to
/// run a crowd ahead on every drag; the page draws no predicted paths and says so.
pub const MAX_PREDICTED_ROBOTS: usize = 100;
/// A prediction runs at most this many robot-steps: it looks `PREDICTION_WORK / robots` steps
/// ahead (and at most [`MAX_PREDICTION_STEPS`]), so that an edit, and a link someone shares,
/// cannot freeze the page. Example 4 (10 robots, 2,500 steps) is predicted to its end; 100
/// robots look 5,000 steps ahead.
pub const PREDICTION_WORK: usize = 500_000;
/// While a drag is under way a prediction runs at most this many robot-steps: at
/// [`MAX_PREDICTED_ROBOTS`] robots it looks 300 steps ahead, which keeps a pointer move with its
/// prediction within a frame (`benches/drag.mjs --robots 100`); Example 4 (10 robots, 2,500
/// steps) is still predicted to its end. The drag's end predicts within [`PREDICTION_WORK`]
/// again ([`super::Live::set_dragging`]).
pub const DRAG_PREDICTION_WORK: usize = 30_000;
/// A predicted path looks at most this many steps ahead.
pub const MAX_PREDICTION_STEPS: usize = 200_000;
/// At most this many samples per robot in a predicted path (the current state included).
pub const PREDICTION_SAMPLES: usize = 400;

/// The predicted paths of one live simulation.
#[derive(Clone, Debug, Default)]
pub struct Prediction {
    poses: Vec<f64>,
    times: Vec<f64>,
    min_pair: Vec<f64>,
    samples: usize,
    // Time-major samples as they arrive, transposed into `poses` at the end.
    by_time: Vec<f64>,
}

impl Prediction {
    /// Runs a copy of `sim` up to `left` steps ahead (or until every robot has converged, and
    /// at most `work / robots` and [`MAX_PREDICTION_STEPS`] steps: `work` is
    /// [`PREDICTION_WORK`], or [`DRAG_PREDICTION_WORK`] during a drag) and keeps at most
    /// [`PREDICTION_SAMPLES`] evenly spaced samples of it, their times offset by `base_time`.
    /// More than [`MAX_PREDICTED_ROBOTS`] robots are not predicted: no samples.
    pub fn run(
        &mut self,
        sim: &Simulation,
        left: usize,
        base_time: f64,
        pairs: &mut PairDistance,
        work: usize,
    ) {
        let n = sim.robots().len();
        self.times.clear();
        self.min_pair.clear();
        self.poses.clear();
        self.by_time.clear();
        self.samples = 0;
        if n > MAX_PREDICTED_ROBOTS {
            return;
        }
        let left = left.min(MAX_PREDICTION_STEPS).min(work / n.max(1));
        let every = left.div_ceil(PREDICTION_SAMPLES - 1).max(1);
        let mut sim = sim.clone();
        let (times, min_pair, by_time) = (&mut self.times, &mut self.min_pair, &mut self.by_time);
        let mut push = |sim: &Simulation| {
            times.push(base_time + sim.time());
            min_pair.push(pairs.of(sim));
            for r in sim.robots() {
                by_time.extend_from_slice(&r.pose.to_array());
            }
        };
        push(&sim);
        for k in 1..=left {
            sim.step();
            let done = k == left || all_converged(&sim);
            if k % every == 0 || done {
                push(&sim);
            }
            if done {
                break;
            }
        }
        let samples = self.times.len();
        self.samples = samples;
        // Robot-major layout, but samples arrived time-major: transpose.
        self.poses.resize(n * samples * POSE_STRIDE, 0.0);
        for k in 0..samples {
            for i in 0..n {
                let src = (k * n + i) * POSE_STRIDE;
                let dst = (i * samples + k) * POSE_STRIDE;
                self.poses[dst..dst + POSE_STRIDE]
                    .copy_from_slice(&self.by_time[src..src + POSE_STRIDE]);
            }
        }
    }

    /// `[robots · samples · 3]` predicted poses.
    #[must_use]
    pub fn poses(&self) -> &[f64] {
        &self.poses
    }
    /// Samples per robot: at least 1 (the current state), 0 for more than
    /// [`MAX_PREDICTED_ROBOTS`] robots.
    #[must_use]
    pub fn samples(&self) -> usize {
        self.samples
    }
    /// `[samples]` times of the samples (s).
    #[must_use]
    pub fn times(&self) -> &[f64] {
        &self.times
    }
    /// `[samples]` predicted minimum pair distance (NaN: no pair).
    #[must_use]
    pub fn min_pair(&self) -> &[f64] {
        &self.min_pair
    }
}

fn all_converged(sim: &Simulation) -> bool {
    let p = sim.params();
    sim.robots()
        .iter()
        .all(|r| r.position_error() <= p.tol_position && r.heading_error_abs() <= p.tol_heading)
}
