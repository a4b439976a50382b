//! One scenario of a sweep as a shard records it: its seed, its recipe's key and what happened,
//! in numbers that read back from JSON to the same bits.

use super::generate::scenario;
use super::recipe::{Family, Recipe, DT};
use crate::params::Avoidance;
use crate::scenario::Scenario;
use crate::sim::smoothness::Sums;
use crate::sim::{self, Report};
use serde::{Deserialize, Serialize};

/// What a shard records of a recipe, so that outcomes of different recipes are not merged:
/// the ranges and the settings the command line can change.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RecipeKey {
    /// The family (a line without one is of the random family).
    #[serde(default)]
    pub family: Family,
    /// The formation family's goal spacing `[min, max]`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spacing: Option<[f64; 2]>,
    /// Robots per scenario, `[min, max]`.
    pub robots: [usize; 2],
    /// Obstacles per scenario, `[min, max]`.
    pub obstacles: [usize; 2],
    /// Robot avoidance.
    pub avoidance: Avoidance,
    /// The barrier's rate (`None`: no barrier).
    pub barrier_rate: Option<f64>,
}

impl RecipeKey {
    /// The key of `recipe`.
    #[must_use]
    pub fn of(recipe: &Recipe) -> Self {
        Self {
            family: recipe.family,
            spacing: (recipe.family == Family::Formation)
                .then(|| [*recipe.spacing.start(), *recipe.spacing.end()]),
            robots: [*recipe.robots.start(), *recipe.robots.end()],
            obstacles: [*recipe.obstacles.start(), *recipe.obstacles.end()],
            avoidance: recipe.params.avoidance,
            barrier_rate: recipe.params.barrier_rate,
        }
    }
}

/// One scenario of a sweep: its seed, its recipe and what happened (one JSON line of a shard).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Outcome {
    /// The scenario's seed.
    pub seed: u64,
    /// The recipe it was drawn from.
    pub recipe: RecipeKey,
    /// Its poses could not be placed: not run.
    pub skipped: bool,
    /// Robots.
    pub robots: usize,
    /// The step after which each converged robot stayed converged (its time is `k · DT`), in
    /// robot order: steps rather than seconds, so that the line reads back to the same bits.
    pub converged_steps: Vec<u64>,
    /// Violation events.
    pub violations: usize,
    /// The robots' smoothness tallies, summed, the largest steps of ω rounded to 1e-3 rad/s
    /// (a short decimal reads back to the same bits, so that a merge gives exactly the
    /// unsharded summary).
    pub smoothness: Sums,
}

impl Outcome {
    /// Runs scenario `seed` of `recipe`; `on_report` sees the run.
    pub fn run(recipe: &Recipe, seed: u64, on_report: impl FnOnce(&Scenario, &Report)) -> Self {
        let mut outcome = Self {
            seed,
            recipe: RecipeKey::of(recipe),
            skipped: true,
            robots: 0,
            converged_steps: Vec::new(),
            violations: 0,
            smoothness: Sums::default(),
        };
        if let Some(scenario) = scenario(recipe, seed) {
            // A generated scenario passes its checks (`generate.rs`); one that did not would
            // count as skipped.
            let Ok(report) = sim::run(&scenario) else {
                return outcome;
            };
            outcome.skipped = false;
            outcome.robots = report.robots.len();
            outcome.converged_steps = report
                .robots
                .iter()
                .filter_map(|r| r.converged_at)
                .map(|t| (t / DT).round() as u64)
                .collect();
            outcome.violations = report.violations;
            let sums = &mut outcome.smoothness;
            for r in &report.robots {
                sums.add(&r.smoothness, report.steps as u64, DT);
            }
            let round = |x: f64| (x * 1e3).round() / 1e3;
            sums.max_omega_step = round(sums.max_omega_step);
            sums.settled_max_omega_step = round(sums.settled_max_omega_step);
            on_report(&scenario, &report);
        }
        outcome
    }
}
