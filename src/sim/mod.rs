//! The simulation: N unicycles ([`crate::unicycle`]) under the DVF controller, a fixed step,
//! deterministic, with the metrics of the paper's figures (`metrics.rs`) and its report
//! ([`report`]); [`run()`] runs a scenario to its end.
//!
//! Each robot's `(v, ω)` is computed from the state at the start of a step (all robots from the
//! same snapshot) and held over the step, and the unicycle is integrated in closed form over it
//! ([`crate::unicycle::integrate`]). A digital controller does exactly this, so there is no
//! integration error to tune away; RK4 would instead re-evaluate the controller inside the
//! step, which no real robot does. The same input gives the same bits on the same platform:
//! there is no randomness and no iteration over hashed containers, and the one parallelism
//! (a large crowd's passes over its robots on rayon's threads, natively) puts each robot's
//! result in its own slot and takes minima, which are exact in any order.
//!
//! Over 500 lines with its tests: the loop, the robot's state and the two in-place edits
//! (`place_robot`, `place_obstacle`) share the loop's private state (the neighbour lists, the
//! snapshot speeds); apart, that state would have to be public.
//!
//! # Where a planner enters
//! The loop (integrate, find neighbours, evaluate, observe) and the metrics know nothing of the
//! method but `Simulation::evaluation`, which asks the DVF controller
//! ([`crate::controller::evaluate`]) and the safety barrier ([`crate::safety::filter`]) for one
//! robot's command from what it senses. A baseline planner (ORCA, a unicycle CLF controller
//! with the barrier, the dipole field) would be a module beside `controller` and a branch
//! there, sharing the scenario, this loop, [`crate::grid`]'s neighbourhoods, the metrics and
//! the report.

mod metrics;
pub mod report;
pub mod run;
pub mod smoothness;

pub use report::{Report, RobotReport};
pub use run::{run, run_recorded, run_with, Sample};

