//! DVF against a peer on the same crowd: ORCA as the crate `dodgy_2d` implements it (a port of
//! RVO2), both given the neighbours within the same radius from the same grid
//! (`dvf::grid::Neighbours`), stepped with the same `dt`, timed alternating in one process so
//! that both see the same machine load.
//!
//! For each crowd size: milliseconds per step in open space (the first 2 s), in the jam at the
//! centre (a window of steps around the time the crowd meets there), and over the whole run to
//! the last arrival (total compute and simulated makespan), each planner on one thread; then
//! DVF's step on all of rayon's threads against one (`RAYON_NUM_THREADS` sets the count). Prints one JSON line per figure
//! with the ratio ORCA / DVF, appends them to `test-results/bench-peer.jsonl`, and checks
//! nothing: a time is not behaviour. Not part of `make test`.
//!
//!   cargo bench --bench peer                 # 1,000 robots: every phase
//!   cargo bench --bench peer -- 10000 open   # 10,000 robots, open space only
//!   cargo bench --bench peer -- 1000 jam     # open space and the jam, not the whole run
//!   cargo bench --bench peer -- 1000 profile # the cost of a step along the whole run
//!
//! `profile` times windows of [`PROFILE_STEPS`] steps from the states every
//! [`PROFILE_EVERY_S`] seconds of each planner's run, in rounds over all of them (both planners
//! in each round), and prints each window's median over the rounds and its ratio to the first
//! window's, then each planner's dearest window over its first and over the cheapest before
//! it: how the cost moves through the crossing, whichever window one calls open space.
//!
//! ORCA's agents are holonomic discs of radius `r_ij` with the crowd's speed limit, preferring
//! the velocity straight to their goal (slowing to land on it); an agent has arrived within
//! `tol_position` of its goal. DVF's robots are unicycles that must also reach the goal
//! heading; a robot has arrived when its report says it has converged. The two finish
//! different tasks, so the makespans are quoted side by side, not as a ratio of merit.

use dodgy_2d::{Agent, AvoidanceOptions, Vec2};
use dvf::grid::Neighbours;
use dvf::presets::crowd;
use dvf::sweep::Quantiles;
use dvf::{Scenario, Simulation};
use glam::DVec2;
use std::borrow::Cow;
use std::io::Write;
use std::time::Instant;

/// ORCA's time horizon for other agents (s): RVO2's examples use a few seconds.
const TIME_HORIZON: f32 = 3.0;
/// Open space: the first this many seconds.
const OPEN_S: f64 = 2.0;
/// Steps timed in the jam (around the middle of the crossing).
const JAM_STEPS: usize = 200;
/// The jam against open space ([`turns`]): rounds from fresh copies, the median quoted. One
/// round is at the mercy of the host, whose cores change speed from second to second.
const TURN_ROUNDS: usize = 9;
/// `profile`: the steps of a window, ...
const PROFILE_STEPS: usize = 50;
/// ... the seconds between two windows' starts, ...
const PROFILE_EVERY_S: f64 = 5.0;
/// ... and the rounds over all windows (the median is quoted).
const PROFILE_ROUNDS: usize = 9;
/// RVO2's usual neighbourhood, ORCA's second setting: the nearest this many agents within
/// [`RVO2_RADIUS`].
const RVO2_NEIGHBOURS: usize = 10;
/// RVO2's usual neighbour radius (m).
const RVO2_RADIUS: f64 = 15.0;

/// ORCA on the crowd of a scenario.
#[derive(Clone)]
struct Orca {
    agents: Vec<Cow<'static, Agent>>,
    goals: Vec<Vec2>,
    max_speed: f32,
    dt: f32,
    reach: f64,
    /// At most this many neighbours, the nearest (RVO2's `maxNeighbors`); all when `None`.
    nearest: Option<usize>,
    tol: f32,
    near: Neighbours,
    positions: Vec<DVec2>,
    velocities: Vec<Vec2>,
    neighbours: Vec<Cow<'static, Agent>>,
}

impl Orca {
    /// Every agent within the scenario's sensing radius as a neighbour (DVF's own setting).
    fn new(s: &Scenario) -> Self {
        Self::within(s, s.params.sense_radius, None)
    }

