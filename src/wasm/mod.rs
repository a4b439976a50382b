//! The JavaScript facade (wasm32 only): presets, scenarios and whole recorded runs for the
//! page in `www/`. The core knows nothing of JavaScript; this module only converts.
//!
//! Scenarios come in as objects or JSON text; scenarios and reports leave as plain JS objects
//! (serde-wasm-bindgen, JSON-compatible: a missing value is `null`, maps are objects).
//! Per-sample data leaves as flat `Float64Array`s whose layouts are documented on [`Run`].
//! Every function that takes input returns `Result<_, JsError>` whose message is the core's
//! [`Error`] text, which names the offending field (`params.k_v: must be positive, not -1`).
//!
//! [`Run`] is a whole recorded run; [`Playground`] is the live, editable simulation of the
//! page (its layouts are documented on it).

use crate::error::Error;
use crate::playground::{self, Live};
use crate::presets::{self, PRESETS};
use crate::scenario::Scenario;
use crate::se2::Pose;
use crate::sim::{self, Report, Sample};
use js_sys::Float64Array;
use serde::Serialize;
use wasm_bindgen::prelude::*;

/// At most this many samples are kept per robot (the first and the last always).
pub const MAX_SAMPLES_PER_ROBOT: usize = 2_000;
/// At most this many samples are kept over all robots, so that a scenario with very many
/// robots thins its trajectories instead of exhausting the module's memory.
pub const MAX_SAMPLES_TOTAL: usize = 1_000_000;
/// Values per trajectory sample: `[t, x, y, θ, v, ω]`.
pub const SAMPLE_STRIDE: usize = 6;

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
        Ok(Self::simulate(s))
    }

    /// Runs the preset `name`.
    ///
    /// # Errors
    /// An unknown name; the message lists the names that exist.
    #[wasm_bindgen(js_name = fromPreset)]
    pub fn from_preset(name: &str) -> Result<Run, JsError> {
        let s = presets::preset(name).map_err(js_error)?;
        Ok(Self::simulate(s))
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
    /// Simulates a validated scenario, keeping at most [`MAX_SAMPLES_PER_ROBOT`] samples per
    /// robot.
    fn simulate(scenario: Scenario) -> Run {
        let every = decimation(scenario.steps(), scenario.robots.len());
        let (report, traj) = sim::run_recorded(&scenario, every);
        let samples = traj.first().map_or(0, Vec::len);
        // Every robot is recorded at the same steps, so the rows are equally long.
        debug_assert!(traj.iter().all(|t| t.len() == samples));
        let trajectories = traj.iter().flatten().flat_map(|s: &Sample| *s).collect();
        Run {
            scenario,
            report,
            samples,
            trajectories,
        }
    }
}

/// The crowd of `dvf bench` (N robots swapping across a circle at constant density, M
/// obstacles on the way), for timing the simulation in a JS engine (`www/bench.mjs`): set up
/// by the constructor, timed around [`step`](CrowdBench::step).
#[wasm_bindgen(js_name = CrowdBench)]
pub struct CrowdBench {
    sim: sim::Simulation,
}

/// Methods exported to JavaScript.
#[wasm_bindgen(js_class = CrowdBench)]
impl CrowdBench {
    /// A crowd of `robots` (0 … 10 000, at least one is made) with `obstacles` (0 … 1 000)
    /// at `t = 0`.
    ///
    /// # Errors
    /// A count out of range.
    #[wasm_bindgen(constructor)]
    pub fn new(robots: f64, obstacles: f64) -> Result<CrowdBench, JsError> {
        let robots = whole("robots", robots, crate::scenario::MAX_ROBOTS)?.max(1);
        let obstacles = whole("obstacles", obstacles, crate::scenario::MAX_OBSTACLES)?;
        Ok(CrowdBench {
            sim: sim::Simulation::new(&presets::crowd_with_obstacles(robots, obstacles)),
        })
    }