use crate::controller::{evaluate_facing, Evaluation, Facing};
use crate::grid::{Neighbours, ObstacleCells};
use crate::obstacle::Obstacle;
use crate::params::{Avoidance, Params};
use crate::safety;
use crate::scenario::Scenario;
use crate::se2::{continue_branch, heading, unrotate_by, wrap_angle, Pose};
use crate::swarm::{at_rest_beside, cluster_reach, pair_range, Neighbour, SLOWEST_UNKNOWN};
use crate::unicycle::{integrate_along, Motion};
use crate::Command;
use glam::DVec2;
use metrics::{Metrics, Observed};

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
    // Scratch, reused every step.
    // The Verlet lists (see `find_neighbours`): built at `positions` for `reach` and its skin.
    near: Neighbours,
    positions: Vec<DVec2>,
    // `list_reach(&params)`, once: the parameters of a simulation never change.
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
    scratch: Scratch,
    // The parallel step (native only): whether it is on, and its buffers (one per chunk).
    #[cfg(not(target_arch = "wasm32"))]
    parallel: bool,
    #[cfg(not(target_arch = "wasm32"))]
    scratches: Vec<Scratch>,
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
            .map(|r| Robot::at(r.start_pose(), r.goal_pose()))
            .collect();
        let n = robots.len();
        let slowest_known =
            !s.independent && neighbourhood == Neighbourhood::Grid && slowest_known(&s.params);
        let mut sim = Self {
            name: s.name.clone(),
            params: s.params,
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
            reach: list_reach(&s.params, slowest_known),
            controller_reach: controller_reach(&s.params, slowest_known),
            slowest_known,
            sensed: Vec::new(),
            closest2: None,
            scratch: Scratch::default(),
            #[cfg(not(target_arch = "wasm32"))]
            parallel: true,
            #[cfg(not(target_arch = "wasm32"))]
            scratches: Vec::new(),
            commands: vec![Command::default(); n],
            chords: vec![DVec2::ZERO; n],
            headings_after: vec![DVec2::ZERO; n],
            speeds: vec![0.0; n],
            goal_headings: Vec::new(),
            headings: Vec::new(),
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

    /// Makes room for `factor` times as many sensed pairs as the current step has, so that
    /// steps allocate nothing while the swarm senses fewer (the lists grow by doubling
    /// otherwise, a few times over a run whose robots close in).
    pub fn reserve_neighbours(&mut self, factor: f64) {
        self.near.reserve(factor);
        // The barrier's constraints: a robot's listed neighbours (without lists, every robot)
        // and the obstacles at most.
        let longest = if self.listed() {
            (0..self.robots.len())
                .map(|i| self.near.of(i).len())
                .max()
                .unwrap_or(0)
        } else {
            self.robots.len()
        };
        let obstacles = self.obstacles.len();
        let most = (longest as f64 * factor) as usize + obstacles;
        let reserve = |scratch: &mut Scratch| {
            scratch.constraints.reserve(most);
            // The sensing loop's two runs take up to twice a list (`evaluation`).
            let have = scratch.neighbours.len();
            scratch.neighbours.reserve((2 * most).saturating_sub(have));
            // The sensed obstacles: all of them at most.
            scratch.obstacles.reserve(obstacles);
        };
        reserve(&mut self.scratch);
        #[cfg(not(target_arch = "wasm32"))]
        self.scratches.iter_mut().for_each(reserve);
    }

    /// The reach of what a robot senses: the sensing radius, and the collision distance
    /// `2·r_ij` of the violation count should it be larger (the obstacles' cells and the
    /// clearance metric).
    fn sense_reach(&self) -> f64 {
        self.params.sense_radius.max(2.0 * self.params.safe_radius)
    }

    fn build_obstacle_cells(&mut self) {
        self.obstacle_cells = match self.neighbourhood {
            Neighbourhood::Grid => ObstacleCells::build(&self.obstacles, self.sense_reach()),
            Neighbourhood::AllPairs => ObstacleCells::all(self.obstacles.len()),
        };
    }

    /// Whether the robots' neighbours come from the grid's lists.
    fn listed(&self) -> bool {
        !self.independent && self.neighbourhood == Neighbourhood::Grid
    }

    /// Keeps the grid's lists holding every pair within `list_reach` where the robots are
    /// now. They are built for a reach widened by a skin of [`SKIN`]`·reach` (Verlet lists):
    /// while no robot has moved more than half the skin since, a pair within the reach now was
    /// within the widened reach then. Once some robot has, they are kept while a search around
    /// the robots that have finds them still whole ([`Self::lists_still_hold`]), and rebuilt
    /// otherwise. Readers test the distance (the evaluation, the metrics,
    /// `min_listed_pair_distance`), so they see exactly the pairs within the reach, in
    /// ascending index, whenever the lists were built. A crowd at 20 m/s (reach 10 m, skin
    /// 2.5 m) rebuilds about every seventh step in open space, and every twelfth in its jam.
    ///
    /// `none_moved` is whether no robot has moved more than half the skin since, when the
    /// caller has found it already (the step's integration, on threads); `None` tests it here.
    fn find_neighbours(&mut self, none_moved: Option<bool>) {
        if !self.listed() {
            return;
        }
        // Never built (`positions` is empty until then), or some robot moved too far since and
        // the lists miss a pair.
        let fresh = self.positions.len() == self.robots.len()
            && (none_moved.unwrap_or_else(|| self.none_moved_beyond(self.half_skin()))
                || self.lists_still_hold());
        if !fresh {
            // The positions packed together: the search reads them many times over, and a
            // robot's whole state is some 200 bytes.
            self.positions.clear();
            self.positions.extend(self.robots.iter().map(|r| r.pose.p));
            let built = self.built_reach();
            if self.threaded() {
                #[cfg(not(target_arch = "wasm32"))]
                self.near.build_on_threads(&self.positions, built);
            } else {
                self.near.build(&self.positions, built);
            }
        }
    }

    /// Whether the lists still hold every pair within their reach, once some robot has moved
    /// more than half the skin since they were built: a pair of robots that have each moved
    /// less is within the widened reach still (see [`Self::find_neighbours`]), and the pairs of
    /// the robots that have moved more are looked for in the cells of the lists' last build
    /// ([`Neighbours::list_all_near`]), which hold every robot that has moved less than the
    /// whole skin. The lists are rebuilt instead once a robot has moved farther, or once more
    /// than one robot in [`MOVED_SHARE`] has moved more than half the skin.
    ///
    /// In a jam a few robots move at the speed limit and the rest crawl: the lists are then
    /// rebuilt about when the fastest robot nears the whole skin rather than half of it. The
    /// crowd of 1,000 from t = 42 s: the first robot crosses half the skin 7 steps after a
    /// build, 13 robots then, 74 by the eleventh step and 92 by the twelfth, when the lists are
    /// rebuilt. In open space every robot moves about as fast as the fastest, and the lists
    /// are rebuilt as before.
    ///
    /// The wasm build rebuilds instead, at half the skin: this search is 822 bytes of its
    /// module, which stays under 250 KB (README, Performance, "The lists kept past half their
    /// skin").
    fn lists_still_hold(&self) -> bool {
        if cfg!(target_arch = "wasm32") {
            return false;
        }
        let half = self.half_skin();
        let whole = 2.0 * half;
        let most = self.robots.len() / MOVED_SHARE;
        let mut moved = 0;
        for (&was, r) in self.positions.iter().zip(&self.robots) {
            if !moved_within(was, r.pose.p, whole) {
                return false;
            }
            moved += usize::from(!moved_within(was, r.pose.p, half));
            if moved > most {
                return false;
            }
        }
        let (reach, built) = (self.reach, self.built_reach());
        let now = |i: usize| self.robots[i].pose.p;
        (self.positions.iter().zip(&self.robots).enumerate()).all(|(j, (&was, r))| {
            moved_within(was, r.pose.p, half)
                || self
                    .near
                    .list_all_near(&self.positions, now, j, reach, built)
        })
    }

    /// The reach the lists are built for: their reach widened by the skin. The search of
    /// [`Self::lists_still_hold`] takes the build's test again with it, so both take it here.
    fn built_reach(&self) -> f64 {
        self.reach + SKIN * self.reach
    }

    /// How far a robot may move before the lists are rebuilt: half their skin, less the
    /// round-off of a few ulps in the distances, which must not spend the whole skin.
    fn half_skin(&self) -> f64 {
        let skin = SKIN * self.reach;
        0.5 * skin * (1.0 - 1e-6)
    }

    /// Whether no robot has moved more than `half` since the lists were built at `positions`
    /// (a pass of its own on one thread; a step on threads finds it while it integrates).
    fn none_moved_beyond(&self, half: f64) -> bool {
        self.positions
            .iter()
            .zip(&self.robots)
            .all(|(&was, r)| moved_within(was, r.pose.p, half))
    }

    /// Each robot as the others sense it this step, into `sensed`: its position, its speed
    /// and, when the step knows it ([`slowest_known`]), its slowest robot within the
    /// avoidance range of it (at another position), from the lists and the snapshot's speeds.
    /// A robot deciding whether a neighbour stands in a parked formation reads that
    /// ([`Neighbour::slowest_near`]) instead of searching its own neighbours around that one.
    /// The same answer, since it would find the same robots: with `R_s` at least twice the
    /// range, every robot within the range of a neighbour within the range is sensed. The
    /// deciding robot itself may be the slowest, which changes nothing: it is never at rest
    /// next to itself (`swarm::AT_REST_RATIO` < 1), nor is any robot at least as fast.
    ///
    /// A robot's slowest neighbour is read only when that robot is at rest beside the robot
    /// deciding (`swarm::in_a_parked_formation`), and a robot deciding moves at most as fast
    /// as the fastest robot, or at the circling speed `v_c` on an obstacle's surface
    /// (`Approach::speed`): the robots not at rest beside the faster of those two are given
    /// `+∞` without a search, which nothing reads. In open space that is every robot.
    ///
    /// One record per robot and step, read by every robot that lists it: the sensing loop of
    /// an evaluation copies it whole rather than gathering position, speed and slowest robot
    /// from three arrays (one of them the robots' whole states).
    fn sense_all(&mut self) {
        if self.independent {
            return;
        }
        let known = self.slowest_known;
        let range = pair_range(self.params.avoid_radius, self.params.transition_width);
        let range2 = range * range;
        let fastest = self
            .speeds
            .iter()
            .fold(self.params.avoid_speed, |m, &s| if s > m { s } else { m });
        let mut out = std::mem::take(&mut self.sensed);
        // The robots and their speeds walked together, the search out of line: a robot that
        // is not at rest (every one in open space) costs a comparison and a copy.
        let record = |(n, (r, &speed)): (usize, (&Robot, &f64))| Neighbour {
            position: r.pose.p,
            speed,
            slowest_near: if !known {
                SLOWEST_UNKNOWN
            } else if at_rest_beside(speed, fastest) {
                self.slowest_near(n, range2)
            } else {
                f64::INFINITY
            },
        };
        if self.threaded() {
            #[cfg(not(target_arch = "wasm32"))]
            {
                use rayon::prelude::*;
                self.robots
                    .par_iter()
                    .zip(&self.speeds[..])
                    .enumerate()
                    .with_min_len(CHEAP_CHUNK)
                    .map(record)
                    .collect_into_vec(&mut out);
            }
        } else {
            out.clear();
            out.extend(self.robots.iter().zip(&self.speeds).enumerate().map(record));
        }
        self.sensed = out;
    }

    /// The smallest snapshot speed of the robots within `√range2` of robot `n` (at another
    /// position), from its list: [`Self::sense_all`]'s search, for a robot at rest.
    #[inline(never)]
    fn slowest_near(&self, n: usize, range2: f64) -> f64 {
        let p = self.robots[n].pose.p;
        let mut slowest = f64::INFINITY;
        for &m in self.near.of(n) {
            let q = self.robots[m as usize].pose.p;
            // Without a branch to mispredict (in a jam about half the listed robots are in the
            // range): a select, which is also one instruction in wasm, where `f64::min` is a
            // call (to `fmin`, for its rule on NaN). The same minimum: speeds are `|v|`, never
            // NaN nor −0.
            let near = (q != p) & (q.distance_squared(p) <= range2);
            let speed = self.speeds[m as usize];
            slowest = if near & (speed < slowest) {
                speed
            } else {
                slowest
            };
        }
        slowest
    }

    /// Evaluates every robot's controller from the current snapshot into `last`/`commands`.
    /// Every robot sees the speeds of the same snapshot, whatever the loop order: the step's
    /// integration has copied them (`step_here`), and a new simulation's are all 0.
    ///
    /// `advanced` is `Some` when the step's integration has also tested whether no robot moved
    /// more than half the lists' skin (see [`Self::find_neighbours`]); `None` tests it here.
    fn evaluate_all(&mut self, advanced: Option<bool>) {
        self.find_neighbours(advanced);
        self.sense_all();
        self.scratch.closest2 = f64::INFINITY;
        #[cfg(not(target_arch = "wasm32"))]
        let parallel = self.evaluate_in_parallel();
        #[cfg(target_arch = "wasm32")]
        let parallel = false;
        if !parallel {
            // The buffers taken out of `self` once for all robots, not once per robot.
            let mut scratch = std::mem::take(&mut self.scratch);
            // Natively in runs that store their evaluations a few dozen at a time
            // (`evaluate_run`), as on threads. The wasm build stores each as it comes, with
            // less code.
            #[cfg(not(target_arch = "wasm32"))]
            {
                let mut slots = self.take_slots();
                self.evaluate_run(0, slots.run(), &mut scratch);
                self.put_slots(slots);
            }
            #[cfg(target_arch = "wasm32")]
            for i in 0..self.robots.len() {
                self.evaluate_robot_with(i, &mut scratch);
            }
            self.scratch = scratch;
        }
        #[cfg(not(target_arch = "wasm32"))]
        let closest2 = if parallel {
            self.scratches
                .iter()
                .fold(f64::INFINITY, |m, s| m.min(s.closest2))
        } else {
            self.scratch.closest2
        };
        #[cfg(target_arch = "wasm32")]
        let closest2 = self.scratch.closest2;
        // The evaluations saw every listed pair within the lists' reach when their sensing
        // radius is at least that reach (`evaluation`).
        self.closest2 =
            (self.listed() && self.reach <= self.params.sense_radius).then_some(closest2);
    }

    /// Robot `i`'s command from what it senses now, into `last`/`commands` (see
    /// [`Self::evaluation`]): for the in-place edits, which evaluate a few robots.
    fn evaluate_robot(&mut self, i: usize) {
        let mut scratch = std::mem::take(&mut self.scratch);
        self.evaluate_robot_with(i, &mut scratch);
        self.scratch = scratch;
    }

    /// [`Self::evaluate_robot`] with the buffers of `scratch`, taken out of `self` by the caller
    /// (a step, once for all its robots).
    // Not inlined: a step and the in-place edits call it, and one copy keeps the wasm module
    // small (a call per robot costs nothing next to its evaluation).
    #[inline(never)]
    fn evaluate_robot_with(&mut self, i: usize, scratch: &mut Scratch) {
        // Stored from where the evaluation returned it, not taken apart and put together again
        // first: the copy then reads the memory in the pieces the evaluation wrote it in, and
        // the processor forwards each piece from its store (a read across two stores waits for
        // both to reach the cache: in open space a twentieth of the step's time went there).
        let mut evaluated = (Evaluation::default(), Motion::default());
        self.evaluation(i, &self.robots[i], scratch, &mut evaluated);
        put(
            (
                &mut self.robots[i],
                &mut self.commands[i],
                &mut self.chords[i],
                &mut self.headings_after[i],
            ),
            &evaluated,
        );
    }

    /// Robot `i`'s command from what it senses now (the robots within `R_s` at the snapshot's
    /// speeds, the obstacles within `R_s`): the DVF controller made safe by the barrier, with
    /// the chord of its step. The one place where the method enters the loop (see the module
    /// doc). It reads the snapshot only, so robots can be evaluated in any order or at once.
    // Inlined into its one caller in the wasm build (which has no parallel step): smaller.
    // Natively out of line: inlined into `evaluate_run`, it took 2 % more instructions in the
    // jam, and 4.5 % more where it was inlined before.
    #[cfg_attr(target_arch = "wasm32", inline(always))]
    #[cfg_attr(not(target_arch = "wasm32"), inline(never))]
    fn evaluation(
        &self,
        i: usize,
        me: &Robot,
        scratch: &mut Scratch,
        out: &mut (Evaluation, Motion),
    ) {
        let rs = self.params.sense_radius;
        let listed = self.listed();
        // The grid's lists hold the robots within their reach: when that is at most the sensing
        // radius, they are the sensed robots that can change the command (see `reach`).
        let r = if listed { self.reach.min(rs) } else { rs };
        let r2 = r * r;
        let neighbours = &mut scratch.neighbours;
        let p = me.pose.p;
        // The error pose, and the heading and the heading error's cosine and sine (the heading
        // rotated back by the goal's) for the controller and the barrier: taken before the
        // sensing loop, whose end the processor mispredicts when the number of listed robots
        // varies, so that the controller finds them ready when it starts again there (the jam
        // of the crowd of 1,000: 1.7 % less time a step than with them taken after the loop).
        let err = Pose {
            p: self.error_position(i, me),
            theta: me.heading_error,
        };
        let h = self.headings[i];
        let facing = Facing {
            heading: h,
            error: unrotate_by(self.goal_headings[i], h),
        };
        // The sensed robots within the controller's reach, as a count of the buffer's first
        // slots, and the others sensed, as a range of its slots. Either way those within reach
        // come in ascending index: the grid's lists are sorted.
        let split = self.controller_reach.min(r);
        let (count, others) = if listed {
            // Each listed robot's record (`sense_all`) written in the next free slot of one of
            // two runs, and kept by moving that run's end when it is sensed: no branch to
            // mispredict (in a jam about a third of the listed robots lie in the lists' skin).
            // The lists never hold the robot itself.
            // The first run, from the buffer's start in ascending index, holds the sensed
            // robots within the controller's reach (`controller_reach`); the second, from the
            // end down, the others sensed, which only the barrier reads. The controller is then
            // given the first alone: the virtual obstacle's choice (`swarm::cluster`) tests
            // every robot it is given for the avoidance range, and in a jam that test was a
            // coin toss (six of ten sensed robots within it). The same bits: the controller
            // sees the robots it can use in the same order, and the barrier's limits are minima
            // and maxima, whatever the order.
            // On the way, the closest listed robot, for the metrics' closest pair (the least
            // squared distance over the robots' lists is that of the closest pair, each pair
            // being seen from both ends, with the same bits: (a − b)² = (b − a)²). The nearest
            // listed robot is sensed exactly when any is, and is then the nearest sensed: the
            // loop keeps it by a select alone (`minsd`) and compares it with the radius once.
            // The buffer only grows, so that it is not filled anew for every robot: its slots
            // outside the runs hold robots of earlier evaluations, never read.
            let list = self.near.of(i);
            let len = list.len();
            if neighbours.len() < 2 * len {
                neighbours.resize(2 * len, Neighbour::default());
            }
            let split2 = split * split;
            // The first run's end, and the second's start: it grows down from the buffer's
            // end, and its next slot `far − 1` stays above the first run's slots (at least
            // `len` while a listed robot is left to place).
            let (mut near, mut far) = (0, 2 * len);
            let mut nearest2 = f64::INFINITY;
            for &j in list {
                let neighbour = self.sensed[j as usize];
                let d2 = neighbour.position.distance_squared(p);
                let within = d2 <= split2;
                neighbours[std::hint::select_unpredictable(within, near, far - 1)] = neighbour;
                near += usize::from(within);
                // Those within the controller's reach are sensed (`split ≤ r`): the second run
                // takes the others sensed.
                far -= usize::from(d2 <= r2) - usize::from(within);
                nearest2 = if d2 < nearest2 { d2 } else { nearest2 };
            }
            if nearest2 <= r2 && nearest2 < scratch.closest2 {
                scratch.closest2 = nearest2;
            }
            (near, far..2 * len)
        } else if !self.independent {
            neighbours.clear();
            neighbours.extend(
                self.sensed
                    .iter()
                    .enumerate()
                    .filter(|&(j, n)| j != i && n.position.distance_squared(p) <= r2)
                    .map(|(_, &n)| n),
            );
            (neighbours.len(), 0..0)
        } else {
            (0, 0..0)
        };
        let (near, far) = (&neighbours[..count], &neighbours[others]);
        // The sensed obstacles, found once for the controller's passes and the barrier's (none
        // to look up in a scene without obstacles, a crowd's).
        let sensed = &mut scratch.obstacles;
        sensed.clear();
        if !self.obstacles.is_empty() {
            sensed.extend(self.sensed_obstacles(me.pose.p));
        }
        // Written in its slot and changed there, not returned: a copy would read the command
        // in one piece right after the barrier wrote it in two, and wait for both writes
        // to reach the cache (in open space about 5 % of the step's time).
        let e = &mut out.0;
        self.evaluate_facing(me.pose, facing, err, self.speeds[i], near, sensed, e);
        let sensed = sensed.iter().map(|&k| &self.obstacles[k as usize]);
        // The neighbours the barrier can bind on at this speed (the others change nothing).
        // The second run lies beyond the controller's reach: only a robot whose barrier reaches
        // farther reads it (a slow robot's reaches 2.8 m in a crowd, the controller's 8): in the
        // jam of the crowd of 1,000, 1 % less time a step, and the same bits.
        let binding = safety::neighbour_reach(&self.params, e.command.v);
        let binding2 = binding * binding;
        (e.command, out.1) = safety::filter_facing(
            &mut scratch.constraints,
            &self.params,
            self.dt,
            me.pose.p,
            h,
            e.command,
            e.field,
            near.iter()
                .chain(if binding > split { far } else { &[] })
                .map(|n| n.position)
                .filter(|q| q.distance_squared(me.pose.p) <= binding2),
            sensed,
        );
    }

    /// Robot `i`'s `pose.error_to(goal).p`, with its goal's sine and cosine taken once
    /// (`goal_headings`): the same bits.
    #[inline]
    fn error_position(&self, i: usize, me: &Robot) -> DVec2 {
        unrotate_by(self.goal_headings[i], me.pose.p - me.goal.p)
    }

    /// Evaluates the robots `base..` whose slots `run` holds (taken out of the simulation,
    /// which the evaluations read meanwhile), with the buffers of `scratch`. Each evaluation is
    /// written in a buffer of [`STORED_BY`] that stays in the first-level cache, and the
    /// buffer is stored once full: copied to its robot right after it was written, an
    /// evaluation is read in other pieces than it was written in, and each read across two
    /// writes waits for both to reach the cache (in open space about 5 % of the step's time).
    // Not inlined: one copy for one thread and for each chunk on threads, with the evaluation
    // kept out of line (inlined into such a run, one thread took 10–20 % longer).
    #[cfg(not(target_arch = "wasm32"))]
    #[inline(never)]
    fn evaluate_run(&self, base: usize, run: Run<'_>, scratch: &mut Scratch) {
        let (robots, commands, chords, after) = run;
        let mut block = std::mem::take(&mut scratch.evaluated);
        block.resize(STORED_BY, (Evaluation::default(), Motion::default()));
        for start in (0..robots.len()).step_by(STORED_BY) {
            let end = (start + STORED_BY).min(robots.len());
            for ((j, me), slot) in (start..end).zip(&robots[start..end]).zip(&mut block) {
                self.evaluation(base + j, me, scratch, slot);
            }
            for ((((r, command), chord), after), evaluated) in robots[start..end]
                .iter_mut()
                .zip(&mut commands[start..end])
                .zip(&mut chords[start..end])
                .zip(&mut after[start..end])
                .zip(&block)
            {
                put((r, command, chord, after), evaluated);
            }
        }
        scratch.evaluated = block;
    }

    /// The robots' slots that an evaluation writes, taken out of the simulation while the
    /// evaluations read it ([`Self::evaluate_run`]); [`Self::put_slots`] puts them back.
    #[cfg(not(target_arch = "wasm32"))]
    fn take_slots(&mut self) -> Slots {
        Slots {
            robots: std::mem::take(&mut self.robots),
            commands: std::mem::take(&mut self.commands),
            chords: std::mem::take(&mut self.chords),
            after: std::mem::take(&mut self.headings_after),
        }
    }

    /// Puts back the slots [`Self::take_slots`] took.
    #[cfg(not(target_arch = "wasm32"))]
    fn put_slots(&mut self, slots: Slots) {
        self.robots = slots.robots;
        self.commands = slots.commands;
        self.chords = slots.chords;
        self.headings_after = slots.after;
    }

    /// Evaluates every robot on the threads of rayon's pool, in chunks, each with its own
    /// buffers and storing its own robots (`evaluate_run`): the same bits as one after the
    /// other (each evaluation reads the snapshot only, and lands in its own slots). Returns
    /// `false`, doing nothing, below [`PARALLEL_FROM`] robots, on one thread, or when
    /// [`Self::set_parallel`] turned it off.
    #[cfg(not(target_arch = "wasm32"))]
    fn evaluate_in_parallel(&mut self) -> bool {
        use rayon::prelude::*;
        if !self.threaded() {
            return false;
        }
        let n = self.robots.len();
        // A few chunks per thread, so that one slow chunk does not hold the others up.
        let chunks = 4 * rayon::current_num_threads();
        let size = n.div_ceil(chunks);
        let mut scratches = std::mem::take(&mut self.scratches);
        scratches.resize_with(chunks, Scratch::default);
        for s in &mut scratches {
            s.closest2 = f64::INFINITY;
        }
        let mut slots = self.take_slots();
        let this = &*self;
        (
            slots.robots.par_chunks_mut(size),
            slots.commands.par_chunks_mut(size),
            slots.chords.par_chunks_mut(size),
            slots.after.par_chunks_mut(size),
            scratches.par_iter_mut(),
        )
            .into_par_iter()
            .enumerate()
            .for_each(|(k, (robots, commands, chords, after, scratch))| {
                this.evaluate_run(k * size, (robots, commands, chords, after), scratch);
            });
        self.put_slots(slots);
        self.scratches = scratches;
        true
    }

    /// Whether this step's passes over the robots run on rayon's threads: from
    /// [`PARALLEL_FROM`] robots, on two threads or more, unless [`Self::set_parallel`] turned
    /// it off. Never in the wasm build, which has no threads.
    #[cfg_attr(target_arch = "wasm32", allow(clippy::unused_self))]
    fn threaded(&self) -> bool {
        #[cfg(not(target_arch = "wasm32"))]
        return self.parallel
            && self.robots.len() >= PARALLEL_FROM
            && rayon::current_num_threads() >= 2;
        #[cfg(target_arch = "wasm32")]
        false
    }

    /// Whether a step of a large crowd evaluates its robots on several threads (natively, with
    /// rayon; on by default). The same bits either way: this only chooses the cost, for
    /// instance to measure one thread against several, or for a caller that runs many
    /// simulations on the threads already.
    #[cfg_attr(target_arch = "wasm32", allow(clippy::unused_self, unused_variables))]
    pub fn set_parallel(&mut self, on: bool) {
        #[cfg(not(target_arch = "wasm32"))]
        {
            self.parallel = on;
        }
    }

    /// The controller ([`crate::controller::evaluate`]) of a robot at `pose` with error `err`
    /// (to its goal) and speed `speed`, among the obstacles within `R_s` of it and the sensed
    /// `neighbours`: what a step computes for each robot, and what the playground samples as
    /// the field around one. One function for both (through `evaluate_facing`), so that the
    /// controller is compiled once into the wasm module.
    #[inline]
    #[must_use]
    pub fn evaluate_at(
        &self,
        pose: Pose,
        err: Pose,
        speed: f64,
        neighbours: &[Neighbour],
    ) -> Evaluation {
        self.evaluate_at_with(pose, err, speed, neighbours, &mut Vec::new())
    }

    /// [`Self::evaluate_at`] with a buffer for the indices of the obstacles it senses, reused
    /// from call to call by a caller that samples many points (the playground's field view),
    /// so that a call allocates nothing once the buffer has grown.
    #[inline]
    #[must_use]
    pub fn evaluate_at_with(
        &self,
        pose: Pose,
        err: Pose,
        speed: f64,
        neighbours: &[Neighbour],
        obstacles: &mut Vec<u32>,
    ) -> Evaluation {
        obstacles.clear();
        obstacles.extend(self.sensed_obstacles(pose.p));
        let mut e = Evaluation::default();
        self.evaluate_facing(
            pose,
            Facing::of(pose.theta, err.theta),
            err,
            speed,
            neighbours,
            obstacles,
            &mut e,
        );
        e
    }

    /// The obstacles a robot at `p` senses: those whose surface is within `R_s`, as indices in
    /// ascending order (the cells' candidates, tested).
    fn sensed_obstacles(&self, p: DVec2) -> impl Iterator<Item = u32> + '_ {
        let rs = self.params.sense_radius;
        self.obstacle_cells
            .near(p)
            .filter(move |&k| self.obstacles[k].clearance(p) <= rs)
            .map(|k| k as u32)
    }

    /// [`Self::evaluate_at`] with the heading and heading error of `pose` taken by the caller
    /// ([`evaluate_facing`]) and the obstacles it senses found already
    /// ([`Self::sensed_obstacles`]).
    // Not inlined, natively either: inlined into the step's evaluation it took 1.6 % fewer
    // instructions and 2–5 % more time (the crowd of 1,000, open space and the jam).
    // Its evaluation written through `out` rather than returned: returned, it went through
    // a temporary whose copy read it in other pieces than it was written in, and waited for
    // the writes to reach the cache. That takes an eighth argument.
    #[inline(never)]
    #[allow(clippy::too_many_arguments)]
    fn evaluate_facing(
        &self,
        pose: Pose,
        facing: Facing,
        err: Pose,
        speed: f64,
        neighbours: &[Neighbour],
        sensed: &[u32],
        out: &mut Evaluation,
    ) {
        *out = evaluate_facing(
            &self.params,
            pose,
            facing,
            err,
            speed,
            sensed.iter().map(|&k| &self.obstacles[k as usize]),
            neighbours.iter().copied(),
        );
    }

    /// Advances one step of `dt`.
    // Not inlined: the playground calls it from several places, and one copy keeps the wasm
    // module small (a call per step costs nothing next to the step).
    #[inline(never)]
    pub fn step(&mut self) {
        #[cfg(not(target_arch = "wasm32"))]
        if self.threaded() && rayon::current_thread_index().is_none() {
            // Moved onto one of the pool's threads, the step's passes hand work to the others
            // and take it back there, instead of putting this thread to sleep and waking it at
            // the end of each pass (measured: two threads took 0.72–0.89 of one thread's time
            // with a wake-up per pass, 0.65–0.67 without).
            return rayon::scope(|_| self.step_here());
        }
        self.step_here();
    }

    /// [`Self::step`] on the calling thread.
    #[cfg_attr(target_arch = "wasm32", inline(always))]
    fn step_here(&mut self) {
        let (dt, half, was) = (self.dt, self.half_skin(), &self.positions[..]);
        // The integration also copies the snapshot's speeds and tests the lists' freshness,
        // robot by robot, rather than in passes of their own: on threads, two serial passes
        // fewer, during which the other threads would fall asleep and after which they would
        // have to be woken (measured at 10,000 robots, two threads against one, six runs each:
        // 0.65–0.70 with those passes apart, 0.55–0.64 with them here); on one thread, two
        // passes fewer over the robots.
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
        // No threads in the wasm build, whose block is the serial pass alone.
        #[cfg_attr(target_arch = "wasm32", allow(unused_labels))]
        let none_moved = 'advanced: {
            #[cfg(not(target_arch = "wasm32"))]
            if self.threaded() {
                use rayon::prelude::*;
                break 'advanced self
                    .robots
                    .par_iter_mut()
                    .zip(&self.commands[..])
                    .zip(&self.chords[..])
                    .zip(&mut self.speeds[..])
                    .enumerate()
                    .with_min_len(CHEAP_CHUNK)
                    .map(advance)
                    .reduce(|| true, |a, b| a && b);
            }
            self.robots
                .iter_mut()
                .zip(&self.commands)
                .zip(&self.chords)
                .zip(&mut self.speeds)
                .enumerate()
                .map(advance)
                .fold(true, |a, b| a & b)
        };
        // Each robot's heading after the step, as its evaluation found it, is now its heading;
        // the evaluations below fill the other buffer.
        std::mem::swap(&mut self.headings, &mut self.headings_after);
        self.steps += 1;
        self.time = self.steps as f64 * self.dt;
        self.evaluate_all(Some(none_moved));
        self.observe();
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
            #[cfg(not(target_arch = "wasm32"))]
            threaded: self.threaded(),
        });
    }

    /// The smallest distance between two robots now, when the neighbour lists hold it: the
    /// lists (always built for the current positions) hold every pair within their reach (at
    /// least `2·r_ij`, at most `max(R_s, 2·r_ij)`), so when some pair is listed their minimum is the minimum over all
    /// pairs (the same value as a scan). `None` when there are no lists (independent robots,
    /// [`Neighbourhood::AllPairs`]) or no pair within their reach.
    #[must_use]
    pub fn min_listed_pair_distance(&self) -> Option<f64> {
        if !self.listed() {
            return None;
        }
        let r = &self.robots;
        let mut m = f64::INFINITY;
        metrics::listed_pairs(r, &self.near, self.reach, |i, j| {
            m = m.min(r[i].pose.p.distance(r[j].pose.p));
        });
        m.is_finite().then_some(m)
    }

    /// Puts robot `i` at `pose`, bound for `goal`, in a simulation that has taken no step yet:
    /// afterwards it holds the same bits as [`Simulation::new`] of the scenario with that robot
    /// there, at the cost of the robots that sense it (where it was and where it is now) and an
    /// O(N) rebuild of the neighbour lists, rather than a whole step's evaluation. The
    /// playground's drags go through here.
    ///
    /// Returns `false`, changing nothing, once a step has been taken (the snapshot speeds are
    /// then no longer those of a new simulation) or for an index out of range: build a new
    /// simulation then.
    pub fn place_robot(&mut self, i: usize, pose: Pose, goal: Pose) -> bool {
        if self.steps != 0 || i >= self.robots.len() {
            return false;
        }
        let was = self.robots[i].pose.p;
        self.robots[i] = Robot::at(pose, goal);
        self.goal_headings[i] = heading(self.robots[i].goal.theta);
        self.headings[i] = heading(self.robots[i].pose.theta);
        let now = self.robots[i].pose.p;
        if now == was {
            // Only robot `i` depends on its own goal and heading.
            self.evaluate_robot(i);
        } else {
            self.find_neighbours(None);
            self.sense_all();
            let near = self.sense_margin();
            let affected = |q: DVec2| q.distance(was) <= near || q.distance(now) <= near;
            for j in 0..self.robots.len() {
                if j == i || (!self.independent && affected(self.robots[j].pose.p)) {
                    self.evaluate_robot(j);
                }
            }
        }
        self.observe_again();
        true
    }

    /// Replaces obstacle `k` in a simulation that has taken no step yet, with the same bits as
    /// [`Simulation::new`] of the scenario with that obstacle: the robots within `R_s` of its
    /// old or new disc are evaluated again. Returns `false`, changing nothing, once a step has
    /// been taken or for an index out of range.
    pub fn place_obstacle(&mut self, k: usize, obstacle: Obstacle) -> bool {
        if self.steps != 0 || k >= self.obstacles.len() {
            return false;
        }
        let was = self.obstacles[k];
        self.obstacles[k] = obstacle;
        self.build_obstacle_cells();
        let near = self.sense_margin();
        for j in 0..self.robots.len() {
            let p = self.robots[j].pose.p;
            if was.clearance(p) <= near || obstacle.clearance(p) <= near {
                self.evaluate_robot(j);
            }
        }
        self.observe_again();
        true
    }

    /// A distance beyond which nothing is sensed: `R_s` and a relative margin, so that
    /// round-off in a distance cannot leave out a robot whose evaluation changes (evaluating
    /// one too many gives the same bits).
    fn sense_margin(&self) -> f64 {
        self.params.sense_radius * (1.0 + 1e-9) + 1e-9
    }

    /// The metrics of a simulation that has taken no step, observed again from scratch.
    fn observe_again(&mut self) {
        // Only some robots were evaluated again: the metrics search the lists themselves.
        self.closest2 = None;
        self.metrics.clear();
        self.observe();
    }

    /// The report of the run so far.
    #[must_use]
    // The index picks the smoothness tally, which the wasm module leaves out.
    #[cfg_attr(
        target_arch = "wasm32",
        allow(unused_variables, clippy::unused_enumerate_index)
    )]
    pub fn report(&self) -> Report {
        Report {
            name: self.name.clone(),
            time: self.time,
            steps: self.steps,
            robots: self
                .robots
                .iter()
                .zip(&self.metrics.inside_since)
                .enumerate()
                .map(|(i, (r, since))| RobotReport {
                    final_pose: r.pose.to_array(),
                    position_error: r.position_error(),
                    heading_error: r.heading_error_abs(),
                    converged_at: *since,
                    #[cfg(not(target_arch = "wasm32"))]
                    smoothness: self.metrics.tallies[i],
                })
                .collect(),
            min_pair_distance: self.metrics.min_pair,
            min_obstacle_clearance: self.metrics.min_clearance,
            violations: self.metrics.violations,
            #[cfg(not(target_arch = "wasm32"))]
            smoothness: smoothness::Smoothness::of(
                &self.metrics.tallies,
                self.steps.max(1) as u64,
                self.dt,
            ),
        }
    }
}

