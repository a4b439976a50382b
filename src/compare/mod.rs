//! Planners side by side: one scenario run with each of a list of planners
//! ([`crate::planner::PLANNERS`]) on the same unicycles, sensing, limits and safety barrier,
//! and the same metrics for each, per robot and per run ([`compare`]).
//!
//! Every metric but the compute time is a function of the run alone: the same bits natively
//! and in the wasm build (the same step, the same sums in the same order). The compute time
//! per step is read from a clock the caller passes in ([`compare_with`]; [`compare`] takes the
//! platform's: `std::time::Instant` natively, `performance.now()` in the browser, since
//! `Instant` panics on wasm32-unknown-unknown), and is the one number that differs between
//! two runs.
//!
//! - `mod.rs`: the comparison and its metrics;
//! - `clock.rs`: the platform's clock;
//! - [`table`]: the Markdown tables of `make compare-table` (the paper's examples and the
//!   sweep families, every planner).

mod clock;
pub mod table;

pub use clock::now_ms;

use crate::error::Error;
use crate::planner::{entry, Spec, PLANNERS};
use crate::scenario::Scenario;
use crate::sim::Simulation;
use serde::Serialize;

/// A command slower than this (m/s) has no curvature counted in [`RobotMetrics::peak_curvature`]:
/// a robot turning on the spot (or creeping) has a curvature `|ω|/|v|` as large as one likes,
/// which says nothing of the path it drives.
pub const CURVATURE_MIN_SPEED: f64 = 0.01;

/// The scene every planner of a comparison runs on.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Conditions {
    /// The step (s).
    pub dt: f64,
    /// Simulated seconds.
    pub duration: f64,
    /// The robots' forward speed limit (m/s), `None` for none.
    pub v_max: Option<f64>,
    /// The robots' turn rate limit (rad/s), `None` for none.
    pub omega_max: Option<f64>,
    /// Whether the shared safety barrier is on (`params.barrier_rate` set).
    pub barrier: bool,
    /// Robots in the scene.
    pub robots: usize,
    /// Obstacles in the scene.
    pub obstacles: usize,
}

/// One robot's metrics under one planner.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RobotMetrics {
    /// Its index in the scenario.
    pub robot: usize,
    /// Whether it was at its goal pose, position and heading within the tolerances
    /// (`tol_position`, `tol_heading`), from some time to the end.
    pub arrived: bool,
    /// That time (s); `None` if it did not arrive.
    pub arrival_time: Option<f64>,
    /// Distance driven, `Σ|v|·dt` (m).
    pub path_length: f64,
    /// Control effort `Σ(v² + ω²)·dt` (m²/s and rad²/s added as numbers).
    pub control_effort: f64,
    /// Largest `|ω|/|v|` over the commands with `|v| >` [`CURVATURE_MIN_SPEED`] (1/m); 0 when
    /// it never drove that fast.
    pub peak_curvature: f64,
    /// Reversals of its turn rate ([`crate::sim::smoothness`]).
    pub reversals: u64,
    /// Whether it chatters after reaching its goal position
    /// ([`crate::sim::smoothness::Tally::chatters`]).
    pub chatters: bool,
    /// Distance to its goal position at the end (m).
    pub position_error: f64,
    /// `|wrap(θ − θ_d)|` at the end (rad).
    pub heading_error: f64,
}

/// One planner's metrics over the run.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RunMetrics {
    /// Robots that arrived with their heading ([`RobotMetrics::arrived`]).
    pub arrived: usize,
    /// `arrived / robots`.
    pub arrival_rate: f64,
    /// The time the last robot arrived (s); `None` if one did not arrive.
    pub time_to_last_arrival: Option<f64>,
    /// Sum of the robots' path lengths (m).
    pub path_length: f64,
    /// Sum of the robots' control efforts.
    pub control_effort: f64,
    /// Largest of the robots' peak curvatures (1/m).
    pub peak_curvature: f64,
    /// Reversals of the turn rate over all robots.
    pub reversals: u64,
    /// Robots that chatter after reaching their goal position.
    pub chattering_robots: usize,
    /// Smallest distance between two robots over the run (m); `None` with fewer than two
    /// interacting robots.
    pub min_pair_distance: Option<f64>,
    /// Smallest clearance from a robot to an obstacle it senses (m, negative inside); `None`
    /// when none came within sensing range.
    pub min_obstacle_clearance: Option<f64>,
    /// Violation events (a pair closer than `2·r_ij`, a robot entering a disc).
    pub violations: usize,
    /// Steps simulated.
    pub steps: usize,
    /// Wall-clock milliseconds per step, the metrics' bookkeeping included: the one number
    /// that is not the same from one run to the next.
    pub ms_per_step: f64,
}

/// One planner's run of the scenario.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PlannerRun {
    /// The planner as the scenario names it (a name, or an object with its gains).
    pub planner: Spec,
    /// What it is ([`crate::planner::Entry::title`]).
    pub title: &'static str,
    /// What it avoids on its own, before the shared barrier.
    pub avoids: &'static str,
    /// Over the run.
    pub metrics: RunMetrics,
    /// Per robot, in scenario order.
    pub robots: Vec<RobotMetrics>,
}

