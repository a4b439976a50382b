//! A sweep and its statistics: the outcomes of its scenarios summarised in seed order, so that
//! the summary is the same bits however the scenarios were run or split.

use super::outcome::Outcome;
use super::recipe::{Recipe, DT};
use super::settings::Values;
use crate::planner::Spec;
use crate::scenario::Scenario;
use crate::sim::smoothness::{Smoothness, Sums};
use crate::sim::Report;
use serde::Serialize;

/// One scenario of a sweep that did not keep every promise.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Failure {
    /// Its seed: `random_scenario(recipe, seed)` rebuilds it.
    pub seed: u64,
    /// Robots that had not converged at the end.
    pub unconverged: usize,
    /// Violation events (see [`Report::violations`]).
    pub violations: usize,
}

/// What a sweep found.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Summary {
    /// The planner the scenarios ran with, when it is not DVF.
    #[serde(skip_serializing_if = "Spec::is_default")]
    pub planner: Spec,
    /// First seed.
    pub seed: u64,
    /// Scenarios run.
    pub scenarios: usize,
    /// Robots over all scenarios.
    pub robots: usize,
    /// Robots that converged (within tolerance from some time to the end).
    pub converged: usize,
    /// `converged / robots`; `None` (null) when no scenario ran, so that a sweep of nothing
    /// never reads as a success.
    pub success_rate: Option<f64>,
    /// Violation events over all scenarios.
    pub violations: usize,
    /// Scenarios whose poses could not be placed (not run).
    pub skipped: usize,
    /// Quantiles of the convergence time of converged robots (s): min, 10 %, median, 90 %, max.
    pub convergence_time: Quantiles,
    /// How smooth the turn rates were, over all robots of all scenarios.
    pub smoothness: Smoothness,
    /// Every scenario with an unconverged robot or a violation.
    pub failures: Vec<Failure>,
}

/// Order statistics of a sample.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Quantiles {
    /// Smallest value.
    pub min: f64,
    /// 10th percentile.
    pub p10: f64,
    /// Median.
    pub p50: f64,
    /// 90th percentile.
    pub p90: f64,
    /// Largest value.
    pub max: f64,
}

impl Quantiles {
    /// Nearest-rank quantiles of `values` (all zero when empty).
    #[must_use]
    pub fn of(mut values: Vec<f64>) -> Self {
        if values.is_empty() {
            return Self::default();
        }
        values.sort_by(f64::total_cmp);
        let at = |q: f64| values[((values.len() - 1) as f64 * q).round() as usize];
        Self {
            min: at(0.0),
            p10: at(0.1),
            p50: at(0.5),
            p90: at(0.9),
            max: at(1.0),
        }
    }
}

/// Runs scenarios `seed, seed + 1, …` (`count` of them) and summarises them. `on_report`
/// sees each run (for writing failures out). Natively the scenarios run on every core
/// (rayon); the summary is the same bits with any number of threads, since [`Summary::of`]
/// takes the outcomes in seed order.
pub fn sweep(
    recipe: &Recipe,
    seed: u64,
    count: usize,
    on_report: impl Fn(u64, &Scenario, &Report) + Sync,
) -> Summary {
    let run = |k: u64| {
        let s = seed.wrapping_add(k);
        Outcome::run(recipe, s, |scenario, report| on_report(s, scenario, report))
    };
    #[cfg(not(target_arch = "wasm32"))]
    let outcomes: Vec<Outcome> = {
        use rayon::prelude::*;
        (0..count as u64).into_par_iter().map(run).collect()
    };
    #[cfg(target_arch = "wasm32")]
    let outcomes: Vec<Outcome> = (0..count as u64).map(run).collect();
    Summary::of(seed, &outcomes)
}

/// [`sweep`] at each point of a grid: `points` are the points' values and recipes, in the
/// grid's order (one point without values: a sweep without a grid, summarised as one).
/// `on_report` sees each run with its point's values.
pub fn sweep_points(
    points: &[(Values, Recipe)],
    seed: u64,
    count: usize,
    on_report: impl Fn(&Values, u64, &Scenario, &Report) + Sync,
) -> Summaries {
    let run = |(values, recipe): &(Values, Recipe)| {
        sweep(recipe, seed, count, |s, scenario, report| {
            on_report(values, s, scenario, report);
        })
    };
    match points {
        [point] if point.0.is_empty() => Summaries::One(run(point)),
        _ => Summaries::Grid(Groups {
            groups: points
                .iter()
                .map(|point| Group {
                    values: point.0.clone(),
                    summary: run(point),
                })
                .collect(),
        }),
    }
}