/// Whether a step can find each robot's slowest robots within the avoidance range
/// ([`Simulation::sense_all`]) and give its neighbours' to the robot that senses them: with
/// the default avoidance (the paper's looks for no parked formation) and a sensing radius at
/// least twice the range (so that a robot senses every robot its search would have found).
fn slowest_known(p: &Params) -> bool {
    let range = pair_range(p.avoid_radius, p.transition_width);
    p.avoidance == Avoidance::Exit
        && p.sense_radius >= safety::widened(cluster_reach(range, p.avoidance, false))
}

/// The reach of the sensed robots the controller can use ([`crate::controller::evaluate_facing`]):
/// the avoidance range `2(R_c + ε)` within which the virtual obstacle's choice takes them
/// ([`crate::swarm::cluster`]), and the reach of `make_room` (`PRESSED·r_ij`), each widened
/// ([`safety::widened`]). A robot farther than both changes neither: the choice leaves
/// it out, and `make_room` adds an exact zero for it (its transition is 1 beyond its reach).
/// Everything sensed with the default avoidance when the step does not know its neighbours'
/// slowest robots ([`slowest_known`]): the choice then looks among them for parked ones
/// around each neighbour within the range.
fn controller_reach(p: &Params, slowest_known: bool) -> f64 {
    if p.avoidance == Avoidance::Exit && !slowest_known {
        return f64::INFINITY;
    }
    let range = pair_range(p.avoid_radius, p.transition_width);
    let room = crate::swarm::PRESSED * p.safe_radius;
    safety::widened(range.max(room))
}

