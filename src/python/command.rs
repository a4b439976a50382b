//! The controller over arrays of robots: [`crate::command`] for each row, in one call.

use super::{matrix, value_error};
use crate::obstacle::Obstacle;
use crate::params::Params;
use crate::scenario::Scenario;
use crate::se2::Pose;
use glam::DVec2;
use numpy::{PyArray2, PyReadonlyArray2};
use pyo3::prelude::*;

/// The parameters of `text` (a JSON object, missing keys at their defaults), checked as a
/// scenario's `params` are: the message names `params.KEY`. The scenario around them has one
/// robot and a step short enough for any gain, so that only the parameters can fail.
pub(crate) fn params_of(text: &str) -> PyResult<Params> {
    let doc = format!(
        r#"{{"duration":1e-9,"dt":1e-9,"robots":[{{"start":[0,0,0],"goal":[0,0,0]}}],"params":{text}}}"#
    );
    Ok(Scenario::from_json(&doc).map_err(value_error)?.params)
}

/// Checks that every value of `rows` is finite and that it has `columns` columns; names the
/// first offending entry `name[i][k]`.
fn finite_rows(name: &str, rows: &PyReadonlyArray2<'_, f64>, columns: usize) -> PyResult<()> {
    let a = rows.as_array();
    if a.ncols() != columns {
        return Err(value_error(format!(
            "{name}: must have {columns} columns, not {}",
            a.ncols()
        )));
    }
    for ((i, k), v) in a.indexed_iter() {
        if !v.is_finite() {
            return Err(value_error(format!(
                "{name}[{i}][{k}]: must be finite, not {v}"
            )));
        }
    }
    Ok(())
}

/// `(v, ω)` of each robot (eq. `eq_nonholo_controller` and its avoidance forms
/// `eq_nonholo_controller_ob_avoid`, `eq_nonholo_controller_co_avoid`): row `i` is
/// [`crate::command`] of `poses[i]` towards `goals[i]`, sensing every obstacle of `obstacles`
/// (rows `[x, y, r_o, R_o]`) and the neighbours `neighbours[offset_i .. offset_i + counts[i]]`
/// (rows `[x, y]`, robot `i`'s taken in order). Shape `(robots, 2)`.
#[pyfunction]
pub(crate) fn command<'py>(
    py: Python<'py>,
    params: &str,
    poses: PyReadonlyArray2<'py, f64>,
    goals: PyReadonlyArray2<'py, f64>,
    obstacles: PyReadonlyArray2<'py, f64>,
    neighbours: PyReadonlyArray2<'py, f64>,
    counts: Vec<usize>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let params = params_of(params)?;
    finite_rows("poses", &poses, 3)?;
    finite_rows("goals", &goals, 3)?;
    finite_rows("obstacles", &obstacles, 4)?;
    finite_rows("neighbours", &neighbours, 2)?;
    let (poses, goals) = (poses.as_array(), goals.as_array());
    let n = poses.nrows();
    if goals.nrows() != n {
        return Err(value_error(format!(
            "goals: must have one row per pose ({n}), not {}",
            goals.nrows()
        )));
    }
    if counts.len() != n {
        return Err(value_error(format!(
            "neighbours: must give one list per pose ({n}), not {}",
            counts.len()
        )));
    }
    let listed: usize = counts.iter().sum();
    if listed != neighbours.as_array().nrows() {
        return Err(value_error(format!(
            "neighbours: the lists hold {listed} positions, the array {}",
            neighbours.as_array().nrows()
        )));
    }
    let mut sensed = Vec::with_capacity(obstacles.as_array().nrows());
    for (i, o) in obstacles.as_array().rows().into_iter().enumerate() {
        if o[2] <= 0.0 {
            return Err(value_error(format!(
                "obstacles[{i}].radius: must be positive, not {}",
                o[2]
            )));
        }
        if o[3] <= o[2] {
            return Err(value_error(format!(
                "obstacles[{i}].influence: must exceed the radius ({})",
                o[2]
            )));
        }
        sensed.push(Obstacle {
            center: DVec2::new(o[0], o[1]),
            radius: o[2],
            influence: o[3],
        });
    }
    let others: Vec<DVec2> = neighbours
        .as_array()
        .rows()
        .into_iter()
        .map(|r| DVec2::new(r[0], r[1]))
        .collect();
    let pose = |a: numpy::ndarray::ArrayView1<'_, f64>| Pose::new(a[0], a[1], a[2]);
    let rows: Vec<(Pose, Pose)> = poses
        .rows()
        .into_iter()
        .zip(goals.rows())
        .map(|(p, g)| (pose(p), pose(g)))
        .collect();
    let out = py.detach(|| {
        let mut out = Vec::with_capacity(2 * n);
        let mut from = 0;
        for ((p, g), &count) in rows.iter().zip(&counts) {
            let c = crate::command(&params, *p, *g, &sensed, &others[from..from + count]);
            from += count;
            out.extend_from_slice(&[c.v, c.omega]);
        }
        out
    });
    matrix(py, out, 2)
}
