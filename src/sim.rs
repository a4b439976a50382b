//! The simulator: N unicycles (eq. `eq_kine_nonho`) under the DVF controller, a fixed step,
//! deterministic, with trajectories and the metrics of the paper's figures.
//!
//! Integration is exact for the zero-order hold the controller implies: each robot's `(v, ω)`
//! is computed from the state at the start of a step (all robots from the same snapshot) and
//! held over the step, and the unicycle is integrated in closed form over it (an arc of a
//! circle, or a segment when `ω = 0`). A digital controller does exactly this, so there is no
//! integration error to tune away; RK4 would instead re-evaluate the controller inside the step,
//! which no real robot does. The same input gives the same bits on the same platform: there is
//! no randomness, no parallelism and no iteration over hashed containers.

use crate::controller::{evaluate, Command, Evaluation};
use crate::grid::{Neighbours, ObstacleCells};
use crate::obstacle::Obstacle;
use crate::params::Params;
use crate::safety;
use crate::scenario::Scenario;
use crate::se2::{continue_branch, heading, wrap_angle, Pose};
use crate::swarm::Neighbour;
use glam::DVec2;
use serde::Serialize;

/// Below this `|ω·dt|` the arc's `sin(x)/x` is taken from its series.
const SINC_SERIES_BELOW: f64 = 1e-4;

/// The chord of one step: holding `(v, ω)` for `dt` from heading `theta` moves a unicycle by
/// `v·dt·chord(theta, ω, dt)`, that is `v·dt·sinc(ω·dt/2)` along the mean heading
/// `θ + ω·dt/2` (eq. `eq_kine_nonho` integrated in closed form over an arc).
#[inline]
#[must_use]
pub fn chord(theta: f64, omega: f64, dt: f64) -> DVec2 {
    let half = 0.5 * omega * dt;
    let sinc = if half.abs() < SINC_SERIES_BELOW {
        1.0 - half * half / 6.0
    } else {
        half.sin() / half
    };
    sinc * heading(theta + half)
}

/// Exact pose after holding `c` for `dt` from `pose` (see [`chord`]).
#[inline]
#[must_use]
pub fn integrate(pose: Pose, c: Command, dt: f64) -> Pose {
    Pose {
        p: pose.p + c.v * dt * chord(pose.theta, c.omega, dt),
        theta: wrap_angle(pose.theta + c.omega * dt),
    }
}

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
}

/// The outcome of a run (the JSON that `dvf simulate` prints).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Report {
    /// The scenario's name.
    pub name: String,
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
    // Metrics.
    inside_since: Vec<Option<f64>>,
    min_pair: Option<f64>,
    min_clearance: Option<f64>,
    violations: usize,
    // The pairs `(i, j)`, `i < j`, closer than `2·r_ij`, ascending; `pair_scratch` receives the
    // current step's before the two are swapped.
    pair_violating: Vec<(u32, u32)>,
    pair_scratch: Vec<(u32, u32)>,
    // The pairs `(robot, obstacle)` with the robot inside the disc, ascending, and the
    // current step's.
    obstacle_violating: Vec<(u32, u32)>,
    obstacle_scratch: Vec<(u32, u32)>,
    neighbourhood: Neighbourhood,
    // The obstacles near each point (static: built once).
    obstacle_cells: ObstacleCells,
    // Scratch, reused every step.
    near: Neighbours,
    positions: Vec<DVec2>,
    constraints: safety::Constraints,
    commands: Vec<Command>,
    neighbours: Vec<Neighbour>,
    speeds: Vec<f64>,
}

impl Simulation {
    /// A simulation at time 0 of a (validated) scenario, finding neighbours by a grid.
    #[must_use]
    pub fn new(s: &Scenario) -> Self {
        Self::with_neighbourhood(s, Neighbourhood::Grid)
    }