/// The reach of the neighbour lists: the sensed robots that can change a command, and the
/// collision distance `2·r_ij`. A sensed robot changes a command only within the reach of
/// the virtual obstacle's choice ([`crate::swarm::cluster_reach`]: the avoidance range
/// `2(R_c + ε)`, twice that where a parked formation is looked for among the robot's own
/// neighbours, not when `slowest_known`) or within the barrier's
/// [`safety::neighbour_reach`] at the fastest speed `v_max` allows; beyond both, it is
/// sensed and ignored, so the lists leave it out with the same bits. In a crowd with the
/// default avoidance that is the barrier's 10 m instead of `R_s` = 20. Without `v_max` and
/// with a barrier, the sensing radius.
fn list_reach(p: &Params, slowest_known: bool) -> f64 {
    let range = pair_range(p.avoid_radius, p.transition_width);
    let avoidance = safety::widened(cluster_reach(range, p.avoidance, slowest_known));
    let barrier = match (p.barrier_rate, p.v_max) {
        (None, _) => 0.0,
        (Some(_), Some(v)) => safety::neighbour_reach(p, v),
        (Some(_), None) => f64::INFINITY,
    };
    p.sense_radius
        .min(avoidance.max(barrier))
        .max(2.0 * p.safe_radius)
}