    /// Advances `steps` steps (0 … 1 000 000).
    ///
    /// # Errors
    /// A count out of range.
    pub fn step(&mut self, steps: f64) -> Result<(), JsError> {
        for _ in 0..whole("steps", steps, 1_000_000)? {
            self.sim.step();
        }
        Ok(())
    }
}

/// The live simulation behind `<dvf-playground>`: edits apply at once and re-predict (see
/// [`crate::playground`] for what an edit means at `t > 0`).
///
/// Flat array layouts (all `Float64Array`, robots in scenario order, lengths in brackets):
/// - [`poses`](Playground::poses) `[robots · 3]`: `x, y, θ` now (m, m, rad in `(−π, π]`).
/// - [`status`](Playground::status) `[robots · 6]`: `v, ω, Π ς_i, ς_c, vo_x, vo_y` now
///   (m/s, rad/s, obstacle keep, robot keep; the virtual obstacle, NaN when there is none).
/// - [`trails`](Playground::trails) `[robots · cap · 3]`, `cap` =
///   [`trailCapacity`](Playground::trail_capacity): one ring of past `x, y, θ` per robot.
///   The next slot written is [`trailHead`](Playground::trail_head), shared by all; robot `i`
///   holds its last [`trailLength`](Playground::trail_length)`(i)` samples (all of them:
///   `trailLengths`, a `Uint32Array [robots]`), the oldest at `(head − len + cap) % cap`.
///   [`trailTimes`](Playground::trail_times) and [`trailMinPair`](Playground::trail_min_pair)
///   `[cap]` are rings of the same slots (time in s, the smallest distance between
///   two robots, NaN for none), [`historyLength`](Playground::history_length) long.
/// - [`predicted`](Playground::predicted) `[robots · samples · 3]`: `x, y, θ` from now on,
///   sample 0 now (no samples above 100 robots); [`predictedTimes`](Playground::predicted_times) and
///   [`predictedMinPair`](Playground::predicted_min_pair) `[samples]`.
/// - [`sampleField`](Playground::sample_field) `[nx · ny · 4]`: `x, y, Γx, Γy`, row by row
///   from `ymin`.
/// - [`integralCurves`](Playground::integral_curves) `[n · n · CURVE_POINTS · 2]`: `x, y`.
///
/// # Views instead of copies
/// Each array above also has a `…Pointer` getter (`posesPointer`, `statusPointer`,
/// `trailsPointer`, `trailLengthsPointer`, `trailTimesPointer`, `trailMinPairPointer`,
/// `predictedPointer`, `predictedTimesPointer`, `predictedMinPairPointer`): its address in the
/// module's memory, for `new Float64Array(memory.buffer, pointer, length)` (`Uint32Array` for
/// the trail lengths). A view costs no copy; it is valid until the next call that steps or
/// edits (which may move the array, or grow the memory and detach every view), so a page
/// re-reads the pointers after such calls and makes views only when one changed. Stepping
/// never moves the arrays of a fixed robot count.
///
/// Indices and counts arrive as JS numbers and are checked (NaN, negative, fractional and
/// out-of-range values are errors, never a wrapped index).
#[wasm_bindgen]
pub struct Playground {
    live: Live,
}

/// Methods exported to JavaScript.
#[wasm_bindgen]
impl Playground {
    /// A live simulation of `scenario` (object or JSON text) at `t = 0`.
    ///
    /// # Errors
    /// The first offending field, or more robots than the playground simulates live.
    #[wasm_bindgen(constructor)]
    pub fn new(scenario: JsValue) -> Result<Playground, JsError> {
        let s = scenario_from_js(scenario).map_err(js_error)?;
        Ok(Playground {
            live: Live::new(s).map_err(js_error)?,
        })
    }

    /// A live simulation of the preset `name`.
    ///
    /// # Errors
    /// An unknown name; the message lists the names that exist.
    #[wasm_bindgen(js_name = fromPreset)]
    pub fn from_preset(name: &str) -> Result<Playground, JsError> {
        let s = presets::preset(name).map_err(js_error)?;
        Ok(Playground {
            live: Live::new(s).map_err(js_error)?,
        })
    }

