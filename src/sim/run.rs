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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::test;

    /// Three of the paper's examples give, bit for bit, the reports `dvf simulate` wrote
    /// natively (`tests/data/reports/`), every field of them. Natively this checks the stored
    /// data; under `wasm-pack test` it shows that the wasm build computes the very same
    /// numbers, the commands' smoothness included: the same step, the same arithmetic, and the
    /// same maths library in both (`crate::maths`).
    #[test]
    fn runs_give_the_stored_reports_in_every_build() {
        use serde_json::Value;
        for (name, stored) in [
            (
                "table2-obstacles",
                include_str!("../../tests/data/reports/table2-obstacles.json"),
            ),
            (
                "example3-circle-swap",
                include_str!("../../tests/data/reports/example3-circle-swap.json"),
            ),
            (
                "example4-obstacle-formation",
                include_str!("../../tests/data/reports/example4-obstacle-formation.json"),
            ),
        ] {
            let report = run(&crate::presets::preset(name).expect("a preset"));
            // Through the text, as `dvf simulate` writes it (shortest round-trip decimals), read
            // back to the bits (serde_json's `float_roundtrip`, natively and in the tests of the
            // wasm build).
            let ours: Value =
                serde_json::from_str(&serde_json::to_string(&report).expect("serialises"))
                    .expect("parses");
            let stored: Value = serde_json::from_str(stored).expect("a stored report");
            assert_eq!(
                ours["robots"].as_array().map(Vec::len),
                Some(report.robots.len())
            );
            assert_eq!(stored, ours, "{name}");
        }
    }
}