/// From this many robots a step runs its passes on several threads (natively): below, rayon's
/// hand-offs cost more than they save. Measured on `presets::crowd(n)` in open space on two
/// cores, two threads against one: 1.11–1.16 times the time at 1,000 robots, 1.01–1.12 at
/// 2,000, 0.62–0.65 at 4,000, 0.57–0.58 at 10,000 (README, Performance, "Two threads").
pub const PARALLEL_FROM: usize = 2048;

/// The fewest robots a thread takes at once in the step's cheap passes (integration, the
/// slowest neighbours, storing the evaluations, the metrics). Small pieces let a thread that
/// wakes late still take its share of a pass: measured at 10,000 robots, two threads against
/// one, 0.62–0.63 with 1,024, 0.57–0.58 with 256 (0.57–0.63 with 128, 0.58 with 64); at 4,000
/// robots 0.76–0.80 with 1,024, 0.62–0.65 with 256.
#[cfg(not(target_arch = "wasm32"))]
pub(crate) const CHEAP_CHUNK: usize = 256;

/// On one thread, a step stores its evaluations this many at a time (`evaluate_all`): written
/// in a buffer that stays in the first-level cache, and stored once a few dozen other robots
/// have been evaluated since.
#[cfg(not(target_arch = "wasm32"))]
const STORED_BY: usize = 64;