    /// A simulation at time 0 of a (validated) scenario, finding neighbours as `neighbourhood`
    /// says (the result is the same either way).
    #[must_use]
    pub fn with_neighbourhood(s: &Scenario, neighbourhood: Neighbourhood) -> Self {
        let robots: Vec<Robot> = s
            .robots
            .iter()
            .map(|r| {
                let pose = r.start_pose().wrapped();
                let goal = r.goal_pose().wrapped();
                Robot {
                    pose,
                    goal,
                    heading_error: wrap_angle(pose.theta - goal.theta),
                    last: Evaluation::default(),
                }
            })
            .collect();
        let n = robots.len();
        let mut sim = Self {
            name: s.name.clone(),
            params: s.params,
            dt: s.dt,
            independent: s.independent,
            obstacles: s.obstacles.clone(),
            robots,
            time: 0.0,
            steps: 0,
            inside_since: vec![None; n],
            min_pair: None,
            min_clearance: None,
            violations: 0,
            // Room for a violating pair per robot: a violation allocates nothing.
            pair_violating: Vec::with_capacity(n),
            pair_scratch: Vec::with_capacity(n),
            obstacle_violating: Vec::with_capacity(n),
            obstacle_scratch: Vec::with_capacity(n),
            neighbourhood,
            obstacle_cells: match neighbourhood {
                Neighbourhood::Grid => ObstacleCells::build(
                    &s.obstacles,
                    s.params.sense_radius.max(2.0 * s.params.safe_radius),
                ),
                Neighbourhood::AllPairs => ObstacleCells::all(s.obstacles.len()),
            },
            near: Neighbours::new(),
            positions: Vec::with_capacity(n),
            constraints: safety::Constraints::new(),
            commands: vec![Command::default(); n],
            neighbours: Vec::new(),
            speeds: vec![0.0; n],
        };
        sim.evaluate_all();
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
    /// How neighbours are found.
    #[must_use]
    pub fn neighbourhood(&self) -> Neighbourhood {
        self.neighbourhood
    }

    /// Makes room for `factor` times as many sensed pairs as the current step has, so that
    /// steps allocate nothing while the swarm senses fewer (the lists grow by doubling
    /// otherwise, a few times over a run whose robots close in).
    pub fn reserve_neighbours(&mut self, factor: f64) {
        self.near.reserve(factor);
    }

    /// The reach of the neighbour lists: the sensing radius, and the collision distance
    /// `2·r_ij` of the violation count should it be larger.
    fn reach(&self) -> f64 {
        self.params.sense_radius.max(2.0 * self.params.safe_radius)
    }

    /// Evaluates every robot's controller from the current snapshot into `last`/`commands`.
    fn evaluate_all(&mut self) {
        let rs = self.params.sense_radius;
        // Every robot sees the speeds of the same snapshot, whatever the loop order.
        for (s, r) in self.speeds.iter_mut().zip(&self.robots) {
            *s = r.last.command.v.abs();
        }
        let grid = !self.independent && self.neighbourhood == Neighbourhood::Grid;
        if grid {
            let reach = self.reach();
            // The positions packed together: the search reads them many times over, and a robot's
            // whole state is some 200 bytes.
            self.positions.clear();
            self.positions.extend(self.robots.iter().map(|r| r.pose.p));
            self.near.build_points(&self.positions, reach);
        }
        // The grid's lists hold the robots within its reach: when that is the sensing radius,
        // they are the sensed robots (the same test on the same bits).
        let listed_are_sensed = grid && self.reach() == rs;
        for i in 0..self.robots.len() {
            let me = self.robots[i];
            self.neighbours.clear();
            // Either way the sensed robots come in ascending index: the grid's lists are sorted.
            let mut sense = |j: usize, other: &Robot| {
                if listed_are_sensed
                    || (j != i && other.pose.p.distance_squared(me.pose.p) <= rs * rs)
                {
                    self.neighbours.push(Neighbour {
                        position: other.pose.p,
                        speed: self.speeds[j],
                    });
                }
            };
            if grid {
                for &j in self.near.of(i) {
                    sense(j as usize, &self.robots[j as usize]);
                }
            } else if !self.independent {
                for (j, other) in self.robots.iter().enumerate() {
                    sense(j, other);
                }
            }
            let err = Pose {
                p: me.pose.error_to(me.goal).p,
                theta: me.heading_error,
            };
            let mut e = self.evaluate_at(me.pose, err, self.speeds[i], &self.neighbours);
            let sensed = sensed_obstacles(&self.obstacles, &self.obstacle_cells, me.pose.p, rs);
            e.command = safety::filter_with(
                &mut self.constraints,
                &self.params,
                self.dt,
                me.pose,
                e.command,
                e.field,
                self.neighbours.iter().map(|n| n.position),
                sensed,
            );
            self.robots[i].last = e;
            self.commands[i] = e.command;
        }
    }

    /// The controller ([`evaluate`]) of a robot at `pose` with error `err` (to its goal) and
    /// speed `speed`, among the obstacles within `R_s` of it and the sensed `neighbours`: what
    /// a step computes for each robot, and what the playground samples as the field around one.
    /// One function for both, so that the controller is compiled once into the wasm module.
    #[inline(never)]
    #[must_use]
    pub fn evaluate_at(
        &self,
        pose: Pose,
        err: Pose,
        speed: f64,
        neighbours: &[Neighbour],
    ) -> Evaluation {
        let rs = self.params.sense_radius;
        evaluate(
            &self.params,
            pose,
            err,
            speed,
            sensed_obstacles(&self.obstacles, &self.obstacle_cells, pose.p, rs),
            neighbours.iter().copied(),
        )
    }

    /// Advances one step of `dt`.
    // Not inlined: the playground calls it from several places, and one copy keeps the wasm
    // module small (a call per step costs nothing next to the step).
    #[inline(never)]
    pub fn step(&mut self) {
        for (r, c) in self.robots.iter_mut().zip(&self.commands) {
            r.pose = integrate(r.pose, *c, self.dt);
            // Continued while the robot follows its goal field; back on the principal branch
            // while it circles robots, where the attitude feedback is faded out and the heading
            // error could otherwise run on to where the continued field points away from the
            // goal.
            r.heading_error = if r.last.robot_keep < 1.0 {
                wrap_angle(r.pose.theta - r.goal.theta)
            } else {
                continue_branch(r.heading_error, r.pose.theta, r.goal.theta)
            };
        }
        self.steps += 1;
        self.time = self.steps as f64 * self.dt;
        self.evaluate_all();
        self.observe();
    }

    /// Updates the metrics from the current state (after [`Self::evaluate_all`], whose
    /// neighbour lists it reuses).
    fn observe(&mut self) {
        let p = self.params;
        let reach = self.reach();
        self.obstacle_scratch.clear();
        for (i, r) in self.robots.iter().enumerate() {
            let inside =
                r.position_error() <= p.tol_position && r.heading_error_abs() <= p.tol_heading;
            match (inside, self.inside_since[i]) {
                (true, None) => self.inside_since[i] = Some(self.time),
                (false, Some(_)) => self.inside_since[i] = None,
                _ => {}
            }
            // The obstacles within the reach, as the robot senses them: the clearance metric
            // and the violations (a robot inside a disc is within every reach).
            for k in self.obstacle_cells.near(r.pose.p) {
                let c = self.obstacles[k].clearance(r.pose.p);
                if c <= reach {
                    self.min_clearance = Some(self.min_clearance.map_or(c, |m: f64| m.min(c)));
                }
                if c < 0.0 {
                    self.obstacle_scratch.push((i as u32, k as u32));
                }
            }
        }
        self.violations += new_events(&self.obstacle_violating, &self.obstacle_scratch);
        std::mem::swap(&mut self.obstacle_violating, &mut self.obstacle_scratch);
        if self.independent {
            return;
        }
        let safe = 2.0 * p.safe_radius;
        let n = self.robots.len();
        self.pair_scratch.clear();
        // The pairs in ascending (i, j), as a scan over all pairs visits them.
        let mut pair = |i: usize, j: usize, min: &mut Option<f64>| {
            let d = self.robots[i].pose.p.distance(self.robots[j].pose.p);
            *min = Some(min.map_or(d, |m: f64| m.min(d)));
            if d < safe {
                self.pair_scratch.push((i as u32, j as u32));
            }
        };
        let mut min = None;
        match self.neighbourhood {
            Neighbourhood::AllPairs => {
                for i in 0..n {
                    for j in i + 1..n {
                        pair(i, j, &mut min);
                    }
                }
            }
            Neighbourhood::Grid => {
                // Every pair closer than `2·r_ij` is in the lists (the reach is at least that),
                // and so is the closest pair whenever some pair is within the reach.
                for i in 0..n {
                    for &j in self.near.of(i) {
                        if j as usize > i {
                            pair(i, j as usize, &mut min);
                        }
                    }
                }
                // No pair within the reach: the closest pair matters only while no closer one
                // has been seen, which a swarm at bounded density leaves behind at once.
                if min.is_none() && self.min_pair.map_or(true, |m| m > reach) {
                    for i in 0..n {
                        for j in i + 1..n {
                            let d = self.robots[i].pose.p.distance(self.robots[j].pose.p);
                            min = Some(min.map_or(d, |m: f64| m.min(d)));
                        }
                    }
                }
            }
        }
        if let Some(d) = min {
            self.min_pair = Some(self.min_pair.map_or(d, |m: f64| m.min(d)));
        }
        self.violations += new_events(&self.pair_violating, &self.pair_scratch);
        std::mem::swap(&mut self.pair_violating, &mut self.pair_scratch);
    }

    /// The report of the run so far.
    #[must_use]
    pub fn report(&self) -> Report {
        Report {
            name: self.name.clone(),
            time: self.time,
            steps: self.steps,
            robots: self
                .robots
                .iter()
                .zip(&self.inside_since)
                .map(|(r, since)| RobotReport {
                    final_pose: r.pose.to_array(),
                    position_error: r.position_error(),
                    heading_error: r.heading_error_abs(),
                    converged_at: *since,
                })
                .collect(),
            min_pair_distance: self.min_pair,
            min_obstacle_clearance: self.min_clearance,
            violations: self.violations,
        }
    }
}

/// One recorded sample of one robot: `[t, x, y, θ, v, ω]`.
pub type Sample = [f64; 6];

/// The obstacles a robot at `p` senses: those whose surface is within `rs`, ascending (the
/// cells' candidates, tested).
fn sensed_obstacles<'a>(
    obstacles: &'a [Obstacle],
    cells: &'a ObstacleCells,
    p: DVec2,
    rs: f64,
) -> impl Iterator<Item = &'a Obstacle> + Clone + 'a {
    cells
        .near(p)
        .map(move |k| &obstacles[k])
        .filter(move |o| o.clearance(p) <= rs)
}

