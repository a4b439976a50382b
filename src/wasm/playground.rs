//! `Playground`: the live simulation behind `<dvf-playground>` ([`crate::playground::Live`]),
//! its edits, and its buffers read in place.
//!
//! # Buffers, read in place
//! [`Playground::layout`] names every buffer once: its address in the module's memory, its
//! length (in elements) and its stride (values per item), for
//! `new Float64Array(memory.buffer, pointer, length)` (`Uint32Array` for `trailLengths`). A view
//! costs no copy; it is valid until the next call that steps or edits (which may move a buffer,
//! or grow the memory and detach every view), so a page asks for the layout again after such
//! calls and re-makes only the views whose pointer or length changed. Stepping never moves the
//! buffers of a fixed robot count. The layouts (robots in scenario order; `robots` is
//! `poses.length / 3`, `trailCapacity` is `trailTimes.length`, `predictedSamples` is
//! `predictedTimes.length`):
//! - `poses` `[robots · 3]`: `x, y, θ` now (m, m, rad in `(−π, π]`);
//! - `status` `[robots · 6]`: `v, ω, Π ς_i, ς_c, vo_x, vo_y` now (m/s, rad/s, obstacle keep,
//!   robot keep; the virtual obstacle, NaN when there is none);
//! - `trails` `[robots · trailCapacity · 3]`: one ring of past `x, y, θ` per robot; the next
//!   slot written is `trailHead`, shared by all; robot `i` holds its last `trailLengths[i]`
//!   samples, the oldest at `(head − len + cap) % cap`; `trailTimes` and `trailMinPair`
//!   `[trailCapacity]` are rings of the same slots (s; the smallest distance between two robots,
//!   NaN for none), `historyLength` long; sample `g` since the reset is in slot
//!   `g % trailCapacity` (`trailRecorded` written so far);
//! - `predicted` `[robots · predictedSamples · 3]`: `x, y, θ` from now on, sample 0 now (none
//!   above 100 robots); `predictedTimes`, `predictedMinPair` `[predictedSamples]`;
//! - `field` `[nx · ny · 4]`: `x, y, Γx, Γy` of the last [`Playground::refresh_field`], row by
//!   row from `ymin`.
//!
//! Indices and counts arrive as JS numbers and are checked (NaN, negative, fractional and
//! out-of-range values are errors, never a wrapped index).

use super::convert::{js_error, scenario_from_js, to_js, whole};
use crate::error::Error;
use crate::obstacle::Obstacle;
use crate::playground::edits::ParamValue;
use crate::playground::{self as live, Live};
use crate::presets;
use crate::scenario::RobotSpec;
use crate::se2::Pose;
use glam::DVec2;
use js_sys::Float64Array;
use serde::Serialize;
use wasm_bindgen::prelude::*;

/// One buffer of [`Layout`]: `length` elements from `pointer`, `stride` values per item.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Buffer {
    /// Byte address in the module's memory.
    pub pointer: usize,
    /// Elements (`f64`, or `u32` for the trail lengths).
    pub length: usize,
    /// Values per item (a pose: 3).
    pub stride: usize,
}

impl Buffer {
    fn of<T>(v: &[T], stride: usize) -> Self {
        Self {
            pointer: v.as_ptr() as usize,
            length: v.len(),
            stride,
        }
    }
}

/// Every buffer of a [`Playground`] and the counts that index them (see the module doc).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "camelCase")]
#[allow(missing_docs)]
pub struct Layout {
    pub poses: Buffer,
    pub status: Buffer,
    pub trails: Buffer,
    pub trail_lengths: Buffer,
    pub trail_times: Buffer,
    pub trail_min_pair: Buffer,
    pub trail_head: usize,
    pub trail_recorded: usize,
    pub history_length: usize,
    pub predicted: Buffer,
    pub predicted_times: Buffer,
    pub predicted_min_pair: Buffer,
    pub field: Buffer,
}

