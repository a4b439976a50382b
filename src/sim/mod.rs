//! The simulation: N unicycles ([`crate::unicycle`]) under the DVF controller, a fixed step,
//! deterministic, with the metrics of the paper's figures (`metrics.rs`) and its report
//! ([`report`]); [`run()`] runs a scenario to its end.
//!
//! Each robot's `(v, ω)` is computed from the state at the start of a step (all robots from the
//! same snapshot) and held over the step, and the unicycle is integrated in closed form over it
//! ([`crate::unicycle::integrate`]). A digital controller does exactly this, so there is no
//! integration error to tune away; RK4 would instead re-evaluate the controller inside the
//! step, which no real robot does. The same input gives the same bits on every platform:
//! there is no randomness and no iteration over hashed containers, and the one parallelism
//! (a large crowd's passes over its robots on rayon's threads, natively) puts each robot's
//! result in its own slot and takes minima, which are exact in any order. The native and the
//! wasm build run the same step; only the choice of threads differs (`parallel.rs`).
//!
//! # The modules of a step
//! [`Simulation`] holds the state; its methods live beside the part of the step they serve:
//! - `lists.rs`: the Verlet lists of the robots near each robot, and when they are rebuilt;
//! - `sensing.rs`: what each robot senses (the packed records of its neighbours, the
//!   obstacles near it) and the reaches that bound it;
//! - `evaluation.rs`: each robot's command from what it senses, and where it is stored;
//! - `parallel.rs`: the passes over the robots on rayon's threads, natively;
//! - `edits.rs`: the in-place edits of a simulation that has taken no step (the playground's
//!   drags);
//! - `metrics.rs`, [`smoothness`], [`report`]: what is observed after each step and reported.
//!
//! # Where a planner enters
//! The loop (integrate, find neighbours, evaluate, observe) and the metrics know nothing of the
//! method but `Simulation::evaluation` (`evaluation.rs`), which asks the DVF controller
//! ([`crate::controller::evaluate`]) and the safety barrier ([`crate::safety::filter`]) for one
//! robot's command from what it senses, and `Simulation::plan_all` (`planned.rs`), which asks
//! another planner ([`crate::planner`], the scenario's `planner`) for every robot's command
//! and puts each through the same limits and barrier. Both share the scenario, this loop,
//! [`crate::grid`]'s neighbourhoods, the metrics and the report.

mod edits;
mod evaluation;
mod lists;
mod metrics;
mod parallel;
mod planned;
pub mod report;
pub mod run;
mod sensing;
pub mod smoothness;

pub use parallel::PARALLEL_FROM;
pub use report::{Report, RobotReport};
pub use run::{run, run_recorded, run_streamed, run_with, step_time, Sample};

use crate::controller::Evaluation;
use crate::error::Error;
use crate::grid::{Neighbours, ObstacleCells};
use crate::obstacle::Obstacle;
use crate::params::Params;
use crate::planner::Built;
use crate::scenario::Scenario;
use crate::se2::{continue_branch, heading, wrap_angle, Pose};
use crate::swarm::Neighbour;
use crate::unicycle::integrate_along;
use crate::Command;
use evaluation::Scratch;
use glam::DVec2;
use lists::moved_within;
use metrics::{Metrics, Observed};
use planned::Planned;

/// A robot's state in the simulation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Robot {
    /// Current pose, heading in `(−π, π]`.
    pub pose: Pose,
    /// Goal pose.
    pub goal: Pose,
    /// Heading error `θ̃`, continued along the trajectory (see [`continue_branch`]).
    pub heading_error: f64,
    /// The controller's last evaluation (the command held over the current step).
    pub last: Evaluation,
}

