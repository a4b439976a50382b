//! The playground's live simulation: a [`Simulation`] that a person edits while it runs, with
//! the buffers the page draws from (bounded trails, predicted paths, field samples, integral
//! curves, error series). Pure Rust: `src/wasm.rs` only hands these buffers to JavaScript.
//!
//! # Editing while the clock runs
//! - At `t = 0` every edit is an edit of the scenario: moving a robot moves its start.
//! - At `t > 0` goals, obstacles and parameters apply at once and the robots continue from
//!   where they are now; moving a robot moves its current pose, not its start (so
//!   [`Live::reset`] brings back the scenario's starts). A robot added at `t > 0` appears at
//!   its start. After an edit the heading error restarts on its principal branch (the
//!   continued branch of [`crate::se2::continue_branch`] belongs to the path before the edit).
//! - Every edit recomputes the predicted paths: a copy of the simulation run from the current
//!   state towards the scenario's end (within [`PREDICTION_WORK`]), so that the prediction is
//!   exactly what playing will show.
//!
//! # Buffers (all flat `f64`, robots in scenario order)
//! - poses `[robots · 3]`: `x, y, θ` now.
//! - trails `[robots · cap · 3]`, `cap` = [`Live::trail_capacity`] (a fixed budget of samples
//!   shared by all robots): a ring of past `x, y, θ` per robot, written at slot
//!   [`Live::trail_head`] (the next to write, shared by all robots); robot `i` holds its last
//!   [`Live::trail_len`]`(i)` samples, the oldest at slot `(head − len + cap) % cap`; sample `g`
//!   since the reset is in slot `g % cap` ([`Live::recorded`]). The time and minimum pair
//!   distance of each slot are in two rings of `cap` ([`Live::trail_times`],
//!   [`Live::trail_min_pair`]), whose own length is [`Live::history_len`].
//! - predicted `[robots · samples · 3]`, with [`Live::predicted_times`] and
//!   [`Live::predicted_min_pair`] `[samples]`; sample 0 is the current state (no samples above
//!   [`MAX_PREDICTED_ROBOTS`] robots).
//! - status `[robots · 6]`: `v, ω, Π ς_i, ς_c, vo_x, vo_y` (the virtual obstacle, NaN when
//!   none).
//! - field grid `[nx · ny · 4]`: `x, y, Γx, Γy`, row by row from `ymin`.
//! - integral curves `[curves · points · 2]`: `x, y`.
//!
//! A missing pair distance (fewer than two interacting robots) is NaN.

use crate::error::Error;
use crate::field::integral_curve;
use crate::grid::{closest_pair_below, min_pair_distance, Neighbours};
use crate::scenario::{RobotSpec, Scenario};
use crate::se2::Pose;
use crate::sim::Simulation;
use crate::swarm::Neighbour;
use glam::DVec2;

/// At most this many robots in the playground: the scenario format's own limit. A step, a
/// trail sample, a pair distance and a field sample all cost O(robots) (grid neighbour search),
/// so a crowd of 10,000 plays live; only the predicted paths stop at
/// [`MAX_PREDICTED_ROBOTS`].
pub const MAX_LIVE_ROBOTS: usize = crate::scenario::MAX_ROBOTS;
/// Predicted paths are computed for at most this many robots. Above, an edit would have to
/// run a crowd ahead on every drag; the page draws no predicted paths and says so.
pub const MAX_PREDICTED_ROBOTS: usize = 100;
/// A prediction runs at most this many robot-steps: it looks `PREDICTION_WORK / robots` steps
/// ahead (and at most [`MAX_PREDICTION_STEPS`]), so that an edit, and a link someone shares,
/// cannot freeze the page. Example 4 (10 robots, 2,500 steps) is predicted to its end; 100
/// robots look 5,000 steps ahead.
pub const PREDICTION_WORK: usize = 500_000;
/// Trail samples kept in all robots' rings together: a robot keeps
/// `TRAIL_BUDGET / robots` samples, at most [`TRAIL_CAPACITY`]. 2¹⁸ samples are 6 MiB, and
/// bound what the page draws when it redraws every trail (about 0.1 s in Chromium without a
/// GPU, after a pan or zoom).
pub const TRAIL_BUDGET: usize = 1 << 18;
/// At most this many steps (`duration / dt`) in a live scenario: the trails are bounded, so
/// a long run costs time, not memory.
pub const MAX_LIVE_STEPS: usize = 1_000_000;
/// A predicted path looks at most this many steps ahead.
pub const MAX_PREDICTION_STEPS: usize = 200_000;
/// Samples kept per robot in the trail ring, for up to `TRAIL_BUDGET / 2,048` = 128 robots
/// (see [`Live::trail_capacity`]).
pub const TRAIL_CAPACITY: usize = 2_048;
/// At most this many samples per robot in a predicted path (the current state included).
pub const PREDICTION_SAMPLES: usize = 400;
/// Values per pose: `x, y, θ`.
pub const POSE_STRIDE: usize = 3;
/// Values per robot status: `v, ω, Π ς_i, ς_c, vo_x, vo_y`.
pub const STATUS_STRIDE: usize = 6;
/// Values per field sample: `x, y, Γx, Γy`.
pub const FIELD_STRIDE: usize = 4;
/// The largest field grid side.
pub const MAX_GRID_SIDE: usize = 200;
/// The largest number of integral curves per side (each is an RK4 run of its own).
pub const MAX_CURVE_SIDE: usize = 40;
/// Integration step of the integral curves (field time units) and their length.
const CURVE_DT: f64 = 0.05;
/// `θ̃` decays like `e^{−t}` along a curve: 8 time units leave `e^{−8} ≈ 3e-4` of it.
const CURVE_TIME: f64 = 8.0;
/// Points kept per integral curve.
pub const CURVE_POINTS: usize = 81;
/// Field sampling bins the robots near the sampled box in at most this many cells per side.
const FIELD_BINS: usize = 64;
/// Below this many robots the smallest pair distance is a scan over all pairs.
const PAIR_SCAN_MAX: usize = 64;

