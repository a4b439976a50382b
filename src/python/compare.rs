//! Planners side by side ([`crate::compare`]): the list of planners, and a scenario run with
//! each of several, as the JSON `dvf compare --json` prints.

use super::{json, value_error};
use crate::compare::{all_planners, compare as run_compare};
use crate::planner::{Spec, PLANNERS};
use crate::scenario::Scenario;
use pyo3::prelude::*;

/// Every planner as `(name, title, source, avoids)`, in the menus' order.
#[pyfunction]
pub(crate) fn planners() -> Vec<(&'static str, &'static str, &'static str, &'static str)> {
    PLANNERS
        .iter()
        .map(|e| (e.name, e.title, e.source, e.avoids))
        .collect()
}

/// A planner from its JSON text (a name or an object with its gains), a refusal naming
/// `field`.
pub(crate) fn spec_of(field: &str, text: &str) -> PyResult<Spec> {
    serde_json::from_str(text).map_err(|e| value_error(format!("{field}: {e}")))
}

/// Scenario JSON run with each of `planners` (JSON texts of names or objects; all of them when
/// `None`), the comparison as JSON. The computation runs without the GIL.
#[pyfunction]
#[pyo3(signature = (text, planners = None))]
pub(crate) fn compare(
    py: Python<'_>,
    text: &str,
    planners: Option<Vec<String>>,
) -> PyResult<String> {
    let scenario = Scenario::from_json(text).map_err(value_error)?;
    let specs = match planners {
        None => all_planners(),
        Some(texts) => texts
            .iter()
            .enumerate()
            .map(|(k, t)| spec_of(&format!("planners[{k}]"), t))
            .collect::<PyResult<_>>()?,
    };
    let comparison = py
        .detach(|| run_compare(&scenario, &specs))
        .map_err(value_error)?;
    json(&comparison)
}