impl Robot {
    /// A robot at rest at `pose` (wrapped) bound for `goal` (wrapped), its heading error on the
    /// principal branch.
    #[must_use]
    pub fn at(pose: Pose, goal: Pose) -> Self {
        let (pose, goal) = (pose.wrapped(), goal.wrapped());
        Self {
            pose,
            goal,
            heading_error: wrap_angle(pose.theta - goal.theta),
            last: Evaluation::default(),
        }
    }
    /// Distance to the goal position.
    #[must_use]
    pub fn position_error(&self) -> f64 {
        self.pose.p.distance(self.goal.p)
    }
    /// `|wrap(θ − θ_d)|` (rad).
    #[must_use]
    pub fn heading_error_abs(&self) -> f64 {
        wrap_angle(self.pose.theta - self.goal.theta).abs()
    }
}

/// How a [`Simulation`] finds the robots near each robot (the sensed set of eq.
/// `eq_nonholo_controller_co_avoid` and the pairs of the safety metrics). Both give the same
/// bits; they differ in cost only.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Neighbourhood {
    /// A uniform grid ([`crate::grid`]): O(N) per step at bounded density.
    #[default]
    Grid,
    /// Every pair, O(N²) per step: the reference the grid is tested against.
    AllPairs,
}

/// A running simulation.
#[derive(Clone, Debug)]
pub struct Simulation {
    name: String,
    params: Params,
    dt: f64,
    independent: bool,
    obstacles: Vec<Obstacle>,
    robots: Vec<Robot>,
    time: f64,
    steps: usize,
    metrics: Metrics,
    neighbourhood: Neighbourhood,
    // The obstacles near each point (rebuilt only when an obstacle is edited).
    obstacle_cells: ObstacleCells,
    // The Verlet lists (`lists.rs`): built at `positions` for `reach` and its skin.
    near: Neighbours,
    positions: Vec<DVec2>,
    // `list_reach(&params, slowest_known)`, once: the parameters of a simulation never change.
    reach: f64,
    // Whether the step finds each robot's slowest robots within the avoidance range
    // (`sense_all`), so that the lists need not reach twice that range (`slowest_known`).
    slowest_known: bool,
    // `controller_reach(&params, slowest_known)`, once.
    controller_reach: f64,
    // Each robot as the others sense it this step (`sense_all`): its position, its speed and,
    // when `slowest_known`, the smallest speed of the robots within the avoidance range of it
    // (at another position, +∞ for none). Packed, so that the sensing loop of an evaluation
    // reads one record per listed robot.
    sensed: Vec<Neighbour>,
    // The smallest squared distance between two listed robots within the lists' reach, as the
    // evaluations of the last `evaluate_all` found it on their way (`+∞` for none), for the
    // metrics' closest pair; `None` when they did not see the whole reach (`R_s` shorter
    // than it) or an edit has evaluated some robots since.
    closest2: Option<f64>,
    // An evaluation's buffers on the calling thread, and one per chunk on threads.
    scratch: Scratch,
    scratches: Vec<Scratch>,
    // Whether a large crowd's step may run on threads (`set_parallel`).
    parallel: bool,
    commands: Vec<Command>,
    // Each command's chord (see `safety::filter`).
    chords: Vec<DVec2>,
    speeds: Vec<f64>,
    // Each robot's goal attitude as a unit vector (`heading(goal.theta)`), by which its error
    // pose and its heading error rotate at every step: the goal changes only in `place_robot`.
    goal_headings: Vec<DVec2>,
    // Each robot's heading `(cos θ, sin θ)`: taken from `θ` when the robot is placed, and then
    // turned by each step's turn `ω·dt` rather than taken again, so that a step takes no sine
    // or cosine of the heading (see `step_here`).
    headings: Vec<DVec2>,
    // Each robot's heading after its command's step (`unicycle::turned`): the barrier takes it
    // with the step's chord (`unicycle::motion`), and it is stored with the chord. Like the
    // chords, it always belongs to the robot's current command; a step swaps it with
    // `headings` once the robots have moved, and its evaluations fill it again.
    headings_after: Vec<DVec2>,
    // The scenario's planner when it is not DVF (`planned.rs`); `None` for DVF, which this
    // module's evaluation is.
    planned: Option<Planned>,
    // The planner's name in the report (`None` for `dvf`).
    planner: Option<String>,
}