    /// The agents within `reach` as neighbours, only the `nearest` ones when given.
    fn within(s: &Scenario, reach: f64, nearest: Option<usize>) -> Self {
        let agents = s
            .robots
            .iter()
            .map(|r| {
                let p = r.start_pose().p;
                Cow::Owned(Agent {
                    position: Vec2::new(p.x as f32, p.y as f32),
                    velocity: Vec2::ZERO,
                    radius: s.params.safe_radius as f32,
                    avoidance_responsibility: 1.0,
                })
            })
            .collect();
        let goals = s
            .robots
            .iter()
            .map(|r| {
                let g = r.goal_pose().p;
                Vec2::new(g.x as f32, g.y as f32)
            })
            .collect();
        Self {
            agents,
            goals,
            max_speed: s.params.v_max.unwrap_or(f64::INFINITY) as f32,
            dt: s.dt as f32,
            reach,
            nearest,
            tol: s.params.tol_position as f32,
            near: Neighbours::new(),
            positions: Vec::new(),
            velocities: Vec::new(),
            neighbours: Vec::new(),
        }
    }

    fn step(&mut self) {
        self.positions.clear();
        self.positions.extend(
            self.agents
                .iter()
                .map(|a| DVec2::new(f64::from(a.position.x), f64::from(a.position.y))),
        );
        self.near.build(&self.positions, self.reach);
        let options = AvoidanceOptions {
            obstacle_margin: 0.0,
            time_horizon: TIME_HORIZON,
            obstacle_time_horizon: TIME_HORIZON,
        };
        self.velocities.clear();
        for i in 0..self.agents.len() {
            self.neighbours.clear();
            self.neighbours.extend(
                self.near
                    .of(i)
                    .iter()
                    .map(|&j| self.agents[j as usize].clone()),
            );
            let a = &self.agents[i];
            if let Some(k) = self.nearest.filter(|&k| k < self.neighbours.len()) {
                // RVO2 keeps the nearest `maxNeighbors` (by insertion into a sorted list; the
                // order among them does not change ORCA's answer much, and a selection costs
                // less).
                let p = a.position;
                self.neighbours.select_nth_unstable_by(k, |x, y| {
                    p.distance_squared(x.position)
                        .total_cmp(&p.distance_squared(y.position))
                });
                self.neighbours.truncate(k);
            }
            let to_goal = self.goals[i] - a.position;
            let preferred =
                to_goal.clamp_length_max(self.max_speed.min(to_goal.length() / self.dt));
            self.velocities.push(a.compute_avoiding_velocity(
                &self.neighbours,
                &[],
                preferred,
                self.max_speed,
                self.dt,
                &options,
            ));
        }
        for (a, v) in self
            .agents
            .iter_mut()
            .map(Cow::to_mut)
            .zip(&self.velocities)
        {
            a.velocity = *v;
            a.position += *v * self.dt;
        }
    }

    fn all_arrived(&self) -> bool {
        self.agents
            .iter()
            .zip(&self.goals)
            .all(|(a, g)| a.position.distance(*g) <= self.tol)
    }
}

/// Milliseconds per step of `step` over `steps` steps.
fn time(steps: usize, mut step: impl FnMut()) -> f64 {
    let t0 = Instant::now();
    for _ in 0..steps {
        step();
    }
    t0.elapsed().as_secs_f64() * 1e3 / steps.max(1) as f64
}

/// Milliseconds per step of copies of `open` and of `jam`, each stepped on in turns of a few
/// steps (ten turns of 20 steps: the first 2 s of open space, and the jam's 2 s from `jam`),
/// in [`TURN_ROUNDS`] rounds from fresh copies: the medians of the jam's time and of the
/// rounds' ratios of the jam's time over open space's.
fn turns<T: Clone>(open: &T, jam: &T, step: fn(&mut T)) -> (f64, f64) {
    let (mut b, mut ratio) = (Vec::new(), Vec::new());
    for _ in 0..TURN_ROUNDS {
        let (mut x, mut y) = (open.clone(), jam.clone());
        let (mut p, mut q) = (0.0, 0.0);
        for _ in 0..10 {
            p += time(20, || step(&mut x));
            q += time(20, || step(&mut y));
        }
        b.push(q / 10.0);
        ratio.push(q / p);
    }
    let median = |v: Vec<f64>| Quantiles::of(v).p50;
    (median(b), median(ratio))
}

/// The states of a run from `start`, every `every` steps until `done` or `end` steps.
fn marks<T: Clone>(
    start: T,
    step: fn(&mut T),
    done: impl Fn(&T) -> bool,
    every: usize,
    end: usize,
) -> Vec<T> {
    let (mut x, mut out, mut k) = (start, Vec::new(), 0);
    loop {
        out.push(x.clone());
        for _ in 0..every {
            step(&mut x);
        }
        k += every;
        if k >= end || done(&x) {
            return out;
        }
    }
}