/// A robot's slots as the step's integration advances them (`Simulation::step_here`): its
/// state, command, chord and snapshot speed.
type Advanced<'a> = (((&'a mut Robot, &'a Command), &'a DVec2), &'a mut f64);

/// The robots' slots that their evaluations write (`Simulation::take_slots`): their states
/// (`last`), commands, chords and headings after the step.
#[cfg(not(target_arch = "wasm32"))]
struct Slots {
    robots: Vec<Robot>,
    commands: Vec<Command>,
    chords: Vec<DVec2>,
    after: Vec<DVec2>,
}

#[cfg(not(target_arch = "wasm32"))]
impl Slots {
    /// The slots of all the robots, as one run.
    fn run(&mut self) -> Run<'_> {
        (
            &mut self.robots,
            &mut self.commands,
            &mut self.chords,
            &mut self.after,
        )
    }
}

/// The slots of a run of robots ([`Slots::run`]).
#[cfg(not(target_arch = "wasm32"))]
type Run<'a> = (
    &'a mut [Robot],
    &'a mut [Command],
    &'a mut [DVec2],
    &'a mut [DVec2],
);

/// Stores a robot's evaluation and the motion of its step in its slots: its state's `last`, its
/// command, its chord and its heading after the step.
#[inline]
fn put(
    (r, command, chord, after): (&mut Robot, &mut Command, &mut DVec2, &mut DVec2),
    &(e, m): &(Evaluation, Motion),
) {
    r.last = e;
    *command = e.command;
    *chord = m.chord;
    *after = m.heading;
}

