//! Planners side by side for the page: the list of planners and a scenario run with each of
//! several ([`crate::compare`]), as the same JSON `dvf compare --json` prints.

use super::convert::{js_error, scenario_from_js, to_js};
use crate::compare::{all_planners, compare as run_compare};
use crate::error::Error;
use crate::planner::{Spec, PLANNERS};
use serde::Serialize;
use wasm_bindgen::prelude::*;

/// One entry of [`planners`].
#[derive(Serialize)]
struct PlannerInfo {
    name: &'static str,
    title: &'static str,
    source: &'static str,
    avoids: &'static str,
}

/// Every planner as `[{name, title, source, avoids}]`, in the menus' order (`dvf planners`).
///
/// # Errors
/// Only if the JS engine refuses to build the array.
#[wasm_bindgen]
pub fn planners() -> Result<JsValue, JsError> {
    let list: Vec<PlannerInfo> = PLANNERS
        .iter()
        .map(|e| PlannerInfo {
            name: e.name,
            title: e.title,
            source: e.source,
            avoids: e.avoids,
        })
        .collect();
    to_js(&list)
}

/// Runs `scenario` (an object or JSON text) with each of `planners` (an array of names, or of
/// objects `{name, gains…}`; all of them when `undefined` or `null`) and returns the
/// comparison: `{scenario, conditions, planners: [{planner, title, avoids, metrics, robots}]}`,
/// the JSON of `dvf compare --json`. Every number but `metrics.ms_per_step` is the native
/// run's, to the bit.
///
/// # Errors
/// A scenario that does not validate, or a planner list that is not an array of names or
/// objects, or names an unknown planner or gains it refuses; the message names the field
/// (`planners[1]`).
#[wasm_bindgen]
pub fn compare(scenario: JsValue, planners: JsValue) -> Result<JsValue, JsError> {
    let s = scenario_from_js(scenario).map_err(js_error)?;
    let specs = specs_from_js(&planners).map_err(js_error)?;
    to_js(&run_compare(&s, &specs).map_err(js_error)?)
}

/// The planners of a JS value: all of them for `undefined` or `null`, else an array read
/// through its JSON text, so that a wrong entry is named (`planners[1]`).
fn specs_from_js(value: &JsValue) -> Result<Vec<Spec>, Error> {
    if value.is_undefined() || value.is_null() {
        return Ok(all_planners());
    }
    let invalid = |field: String, message: String| Error::Invalid { field, message };
    if !js_sys::Array::is_array(value) {
        return Err(invalid(
            "planners".into(),
            "expected an array of planner names or objects {name, gains…}".into(),
        ));
    }
    let text = js_sys::JSON::stringify(value)
        .ok()
        .and_then(|t| t.as_string())
        .ok_or_else(|| invalid("planners".into(), "cannot be written as JSON".into()))?;
    let mut de = serde_json::Deserializer::from_str(&text);
    serde_path_to_error::deserialize::<_, Vec<Spec>>(&mut de).map_err(|e| {
        invalid(
            format!("planners{}", e.path()).replace("planners.", "planners"),
            e.into_inner().to_string(),
        )
    })
}
