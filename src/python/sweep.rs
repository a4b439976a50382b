//! Random sweeps ([`crate::sweep`]): the summary of a whole sweep, one shard's outcomes, and the
//! summary of shards' outcomes, which is the same bits as the unsharded summary (what
//! `dvf sweep`, `dvf sweep --shard K/N` and `dvf sweep merge` print).

use super::{json, value_error};
use crate::params::{Avoidance, DEFAULT_BARRIER_RATE};
use crate::scenario::{MAX_OBSTACLES, MAX_ROBOTS};
use crate::sweep::{Family, Outcome, Recipe, Summary};
use pyo3::prelude::*;

/// Largest `count` of a sweep, as on the command line.
const MAX_SWEEP: usize = 1_000_000;

/// The recipe the options describe, each checked and named as the command line names it.
#[allow(clippy::too_many_arguments)]
fn recipe(
    family: &str,
    count: usize,
    robots: Option<(usize, usize)>,
    obstacles: Option<(usize, usize)>,
    spacing: Option<(f64, f64)>,
    avoidance: &str,
    barrier_rate: Option<f64>,
) -> PyResult<Recipe> {
    let family = match family {
        "random" => Family::Random,
        "dense" => Family::Dense,
        "formation" => Family::Formation,
        other => {
            return Err(value_error(format!(
                "family: must be random, dense or formation, not {other:?}"
            )))
        }
    };
    let mut recipe = Recipe::of(family);
    if !(1..=MAX_SWEEP).contains(&count) {
        return Err(value_error(format!(
            "count: must be between 1 and {MAX_SWEEP}, not {count}"
        )));
    }
    let robots = robots.unwrap_or((*recipe.robots.start(), *recipe.robots.end()));
    if robots.0 == 0 || robots.1 > MAX_ROBOTS || robots.0 > robots.1 {
        return Err(value_error(format!(
            "robots: must be a range within 1..={MAX_ROBOTS}, not {}..={}",
            robots.0, robots.1
        )));
    }
    let obstacles = obstacles.unwrap_or((*recipe.obstacles.start(), *recipe.obstacles.end()));
    if obstacles.1 > MAX_OBSTACLES || obstacles.0 > obstacles.1 {
        return Err(value_error(format!(
            "obstacles: must be a range within 0..={MAX_OBSTACLES}, not {}..={}",
            obstacles.0, obstacles.1
        )));
    }
    if let Some((a, b)) = spacing {
        if family != Family::Formation {
            return Err(value_error(
                "spacing: only the formation family has goal slots",
            ));
        }
        if !(a.is_finite() && b.is_finite() && 2.0 <= a && a <= b && b <= 100.0) {
            return Err(value_error(format!(
                "spacing: must be a range within 2..=100 safe radii, not {a}..={b}"
            )));
        }
        recipe.spacing = a..=b;
    }
    recipe.robots = robots.0..=robots.1;
    recipe.obstacles = obstacles.0..=obstacles.1;
    recipe.params.avoidance = Avoidance::from_name(avoidance).ok_or_else(|| {
        value_error(format!(
            "avoidance: must be exit or paper, not {avoidance:?}"
        ))
    })?;
    if let Some(r) = barrier_rate {
        if !(r.is_finite() && r > 0.0) {
            return Err(value_error(format!(
                "barrier_rate: must be a positive rate or None, not {r}"
            )));
        }
    }
    recipe.params.barrier_rate = barrier_rate;
    Ok(recipe)
}

/// The recipe's first scenario checked: the parameters are the same for every scenario.
fn check_first(recipe: &Recipe, seed: u64) -> PyResult<()> {
    if let Some(first) = crate::sweep::scenario(recipe, seed) {
        first.validate().map_err(value_error)?;
    }
    Ok(())
}