impl Simulation {
    /// A simulation at time 0 of scenario `s`, finding neighbours by a grid.
    ///
    /// # Errors
    /// A scenario that [`Scenario::validate`] refuses (`dt = 0`, a NaN start, …), with the
    /// message the file reader gives, naming the field.
    pub fn new(s: &Scenario) -> Result<Self, Error> {
        Self::with_neighbourhood(s, Neighbourhood::Grid)
    }

    /// A simulation at time 0 of scenario `s`, finding neighbours as `neighbourhood` says (the
    /// result is the same either way).
    ///
    /// # Errors
    /// As [`Self::new`].
    pub fn with_neighbourhood(s: &Scenario, neighbourhood: Neighbourhood) -> Result<Self, Error> {
        s.validate()?;
        Ok(Self::of_valid(s, neighbourhood))
    }

    /// [`Self::with_neighbourhood`] of a scenario the caller has validated already (the
    /// playground checks its edits robot by robot, `Scenario::validate_robot`).
    #[must_use]
    pub(crate) fn of_valid(s: &Scenario, neighbourhood: Neighbourhood) -> Self {
        let robots: Vec<Robot> = s
            .robots
            .iter()
            .map(|r| Robot::at(r.start_pose(), r.goal_pose()))
            .collect();
        let n = robots.len();
        // A valid scenario's planner builds (`Scenario::validate`); DVF otherwise.
        let mut params = s.params;
        let planned = match s.planner.build() {
            Ok(Built::Other(planner)) => Some(Planned::new(planner)),
            Ok(Built::Dvf(avoidance)) => {
                params.avoidance = avoidance.unwrap_or(params.avoidance);
                None
            }
            Err(_) => None,
        };
        let slowest_known = !s.independent
            && neighbourhood == Neighbourhood::Grid
            && sensing::slowest_known(&params);
        let mut sim = Self {
            name: s.name.clone(),
            params,
            dt: s.dt,
            independent: s.independent,
            obstacles: s.obstacles.clone(),
            robots,
            time: 0.0,
            steps: 0,
            metrics: Metrics::new(n),
            neighbourhood,
            obstacle_cells: ObstacleCells::default(),
            near: Neighbours::new(),
            positions: Vec::with_capacity(n),
            reach: lists::list_reach(&params, slowest_known),
            controller_reach: sensing::controller_reach(&params, slowest_known),
            slowest_known,
            sensed: Vec::new(),
            closest2: None,
            scratch: Scratch::default(),
            scratches: Vec::new(),
            parallel: true,
            commands: vec![Command::default(); n],
            chords: vec![DVec2::ZERO; n],
            headings_after: vec![DVec2::ZERO; n],
            speeds: vec![0.0; n],
            goal_headings: Vec::new(),
            headings: Vec::new(),
            planned,
            planner: (!s.planner.is_default()).then(|| s.planner.name.clone()),
        };
        sim.goal_headings = sim.robots.iter().map(|r| heading(r.goal.theta)).collect();
        sim.headings = sim.robots.iter().map(|r| heading(r.pose.theta)).collect();
        sim.build_obstacle_cells();
        // Room for every obstacle to be sensed (`Scratch::obstacles`).
        sim.scratch.obstacles.reserve(sim.obstacles.len());
        sim.evaluate_all(None);
        sim.observe();
        sim
    }

    /// The robots, in scenario order.
    #[must_use]
    pub fn robots(&self) -> &[Robot] {
        &self.robots
    }
    /// The obstacles.
    #[must_use]
    pub fn obstacles(&self) -> &[Obstacle] {
        &self.obstacles
    }
    /// The parameters.
    #[must_use]
    pub fn params(&self) -> &Params {
        &self.params
    }
    /// Simulated time (s).
    #[must_use]
    pub fn time(&self) -> f64 {
        self.time
    }
    /// Steps taken.
    #[must_use]
    pub fn steps(&self) -> usize {
        self.steps
    }
    /// The step size (s).
    #[must_use]
    pub fn dt(&self) -> f64 {
        self.dt
    }
    /// Whether the robots are independent runs drawn together (they sense no robots).
    #[must_use]
    pub fn independent(&self) -> bool {
        self.independent
    }
    /// How neighbours are found.
    #[must_use]
    pub fn neighbourhood(&self) -> Neighbourhood {
        self.neighbourhood
    }

