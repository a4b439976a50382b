//! Whole runs: a scenario simulated to its end, with or without its trajectories, which can
//! be kept in memory ([`run_recorded`]) or handed on step by step as the run goes
//! ([`run_streamed`]).

use super::{Report, Simulation};
use crate::error::Error;
use crate::scenario::Scenario;

/// One recorded sample of one robot: `[t, x, y, θ, v, ω]`, `t` the step's time as
/// [`step_time`] gives it.
pub type Sample = [f64; 6];

/// Runs a scenario to its end and returns the report, calling `on_step` after time 0 and
/// after every step; an error from `on_step` ends the run and is returned.
///
/// # Errors
/// A scenario that [`Scenario::validate`] refuses, or the first error of `on_step`.
pub fn run_with<E: From<Error>>(
    s: &Scenario,
    mut on_step: impl FnMut(&Simulation) -> Result<(), E>,
) -> Result<Report, E> {
    let mut sim = Simulation::new(s)?;
    on_step(&sim)?;
    for _ in 0..s.steps() {
        sim.step();
        on_step(&sim)?;
    }
    Ok(sim.report())
}

/// Runs a scenario to its end.
///
/// # Errors
/// A scenario that [`Scenario::validate`] refuses, with the message the file reader gives.
pub fn run(s: &Scenario) -> Result<Report, Error> {
    run_with(s, |_| Ok::<(), Error>(()))
}

/// Runs a scenario to its end and hands `sink`, after time 0 and after every step, the
/// simulation and every robot's [`Sample`] (in robot order) at steps `0, every, 2·every, …` and
/// the last; at the other steps the samples are empty. One step's samples are held at a time,
/// so the run takes the memory of its simulation whatever its length (`dvf simulate --csv`
/// writes the rows to its file as they come). An error from `sink` ends the run and is
/// returned.
///
/// # Errors
/// A scenario that [`Scenario::validate`] refuses, or the first error of `sink`.
pub fn run_streamed<E: From<Error>>(
    s: &Scenario,
    every: usize,
    mut sink: impl FnMut(&Simulation, &[Sample]) -> Result<(), E>,
) -> Result<Report, E> {
    let every = every.max(1);
    let total = s.steps();
    let mut samples = Vec::with_capacity(s.robots.len());
    run_with(s, |sim| {
        samples.clear();
        if sim.steps() % every == 0 || sim.steps() == total {
            let t = step_time(sim.steps(), sim.dt());
            samples.extend(sim.robots().iter().map(|r| {
                let c = r.last.command;
                [t, r.pose.p.x, r.pose.p.y, r.pose.theta, c.v, c.omega]
            }));
        }
        sink(sim, &samples)
    })
}

/// Runs a scenario and records every robot at every `every`-th step (and the last):
/// `trajectories[robot]` is a list of [`Sample`]s.
///
/// # Errors
/// A scenario that [`Scenario::validate`] refuses.
pub fn run_recorded(s: &Scenario, every: usize) -> Result<(Report, Vec<Vec<Sample>>), Error> {
    let every = every.max(1);
    let mut traj = vec![Vec::new(); s.robots.len()];
    let report = run_streamed(s, every, |sim, samples| {
        for (k, sample) in samples.iter().enumerate() {
            // Room for the whole run once the scenario has passed its checks (`s.steps()` of
            // a step of 0 would be unbounded).
            if sim.steps() == 0 {
                traj[k].reserve_exact(s.steps() / every + 2);
            }
            traj[k].push(*sample);
        }
        Ok::<(), Error>(())
    })?;
    Ok((report, traj))
}

/// The time of step `steps` of size `dt`, `steps·dt` computed in decimal: `dt`'s shortest
/// decimal (`0.01`) times `steps`, read as the nearest `f64`, so that it prints as the short
/// decimal a person expects (`0.35`, where the product `35 · 0.01` in binary prints
/// `0.35000000000000003`) and compares equal to that decimal read back (`t == 0.35`).
/// A `dt` whose decimal has more than 17 significant digits, or a product beyond 2⁵³ units of
/// its last digit, gets the binary product `steps as f64 · dt`.
#[must_use]
pub fn step_time(steps: usize, dt: f64) -> f64 {
    // The fewest decimals `d` that hold `dt` (`dt = m / 10^d` read back to the same bits);
    // `m` and `10^d` are exact in `f64`, and a quotient of two exact numbers is rounded once,
    // to the nearest `f64`: the decimal `steps·m / 10^d` read as a number.
    const EXACT: f64 = 9_007_199_254_740_992.0; // 2^53
    let mut scale = 1.0;
    for _ in 0..=22 {
        let m = (dt * scale).round();
        if m > EXACT {
            break;
        }
        if m / scale == dt {
            let units = steps as f64 * m;
            if units <= EXACT {
                return units / scale;
            }
            break;
        }
        scale *= 10.0;
    }
    steps as f64 * dt
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
            let report =
                run(&crate::presets::preset(name).expect("a preset")).expect("a valid preset");
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
