//! `Run`: a scenario simulated to its end, its trajectories recorded, for pages that draw a
//! whole run at once.

use super::convert::{js_error, scenario_from_js, to_js};
use crate::presets;
use crate::scenario::Scenario;
use crate::sim::{self, Report, Sample};
use js_sys::Float64Array;
use wasm_bindgen::prelude::*;

/// At most this many samples are kept per robot (the first and the last always).
pub const MAX_SAMPLES_PER_ROBOT: usize = 2_000;
/// At most this many samples are kept over all robots, so that a scenario with very many
/// robots thins its trajectories instead of exhausting the module's memory.
pub const MAX_SAMPLES_TOTAL: usize = 1_000_000;
/// Values per trajectory sample: `[t, x, y, θ, v, ω]`.
pub const SAMPLE_STRIDE: usize = 6;

/// A scenario simulated to its end, with every robot's trajectory recorded.
///
/// Flat array layouts (all `Float64Array`, robots in scenario order, lengths in brackets):
/// - [`trajectories`](Run::trajectories) `[robots · samples · 6]`: robot-major, then sample,
///   then `t, x, y, θ, v, ω` (s, m, m, rad in `(−π, π]`, m/s, rad/s). Sample `k` of robot
///   `i` starts at `(i · samples + k) · 6`. Every robot has the same sample times: `t = 0`
///   first, the end of the run last, evenly spaced in between.
/// - [`starts`](Run::starts) and [`goals`](Run::goals) `[robots · 3]`: `x, y, θ`.
/// - [`obstacles`](Run::obstacles) `[obstacles · 4]`: `cx, cy, r_o, R_o` (centre, disc radius,
///   influence radius).
/// - [`bounds`](Run::bounds) `[4]`: `xmin, ymin, xmax, ymax`.
#[wasm_bindgen]
pub struct Run {
    scenario: Scenario,
    report: Report,
    samples: usize,
    trajectories: Vec<f64>,
}

/// Methods exported to JavaScript.
#[wasm_bindgen]
impl Run {
    /// Validates `scenario` (a scenario object such as [`preset_scenario`] returns, or JSON
    /// text) and simulates it to its end.
    ///
    /// # Errors
    /// A scenario that does not parse or validate; the message names the field.
    #[wasm_bindgen(constructor)]
    pub fn new(scenario: JsValue) -> Result<Run, JsError> {
        let s = scenario_from_js(scenario).map_err(js_error)?;
        Self::simulate(s)
    }

    /// Runs the preset `name`.
    ///
    /// # Errors
    /// An unknown name; the message lists the names that exist.
    #[wasm_bindgen(js_name = fromPreset)]
    pub fn from_preset(name: &str) -> Result<Run, JsError> {
        let s = presets::preset(name).map_err(js_error)?;
        Self::simulate(s)
    }

    /// The scenario's name (free text: show it with `textContent`).
    #[wasm_bindgen(getter)]
    #[must_use]
    pub fn name(&self) -> String {
        self.scenario.name.clone()
    }

    /// Number of robots.
    #[wasm_bindgen(getter, js_name = robotCount)]
    #[must_use]
    pub fn robot_count(&self) -> usize {
        self.scenario.robots.len()
    }

    /// Number of recorded samples per robot (at least 2).
    #[wasm_bindgen(getter, js_name = sampleCount)]
    #[must_use]
    pub fn sample_count(&self) -> usize {
        self.samples
    }

    /// Simulated time at the end (s).
    #[wasm_bindgen(getter)]
    #[must_use]
    pub fn duration(&self) -> f64 {
        self.report.time
    }

    /// Whether the robots are independent runs drawn together (no pair metrics).
    #[wasm_bindgen(getter)]
    #[must_use]
    pub fn independent(&self) -> bool {
        self.scenario.independent
    }

    /// The safe radius `r_ij` (m): two robots closer than twice this are a violation.
    #[wasm_bindgen(getter, js_name = safeRadius)]
    #[must_use]
    pub fn safe_radius(&self) -> f64 {
        self.scenario.params.safe_radius
    }

    /// `[robots · samples · 6]`: see [`Run`].
    #[must_use]
    pub fn trajectories(&self) -> Float64Array {
        Float64Array::from(self.trajectories.as_slice())
    }

    /// `[robots · 3]` start poses `x, y, θ`.
    #[must_use]
    pub fn starts(&self) -> Float64Array {
        let v: Vec<f64> = self.scenario.robots.iter().flat_map(|r| r.start).collect();
        Float64Array::from(v.as_slice())
    }

    /// `[robots · 3]` goal poses `x, y, θ`.
    #[must_use]
    pub fn goals(&self) -> Float64Array {
        let v: Vec<f64> = self.scenario.robots.iter().flat_map(|r| r.goal).collect();
        Float64Array::from(v.as_slice())
    }

    /// `[obstacles · 4]`: `cx, cy, r_o, R_o`.
    #[must_use]
    pub fn obstacles(&self) -> Float64Array {
        let v: Vec<f64> = self
            .scenario
            .obstacles
            .iter()
            .flat_map(|o| [o.center.x, o.center.y, o.radius, o.influence])
            .collect();
        Float64Array::from(v.as_slice())
    }

    /// `[4]`: `xmin, ymin, xmax, ymax` of the area to draw.
    #[must_use]
    pub fn bounds(&self) -> Float64Array {
        Float64Array::from(self.scenario.resolved_bounds().as_slice())
    }

    /// The run's report as an object (the JSON of `dvf simulate`).
    ///
    /// # Errors
    /// Only if the JS engine refuses to build the object.
    pub fn report(&self) -> Result<JsValue, JsError> {
        to_js(&self.report)
    }

    /// The scenario that was run, defaults filled in and bounds resolved.
    ///
    /// # Errors
    /// Only if the JS engine refuses to build the object.
    pub fn scenario(&self) -> Result<JsValue, JsError> {
        let mut s = self.scenario.clone();
        s.bounds = Some(s.resolved_bounds());
        to_js(&s)
    }
}

/// Rust-only helpers.
impl Run {
    /// Simulates a scenario, keeping at most [`MAX_SAMPLES_PER_ROBOT`] samples per robot.
    fn simulate(scenario: Scenario) -> Result<Run, JsError> {
        let every = decimation(scenario.steps(), scenario.robots.len());
        let (report, traj) = sim::run_recorded(&scenario, every).map_err(js_error)?;
        let samples = traj.first().map_or(0, Vec::len);
        // Every robot is recorded at the same steps, so the rows are equally long.
        debug_assert!(traj.iter().all(|t| t.len() == samples));
        let trajectories = traj.iter().flatten().flat_map(|s: &Sample| *s).collect();
        Ok(Run {
            scenario,
            report,
            samples,
            trajectories,
        })
    }
}

/// The recording interval (in steps) that keeps a run of `steps` steps within the sample
/// budget. `run_recorded` keeps steps `0, every, 2·every, …` and the last, that is at most
/// `steps / every + 2` samples.
fn decimation(steps: usize, robots: usize) -> usize {
    let per_robot = (MAX_SAMPLES_TOTAL / robots.max(1)).clamp(3, MAX_SAMPLES_PER_ROBOT);
    steps.div_ceil(per_robot - 2).max(1)
}