/// A scenario run with each of a list of planners (the JSON of `dvf compare --json`).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Comparison {
    /// The scenario's name.
    pub scenario: String,
    /// What every planner ran with.
    pub conditions: Conditions,
    /// One run per planner, in the order asked for.
    pub planners: Vec<PlannerRun>,
}

/// Every planner of [`PLANNERS`], with its default gains.
#[must_use]
pub fn all_planners() -> Vec<Spec> {
    PLANNERS.iter().map(|e| Spec::named(e.name)).collect()
}

/// [`compare_with`] on the platform's clock ([`now_ms`]).
///
/// # Errors
/// As [`compare_with`].
pub fn compare(s: &Scenario, planners: &[Spec]) -> Result<Comparison, Error> {
    compare_with(s, planners, now_ms)
}

/// Runs `s` with each of `planners` in turn (the scenario's own `planner` is not used) and
/// measures each run; `clock` gives milliseconds from any origin, read before and after each
/// run's steps.
///
/// # Errors
/// No planner (`planners`), a scenario that does not validate, or a planner whose name is
/// unknown or whose gains its entry refuses, named `planners[k]` (`planners[1].lambda`).
pub fn compare_with(
    s: &Scenario,
    planners: &[Spec],
    mut clock: impl FnMut() -> f64,
) -> Result<Comparison, Error> {
    if planners.is_empty() {
        return Err(Error::Invalid {
            field: "planners".into(),
            message: format!(
                "name at least one planner: {}",
                PLANNERS
                    .iter()
                    .map(|e| e.name)
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        });
    }
    s.validate()?;
    let mut runs = Vec::with_capacity(planners.len());
    for (k, spec) in planners.iter().enumerate() {
        let named = |e: Error| match e {
            Error::Invalid { field, message } => Error::Invalid {
                field: field.replacen("planner", &format!("planners[{k}]"), 1),
                message,
            },
            other => other,
        };
        let e = entry(&spec.name).map_err(named)?;
        spec.build().map_err(named)?;
        let mut scenario = s.clone();
        scenario.planner = spec.clone();
        runs.push(run_one(&scenario, &mut clock, e.title, e.avoids)?);
    }
    Ok(Comparison {
        scenario: s.name.clone(),
        conditions: Conditions {
            dt: s.dt,
            duration: s.duration,
            v_max: s.params.v_max,
            omega_max: s.params.omega_max,
            barrier: s.params.barrier_rate.is_some(),
            robots: s.robots.len(),
            obstacles: s.obstacles.len(),
        },
        planners: runs,
    })
}

/// Each robot's running sums over the commands it was given.
#[derive(Clone, Copy, Default)]
struct Driven {
    path: f64,
    effort: f64,
    curvature: f64,
}

/// Runs `s` (its planner set) to its end, measuring every command held over a step.
fn run_one(
    s: &Scenario,
    clock: &mut impl FnMut() -> f64,
    title: &'static str,
    avoids: &'static str,
) -> Result<PlannerRun, Error> {
    let mut sim = Simulation::new(s)?;
    let dt = s.dt;
    let steps = s.steps();
    let mut driven = vec![Driven::default(); s.robots.len()];
    let start = clock();
    for _ in 0..steps {
        // The command each robot holds over the coming step, as the step integrates it.
        for (d, r) in driven.iter_mut().zip(sim.robots()) {
            let c = r.last.command;
            d.path += c.v.abs() * dt;
            d.effort += (c.v * c.v + c.omega * c.omega) * dt;
            if c.v.abs() > CURVATURE_MIN_SPEED {
                d.curvature = d.curvature.max(c.omega.abs() / c.v.abs());
            }
        }
        sim.step();
    }
    let elapsed = clock() - start;
    let report = sim.report();
    let robots: Vec<RobotMetrics> = report
        .robots
        .iter()
        .zip(&driven)
        .enumerate()
        .map(|(robot, (r, d))| RobotMetrics {
            robot,
            arrived: r.converged_at.is_some(),
            arrival_time: r.converged_at,
            path_length: d.path,
            control_effort: d.effort,
            peak_curvature: d.curvature,
            reversals: r.smoothness.reversals,
            chatters: r.smoothness.chatters(dt),
            position_error: r.position_error,
            heading_error: r.heading_error,
        })
        .collect();
    let arrived = robots.iter().filter(|r| r.arrived).count();
    let metrics = RunMetrics {
        arrived,
        arrival_rate: arrived as f64 / robots.len().max(1) as f64,
        time_to_last_arrival: robots
            .iter()
            .map(|r| r.arrival_time)
            .try_fold(0.0_f64, |m, t| t.map(|t| m.max(t))),
        path_length: robots.iter().map(|r| r.path_length).sum(),
        control_effort: robots.iter().map(|r| r.control_effort).sum(),
        peak_curvature: robots.iter().map(|r| r.peak_curvature).fold(0.0, f64::max),
        reversals: robots.iter().map(|r| r.reversals).sum(),
        chattering_robots: report.smoothness.chattering_robots,
        min_pair_distance: report.min_pair_distance,
        min_obstacle_clearance: report.min_obstacle_clearance,
        violations: report.violations,
        steps: report.steps,
        ms_per_step: if steps == 0 {
            0.0
        } else {
            elapsed / steps as f64
        },
    };
    Ok(PlannerRun {
        planner: s.planner.clone(),
        title,
        avoids,
        metrics,
        robots,
    })
}

#[cfg(test)]
mod tests;