/// Violation events: the pairs violating `now` that were not at the last observation (`was`;
/// both lists ascending: a merge).
fn new_events(was: &[(u32, u32)], now: &[(u32, u32)]) -> usize {
    let mut was = was.iter().peekable();
    let mut events = 0;
    for pair in now {
        while was.next_if(|w| *w < pair).is_some() {}
        if was.next_if(|w| *w == pair).is_none() {
            events += 1;
        }
    }
    events
}

/// Runs a scenario to its end and returns the report, calling `on_step` after time 0 and
/// after every step (for recording trajectories).
pub fn run_with(s: &Scenario, mut on_step: impl FnMut(&Simulation)) -> Report {
    let mut sim = Simulation::new(s);
    on_step(&sim);
    for _ in 0..s.steps() {
        sim.step();
        on_step(&sim);
    }
    sim.report()
}

/// Runs a scenario to its end.
#[must_use]
pub fn run(s: &Scenario) -> Report {
    run_with(s, |_| {})
}

/// Runs a scenario and records every robot at every `every`-th step (and the last):
/// `trajectories[robot]` is a list of [`Sample`]s.
#[must_use]
pub fn run_recorded(s: &Scenario, every: usize) -> (Report, Vec<Vec<Sample>>) {
    let every = every.max(1);
    let total = s.steps();
    let mut traj = vec![Vec::with_capacity(total / every + 2); s.robots.len()];
    let report = run_with(s, |sim| {
        if sim.steps() % every == 0 || sim.steps() == total {
            for (k, r) in sim.robots().iter().enumerate() {
                let c = r.last.command;
                traj[k].push([
                    sim.time(),
                    r.pose.p.x,
                    r.pose.p.y,
                    r.pose.theta,
                    c.v,
                    c.omega,
                ]);
            }
        }
    });
    (report, traj)
}