    /// The scenario now (edits included), defaults filled in and bounds resolved.
    ///
    /// # Errors
    /// Only if the JS engine refuses to build the object.
    pub fn scenario(&self) -> Result<JsValue, JsError> {
        let mut s = self.live.scenario().clone();
        s.bounds = Some(s.resolved_bounds());
        to_js(&s)
    }

    /// Replaces the scenario (object or JSON text): at `t = 0` wholesale, later from where the
    /// robots are now. Re-predicts.
    ///
    /// # Errors
    /// The first offending field; the simulation is unchanged then.
    pub fn edit(&mut self, scenario: JsValue) -> Result<(), JsError> {
        let s = scenario_from_js(scenario).map_err(js_error)?;
        self.live.edit(s).map_err(js_error)
    }

    /// Moves robot `index` to `(x, y, theta)`: its start at `t = 0`, its current pose later.
    /// Re-predicts.
    ///
    /// # Errors
    /// A bad index, a non-finite value or a pose inside an obstacle.
    #[wasm_bindgen(js_name = moveRobot)]
    pub fn move_robot(&mut self, index: f64, x: f64, y: f64, theta: f64) -> Result<(), JsError> {
        let i = self.index(index)?;
        self.live
            .move_robot(i, Pose::new(x, y, theta))
            .map_err(js_error)
    }

    /// Back to `t = 0` at the scenario's starts, trails cleared.
    pub fn reset(&mut self) {
        self.live.reset();
    }

    /// Advances up to `n` steps (stopping at the end); returns the steps taken.
    ///
    /// # Errors
    /// `n` not a whole number from 0 to 10⁶.
    pub fn step(&mut self, n: f64) -> Result<usize, JsError> {
        let n = whole("n", n, 1_000_000)?;
        Ok(self.live.step(n))
    }

    /// Recomputes the predicted paths from now (every edit already does).
    pub fn predict(&mut self) {
        self.live.predict();
    }

    /// Simulated time now (s).
    #[wasm_bindgen(getter)]
    #[must_use]
    pub fn time(&self) -> f64 {
        self.live.time()
    }

    /// The scenario's duration (s).
    #[wasm_bindgen(getter)]
    #[must_use]
    pub fn duration(&self) -> f64 {
        self.live.scenario().duration
    }

    /// The step size (s).
    #[wasm_bindgen(getter)]
    #[must_use]
    pub fn dt(&self) -> f64 {
        self.live.scenario().dt
    }

    /// Whether the clock has reached the end.
    #[wasm_bindgen(getter)]
    #[must_use]
    pub fn finished(&self) -> bool {
        self.live.finished()
    }

    /// Number of robots.
    #[wasm_bindgen(getter, js_name = robotCount)]
    #[must_use]
    pub fn robot_count(&self) -> usize {
        self.live.scenario().robots.len()
    }

    /// `[robots · 3]`: see [`Playground`].
    #[must_use]
    pub fn poses(&self) -> Float64Array {
        Float64Array::from(self.live.poses())
    }

    /// `[robots · 6]`: see [`Playground`].
    #[must_use]
    pub fn status(&self) -> Float64Array {
        Float64Array::from(self.live.status())
    }

    /// `[robots · trailCapacity · 3]`: see [`Playground`].
    #[must_use]
    pub fn trails(&self) -> Float64Array {
        Float64Array::from(self.live.trails())
    }

    /// Samples per robot in the trail rings (2,048 up to 128 robots, fewer in a crowd).
    #[wasm_bindgen(getter, js_name = trailCapacity)]
    #[must_use]
    pub fn trail_capacity(&self) -> usize {
        self.live.trail_capacity()
    }

    /// Address of [`poses`](Playground::poses) (see "Views instead of copies").
    #[wasm_bindgen(getter, js_name = posesPointer)]
    #[must_use]
    pub fn poses_pointer(&self) -> usize {
        self.live.poses().as_ptr() as usize
    }