impl Summary {
    /// The summary of `outcomes`, in seed order from `seed` (the first): what [`sweep`] prints
    /// for the same scenarios, however they were split and in whatever order they arrive.
    #[must_use]
    pub fn of(seed: u64, outcomes: &[Outcome]) -> Self {
        let mut outcomes: Vec<&Outcome> = outcomes.iter().collect();
        outcomes.sort_by_key(|o| o.seed.wrapping_sub(seed));
        let mut robots = 0;
        let mut converged = 0;
        let mut violations = 0;
        let mut skipped = 0;
        let mut times = Vec::new();
        let mut failures = Vec::new();
        let mut smooth = Sums::default();
        // Every scenario of a sweep (or of a grid point) has the recipe's step.
        let dt = outcomes.first().map_or(DT, |o| o.dt);
        for o in &outcomes {
            if o.skipped {
                skipped += 1;
                continue;
            }
            let arrived = o.arrival_steps().count();
            let unconverged = o.robots.len() - arrived;
            robots += o.robots.len();
            converged += arrived;
            violations += o.violations;
            smooth.merge(&o.smoothness);
            times.extend(o.arrival_steps().map(|k| k as f64 * dt));
            if unconverged > 0 || o.violations > 0 {
                failures.push(Failure {
                    seed: o.seed,
                    unconverged,
                    violations: o.violations,
                });
            }
        }
        let count = outcomes.len();
        Summary {
            planner: outcomes
                .first()
                .map(|o| o.recipe.planner.clone())
                .unwrap_or_default(),
            seed,
            scenarios: count - skipped,
            robots,
            converged,
            success_rate: (robots > 0).then(|| converged as f64 / robots as f64),
            violations,
            skipped,
            convergence_time: Quantiles::of(times),
            smoothness: smooth.smoothness(dt),
            failures,
        }
    }
}

/// One point of a grid sweep: its values and the summary of its scenarios.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Group {
    /// The grid point's values, by name.
    pub values: Values,
    /// Its scenarios' summary.
    #[serde(flatten)]
    pub summary: Summary,
}

/// What a sweep over a grid found: one group per point, in the grid's order.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Groups {
    /// The points' summaries.
    pub groups: Vec<Group>,
}

/// A sweep's summary: one, or one per point of its grid.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Summaries {
    /// A sweep without a grid.
    One(Summary),
    /// A sweep over a grid.
    Grid(Groups),
}

impl Summaries {
    /// The summaries with their grid points' values (none without a grid).
    #[must_use]
    pub fn all(&self) -> Vec<(Option<&Values>, &Summary)> {
        match self {
            Self::One(s) => vec![(None, s)],
            Self::Grid(g) => g
                .groups
                .iter()
                .map(|g| (Some(&g.values), &g.summary))
                .collect(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::test;

    #[test]
    fn quantiles_by_nearest_rank() {
        let q = Quantiles::of((0..=10).rev().map(f64::from).collect());
        assert_eq!(
            q,
            Quantiles {
                min: 0.0,
                p10: 1.0,
                p50: 5.0,
                p90: 9.0,
                max: 10.0
            }
        );
        assert_eq!(Quantiles::of(vec![]), Quantiles::default());
    }

    /// A sweep whose every scenario was skipped has no success rate (null), not 1.
    #[test]
    fn a_sweep_of_skipped_scenarios_has_no_success_rate() {
        let recipe = Recipe {
            robots: 1000..=1000,
            ..Recipe::default()
        };
        let s = sweep(&recipe, 0, 2, |_, _, _| {});
        assert_eq!((s.scenarios, s.skipped, s.robots), (0, 2, 0));
        assert_eq!(s.success_rate, None);
        let json = serde_json::to_value(&s).unwrap();
        assert!(json["success_rate"].is_null(), "{json}");
    }
}