/// Runs scenarios `seed … seed + count − 1` on every core and returns their summary as JSON.
#[pyfunction]
#[pyo3(signature = (count, seed = 0, family = "random", robots = None, obstacles = None,
    spacing = None, avoidance = "exit", barrier_rate = Some(DEFAULT_BARRIER_RATE)))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn sweep(
    py: Python<'_>,
    count: usize,
    seed: u64,
    family: &str,
    robots: Option<(usize, usize)>,
    obstacles: Option<(usize, usize)>,
    spacing: Option<(f64, f64)>,
    avoidance: &str,
    barrier_rate: Option<f64>,
) -> PyResult<String> {
    let recipe = recipe(
        family,
        count,
        robots,
        obstacles,
        spacing,
        avoidance,
        barrier_rate,
    )?;
    check_first(&recipe, seed)?;
    let summary = py.detach(|| crate::sweep::sweep(&recipe, seed, count, |_, _, _| {}));
    json(&summary)
}

/// Shard `shard` of `shards` (from 1): scenarios `seed + k` for `k = shard − 1, shard − 1 +
/// shards, …` below `count`, one outcome each as a JSON line of `dvf sweep --shard`.
#[pyfunction]
#[pyo3(signature = (shard, shards, count, seed = 0, family = "random", robots = None,
    obstacles = None, spacing = None, avoidance = "exit",
    barrier_rate = Some(DEFAULT_BARRIER_RATE)))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn sweep_shard(
    py: Python<'_>,
    shard: usize,
    shards: usize,
    count: usize,
    seed: u64,
    family: &str,
    robots: Option<(usize, usize)>,
    obstacles: Option<(usize, usize)>,
    spacing: Option<(f64, f64)>,
    avoidance: &str,
    barrier_rate: Option<f64>,
) -> PyResult<Vec<String>> {
    if shards == 0 || !(1..=shards).contains(&shard) {
        return Err(value_error(format!(
            "shard: must be K/N with 1 ≤ K ≤ N, not {shard}/{shards}"
        )));
    }
    let recipe = recipe(
        family,
        count,
        robots,
        obstacles,
        spacing,
        avoidance,
        barrier_rate,
    )?;
    check_first(&recipe, seed)?;
    let outcomes = py.detach(|| {
        (shard - 1..count)
            .step_by(shards)
            .map(|k| Outcome::run(&recipe, seed.wrapping_add(k as u64), |_, _| {}))
            .collect::<Vec<_>>()
    });
    outcomes.iter().map(json).collect()
}

/// The summary of outcomes (JSON lines of shards, in any order), checked to be of one recipe
/// and to cover its seeds from the smallest, each once: the summary of the unsharded sweep.
#[pyfunction]
pub(crate) fn merge(lines: Vec<String>) -> PyResult<String> {
    let mut outcomes: Vec<Outcome> = Vec::with_capacity(lines.len());
    for (k, line) in lines.iter().enumerate() {
        let o: Outcome = serde_json::from_str(line)
            .map_err(|e| value_error(format!("outcomes[{k}]: not an outcome of a sweep: {e}")))?;
        if let Some(first) = outcomes.first() {
            if first.recipe != o.recipe {
                return Err(value_error(format!(
                    "outcomes[{k}]: seed {} was drawn from another recipe than seed {} (shards of different sweeps)",
                    o.seed, first.seed
                )));
            }
        }
        outcomes.push(o);
    }
    outcomes.sort_by_key(|o| o.seed);
    let Some(first) = outcomes.first().map(|o| o.seed) else {
        return Err(value_error("outcomes: no outcomes to merge"));
    };
    for (k, o) in outcomes.iter().enumerate() {
        let want = first.wrapping_add(k as u64);
        if o.seed != want {
            return Err(value_error(if o.seed < want {
                format!(
                    "outcomes: seed {} appears twice (a shard merged twice?)",
                    o.seed
                )
            } else {
                format!("outcomes: seed {want} is missing (a shard not finished or not given?)")
            }));
        }
    }
    json(&Summary::of(first, &outcomes))
}