    /// Address of [`status`](Playground::status).
    #[wasm_bindgen(getter, js_name = statusPointer)]
    #[must_use]
    pub fn status_pointer(&self) -> usize {
        self.live.status().as_ptr() as usize
    }

    /// Address of [`trails`](Playground::trails).
    #[wasm_bindgen(getter, js_name = trailsPointer)]
    #[must_use]
    pub fn trails_pointer(&self) -> usize {
        self.live.trails().as_ptr() as usize
    }

    /// Address of the `Uint32Array [robots]` of trail lengths.
    #[wasm_bindgen(getter, js_name = trailLengthsPointer)]
    #[must_use]
    pub fn trail_lengths_pointer(&self) -> usize {
        self.live.trail_lens().as_ptr() as usize
    }

    /// Address of [`trailTimes`](Playground::trail_times).
    #[wasm_bindgen(getter, js_name = trailTimesPointer)]
    #[must_use]
    pub fn trail_times_pointer(&self) -> usize {
        self.live.trail_times().as_ptr() as usize
    }

    /// Address of [`trailMinPair`](Playground::trail_min_pair).
    #[wasm_bindgen(getter, js_name = trailMinPairPointer)]
    #[must_use]
    pub fn trail_min_pair_pointer(&self) -> usize {
        self.live.trail_min_pair().as_ptr() as usize
    }

    /// Address of [`predicted`](Playground::predicted).
    #[wasm_bindgen(getter, js_name = predictedPointer)]
    #[must_use]
    pub fn predicted_pointer(&self) -> usize {
        self.live.predicted().as_ptr() as usize
    }

    /// Address of [`predictedTimes`](Playground::predicted_times).
    #[wasm_bindgen(getter, js_name = predictedTimesPointer)]
    #[must_use]
    pub fn predicted_times_pointer(&self) -> usize {
        self.live.predicted_times().as_ptr() as usize
    }

    /// Address of [`predictedMinPair`](Playground::predicted_min_pair).
    #[wasm_bindgen(getter, js_name = predictedMinPairPointer)]
    #[must_use]
    pub fn predicted_min_pair_pointer(&self) -> usize {
        self.live.predicted_min_pair().as_ptr() as usize
    }

    /// The ring slot written next.
    #[wasm_bindgen(getter, js_name = trailHead)]
    #[must_use]
    pub fn trail_head(&self) -> usize {
        self.live.trail_head()
    }

    /// Samples held in robot `index`'s trail.
    ///
    /// # Errors
    /// A bad index.
    #[wasm_bindgen(js_name = trailLength)]
    pub fn trail_length(&self, index: f64) -> Result<usize, JsError> {
        Ok(self.live.trail_len(self.index(index)?))
    }

    /// `[trailCapacity]` ring of sample times (s).
    #[wasm_bindgen(js_name = trailTimes)]
    #[must_use]
    pub fn trail_times(&self) -> Float64Array {
        Float64Array::from(self.live.trail_times())
    }

    /// `[trailCapacity]` ring of minimum pair distances (NaN: no pair).
    #[wasm_bindgen(js_name = trailMinPair)]
    #[must_use]
    pub fn trail_min_pair(&self) -> Float64Array {
        Float64Array::from(self.live.trail_min_pair())
    }

    /// Samples written since the last reset: sample `g` is in ring slot `g % trailCapacity`
    /// (see `Live::recorded`).
    #[wasm_bindgen(getter, js_name = trailRecorded)]
    #[must_use]
    pub fn trail_recorded(&self) -> usize {
        self.live.recorded()
    }

    /// Samples held in the time and pair-distance rings.
    #[wasm_bindgen(getter, js_name = historyLength)]
    #[must_use]
    pub fn history_length(&self) -> usize {
        self.live.history_len()
    }

    /// `[robots · samples · 3]` predicted poses.
    #[must_use]
    pub fn predicted(&self) -> Float64Array {
        Float64Array::from(self.live.predicted())
    }