/// `profile`: a line for each window, with DVF's and ORCA's median milliseconds per step
/// (`null` past the end of a planner's run), then a line for each planner's dearest window.
fn profile(
    s: &Scenario,
    serial: impl Fn(&Scenario) -> Simulation,
    report: &mut impl FnMut(String),
) {
    let every = (PROFILE_EVERY_S / s.dt).round() as usize;
    let dvf = marks(serial(s), Simulation::step, all_converged, every, s.steps());
    let orca = marks(
        Orca::new(s),
        Orca::step,
        Orca::all_arrived,
        every,
        s.steps(),
    );
    let windows = dvf.len().max(orca.len());
    let (mut dvf_times, mut orca_times) =
        (vec![Vec::new(); dvf.len()], vec![Vec::new(); orca.len()]);
    for _ in 0..PROFILE_ROUNDS {
        for k in 0..windows {
            if let Some(x) = dvf.get(k) {
                let mut x = x.clone();
                dvf_times[k].push(time(PROFILE_STEPS, || x.step()));
            }
            if let Some(x) = orca.get(k) {
                let mut x = x.clone();
                orca_times[k].push(time(PROFILE_STEPS, || x.step()));
            }
        }
    }
    let median = |times: Vec<Vec<f64>>| -> Vec<f64> {
        times.into_iter().map(|t| Quantiles::of(t).p50).collect()
    };
    let (dvf_ms, orca_ms) = (median(dvf_times), median(orca_times));
    // A window's milliseconds and their ratio to the first window's, `null` where the planner's
    // run had ended.
    let window = |ms: &[f64], k: usize| {
        ms.get(k).map_or(("null".into(), "null".into()), |m| {
            (format!("{m:.4}"), format!("{:.3}", m / ms[0]))
        })
    };
    for k in 0..windows {
        let ((d, d_first), (o, o_first)): ((String, String), (String, String)) =
            (window(&dvf_ms, k), window(&orca_ms, k));
        report(format!(
            r#"{{"robots": {}, "phase": "profile", "t": {:.1}, "dvf_ms_per_step": {d}, "dvf_over_first": {d_first}, "orca_ms_per_step": {o}, "orca_over_first": {o_first}}}"#,
            s.robots.len(),
            (k * every) as f64 * s.dt,
        ));
    }
    for (planner, ms) in [("dvf", &dvf_ms), ("orca", &orca_ms)] {
        let (at, peak) = ms
            .iter()
            .enumerate()
            .fold((0, 0.0), |m, (k, &x)| if x > m.1 { (k, x) } else { m });
        // Open space at its cheapest: the cheapest window before the dearest.
        let least = ms[..=at].iter().copied().fold(f64::INFINITY, f64::min);
        report(format!(
            r#"{{"robots": {}, "phase": "profile, dearest", "planner": "{planner}", "t": {:.1}, "ms_per_step": {peak:.4}, "over_first": {:.3}, "over_cheapest_before": {:.3}}}"#,
            s.robots.len(),
            (at * every) as f64 * s.dt,
            peak / ms[0],
            peak / least
        ));
    }
}

fn all_converged(sim: &Simulation) -> bool {
    let p = sim.params();
    sim.robots()
        .iter()
        .all(|r| r.position_error() <= p.tol_position && r.heading_error_abs() <= p.tol_heading)
}