/// A live, editable simulation and the buffers drawn from it.
#[derive(Clone, Debug)]
pub struct Live {
    scenario: Scenario,
    sim: Simulation,
    /// Time and steps before the current `sim` started (it restarts at 0 after each edit).
    base_time: f64,
    base_steps: usize,
    /// History is recorded every this many steps, so the ring spans the whole run.
    record_every: usize,
    poses: Vec<f64>,
    status: Vec<f64>,
    /// Samples per robot in the trail ring (see [`Live::trail_capacity`]).
    trail_capacity: usize,
    trails: Vec<f64>,
    trail_lens: Vec<u32>,
    trail_times: Vec<f64>,
    trail_min_pair: Vec<f64>,
    trail_head: usize,
    history_len: usize,
    /// Samples written since the reset (sample `g` is in slot `g % trail_capacity`).
    recorded: usize,
    predicted: Vec<f64>,
    predicted_times: Vec<f64>,
    predicted_min_pair: Vec<f64>,
    predicted_samples: usize,
    field: Vec<f64>,
    curves: Vec<f64>,
    /// Scratch for the pair distance and the field samples, kept from call to call.
    positions: Vec<DVec2>,
    pair_search: Neighbours,
    bin_start: Vec<u32>,
    bin_order: Vec<u32>,
    near: Vec<u32>,
    neighbours: Vec<Neighbour>,
}

