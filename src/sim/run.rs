//! Whole runs: a scenario simulated to its end, with or without its trajectories.

use super::{Report, Simulation};
use crate::scenario::Scenario;

/// One recorded sample of one robot: `[t, x, y, θ, v, ω]`.
pub type Sample = [f64; 6];

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