/// The live simulation behind `<dvf-playground>`: edits apply at once and re-predict (see
/// [`crate::playground`] for what an edit means at `t > 0`). Buffers: see the module doc.
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
    /// robots are now. Re-predicts. For undo, import and links; a drag uses the edits below.
    ///
    /// # Errors
    /// The first offending field; the simulation is unchanged then.
    pub fn edit(&mut self, scenario: JsValue) -> Result<(), JsError> {
        let s = scenario_from_js(scenario).map_err(js_error)?;
        self.live.edit(s).map_err(js_error)
    }

    /// Moves robot `index` to `(x, y, theta)`: its start at `t = 0`, its current pose later.
    /// Checks only what the move touches. Re-predicts.
    ///
    /// # Errors
    /// A bad index, a non-finite value, a pose inside an obstacle or another robot's safe disc.
    #[wasm_bindgen(js_name = moveRobot)]
    pub fn move_robot(&mut self, index: f64, x: f64, y: f64, theta: f64) -> Result<(), JsError> {
        let i = self.index(index)?;
        self.live
            .move_robot(i, Pose::new(x, y, theta))
            .map_err(js_error)
    }

    /// Moves robot `index`'s goal to `(x, y, theta)`. Re-predicts.
    ///
    /// # Errors
    /// A bad index, a non-finite value, a goal inside an obstacle or its ring, or inside
    /// another goal's safe disc.
    #[wasm_bindgen(js_name = moveGoal)]
    pub fn move_goal(&mut self, index: f64, x: f64, y: f64, theta: f64) -> Result<(), JsError> {
        let i = self.index(index)?;
        self.live
            .move_goal(i, Pose::new(x, y, theta))
            .map_err(js_error)
    }

    /// Moves obstacle `index`'s centre to `(x, y)`. Re-predicts.
    ///
    /// # Errors
    /// A bad index, a non-finite value, or a robot the obstacle would cover.
    #[wasm_bindgen(js_name = moveObstacle)]
    pub fn move_obstacle(&mut self, index: f64, x: f64, y: f64) -> Result<(), JsError> {
        let k = whole("obstacle", index, usize::MAX)?;
        self.live
            .move_obstacle(k, DVec2::new(x, y))
            .map_err(js_error)
    }

    /// Gives obstacle `index` the disc radius `radius` and influence radius `influence`.
    ///
    /// # Errors
    /// A bad index or radius, or a robot the obstacle would cover.
    #[wasm_bindgen(js_name = resizeObstacle)]
    pub fn resize_obstacle(
        &mut self,
        index: f64,
        radius: f64,
        influence: f64,
    ) -> Result<(), JsError> {
        let k = whole("obstacle", index, usize::MAX)?;
        self.live
            .resize_obstacle(k, radius, influence)
            .map_err(js_error)
    }

    /// Sets `duration`, `dt` or one parameter by its JSON key (`k_v`, `sense_radius`, …) to
    /// `value` (a number; `null` for "none" where optional; a string for `avoidance`).
    ///
    /// # Errors
    /// An unknown name, a value of the wrong type, or the first invalid field that results.
    #[wasm_bindgen(js_name = setParam)]
    pub fn set_param(&mut self, name: &str, value: JsValue) -> Result<(), JsError> {
        let value = if value.is_null() || value.is_undefined() {
            ParamValue::None
        } else if let Some(v) = value.as_f64() {
            ParamValue::Number(v)
        } else {
            // Text for the avoidance mode; anything else is refused as "of the wrong kind".
            ParamValue::Text(value.as_string().unwrap_or_default())
        };
        self.live.set_param(name, value).map_err(js_error)
    }

    /// Adds a robot from `(sx, sy, sθ)` to `(gx, gy, gθ)` (at its start, also at `t > 0`).
    ///
    /// # Errors
    /// An invalid pose, or too many robots.
    #[wasm_bindgen(js_name = addRobot)]
    #[allow(clippy::too_many_arguments)]
    pub fn add_robot(
        &mut self,
        sx: f64,
        sy: f64,
        stheta: f64,
        gx: f64,
        gy: f64,
        gtheta: f64,
    ) -> Result<(), JsError> {
        self.live
            .add_robot(RobotSpec {
                start: [sx, sy, stheta],
                goal: [gx, gy, gtheta],
            })
            .map_err(js_error)
    }

    /// Removes robot `index`; later robots move down one index.
    ///
    /// # Errors
    /// A bad index, or the last robot.
    #[wasm_bindgen(js_name = removeRobot)]
    pub fn remove_robot(&mut self, index: f64) -> Result<(), JsError> {
        let i = self.index(index)?;
        self.live.remove_robot(i).map_err(js_error)
    }

    /// Adds an obstacle at `(x, y)` with disc radius `radius` and influence radius `influence`.
    ///
    /// # Errors
    /// An invalid obstacle, a robot it would cover, or too many obstacles.
    #[wasm_bindgen(js_name = addObstacle)]
    pub fn add_obstacle(
        &mut self,
        x: f64,
        y: f64,
        radius: f64,
        influence: f64,
    ) -> Result<(), JsError> {
        self.live
            .add_obstacle(Obstacle {
                center: DVec2::new(x, y),
                radius,
                influence,
            })
            .map_err(js_error)
    }

    /// Removes obstacle `index`; later obstacles move down one index.
    ///
    /// # Errors
    /// A bad index.
    #[wasm_bindgen(js_name = removeObstacle)]
    pub fn remove_obstacle(&mut self, index: f64) -> Result<(), JsError> {
        let k = whole("obstacle", index, usize::MAX)?;
        self.live.remove_obstacle(k).map_err(js_error)
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

    /// Says whether a drag is under way: during one, each edit looks a shorter way ahead in a
    /// scene of many robots; its end predicts in full again (`Live::set_dragging`).
    #[wasm_bindgen(js_name = setDragging)]
    pub fn set_dragging(&mut self, dragging: bool) {
        self.live.set_dragging(dragging);
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

    /// Every buffer's pointer, length and stride, and the counts that index them (see the
    /// module doc): `{poses, status, trails, trailLengths, trailTimes, trailMinPair, trailHead,
    /// trailRecorded, historyLength, predicted, predictedTimes, predictedMinPair, field}`, each
    /// buffer `{pointer, length, stride}`.
    ///
    /// # Errors
    /// Only if the JS engine refuses to build the object.
    pub fn layout(&self) -> Result<JsValue, JsError> {
        to_js(&self.layout_now())
    }

    /// Samples the field robot `index` follows on an `nx × ny` grid over the box, at the
    /// robot's current attitude among the obstacles and the other robots, into the `field`
    /// buffer of [`layout`](Playground::layout); returns its length (`nx · ny · 4`).
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

    /// Integral curves of robot `index`'s goal field from an `n × n` grid of starts over the
    /// box, all with attitude `theta0` (rad) at the start: `[n · n · CURVE_POINTS · 2]`, `x, y`
    /// (a copy: curves are computed on request, not kept for every frame).
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
    /// The model behind the facade (for the facade's tests).
    #[must_use]
    pub fn live(&self) -> &Live {
        &self.live
    }

    /// The layout as a Rust value (what [`Playground::layout`] converts).
    #[must_use]
    pub fn layout_now(&self) -> Layout {
        let l = &self.live;
        let (t, p) = (l.trails(), l.prediction());
        Layout {
            poses: Buffer::of(l.poses(), live::POSE_STRIDE),
            status: Buffer::of(l.status(), live::STATUS_STRIDE),
            trails: Buffer::of(t.poses(), live::POSE_STRIDE),
            trail_lengths: Buffer::of(t.lens(), 1),
            trail_times: Buffer::of(t.times(), 1),
            trail_min_pair: Buffer::of(t.min_pair(), 1),
            trail_head: t.head(),
            trail_recorded: t.recorded(),
            history_length: t.history_len(),
            predicted: Buffer::of(p.poses(), live::POSE_STRIDE),
            predicted_times: Buffer::of(p.times(), 1),
            predicted_min_pair: Buffer::of(p.min_pair(), 1),
            field: Buffer::of(l.field(), live::FIELD_STRIDE),
        }
    }

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