    /// Samples per robot in the prediction.
    #[wasm_bindgen(getter, js_name = predictedSamples)]
    #[must_use]
    pub fn predicted_samples(&self) -> usize {
        self.live.predicted_samples()
    }

    /// `[samples]` predicted times (s).
    #[wasm_bindgen(js_name = predictedTimes)]
    #[must_use]
    pub fn predicted_times(&self) -> Float64Array {
        Float64Array::from(self.live.predicted_times())
    }

    /// `[samples]` predicted minimum pair distances (NaN: no pair).
    #[wasm_bindgen(js_name = predictedMinPair)]
    #[must_use]
    pub fn predicted_min_pair(&self) -> Float64Array {
        Float64Array::from(self.live.predicted_min_pair())
    }

    /// The field robot `index` follows, sampled on an `nx × ny` grid over the box, at the
    /// robot's current attitude among the obstacles and the other robots.
    ///
    /// # Errors
    /// A bad index, grid side or box.
    #[wasm_bindgen(js_name = sampleField)]
    #[allow(clippy::too_many_arguments)]
    pub fn sample_field(
        &mut self,
        index: f64,
        xmin: f64,
        ymin: f64,
        xmax: f64,
        ymax: f64,
        nx: f64,
        ny: f64,
    ) -> Result<Float64Array, JsError> {
        let i = self.index(index)?;
        let nx = whole("nx", nx, live::MAX_GRID_SIDE)?;
        let ny = whole("ny", ny, live::MAX_GRID_SIDE)?;
        let out = self
            .live
            .sample_field(i, [xmin, ymin, xmax, ymax], nx, ny)
            .map_err(js_error)?;
        Ok(Float64Array::from(out))
    }

    /// [`sampleField`](Playground::sample_field) without the copy: the samples stay in the
    /// module's memory at [`fieldPointer`](Playground::field_pointer); returns their count of
    /// values (`nx · ny · 4`).
    ///
    /// # Errors
    /// A bad index, grid side or box.
    #[wasm_bindgen(js_name = refreshField)]
    #[allow(clippy::too_many_arguments)]
    pub fn refresh_field(
        &mut self,
        index: f64,
        xmin: f64,
        ymin: f64,
        xmax: f64,
        ymax: f64,
        nx: f64,
        ny: f64,
    ) -> Result<usize, JsError> {
        let i = self.index(index)?;
        let nx = whole("nx", nx, live::MAX_GRID_SIDE)?;
        let ny = whole("ny", ny, live::MAX_GRID_SIDE)?;
        self.live
            .sample_field(i, [xmin, ymin, xmax, ymax], nx, ny)
            .map(<[f64]>::len)
            .map_err(js_error)
    }

    /// Address of the last field samples (see "Views instead of copies").
    #[wasm_bindgen(getter, js_name = fieldPointer)]
    #[must_use]
    pub fn field_pointer(&self) -> usize {
        self.live.field().as_ptr() as usize
    }

    /// Integral curves of robot `index`'s goal field from an `n × n` grid of starts over the
    /// box, all with attitude `theta0` (rad) at the start.
    ///
    /// # Errors
    /// A bad index, `n`, box or angle.
    #[wasm_bindgen(js_name = integralCurves)]
    #[allow(clippy::too_many_arguments)]
    pub fn integral_curves(
        &mut self,
        index: f64,
        theta0: f64,
        xmin: f64,
        ymin: f64,
        xmax: f64,
        ymax: f64,
        n: f64,
    ) -> Result<Float64Array, JsError> {
        let i = self.index(index)?;
        let n = whole("n", n, live::MAX_CURVE_SIDE)?;
        let out = self
            .live
            .integral_curves(i, theta0, [xmin, ymin, xmax, ymax], n)
            .map_err(js_error)?;
        Ok(Float64Array::from(out))
    }
}

/// Rust-only helpers.
impl Playground {
    /// A robot index from a JS number, checked against the robots there are.
    fn index(&self, index: f64) -> Result<usize, JsError> {
        let count = self.live.scenario().robots.len();
        let i = whole("robot", index, usize::MAX)?;
        if i >= count {
            return Err(js_error(Error::RobotIndex { index: i, count }));
        }
        Ok(i)
    }
}