#[cfg(test)]
mod tests {
    use super::*;
    // The same tests run natively and in Chromium (`wasm-pack test --headless --chrome`).
    use crate::approx::assert_close;
    use std::f64::consts::PI;
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    /// Closed-form integration against a fine Euler integration of the same held command.
    #[test]
    fn integration_is_exact_for_a_held_command() {
        let start = Pose::new(1.0, 2.0, 0.4);
        for c in [
            Command { v: 3.0, omega: 2.0 },
            Command {
                v: -1.0,
                omega: -0.5,
            },
            Command { v: 2.0, omega: 0.0 },
            Command {
                v: 2.0,
                omega: 1e-9,
            },
        ] {
            let exact = integrate(start, c, 0.5);
            let mut h = start;
            let n = 200_000;
            for _ in 0..n {
                let dt = 0.5 / n as f64;
                h.p += c.v * dt * heading(h.theta + 0.5 * c.omega * dt);
                h.theta += c.omega * dt;
            }
            // The reference sums 2e5 increments: its round-off alone reaches ~1e-11, so the
            // closed form is checked to 1e-9 in position and 1e-10 rad in heading.
            assert_close!(exact.p.distance(h.p), 0.0, 1e-9);
            assert_close!(wrap_angle(exact.theta - h.theta), 0.0, 1e-10);
        }
    }

    /// Continuity through θ̃ = ±π along a trajectory (MATH-NOTES §2): in this run (one of the
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
        let mut sim = Simulation::new(&s);
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
        let a = run(&s);
        let b = run(&s);
        for (x, y) in a.robots.iter().zip(&b.robots) {
            for k in 0..3 {
                assert_eq!(x.final_pose[k].to_bits(), y.final_pose[k].to_bits());
            }
        }
    }
}