    /// Advances one step of `dt`.
    // Not inlined: the playground calls it from several places, and a call per step costs
    // nothing next to the step.
    #[inline(never)]
    pub fn step(&mut self) {
        self.on_pool(Self::step_here);
    }

    /// [`Self::step`] on the calling thread (or on one of the pool's, `on_pool`).
    fn step_here(&mut self) {
        let (dt, half) = (self.dt, self.half_skin());
        let was = &self.positions[..];
        // The integration also copies the snapshot's speeds and tests the lists' freshness,
        // robot by robot, rather than in passes of their own: on threads, each serial pass
        // lets the other threads fall asleep, to be woken after it; on one thread, it is a
        // pass over the robots fewer.
        let advance = |(i, (((r, c), chord), speed)): (usize, Advanced<'_>)| {
            *speed = r.last.command.v.abs();
            r.pose = integrate_along(r.pose, *c, dt, *chord);
            // Continued while the robot follows its goal field; back on the principal branch
            // while it circles robots, where the attitude feedback is faded out and the heading
            // error could otherwise run on to where the continued field points away from the
            // goal.
            r.heading_error = if r.last.robot_keep < 1.0 {
                wrap_angle(r.pose.theta - r.goal.theta)
            } else {
                continue_branch(r.heading_error, r.pose.theta, r.goal.theta)
            };
            was.get(i).is_some_and(|&w| moved_within(w, r.pose.p, half))
        };
        let none_moved = parallel::advance(
            self.threaded(),
            (
                &mut self.robots,
                &self.commands,
                &self.chords,
                &mut self.speeds,
            ),
            advance,
        );
        // Each robot's heading after the step, as its evaluation found it, is now its heading;
        // the evaluations below fill the other buffer.
        std::mem::swap(&mut self.headings, &mut self.headings_after);
        self.steps += 1;
        self.time = self.steps as f64 * self.dt;
        self.evaluate_all(Some(none_moved));
        self.observe();
    }

    /// Evaluates every robot's controller from the current snapshot into `last`/`commands`.
    /// Every robot sees the speeds of the same snapshot, whatever the loop order: the step's
    /// integration has copied them (`step_here`), and a new simulation's are all 0.
    ///
    /// `advanced` is `Some` when the step's integration has also tested whether no robot moved
    /// more than half the lists' skin (see [`Self::find_neighbours`]); `None` tests it here.
    fn evaluate_all(&mut self, advanced: Option<bool>) {
        self.find_neighbours(advanced);
        if self.planned.is_some() {
            self.plan_all();
            self.closest2 = None;
            return;
        }
        self.sense_all();
        let closest2 = parallel::evaluate(self);
        // The evaluations saw every listed pair within the lists' reach when their sensing
        // radius is at least that reach (`evaluation`).
        self.closest2 =
            (self.listed() && self.reach <= self.params.sense_radius).then_some(closest2);
    }

    /// Updates the metrics from the current state (after [`Self::evaluate_all`], whose
    /// neighbour lists it reuses).
    fn observe(&mut self) {
        let (reach, list_reach) = (self.sense_reach(), self.reach);
        self.metrics.observe(&Observed {
            time: self.time,
            params: &self.params,
            independent: self.independent,
            robots: &self.robots,
            obstacles: &self.obstacles,
            obstacle_cells: &self.obstacle_cells,
            neighbourhood: self.neighbourhood,
            near: &self.near,
            reach,
            list_reach,
            closest2: self.closest2,
            threaded: self.threaded(),
        });
    }