/// Values per pose in [`Playground::poses`], `trails` and `predicted`.
pub const POSE_STRIDE: usize = live::POSE_STRIDE;
/// Values per robot in [`Playground::status`].
pub const STATUS_STRIDE: usize = live::STATUS_STRIDE;
/// Values per field sample in [`Playground::sample_field`].
pub const FIELD_STRIDE: usize = live::FIELD_STRIDE;

/// The playground's layout constants as an object, so that the page reads them rather than
/// copying them: `{trailCapacity, predictionSamples, curvePoints, maxGridSide, maxCurveSide,
/// maxRobots, maxPredictedRobots, crowdMax}` (`trailCapacity` is the largest; a scene's own is
/// [`Playground::trail_capacity`]).
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
    }
    to_js(&Limits {
        trail_capacity: live::TRAIL_CAPACITY,
        prediction_samples: live::PREDICTION_SAMPLES,
        curve_points: live::CURVE_POINTS,
        max_grid_side: live::MAX_GRID_SIDE,
        max_curve_side: live::MAX_CURVE_SIDE,
        max_robots: live::MAX_LIVE_ROBOTS,
        max_predicted_robots: live::MAX_PREDICTED_ROBOTS,
        crowd_max: presets::CROWD_MAX,
    })
}

/// A whole number in `0..=max` from a JS number; NaN, infinities, negatives and fractions are
/// errors naming `field`.
fn whole(field: &str, v: f64, max: usize) -> Result<usize, JsError> {
    if v.is_finite() && v >= 0.0 && v.fract() == 0.0 && v <= max as f64 {
        Ok(v as usize)
    } else {
        Err(JsError::new(&format!(
            "{field}: must be a whole number from 0 to {max}, not {v}"
        )))
    }
}

/// The recording interval (in steps) that keeps a run of `steps` steps within the sample
/// budget. `run_recorded` keeps steps `0, every, 2·every, …` and the last, that is at most
/// `steps / every + 2` samples.
fn decimation(steps: usize, robots: usize) -> usize {
    let per_robot = (MAX_SAMPLES_TOTAL / robots.max(1)).clamp(3, MAX_SAMPLES_PER_ROBOT);
    steps.div_ceil(per_robot - 2).max(1)
}

/// A scenario from a JS object or from JSON text, parsed and validated.
///
/// An object goes through `JSON.stringify` and [`Scenario::from_json`] rather than straight
/// through serde-wasm-bindgen, whose struct deserialiser looks up the known keys only and so
/// would silently ignore a misspelt one (`{"params": {"kv": 1}}`). Objects and text thus get
/// the same checks and the same messages. JSON has no NaN or infinity: such a number arrives
/// as `null` and is reported as a type error at its field.
fn scenario_from_js(value: JsValue) -> Result<Scenario, Error> {
    if let Some(text) = value.as_string() {
        return Scenario::from_json(&text);
    }
    if !value.is_object() || js_sys::Array::is_array(&value) {
        return Err(Error::Parse {
            field: String::new(),
            message: "expected an object with a \"robots\" list (or its JSON text)".into(),
        });
    }
    let text = js_sys::JSON::stringify(&value)
        .ok()
        .and_then(|t| t.as_string())
        .ok_or_else(|| Error::Parse {
            field: String::new(),
            message: "the object cannot be written as JSON (a cycle, a BigInt or a function?)"
                .into(),
        })?;
    Scenario::from_json(&text)
}

/// The one conversion from the core's errors to JS `Error`s.
fn js_error(e: Error) -> JsError {
    JsError::new(&e.to_string())
}

/// Serialises to a plain JS value: `None` as `null`, maps as objects.
fn to_js<T: Serialize + ?Sized>(v: &T) -> Result<JsValue, JsError> {
    v.serialize(&serde_wasm_bindgen::Serializer::json_compatible())
        .map_err(|e| JsError::new(&e.to_string()))
}
