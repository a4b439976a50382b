//! The JavaScript facade (wasm32 only): the core knows nothing of JavaScript; these modules
//! only convert.
//!
//! - `mod.rs`: presets, the parameter table, scenario checks and the playground's limits, as
//!   free functions;
//! - [`playground`]: `Playground`, the live, editable simulation behind `<dvf-playground>`,
//!   its buffers read in place through one [`Playground::layout`](playground::Playground::layout);
//! - [`run`]: `Run`, a whole recorded run; [`bench`]: `CrowdBench`, for timing;
//! - [`compare`]: the planners and a scenario run with each of several (`dvf compare`);
//! - [`convert`]: the one conversion of numbers, scenarios, errors and values.
//!
//! Scenarios come in as objects or JSON text; scenarios and reports leave as plain JS objects
//! (serde-wasm-bindgen, JSON-compatible: a missing value is `null`, maps are objects). Every
//! function that takes input returns `Result<_, JsError>` whose message is the core's
//! [`crate::Error`] text, which names the offending field (`params.k_v: must be positive, not
//! -1`). The TypeScript declarations of the package (`dvf.d.ts`) are generated from here.

pub mod bench;
pub mod compare;
mod convert;
pub mod playground;
pub mod run;

pub use bench::CrowdBench;
pub use compare::{compare, planners};
pub use playground::Playground;
pub use run::{Run, MAX_SAMPLES_PER_ROBOT, MAX_SAMPLES_TOTAL, SAMPLE_STRIDE};

use crate::playground as live;
use crate::presets::{self, PRESETS};
use convert::{js_error, scenario_from_js, to_js};
use serde::Serialize;
use wasm_bindgen::prelude::*;

/// One entry of [`presets`].
#[derive(Serialize)]
struct PresetInfo {
    name: &'static str,
    summary: &'static str,
}

/// Every preset as `[{name, summary}]`, the default first.
///
/// # Errors
/// Only if the JS engine refuses to build the array.
#[wasm_bindgen]
pub fn presets() -> Result<JsValue, JsError> {
    let list: Vec<PresetInfo> = PRESETS
        .iter()
        .map(|p| PresetInfo {
            name: p.name,
            summary: p.summary,
        })
        .collect();
    to_js(&list)
}

/// The parameter table ([`crate::params::PARAMETERS`]) as `{rows, modes}`: `rows` is
/// `[{name, symbol, unit, kind, range, meaning, panel}]` in the panel's order (`kind` is
/// `"number"`, `"optional"` or `"mode"`), `modes` the avoidance modes, the default first. The
/// page's panel and messages read it rather than naming the parameters themselves.
///
/// # Errors
/// Only if the JS engine refuses to build the object.
#[wasm_bindgen]
pub fn parameters() -> Result<JsValue, JsError> {
    #[derive(Serialize)]
    struct Table {
        rows: &'static [crate::params::Parameter],
        modes: [&'static str; 2],
    }
    to_js(&Table {
        rows: crate::params::PARAMETERS,
        modes: crate::params::AVOIDANCE_MODES,
    })
}

/// The name of the preset shown when nothing else is asked for.
#[wasm_bindgen(js_name = defaultPreset)]
#[must_use]
pub fn default_preset() -> String {
    presets::DEFAULT_PRESET.to_owned()
}

/// The preset `name` as a scenario object (the JSON scenario format, bounds resolved).
///
/// # Errors
/// An unknown name; the message lists the names that exist.
#[wasm_bindgen(js_name = presetScenario)]
pub fn preset_scenario(name: &str) -> Result<JsValue, JsError> {
    let mut s = presets::preset(name).map_err(js_error)?;
    s.bounds = Some(s.resolved_bounds());
    to_js(&s)
}

/// Checks a scenario (object or JSON text) without running it and returns it with the
/// defaults filled in and the bounds resolved.
///
/// # Errors
/// The first offending field, as for [`Run::new`].
#[wasm_bindgen(js_name = checkScenario)]
pub fn check_scenario(scenario: JsValue) -> Result<JsValue, JsError> {
    let mut s = scenario_from_js(scenario).map_err(js_error)?;
    s.bounds = Some(s.resolved_bounds());
    to_js(&s)
}

/// The playground's limits and records as an object, so that the page reads them rather than
/// copying them: `{trailCapacity, predictionSamples, curvePoints, maxGridSide, maxCurveSide,
/// maxRobots, maxPredictedRobots, crowdMax, poseStride, statusStride, statusFields, fieldStride,
/// curveStride, sampleStride}`. `statusFields` names the values of a status record in order;
/// `trailCapacity` is the largest (a scene's own is [`Playground::trail_capacity`]).
///
/// # Errors
/// Only if the JS engine refuses to build the object.
#[wasm_bindgen(js_name = playgroundLimits)]
pub fn playground_limits() -> Result<JsValue, JsError> {
    #[derive(Serialize)]
    #[serde(rename_all = "camelCase")]
    struct Limits {
        trail_capacity: usize,
        prediction_samples: usize,
        curve_points: usize,
        max_grid_side: usize,
        max_curve_side: usize,
        max_robots: usize,
        max_predicted_robots: usize,
        crowd_max: usize,
        pose_stride: usize,
        status_stride: usize,
        status_fields: [&'static str; live::STATUS_STRIDE],
        field_stride: usize,
        curve_stride: usize,
        sample_stride: usize,
    }
    to_js(&Limits {
        trail_capacity: live::MAX_TRAIL_SAMPLES,
        prediction_samples: live::PREDICTION_SAMPLES,
        curve_points: live::CURVE_POINTS,
        max_grid_side: live::MAX_GRID_SIDE,
        max_curve_side: live::MAX_CURVE_SIDE,
        max_robots: live::MAX_LIVE_ROBOTS,
        max_predicted_robots: live::MAX_PREDICTED_ROBOTS,
        crowd_max: presets::CROWD_MAX,
        pose_stride: live::POSE_STRIDE,
        status_stride: live::STATUS_STRIDE,
        status_fields: live::STATUS_FIELDS,
        field_stride: live::FIELD_STRIDE,
        curve_stride: live::CURVE_STRIDE,
        sample_stride: SAMPLE_STRIDE,
    })
}
