//! Random sweeps ([`crate::sweep`]): the summary of a whole sweep, one shard's outcomes, and the
//! summary of shards' outcomes, which is the same bits as the unsharded summary. The options
//! are checked and run by [`Plan`], and the shards merged by [`Merge`], as `dvf sweep`,
//! `dvf sweep --shard K/N` and `dvf sweep merge` do.

use super::{json, value_error};
use crate::params::DEFAULT_BARRIER_RATE;
use crate::sweep::{nothing_ran, Merge, Plan, Request, Summaries};
use crate::Error;
use pyo3::prelude::*;

/// The summaries as JSON, or the reason no scenario ran as a `ValueError`.
fn summaries_json(summaries: &Summaries) -> PyResult<String> {
    match nothing_ran(summaries) {
        Some(why) => Err(value_error(why)),
        None => json(summaries),
    }
}

/// A sweep's options, checked into a [`Plan`] (a refusal names the option's field), run whole
/// or one shard at a time.
#[pyclass(frozen)]
pub(crate) struct SweepPlan(Plan);

#[pymethods]
impl SweepPlan {
    #[new]
    #[pyo3(signature = (count, seed = 0, family = "random", robots = None, obstacles = None,
        spacing = None, avoidance = "exit", barrier_rate = Some(DEFAULT_BARRIER_RATE),
        set = Vec::new(), grid = Vec::new(), planner = None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        count: usize,
        seed: u64,
        family: &str,
        robots: Option<(usize, usize)>,
        obstacles: Option<(usize, usize)>,
        spacing: Option<(f64, f64)>,
        avoidance: &str,
        barrier_rate: Option<f64>,
        set: Vec<String>,
        grid: Vec<String>,
        planner: Option<&str>,
    ) -> PyResult<Self> {
        let planner = match planner {
            Some(text) => super::compare::spec_of("planner", text)?,
            None => crate::planner::Spec::default(),
        };
        Plan::new(&Request {
            family: family.to_owned(),
            seed,
            count,
            robots,
            obstacles,
            spacing,
            avoidance: avoidance.to_owned(),
            barrier_rate,
            set,
            grid,
            planner,
        })
        .map(Self)
        .map_err(value_error)
    }

    /// Runs every scenario on every core and returns their summary as JSON (`dvf sweep`).
    fn summary(&self, py: Python<'_>) -> PyResult<String> {
        let summaries = py.detach(|| self.0.summaries(|_, _, _, _| {}));
        summaries_json(&summaries)
    }

    /// Shard `shard` of `shards` (from 1), one outcome per scenario as a JSON line of
    /// `dvf sweep --shard`.
    fn shard(&self, py: Python<'_>, shard: usize, shards: usize) -> PyResult<Vec<String>> {
        let lines = py.detach(|| {
            let mut lines = Vec::new();
            self.0
                .shard(
                    (shard, shards),
                    |_, _, _, _| {},
                    |outcome| {
                        lines.push(serde_json::to_string(&outcome).unwrap_or_default());
                        Ok::<(), Error>(())
                    },
                )
                .map(|()| lines)
        });
        lines.map_err(value_error)
    }
}

/// The summary of outcomes (JSON lines of shards, in any order), checked to be one whole
/// sweep (`dvf sweep merge`): the summary of the unsharded sweep.
#[pyfunction]
pub(crate) fn merge(lines: Vec<String>) -> PyResult<String> {
    let mut merge = Merge::new();
    for (k, line) in lines.iter().enumerate() {
        merge
            .add(&format!("outcomes[{k}]"), line)
            .map_err(value_error)?;
    }
    let summaries = merge
        .finish()
        .map_err(|e| value_error(format!("outcomes: {e}")))?;
    summaries_json(&summaries)
}