/// A robot evaluation's buffers, reused from robot to robot: its sensed neighbours and
/// obstacles, and the barrier's constraints; and the smallest squared distance from a robot
/// evaluated with them to a listed robot of higher index within the lists' reach (`+∞` for
/// none), for the metrics' closest pair (`Simulation::closest_listed2`).
#[derive(Clone, Debug, Default)]
struct Scratch {
    neighbours: Vec<Neighbour>,
    // The robot's sensed obstacles (`Simulation::sensed_obstacles`): found once, read by the
    // controller's passes over them and by the barrier.
    obstacles: Vec<u32>,
    constraints: safety::Constraints,
    closest2: f64,
    // The evaluations of a run before they are stored (`Simulation::evaluate_run`).
    #[cfg(not(target_arch = "wasm32"))]
    evaluated: Vec<(Evaluation, Motion)>,
}

/// Whether a robot at `now` has moved at most `half` from `was` (see
/// `Simulation::find_neighbours`).
#[inline]
fn moved_within(was: DVec2, now: DVec2, half: f64) -> bool {
    was.distance_squared(now) <= half * half
}

/// Once more than one robot in this many has moved more than half the lists' skin, the lists
/// are rebuilt rather than searched around those robots (`Simulation::lists_still_hold`). A
/// search costs about as much as a robot's share of a rebuild, and a rebuild that the lists
/// kept past half their skin postpone is one every twelve steps or so: searching around more
/// than a twelfth of the robots in a step costs more than the step's share of the rebuild.
/// Measured against a rebuild at half the skin (one thread, 200 steps from several times of
/// the run, two processes): the crowd of 1,000 at t = 45 s 0.964–0.970 of the time a step,
/// from t = 35, 55 and 65 s 0.98–1.01, and open space 0.99–1.00. A quarter of the crowd
/// searched around at most between two builds, tried first, left the crowd of 10,000 2.6 %
/// slower in its jam, where one robot in ten runs.
const MOVED_SHARE: usize = 12;

