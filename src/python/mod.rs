//! The Python module `dvf._dvf` (the `python` feature): the core for the `dvf` wheel that
//! maturin builds from python/pyproject.toml. The Python package (python/dvf/) wraps it in
//! Python's idiom; this module only converts.
//!
//! Scenarios, reports and sweep outcomes cross as JSON text: serde_json writes each number as
//! its shortest round-trip decimal and Python's `json` reads it back to the same bits, so a
//! report read in Python is the very report `dvf simulate` prints. Arrays (trajectories,
//! fields, commands) cross as numpy arrays that take over the vector Rust filled: no copy, and
//! no Python object per sample. Every function that takes input raises `ValueError` with the
//! core's message, which names the offending field (`params.k_v: must be positive, not -1`).
//! Long computations release the GIL, so that threads (a Dask worker's among them) run
//! alongside.
//!
//! - `mod.rs`: presets, scenario checks, a whole run and the goal field on a grid;
//! - `command.rs`: the controller over arrays of robots;
//! - `sweep.rs`: random sweeps, their shards and the merge of shards;
//! - `compare.rs`: the planners, and a scenario run with each of several.

mod command;
mod compare;
mod sweep;

use crate::presets::{self as catalogue, PRESETS};
use crate::scenario::Scenario;
use crate::se2::Pose;
use numpy::ndarray::{Array2, Array3};
use numpy::{IntoPyArray, PyArray2, PyArray3};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

/// `ValueError` carrying the message of a core error or of a check here.
pub(crate) fn value_error(e: impl ToString) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// JSON text of `value` (the serialisations here cannot fail: plain structs of numbers).
pub(crate) fn json(value: &impl serde::Serialize) -> PyResult<String> {
    serde_json::to_string(value).map_err(value_error)
}

/// Every preset as `(name, summary)`, the default first.
#[pyfunction]
fn presets() -> Vec<(&'static str, &'static str)> {
    PRESETS.iter().map(|p| (p.name, p.summary)).collect()
}

/// The name of the preset shown when nothing else is asked for.
#[pyfunction]
fn default_preset() -> &'static str {
    catalogue::DEFAULT_PRESET
}

/// The preset `name` (`crowd-N` included) as scenario JSON, bounds resolved.
#[pyfunction]
fn preset(name: &str) -> PyResult<String> {
    Ok(catalogue::preset(name).map_err(value_error)?.to_json())
}

/// Parses and validates scenario JSON; returns it with the defaults filled in and the bounds
/// resolved (what `dvf presets NAME` writes for a preset).
#[pyfunction]
fn check(text: &str) -> PyResult<String> {
    Ok(Scenario::from_json(text).map_err(value_error)?.to_json())
}

/// Runs scenario JSON to its end, recording every robot at every `every`-th step and the last.
/// Returns the report as JSON (what `dvf simulate` prints) and the samples as an array of
/// shape `(samples, robots, 6)`, each `[t, x, y, θ, v, ω]`: the rows of `dvf simulate --csv`
/// in their order.
#[pyfunction]
#[pyo3(signature = (text, every = 1))]
fn simulate<'py>(
    py: Python<'py>,
    text: &str,
    every: usize,
) -> PyResult<(String, Bound<'py, PyArray3<f64>>)> {
    if every == 0 {
        return Err(value_error("every: must be at least 1, not 0"));
    }
    let scenario = Scenario::from_json(text).map_err(value_error)?;
    let robots = scenario.robots.len();
    let total = scenario.steps();
    let (report, flat) = py.detach(|| {
        let mut flat = Vec::with_capacity((total / every + 2) * robots * 6);
        let report = crate::sim::run_streamed(&scenario, every, |_, samples| {
            flat.extend(samples.iter().flatten());
            Ok::<(), crate::Error>(())
        });
        (report, flat)
    });
    let report = report.map_err(value_error)?;
    let samples = flat.len() / (robots * 6);
    let array = Array3::from_shape_vec((samples, robots, 6), flat).map_err(value_error)?;
    Ok((json(&report)?, array.into_pyarray(py)))
}

/// Largest grid side of [`field`]: a million samples.
const MAX_GRID: usize = 1000;

/// The world-frame goal field `Γ̃_d` of `goal` at attitude `theta` on an `n × n` grid over
/// `bounds = [xmin, ymin, xmax, ymax]`, corners included (eqs. `eq_DVF`, `eq_DVF_in_Fb`;
/// [`crate::field::sample_grid`]). Shape `(n, n, 4)`: row `j` at `y_j`, column `i` at `x_i`,
/// each `[x, y, Γx, Γy]`.
#[pyfunction]
fn field<'py>(
    py: Python<'py>,
    goal: [f64; 3],
    theta: f64,
    bounds: [f64; 4],
    n: usize,
) -> PyResult<Bound<'py, PyArray3<f64>>> {
    for (k, v) in goal.iter().enumerate() {
        if !v.is_finite() {
            return Err(value_error(format!("goal[{k}]: must be finite, not {v}")));
        }
    }
    if !theta.is_finite() {
        return Err(value_error(format!("theta: must be finite, not {theta}")));
    }
    for (k, v) in bounds.iter().enumerate() {
        if !v.is_finite() {
            return Err(value_error(format!("bounds[{k}]: must be finite, not {v}")));
        }
    }
    if !(bounds[0] < bounds[2] && bounds[1] < bounds[3]) {
        return Err(value_error(
            "bounds: must be [xmin, ymin, xmax, ymax] with xmin < xmax and ymin < ymax",
        ));
    }
    if !(2..=MAX_GRID).contains(&n) {
        return Err(value_error(format!(
            "grid: must be between 2 and {MAX_GRID}, not {n}"
        )));
    }
    let goal = Pose::new(goal[0], goal[1], goal[2]);
    let points = py.detach(|| crate::field::sample_grid(goal, theta, bounds, n));
    let flat: Vec<f64> = points.into_iter().flatten().collect();
    let array = Array3::from_shape_vec((n, n, 4), flat).map_err(value_error)?;
    Ok(array.into_pyarray(py))
}

/// A `(rows, columns)` array of `values` laid out row by row (no copy).
pub(crate) fn matrix<'py>(
    py: Python<'py>,
    values: Vec<f64>,
    columns: usize,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let rows = values.len() / columns;
    let array = Array2::from_shape_vec((rows, columns), values).map_err(value_error)?;
    Ok(array.into_pyarray(py))
}

/// The module `dvf._dvf`.
#[pymodule]
fn _dvf(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_function(wrap_pyfunction!(presets, m)?)?;
    m.add_function(wrap_pyfunction!(default_preset, m)?)?;
    m.add_function(wrap_pyfunction!(preset, m)?)?;
    m.add_function(wrap_pyfunction!(check, m)?)?;
    m.add_function(wrap_pyfunction!(simulate, m)?)?;
    m.add_function(wrap_pyfunction!(field, m)?)?;
    m.add_function(wrap_pyfunction!(command::command, m)?)?;
    m.add_class::<sweep::SweepPlan>()?;
    m.add_function(wrap_pyfunction!(sweep::merge, m)?)?;
    m.add_function(wrap_pyfunction!(compare::planners, m)?)?;
    m.add_function(wrap_pyfunction!(compare::compare, m)?)?;
    Ok(())
}