impl Live {
    /// A live simulation of `scenario` at `t = 0` (validated here), with its prediction.
    ///
    /// # Errors
    /// The scenario's first invalid field (more than [`MAX_LIVE_ROBOTS`] robots included), or more than
    /// [`MAX_LIVE_STEPS`] steps.
    pub fn new(scenario: Scenario) -> Result<Self, Error> {
        check(&scenario)?;
        let sim = Simulation::new(&scenario);
        let mut live = Self {
            record_every: 1,
            scenario,
            sim,
            base_time: 0.0,
            base_steps: 0,
            poses: Vec::new(),
            status: Vec::new(),
            trail_capacity: 0,
            trails: Vec::new(),
            trail_lens: Vec::new(),
            trail_times: Vec::new(),
            trail_min_pair: Vec::new(),
            trail_head: 0,
            history_len: 0,
            recorded: 0,
            predicted: Vec::new(),
            predicted_times: Vec::new(),
            predicted_min_pair: Vec::new(),
            predicted_samples: 0,
            field: Vec::new(),
            curves: Vec::new(),
            positions: Vec::new(),
            pair_search: Neighbours::new(),
            bin_start: Vec::new(),
            bin_order: Vec::new(),
            near: Vec::new(),
            neighbours: Vec::new(),
        };
        live.reset();
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
        self.sim = Simulation::new(&self.scenario);
        self.base_time = 0.0;
        self.base_steps = 0;
        let n = self.scenario.robots.len();
        let cap = trail_capacity(n);
        self.trail_capacity = cap;
        self.record_every = record_every(&self.scenario, cap);
        // Filled (NaN: not recorded yet) rather than zeroed: a zeroed allocation is committed
        // page by page as the ring fills, which would look like growth in a long run.
        self.trails = vec![f64::NAN; n * cap * POSE_STRIDE];
        self.trail_lens = vec![0; n];
        self.trail_times = vec![f64::NAN; cap];
        self.trail_min_pair = vec![f64::NAN; cap];
        self.trail_head = 0;
        self.history_len = 0;
        self.recorded = 0;
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
            if self.steps() % self.record_every == 0 || self.finished() {
                self.record();
            }
        }
        if n > 0 {
            self.refresh();
        }
        n
    }

    /// Replaces the scenario (see the module doc for what happens at `t > 0`) and predicts
    /// again.
    ///
    /// # Errors
    /// The first invalid field of `scenario`, or a robot that the edit would leave inside an
    /// obstacle; the live simulation is unchanged then.
    pub fn edit(&mut self, scenario: Scenario) -> Result<(), Error> {
        check(&scenario)?;
        if self.steps() == 0 {
            self.scenario = scenario;
            self.reset();
            return Ok(());
        }
        let now: Vec<Pose> = self.sim.robots().iter().map(|r| r.pose).collect();
        self.resume(scenario, &now)?;
        Ok(())
    }

    /// Moves robot `index` to `pose`: its start at `t = 0`, its current pose later.
    ///
    /// # Errors
    /// An index out of range, a non-finite or too large value, or a pose inside an obstacle.
    pub fn move_robot(&mut self, index: usize, pose: Pose) -> Result<(), Error> {
        let count = self.scenario.robots.len();
        if index >= count {
            return Err(Error::RobotIndex { index, count });
        }
        if self.steps() == 0 {
            let mut s = self.scenario.clone();
            s.robots[index].start = pose.to_array();
            return self.edit(s);
        }
        let mut now: Vec<Pose> = self.sim.robots().iter().map(|r| r.pose).collect();
        now[index] = pose;
        self.resume(self.scenario.clone(), &now)
    }

    /// Restarts the simulation from `now` (poses of the first robots) under `scenario`,
    /// keeping the clock and the trails of the robots that remain.
    fn resume(&mut self, scenario: Scenario, now: &[Pose]) -> Result<(), Error> {
        let mut from = scenario.clone();
        for (i, (r, p)) in from.robots.iter_mut().zip(now).enumerate() {
            let field = format!("robots[{i}]");
            for (k, v) in p.to_array().into_iter().enumerate() {
                if !v.is_finite() || v.abs() > crate::scenario::MAX_MAGNITUDE {
                    return Err(Error::Invalid {
                        field: format!("{field}.pose[{k}]"),
                        message: format!(
                            "must be a finite number of magnitude at most {:e}, not {v}",
                            crate::scenario::MAX_MAGNITUDE
                        ),
                    });
                }
            }
            for (j, o) in from.obstacles.iter().enumerate() {
                if o.clearance(p.p) <= 0.0 {
                    return Err(Error::Invalid {
                        field,
                        message: format!(
                            "would be inside obstacles[{j}] (radius {}) where it is now, at t = {:.2} s",
                            o.radius,
                            self.time()
                        ),
                    });
                }
            }
            *r = RobotSpec {
                start: p.to_array(),
                goal: r.goal,
            };
        }
        // The safe distance is a promise: an edit may not put two robots inside each
        // other's safe disc where they are now, added robots at their starts included (at
        // t = 0 the scenario's validation says so).
        let safe = 2.0 * from.params.safe_radius;
        if !from.independent {
            let at: Vec<DVec2> = from.robots.iter().map(|r| r.start_pose().p).collect();
            if let Some((i, j, d)) = closest_pair_below(&at, safe) {
                return Err(Error::Invalid {
                    field: format!("robots[{j}]"),
                    message: format!(
                        "would be {d:.3} from robots[{i}] where they are now, at t = {:.2} s: closer than the safe distance 2 · safe_radius = {safe}",
                        self.time()
                    ),
                });
            }
        }
        let time = self.time();
        let steps = self.steps();
        let old_n = self.scenario.robots.len();
        let n = scenario.robots.len();
        self.sim = Simulation::new(&from);
        self.base_time = time;
        self.base_steps = steps;
        self.scenario = scenario;
        if n != old_n {
            // Robots keep their index; removed ones drop off the end, added ones start empty.
            let cap = self.trail_capacity;
            self.trails.resize(n * cap * POSE_STRIDE, f64::NAN);
            self.trail_lens.resize(n, 0);
            self.relayout_trails(trail_capacity(n));
        }
        self.record_every = record_every(&self.scenario, self.trail_capacity);
        self.refresh();
        self.predict();
        Ok(())
    }

    /// Moves the rings to `cap` samples per robot, keeping the newest samples (as many as
    /// fit) in time order from slot 0.
    fn relayout_trails(&mut self, cap: usize) {
        let old = self.trail_capacity;
        if cap == old {
            return;
        }
        let keep = self.history_len.min(cap);
        // Slot k of the new rings holds the sample of old slot `(head − keep + k) mod old`.
        let head = self.trail_head;
        let slot = move |k: usize| (head + old - keep + k) % old;
        let n = self.trail_lens.len();
        let mut trails = vec![f64::NAN; n * cap * POSE_STRIDE];
        for i in 0..n {
            for k in 0..keep {
                let src = (i * old + slot(k)) * POSE_STRIDE;
                let dst = (i * cap + k) * POSE_STRIDE;
                trails[dst..dst + POSE_STRIDE]
                    .copy_from_slice(&self.trails[src..src + POSE_STRIDE]);
            }
            self.trail_lens[i] = self.trail_lens[i].min(keep as u32);
        }
        let ring = |r: &[f64]| {
            let mut v = vec![f64::NAN; cap];
            for (k, x) in v.iter_mut().enumerate().take(keep) {
                *x = r[slot(k)];
            }
            v
        };
        self.trail_times = ring(&self.trail_times);
        self.trail_min_pair = ring(&self.trail_min_pair);
        self.trails = trails;
        self.trail_capacity = cap;
        self.history_len = keep;
        self.trail_head = keep % cap;
        self.recorded = keep;
    }

    /// Writes the current state into the history rings.
    fn record(&mut self) {
        let h = self.trail_head;
        let cap = self.trail_capacity;
        for (i, r) in self.sim.robots().iter().enumerate() {
            let o = (i * cap + h) * POSE_STRIDE;
            self.trails[o..o + POSE_STRIDE].copy_from_slice(&r.pose.to_array());
            self.trail_lens[i] = (self.trail_lens[i] + 1).min(cap as u32);
        }
        self.trail_times[h] = self.time();
        self.trail_min_pair[h] = min_pair(
            &self.sim,
            self.scenario.independent,
            &mut self.positions,
            &mut self.pair_search,
        );
        self.history_len = (self.history_len + 1).min(cap);
        self.trail_head = (h + 1) % cap;
        self.recorded += 1;
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

    /// Runs a copy of the simulation to the scenario's end (or until every robot has
    /// converged, or [`PREDICTION_WORK`]` / robots` and at most [`MAX_PREDICTION_STEPS`]
    /// steps ahead) and keeps at most [`PREDICTION_SAMPLES`] evenly spaced samples of it.
    /// More than [`MAX_PREDICTED_ROBOTS`] robots are not predicted: no samples.
    pub fn predict(&mut self) {
        let n = self.sim.robots().len();
        self.predicted_times.clear();
        self.predicted_min_pair.clear();
        self.predicted.clear();
        self.predicted_samples = 0;
        if n > MAX_PREDICTED_ROBOTS {
            return;
        }
        let left = self
            .scenario
            .steps()
            .saturating_sub(self.steps())
            .min(MAX_PREDICTION_STEPS)
            .min(PREDICTION_WORK / n.max(1));
        let every = left.div_ceil(PREDICTION_SAMPLES - 1).max(1);
        let mut sim = self.sim.clone();
        // Robot-major layout, but samples arrive time-major: collect per sample, transpose after.
        let mut by_time: Vec<f64> = Vec::with_capacity(PREDICTION_SAMPLES * n * POSE_STRIDE);
        let base = self.base_time;
        let independent = self.scenario.independent;
        let (positions, search) = (&mut self.positions, &mut self.pair_search);
        let mut push = |sim: &Simulation, times: &mut Vec<f64>, pairs: &mut Vec<f64>| {
            times.push(base + sim.time());
            pairs.push(min_pair(sim, independent, positions, search));
            for r in sim.robots() {
                by_time.extend_from_slice(&r.pose.to_array());
            }
        };
        push(
            &sim,
            &mut self.predicted_times,
            &mut self.predicted_min_pair,
        );
        for k in 1..=left {
            sim.step();
            let done = k == left || all_converged(&sim);
            if k % every == 0 || done {
                push(
                    &sim,
                    &mut self.predicted_times,
                    &mut self.predicted_min_pair,
                );
            }
            if done {
                break;
            }
        }
        let samples = self.predicted_times.len();
        self.predicted_samples = samples;
        self.predicted.resize(n * samples * POSE_STRIDE, 0.0);
        for k in 0..samples {
            for i in 0..n {
                let src = (k * n + i) * POSE_STRIDE;
                let dst = (i * samples + k) * POSE_STRIDE;
                self.predicted[dst..dst + POSE_STRIDE]
                    .copy_from_slice(&by_time[src..src + POSE_STRIDE]);
            }
        }
    }

    /// Samples, on an `nx × ny` grid over `bounds = [xmin, ymin, xmax, ymax]`, the field `Γ`
    /// that robot `index` would follow at each point with its current attitude and goal,
    /// among the obstacles and the other robots where they are now (what it senses from
    /// there). The arrows turn as the robot turns: the field is dynamic.
    ///
    /// # Errors
    /// An index out of range, a grid side outside `2..=MAX_GRID_SIDE`, or bad bounds.
    pub fn sample_field(
        &mut self,
        index: usize,
        bounds: [f64; 4],
        nx: usize,
        ny: usize,
    ) -> Result<&[f64], Error> {
        let robot = *self.robot(index)?;
        grid_side("nx", nx)?;
        grid_side("ny", ny)?;
        check_bounds(bounds)?;
        let rs = self.sim.params().sense_radius;
        let independent = self.scenario.independent;
        let [x0, y0, x1, y1] = bounds;
        // The robots that can be sensed from the box, binned in cells at least R_s wide: a
        // sample's sensed robots lie in its cell and the eight around it. O(robots + samples).
        let bins = if independent {
            None
        } else {
            Some(self.bin_robots([x0 - rs, y0 - rs, x1 + rs, y1 + rs], rs))
        };
        self.field.clear();
        for j in 0..ny {
            let y = y0 + (y1 - y0) * j as f64 / (ny - 1) as f64;
            for i in 0..nx {
                let x = x0 + (x1 - x0) * i as f64 / (nx - 1) as f64;
                let pose = Pose::new(x, y, robot.pose.theta);
                self.neighbours.clear();
                if let Some(bins) = &bins {
                    self.near.clear();
                    let robots = self.sim.robots();
                    let (cx, cy) = bins.cell(pose.p);
                    for by in cy.saturating_sub(1)..=(cy + 1).min(bins.rows - 1) {
                        let row = by * bins.cols;
                        let lo = self.bin_start[row + cx.saturating_sub(1)] as usize;
                        let hi = self.bin_start[row + (cx + 1).min(bins.cols - 1) + 1] as usize;
                        self.near
                            .extend(self.bin_order[lo..hi].iter().copied().filter(|&k| {
                                k as usize != index
                                    && robots[k as usize].pose.p.distance_squared(pose.p) <= rs * rs
                            }));
                    }
                    // In robot order, as a scan over all robots would give them. An
                    // insertion sort: a few dozen entries, mostly in order already (each
                    // cell's are), and far less code in the wasm module than a library sort.
                    insertion_sort(&mut self.near);
                    self.neighbours.extend(self.near.iter().map(|&k| {
                        let o = &robots[k as usize];
                        Neighbour {
                            position: o.pose.p,
                            speed: o.last.command.v.abs(),
                        }
                    }));
                }
                let e = self.sim.evaluate_at(
                    pose,
                    pose.error_to(robot.goal),
                    robot.last.command.v.abs(),
                    &self.neighbours,
                );
                self.field.extend_from_slice(&[x, y, e.field.x, e.field.y]);
            }
        }
        Ok(&self.field)
    }

    /// Counting-sorts the robots inside `area` into a row-major grid of cells at least `reach`
    /// wide (at most [`FIELD_BINS`] per side): cell `c` holds
    /// `bin_order[bin_start[c]..bin_start[c + 1]]`. Rows of cells are consecutive, so the
    /// three cells of a row of a 3 × 3 block are one range.
    fn bin_robots(&mut self, area: [f64; 4], reach: f64) -> Bins {
        let [x0, y0, x1, y1] = area;
        let cell = (reach * (1.0 + 1e-6))
            .max((x1 - x0) / FIELD_BINS as f64)
            .max((y1 - y0) / FIELD_BINS as f64)
            .max(f64::MIN_POSITIVE);
        let side = |len: f64| ((len / cell) as usize + 1).min(FIELD_BINS + 1);
        let bins = Bins {
            origin: DVec2::new(x0, y0),
            cell,
            cols: side(x1 - x0),
            rows: side(y1 - y0),
        };
        let inside = |p: DVec2| p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1;
        let cells = bins.cols * bins.rows;
        self.bin_start.clear();
        self.bin_start.resize(cells + 1, 0);
        for r in self.sim.robots().iter().filter(|r| inside(r.pose.p)) {
            let (cx, cy) = bins.cell(r.pose.p);
            self.bin_start[cy * bins.cols + cx + 1] += 1;
        }
        for c in 0..cells {
            self.bin_start[c + 1] += self.bin_start[c];
        }
        self.bin_order.clear();
        self.bin_order.resize(self.bin_start[cells] as usize, 0);
        // `near` serves as the fill cursor of each cell here.
        self.near.clear();
        self.near.extend_from_slice(&self.bin_start[..cells]);
        for (k, r) in self.sim.robots().iter().enumerate() {
            if inside(r.pose.p) {
                let (cx, cy) = bins.cell(r.pose.p);
                let slot = &mut self.near[cy * bins.cols + cx];
                self.bin_order[*slot as usize] = k as u32;
                *slot += 1;
            }
        }
        bins
    }

    /// Integral curves of the goal field of robot `index`'s goal (the paper's Fig. 1): from
    /// each point of an `n × n` grid over `bounds`, with attitude `theta0` (rad) at the start,
    /// [`CURVE_POINTS`] points each.
    ///
    /// # Errors
    /// An index out of range, `n` outside `2..=MAX_CURVE_SIDE`, bad bounds or a non-finite
    /// `theta0`.
    pub fn integral_curves(
        &mut self,
        index: usize,
        theta0: f64,
        bounds: [f64; 4],
        n: usize,
    ) -> Result<&[f64], Error> {
        let goal = self.robot(index)?.goal;
        if !(2..=MAX_CURVE_SIDE).contains(&n) {
            return Err(Error::Invalid {
                field: "n".into(),
                message: format!("must be between 2 and {MAX_CURVE_SIDE}, not {n}"),
            });
        }
        check_bounds(bounds)?;
        if !theta0.is_finite() {
            return Err(Error::Invalid {
                field: "theta0".into(),
                message: format!("must be a finite angle in radians, not {theta0}"),
            });
        }
        let steps = (CURVE_TIME / CURVE_DT).round() as usize;
        let every = steps / (CURVE_POINTS - 1);
        let [x0, y0, x1, y1] = bounds;
        self.curves.clear();
        for j in 0..n {
            // Cell centres, so that no curve starts on the border.
            let y = y0 + (y1 - y0) * (j as f64 + 0.5) / n as f64;
            for i in 0..n {
                let x = x0 + (x1 - x0) * (i as f64 + 0.5) / n as f64;
                let curve = integral_curve(Pose::new(x, y, theta0), goal, CURVE_DT, steps);
                for p in curve.iter().step_by(every).take(CURVE_POINTS) {
                    self.curves.extend_from_slice(&[p.x, p.y]);
                }
            }
        }
        Ok(&self.curves)
    }

    fn robot(&self, index: usize) -> Result<&crate::sim::Robot, Error> {
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
    /// The last field samples ([`Live::sample_field`]).
    #[must_use]
    pub fn field(&self) -> &[f64] {
        &self.field
    }
    /// `[robots · trail_capacity · 3]` trail rings.
    #[must_use]
    pub fn trails(&self) -> &[f64] {
        &self.trails
    }
    /// Samples per robot in the trail rings: `TRAIL_BUDGET / robots`, at most
    /// [`TRAIL_CAPACITY`] (2,048 up to 128 robots, 26 for 10,000). The rings span the whole
    /// run, so a crowd's trails are coarser, not shorter.
    #[must_use]
    pub fn trail_capacity(&self) -> usize {
        self.trail_capacity
    }
    /// `[robots]` valid samples in each robot's trail.
    #[must_use]
    pub fn trail_lens(&self) -> &[u32] {
        &self.trail_lens
    }
    /// The slot the next sample is written to (shared by every ring).
    #[must_use]
    pub fn trail_head(&self) -> usize {
        self.trail_head
    }
    /// Valid samples in robot `index`'s trail (0 for an index out of range).
    #[must_use]
    pub fn trail_len(&self, index: usize) -> usize {
        self.trail_lens.get(index).map_or(0, |&l| l as usize)
    }
    /// `[trail_capacity]` ring of the times of the trail samples (s).
    #[must_use]
    pub fn trail_times(&self) -> &[f64] {
        &self.trail_times
    }
    /// `[trail_capacity]` ring of the minimum pair distance at those times.
    #[must_use]
    pub fn trail_min_pair(&self) -> &[f64] {
        &self.trail_min_pair
    }
    /// Samples written since the last reset: sample `g` lies in slot `g % trail_capacity`, so
    /// a reader that drew up to sample `g` draws only what follows (the page's trail layer).
    /// An edit that changes the ring layout renumbers the kept samples from 0.
    #[must_use]
    pub fn recorded(&self) -> usize {
        self.recorded
    }
    /// Valid samples in the time and pair-distance rings.
    #[must_use]
    pub fn history_len(&self) -> usize {
        self.history_len
    }
    /// `[robots · samples · 3]` predicted poses.
    #[must_use]
    pub fn predicted(&self) -> &[f64] {
        &self.predicted
    }
    /// Samples per robot in the prediction: at least 1 (the current state), 0 for more than
    /// [`MAX_PREDICTED_ROBOTS`] robots.
    #[must_use]
    pub fn predicted_samples(&self) -> usize {
        self.predicted_samples
    }
    /// `[samples]` times of the predicted samples (s).
    #[must_use]
    pub fn predicted_times(&self) -> &[f64] {
        &self.predicted_times
    }
    /// `[samples]` predicted minimum pair distance.
    #[must_use]
    pub fn predicted_min_pair(&self) -> &[f64] {
        &self.predicted_min_pair
    }
}

/// The scenario checks plus the playground's step limit.
fn check(s: &Scenario) -> Result<(), Error> {
    // The robot count is the scenario's own limit (MAX_LIVE_ROBOTS): validated there.
    s.validate()?;
    let steps = s.steps();
    if steps > MAX_LIVE_STEPS {
        return Err(Error::Invalid {
            field: "duration".into(),
            message: format!(
                "the playground runs at most {MAX_LIVE_STEPS} steps live, not {steps} (duration / dt): shorten the duration or raise dt (the `dvf` command line runs longer scenarios)"
            ),
        });
    }
    Ok(())
}

/// Sorts a short, mostly ordered list in place.
fn insertion_sort(v: &mut [u32]) {
    for i in 1..v.len() {
        let x = v[i];
        let mut j = i;
        while j > 0 && v[j - 1] > x {
            v[j] = v[j - 1];
            j -= 1;
        }
        v[j] = x;
    }
}

/// Steps between two trail samples, so that a ring of `cap` samples spans the whole run.
fn record_every(s: &Scenario, cap: usize) -> usize {
    s.steps().div_ceil(cap - 1).max(1)
}

/// Samples per robot in the trail ring for `n` robots.
fn trail_capacity(n: usize) -> usize {
    (TRAIL_BUDGET / n.max(1)).clamp(2, TRAIL_CAPACITY)
}

/// The robots binned by [`Live::bin_robots`]: `cols × rows` cells of side `cell` from `origin`.
struct Bins {
    origin: DVec2,
    cell: f64,
    cols: usize,
    rows: usize,
}

impl Bins {
    /// The cell of `p`, clamped to the grid (a point outside is nearest its border cell).
    fn cell(&self, p: DVec2) -> (usize, usize) {
        let c = (p - self.origin) / self.cell;
        let clamp = |v: f64, n: usize| (v.max(0.0) as usize).min(n - 1);
        (clamp(c.x, self.cols), clamp(c.y, self.rows))
    }
}

fn grid_side(field: &str, n: usize) -> Result<(), Error> {
    if (2..=MAX_GRID_SIDE).contains(&n) {
        Ok(())
    } else {
        Err(Error::Invalid {
            field: field.into(),
            message: format!("must be between 2 and {MAX_GRID_SIDE}, not {n}"),
        })
    }
}

fn check_bounds(b: [f64; 4]) -> Result<(), Error> {
    let ok = b
        .iter()
        .all(|v| v.is_finite() && v.abs() <= crate::scenario::MAX_BOUNDS)
        && b[0] < b[2]
        && b[1] < b[3];
    if ok {
        Ok(())
    } else {
        Err(Error::Invalid {
            field: "bounds".into(),
            message: format!(
                "must be four finite numbers [xmin, ymin, xmax, ymax] with xmin < xmax and ymin < ymax, not {b:?}"
            ),
        })
    }
}

/// The smallest distance between two interacting robots now (NaN when there is no pair):
/// a scan over all pairs for a few robots, the grid search of
/// [`crate::grid::min_pair_distance`] (the same bits) for more. Not inlined: one copy for its
/// three callers keeps the wasm module small.
#[inline(never)]
fn min_pair(
    sim: &Simulation,
    independent: bool,
    positions: &mut Vec<DVec2>,
    search: &mut Neighbours,
) -> f64 {
    let r = sim.robots();
    if independent || r.len() < 2 {
        return f64::NAN;
    }
    if r.len() > PAIR_SCAN_MAX {
        positions.clear();
        positions.extend(r.iter().map(|r| r.pose.p));
        return min_pair_distance(positions, sim.params().sense_radius, search);
    }
    let mut m = f64::INFINITY;
    for i in 0..r.len() {
        for j in i + 1..r.len() {
            m = m.min(r[i].pose.p.distance(r[j].pose.p));
        }
    }
    if m.is_finite() {
        m
    } else {
        f64::NAN
    }
}

fn all_converged(sim: &Simulation) -> bool {
    let p = sim.params();
    sim.robots()
        .iter()
        .all(|r| r.position_error() <= p.tol_position && r.heading_error_abs() <= p.tol_heading)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::controller::evaluate;
    use crate::testing::assert_close;
    use crate::presets::{preset, DEFAULT_PRESET};
    use crate::scenario::RobotSpec;
    use std::f64::consts::FRAC_PI_2;
    use crate::testing::test;

    fn two() -> Scenario {
        Scenario::from_json(
            r#"{"duration":10,"robots":[{"start":[0,0,0],"goal":[10,0,0]},{"start":[10,0,3.14159],"goal":[0,0,3.14159]}],
                "obstacles":[{"center":[5,8],"radius":1,"influence":2}]}"#,
        )
        .unwrap()
    }

    /// The prediction from t = 0 is the run that playing produces, sample for sample.
    #[test]
    fn prediction_is_what_playing_shows() {
        let mut live = Live::new(preset(DEFAULT_PRESET).unwrap()).unwrap();
        let samples = live.predicted_samples();
        assert!((2..=PREDICTION_SAMPLES).contains(&samples));
        let n = live.scenario().robots.len();
        assert_eq!(live.predicted().len(), n * samples * POSE_STRIDE);
        let times = live.predicted_times().to_vec();
        let predicted = live.predicted().to_vec();
        let k = samples / 2;
        let target = ((times[k] - times[0]) / live.scenario().dt).round() as usize;
        live.step(target);
        for i in 0..n {
            let o = (i * samples + k) * POSE_STRIDE;
            assert_eq!(&predicted[o..o + 3], &live.poses()[i * 3..i * 3 + 3]);
        }
        // Predicting again from the middle changes nothing: the rest of the same run.
        let before = predicted[((samples - 1) * POSE_STRIDE)..][..2].to_vec();
        live.predict();
        let s2 = live.predicted_samples();
        assert_eq!(
            &live.predicted()[(s2 - 1) * POSE_STRIDE..][..2],
            &before[..]
        );
    }

    #[test]
    fn the_clock_stops_at_the_end_and_trails_stay_bounded() {
        let mut s = two();
        s.duration = 30.0;
        let mut live = Live::new(s).unwrap();
        let total = live.scenario().steps();
        assert_eq!(live.step(total + 50), total);
        assert!(live.finished());
        assert_eq!(live.step(1), 0);
        assert_close!(live.time(), 30.0, 1e-9);
        assert!(live.history_len() <= TRAIL_CAPACITY);
        assert_eq!(live.trails().len(), 2 * TRAIL_CAPACITY * POSE_STRIDE);
        // The newest trail sample is the pose now.
        let last = (live.trail_head() + TRAIL_CAPACITY - 1) % TRAIL_CAPACITY;
        assert_eq!(&live.trails()[last * 3..last * 3 + 3], &live.poses()[0..3]);
        assert_close!(live.trail_times()[last], 30.0, 1e-9);
        assert!(live.trail_min_pair()[last] > 0.0);
    }

    /// At t = 0 a move edits the start; at t > 0 the current pose, and reset forgets it.
    #[test]
    fn moving_a_robot_edits_the_start_only_at_time_zero() {
        let mut live = Live::new(two()).unwrap();
        live.move_robot(0, Pose::new(0.0, -3.0, FRAC_PI_2)).unwrap();
        assert_eq!(live.scenario().robots[0].start, [0.0, -3.0, FRAC_PI_2]);
        live.step(100);
        let t = live.time();
        live.move_robot(1, Pose::new(5.0, -5.0, 0.0)).unwrap();
        assert_eq!(live.time(), t);
        assert_eq!(&live.poses()[3..6], &[5.0, -5.0, 0.0]);
        assert_eq!(live.scenario().robots[1].start[0], 10.0);
        assert_eq!(live.predicted()[live.predicted_samples() * 3], 5.0);
        live.reset();
        assert_eq!(live.time(), 0.0);
        assert_eq!(&live.poses()[3..5], &[10.0, 0.0]);
    }

    #[test]
    fn bad_edits_are_refused_and_change_nothing() {
        let mut live = Live::new(two()).unwrap();
        live.step(10);
        let before = live.poses().to_vec();
        let e = live.move_robot(5, Pose::IDENTITY).unwrap_err().to_string();
        assert!(e.contains("index 5 is out of range"), "{e}");
        let e = live
            .move_robot(0, Pose::new(f64::NAN, 0.0, 0.0))
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("robots[0].pose[0]: must be a finite number"),
            "{e}"
        );
        let e = live
            .move_robot(0, Pose::new(5.0, 8.0, 0.0))
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("robots[0]: would be inside obstacles[0]"),
            "{e}"
        );
        // Onto the other robot, at t > 0: inside its safe disc.
        let other = live.simulation().robots()[1].pose;
        let e = live
            .move_robot(0, Pose::new(other.p.x + 0.5, other.p.y, 0.0))
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("robots[1]: would be 0.500 from robots[0]"),
            "{e}"
        );
        let mut s = live.scenario().clone();
        s.params.k_v = -1.0;
        let e = live.edit(s).unwrap_err().to_string();
        assert!(e.starts_with("params.k_v: must be positive"), "{e}");
        assert_eq!(live.poses(), &before[..]);
        assert!(live.sample_field(2, [0.0, 0.0, 1.0, 1.0], 4, 4).is_err());
        assert!(live.sample_field(0, [0.0, 0.0, 1.0, 1.0], 1, 4).is_err());
        assert!(live
            .sample_field(0, [0.0, 0.0, f64::NAN, 1.0], 4, 4)
            .is_err());
        assert!(live
            .integral_curves(0, f64::INFINITY, [0.0, 0.0, 1.0, 1.0], 4)
            .is_err());
        let many = Scenario {
            robots: (0..=MAX_LIVE_ROBOTS)
                .map(|k| RobotSpec {
                    start: [10.0 * k as f64, -50.0, 0.0],
                    goal: [10.0 * k as f64, 50.0, 0.0],
                })
                .collect(),
            ..live.scenario().clone()
        };
        let e = Live::new(many).unwrap_err().to_string();
        assert!(e.starts_with("robots: at most 10000"), "{e}");
        let mut long = live.scenario().clone();
        long.duration = 3_000.0;
        long.dt = 0.002;
        let e = Live::new(long).unwrap_err().to_string();
        assert!(
            e.starts_with("duration: the playground runs at most"),
            "{e}"
        );
    }

    /// A prediction runs at most PREDICTION_WORK robot-steps ahead, and none above
    /// MAX_PREDICTED_ROBOTS robots; the simulation itself takes any count up to the limit.
    #[test]
    fn predictions_are_bounded_by_work_and_stop_above_the_robot_limit() {
        let line = |n: usize| Scenario {
            robots: (0..n)
                .map(|k| RobotSpec {
                    start: [k as f64 * 3.0, 0.0, 0.0],
                    goal: [k as f64 * 3.0, 500.0, 0.0],
                })
                .collect(),
            duration: 60.0,
            obstacles: vec![],
            ..two()
        };
        let live = Live::new(line(MAX_PREDICTED_ROBOTS)).unwrap();
        let horizon = PREDICTION_WORK / MAX_PREDICTED_ROBOTS;
        assert!(horizon < live.scenario().steps());
        let last = live.predicted_times()[live.predicted_samples() - 1];
        assert_close!(last, horizon as f64 * live.scenario().dt, 1e-9);
        let mut live = Live::new(line(MAX_PREDICTED_ROBOTS + 1)).unwrap();
        assert_eq!(live.predicted_samples(), 0);
        assert!(live.predicted().is_empty() && live.predicted_times().is_empty());
        assert_eq!(live.step(10), 10);
        assert_eq!(live.poses().len(), (MAX_PREDICTED_ROBOTS + 1) * POSE_STRIDE);
    }

    /// Trails share a fixed budget: fewer samples per robot in a crowd. When an edit changes
    /// the capacity, the newest samples are kept in time order.
    #[test]
    fn trail_rings_shrink_with_the_crowd_and_keep_the_newest_samples() {
        let s = crate::presets::crowd(100);
        let mut live = Live::new(s).unwrap();
        assert_eq!(live.trail_capacity(), TRAIL_CAPACITY);
        while live.history_len() < 1_500 {
            live.step(live.record_every);
            assert_eq!(live.trail_head(), live.recorded() % TRAIL_CAPACITY);
        }
        let (t, pose0) = (live.time(), live.poses()[..3].to_vec());
        let times = live.trail_times().to_vec();
        let head = live.trail_head();
        // 100 more robots, far outside the crowd, at t > 0.
        let mut s = live.scenario().clone();
        for k in 0..100 {
            let x = 1_000.0 + 5.0 * k as f64;
            s.robots.push(RobotSpec {
                start: [x, 0.0, 0.0],
                goal: [x, 50.0, 0.0],
            });
        }
        live.edit(s).unwrap();
        let cap = TRAIL_BUDGET / 200;
        assert!(cap < 1_500);
        assert_eq!(live.trail_capacity(), cap);
        assert_eq!(live.history_len(), cap);
        assert_eq!(live.trails().len(), 200 * cap * POSE_STRIDE);
        assert_eq!(live.trail_times().len(), cap);
        assert_eq!(live.trail_len(0), cap);
        assert_eq!(live.trail_len(199), 0);
        assert_eq!(live.recorded(), cap);
        assert_eq!(live.trail_head(), live.recorded() % cap);
        // The newest sample is still the pose now, and the times are the newest, in order.
        let newest = (live.trail_head() + cap - 1) % cap;
        assert_eq!(&live.trails()[newest * 3..newest * 3 + 3], &pose0[..]);
        assert_eq!(live.trail_times()[newest], t);
        for k in 0..cap {
            let old = (head + TRAIL_CAPACITY - cap + k) % TRAIL_CAPACITY;
            assert_eq!(live.trail_times()[k], times[old]);
        }
    }

    /// The field samples bin the robots by cell; they are those of a scan over all robots,
    /// bit for bit, in a crowd and at a zoom that puts many cells in view.
    #[test]
    fn binned_field_samples_equal_the_scan() {
        let mut live = Live::new(crate::presets::crowd(300)).unwrap();
        live.step(150);
        for (bounds, side) in [
            ([-200.0, -200.0, 200.0, 200.0], 40),
            ([150.0, -30.0, 230.0, 30.0], 23),
            ([-5e6, -5e6, 5e6, 5e6], 7),
        ] {
            let index = 17;
            let got = live
                .sample_field(index, bounds, side, side)
                .unwrap()
                .to_vec();
            let sim = live.simulation();
            let robot = &sim.robots()[index];
            let params = *sim.params();
            let rs = params.sense_radius;
            for k in 0..side * side {
                let pose = Pose::new(got[4 * k], got[4 * k + 1], robot.pose.theta);
                let neighbours: Vec<Neighbour> = sim
                    .robots()
                    .iter()
                    .enumerate()
                    .filter(|&(j, o)| j != index && o.pose.p.distance_squared(pose.p) <= rs * rs)
                    .map(|(_, o)| Neighbour {
                        position: o.pose.p,
                        speed: o.last.command.v.abs(),
                    })
                    .collect();
                let e = evaluate(
                    &params,
                    pose,
                    pose.error_to(robot.goal),
                    robot.last.command.v.abs(),
                    sim.obstacles().iter(),
                    neighbours.iter().copied(),
                );
                assert_eq!(
                    [got[4 * k + 2], got[4 * k + 3]],
                    [e.field.x, e.field.y],
                    "{bounds:?} {k}"
                );
            }
        }
    }

    /// Editing a goal at t > 0 keeps the clock and the poses, adds a robot at its start, and
    /// keeps the trails of the robots that remain.
    #[test]
    fn edits_apply_live() {
        let mut live = Live::new(two()).unwrap();
        live.step(200);
        let (t, poses, len) = (live.time(), live.poses().to_vec(), live.trail_len(0));
        let mut s = live.scenario().clone();
        s.robots[0].goal = [0.0, 10.0, 0.0];
        s.robots.push(RobotSpec {
            start: [-5.0, -5.0, 0.0],
            goal: [-5.0, 5.0, 0.0],
        });
        live.edit(s).unwrap();
        assert_eq!(live.time(), t);
        assert_eq!(&live.poses()[..6], &poses[..]);
        assert_eq!(&live.poses()[6..8], &[-5.0, -5.0]);
        assert_eq!(live.trail_len(0), len);
        assert_eq!(live.trail_len(2), 0);
        live.step(1);
        assert_eq!(
            live.trail_len(2),
            usize::from(live.steps() % live.record_every == 0)
        );
        assert_eq!(live.status().len(), 3 * STATUS_STRIDE);
        // Removing a robot drops it.
        let mut s = live.scenario().clone();
        s.robots.truncate(1);
        live.edit(s).unwrap();
        assert_eq!(live.poses().len(), 3);
        assert!(live.predicted_min_pair()[0].is_nan());
    }

    /// The field at the robot's own position is the field it follows, and it turns with the
    /// robot's attitude.
    #[test]
    fn field_samples_follow_the_robot() {
        let mut live = Live::new(two()).unwrap();
        let e = live.simulation().robots()[0].last.field;
        let grid = live
            .sample_field(0, [0.0, 0.0, 10.0, 10.0], 11, 11)
            .unwrap()
            .to_vec();
        assert_eq!(grid.len(), 11 * 11 * FIELD_STRIDE);
        assert_eq!(&grid[..2], &[0.0, 0.0]);
        assert_close!(grid[2], e.x, 1e-12);
        assert_close!(grid[3], e.y, 1e-12);
        live.move_robot(0, Pose::new(0.0, 0.0, FRAC_PI_2)).unwrap();
        let turned = live
            .sample_field(0, [0.0, 0.0, 10.0, 10.0], 11, 11)
            .unwrap();
        assert!((turned[2] - grid[2]).abs() + (turned[3] - grid[3]).abs() > 0.1);
    }

    #[test]
    fn integral_curves_end_at_the_goal() {
        let mut live = Live::new(two()).unwrap();
        let c = live
            .integral_curves(0, FRAC_PI_2, [-20.0, -20.0, 20.0, 20.0], 3)
            .unwrap();
        assert_eq!(c.len(), 9 * CURVE_POINTS * 2);
        let end = (CURVE_POINTS - 1) * 2;
        assert_close!(
            DVec2::new(c[end], c[end + 1]).distance(DVec2::new(10.0, 0.0)),
            0.0,
            0.1
        );
    }
}