fn main() {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with('-'))
        .collect();
    let n: usize = args.first().and_then(|a| a.parse().ok()).unwrap_or(1_000);
    let only_open = args.iter().any(|a| a == "open");
    let no_whole_run = args.iter().any(|a| a == "jam");
    let s = crowd(n);
    let steps_of = |seconds: f64| (seconds / s.dt).round() as usize;
    let mut lines = Vec::new();
    // One thread each, as ORCA here runs (the threads have their own figure below).
    let serial = |s: &Scenario| {
        let mut sim = Simulation::new(s).unwrap();
        sim.set_parallel(false);
        sim
    };
    if args.iter().any(|a| a == "profile") {
        profile(&s, serial, &mut |line| {
            println!("{line}");
            lines.push(line);
        });
        append(&lines);
        return;
    }
    let mut report = |phase: &str, dvf: f64, orca: f64, extra: String| {
        let line = format!(
            r#"{{"robots": {n}, "phase": "{phase}", "dvf_ms_per_step": {dvf:.4}, "orca_ms_per_step": {orca:.4}, "orca_over_dvf": {:.3}{extra}}}"#,
            orca / dvf
        );
        println!("{line}");
        lines.push(line);
    };

    // Open space, alternating three times, after a window of each left untimed: the first
    // window of a process runs cold (fresh memory, caches, branch history), slower than the
    // next ones.
    let open = steps_of(OPEN_S);
    {
        let mut sim = serial(&s);
        time(open, || sim.step());
        let mut orca = Orca::new(&s);
        time(open, || orca.step());
    }
    for _ in 0..3 {
        let mut sim = serial(&s);
        let dvf = time(open, || sim.step());
        let mut orca = Orca::new(&s);
        let peer = time(open, || orca.step());
        report("open", dvf, peer, String::new());
    }
    // Open space against ORCA in RVO2's usual setting (15 m, the nearest 10), alternating.
    for _ in 0..3 {
        let mut sim = serial(&s);
        let dvf = time(open, || sim.step());
        let mut orca = Orca::within(&s, RVO2_RADIUS, Some(RVO2_NEIGHBOURS));
        let peer = time(open, || orca.step());
        report("open, ORCA 15 m / nearest 10", dvf, peer, String::new());
    }
    if !only_open {
        // The jam: each planner's own crowd, run to the middle of the crossing (the circle's
        // radius at the speed limit), then timed over JAM_STEPS steps.
        let radius = s.robots[0].start_pose().p.length();
        let meet = steps_of(radius / s.params.v_max.unwrap_or(1.0)) + steps_of(10.0);
        let mut sim = serial(&s);
        let mut orca = Orca::new(&s);
        for _ in 0..meet {
            sim.step();
            orca.step();
        }
        // The jam against open space, each planner on its own: copies of the state at t = 0
        // and in the jam stepped in short turns, so that both phases see the same machine load
        // (the ratio the jam's bound is about).
        let (dvf_jam, dvf_ratio) = turns(&serial(&s), &sim, Simulation::step);
        let (orca_jam, orca_ratio) = turns(&Orca::new(&s), &orca, Orca::step);
        report(
            "jam",
            dvf_jam,
            orca_jam,
            format!(
                r#", "t": {:.1}, "dvf_jam_over_open": {:.3}, "orca_jam_over_open": {:.3}"#,
                sim.time(),
                dvf_ratio,
                orca_ratio
            ),
        );
        for _ in 0..3 {
            let dvf = time(JAM_STEPS, || sim.step());
            let peer = time(JAM_STEPS, || orca.step());
            report("jam", dvf, peer, format!(r#", "t": {:.1}"#, sim.time()));
        }
    }
    if !only_open && !no_whole_run {
        // The whole run to the last arrival (or the scenario's end).
        let total = s.steps();
        let mut sim = serial(&s);
        let t0 = Instant::now();
        let mut dvf_steps = 0;
        while dvf_steps < total && !all_converged(&sim) {
            sim.step();
            dvf_steps += 1;
        }
        let dvf_ms = t0.elapsed().as_secs_f64() * 1e3;
        let mut orca = Orca::new(&s);
        let t0 = Instant::now();
        let mut orca_steps = 0;
        while orca_steps < total && !orca.all_arrived() {
            orca.step();
            orca_steps += 1;
        }
        let orca_ms = t0.elapsed().as_secs_f64() * 1e3;
        report(
            "whole run",
            dvf_ms / dvf_steps.max(1) as f64,
            orca_ms / orca_steps.max(1) as f64,
            format!(
                r#", "dvf_total_s": {:.2}, "orca_total_s": {:.2}, "dvf_makespan_s": {:.2}, "orca_makespan_s": {:.2}, "dvf_all_arrived": {}, "orca_all_arrived": {}"#,
                dvf_ms / 1e3,
                orca_ms / 1e3,
                dvf_steps as f64 * s.dt,
                orca_steps as f64 * s.dt,
                all_converged(&sim),
                orca.all_arrived()
            ),
        );
    }
    // DVF on the threads of rayon's pool against one thread, in open space, alternating.
    for _ in 0..3 {
        let mut one = serial(&s);
        let single = time(open, || one.step());
        let mut many = Simulation::new(&s).unwrap();
        let parallel = time(open, || many.step());
        let line = format!(
            r#"{{"robots": {n}, "phase": "open, threads", "threads": {}, "dvf_ms_per_step_one_thread": {single:.4}, "dvf_ms_per_step": {parallel:.4}, "threads_over_one": {:.3}}}"#,
            rayon::current_num_threads(),
            parallel / single
        );
        println!("{line}");
        lines.push(line);
    }
    append(&lines);
}

/// Appends `lines` to `test-results/bench-peer.jsonl`.
fn append(lines: &[String]) {
    let _ = std::fs::create_dir_all("test-results");
    if let Ok(mut f) = std::fs::OpenOptions::new()
        .create(true)
        .append(true)
        .open("test-results/bench-peer.jsonl")
    {
        for l in lines {
            let _ = writeln!(f, "{l}");
        }
    }
}