/// The skin of the Verlet lists, relative to their reach (see `Simulation::find_neighbours`):
/// wider lists to read against fewer rebuilds. A quarter is a usual choice for Verlet lists,
/// and the best of three measured here (callgrind, the crowd of 1,000 on one thread, 200 steps
/// in open space and 200 in the jam): 0.15 made 2 % more instructions in open space and 1 %
/// more in the jam, 0.35 made 0.4 % fewer in open space and 3 % more in the jam.
const SKIN: f64 = 0.25;

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

    /// Through the jam of a crowd, the lists are kept at some steps after a robot has moved
    /// more than half their skin (`lists_still_hold`), and at every such step they list every
    /// pair within their reach (a scan over all pairs): what the step's evaluations and
    /// metrics read from them is then what a rebuild would have given.
    #[test]
    #[cfg(not(target_arch = "wasm32"))]
    fn lists_kept_past_half_the_skin_hold_every_pair() {
        let s = crate::presets::crowd(200);
        let mut sim = Simulation::new(&s);
        let (reach, n) = (sim.reach, sim.robots.len());
        let mut kept = 0;
        // Past the jam at the centre (about 16 s).
        while sim.time() < 25.0 {
            sim.step();
            if sim.none_moved_beyond(sim.half_skin()) {
                continue;
            }
            kept += 1;
            let p = |i: usize| sim.robots[i].pose.p;
            for i in 0..n {
                for j in 0..n {
                    assert!(
                        i == j
                            || p(i).distance_squared(p(j)) > reach * reach
                            || sim.near.of(i).contains(&(j as u32)),
                        "step {}: robots {i} and {j} are within the reach and not listed",
                        sim.steps
                    );
                }
            }
        }
        assert!(
            kept >= 50,
            "the lists were kept past half their skin at {kept} steps"
        );
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