    /// The report of the run so far.
    #[must_use]
    pub fn report(&self) -> Report {
        Report {
            name: self.name.clone(),
            planner: self.planner.clone(),
            time: self.time,
            steps: self.steps,
            robots: self
                .robots
                .iter()
                .zip(&self.metrics.inside_since)
                .zip(&self.metrics.tallies)
                .map(|((r, since), tally)| RobotReport {
                    final_pose: r.pose.to_array(),
                    position_error: r.position_error(),
                    heading_error: r.heading_error_abs(),
                    converged_at: *since,
                    smoothness: *tally,
                })
                .collect(),
            min_pair_distance: self.metrics.min_pair,
            min_obstacle_clearance: self.metrics.min_clearance,
            violations: self.metrics.violations,
            smoothness: smoothness::Smoothness::of(
                &self.metrics.tallies,
                self.steps.max(1) as u64,
                self.dt,
            ),
        }
    }
}

/// A robot's slots as the step's integration advances them (`Simulation::step_here`): its
/// state, command, chord and snapshot speed.
type Advanced<'a> = (((&'a mut Robot, &'a Command), &'a DVec2), &'a mut f64);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::test;
    use std::f64::consts::PI;

    /// Continuity through θ̃ = ±π along a trajectory (docs/notes-on-the-paper.md §2): in this run (one of the
    /// 12 % of random pairs whose heading error passes ±π) the alignment term pushes θ̃ past π.
    /// Where the principal branch jumps from +π to −π its body-frame field −φ̃ flips, by more
    /// than half its length; on the continued branch the simulator uses it changes by no more
    /// than an ordinary step does. Bound: θ̃ moves by at most (k_ω·π + k_a·π/2)·dt ≈ 0.17 rad
    /// per step, near ±π ‖∂Ξ/∂θ‖ ≈ 0.93 and |p̃| ≈ 0.64·|φ̃|, so a step changes φ̃ by at most
    /// about 10 % of its length (the largest step of this run is 3.2 %).
    #[test]
    fn field_is_continuous_where_the_heading_error_crosses_pi() {
        use crate::field::goal_field_body;
        let s = Scenario::from_json(
            r#"{"duration": 20, "independent": true, "robots": [{
                "start": [24.21918875932564, 31.044578697427795, 1.8223317158733334],
                "goal": [43.44229027763088, 63.88736156275513, -1.3015366511357653]}]}"#,
        )
        .unwrap();
        let mut sim = Simulation::new(&s).unwrap();
        let field = |sim: &Simulation| {
            let r = sim.robots()[0];
            let err = Pose {
                p: r.pose.error_to(r.goal).p,
                theta: r.heading_error,
            };
            let principal = r.pose.error_to(r.goal);
            (
                goal_field_body(err),
                goal_field_body(principal),
                principal.theta,
            )
        };
        let mut prev = field(&sim);
        let mut crossings = 0;
        for _ in 0..s.steps() {
            sim.step();
            let now = field(&sim);
            let principal_jumped = (now.2 - prev.2).abs() > PI;
            if principal_jumped {
                crossings += 1;
                assert!(sim.robots()[0].heading_error.abs() > PI - 0.1);
                assert!(now.1.distance(prev.1) > 0.5 * prev.1.length());
                assert!(
                    now.0.distance(prev.0) < 0.1 * prev.0.length(),
                    "continued field jumped from {:?} to {:?}",
                    prev.0,
                    now.0
                );
            }
            prev = now;
        }
        assert!(crossings >= 1, "the run never crossed ±π");
    }

    #[test]
    fn same_input_same_bits() {
        let s = Scenario::from_json(
            r#"{"duration":5,"robots":[{"start":[0,0,0],"goal":[3,4,1]},{"start":[3,4,1],"goal":[0,0,0]}],
                "obstacles":[{"center":[1.5,2],"radius":0.3,"influence":0.8}]}"#,
        )
        .unwrap();
        let a = run(&s).unwrap();
        let b = run(&s).unwrap();
        for (x, y) in a.robots.iter().zip(&b.robots) {
            for k in 0..3 {
                assert_eq!(x.final_pose[k].to_bits(), y.final_pose[k].to_bits());
            }
        }
    }
}
