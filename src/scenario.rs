//! Scenario files: the JSON contract shared by the command line, the browser and tests.
//!
//! ```json
//! { "name": "…", "bounds": [xmin, ymin, xmax, ymax], "duration": 40.0, "dt": 0.01,
//!   "params": { "k_v": …, "k_omega": …, … },
//!   "robots":    [ { "start": [x, y, θ], "goal": [x, y, θ] } ],
//!   "obstacles": [ { "center": [x, y], "radius": r_o, "influence": R_o } ] }
//! ```
//!
//! Everything but `robots` is optional; unknown keys and keys given twice are errors.
//! [`Scenario::from_json`] parses and validates, and every error names the offending field.
//!
//! The format and its validation are one contract: each message stands beside the field it
//! checks, the whole-scenario check beside the per-robot and per-obstacle ones that edits use;
//! the parameters are checked from their table ([`crate::params::PARAMETERS`]).

mod builder;

pub use builder::ScenarioBuilder;

use crate::error::Error;
use crate::obstacle::Obstacle;
use crate::params::{Params, Slot, PARAMETERS};
use crate::planner::Spec;
use crate::se2::Pose;
use glam::DVec2;
use serde::{Deserialize, Serialize};

/// At most this many robots in a scenario.
pub const MAX_ROBOTS: usize = 10_000;
/// At most this many obstacles in a scenario.
pub const MAX_OBSTACLES: usize = 1_000;
/// At most this many simulated seconds.
pub const MAX_DURATION: f64 = 3_600.0;
/// At most this many steps (`duration / dt`) in one run.
pub const MAX_STEPS: f64 = 10_000_000.0;
/// The largest step size accepted (s).
pub const MAX_DT: f64 = 0.1;
/// `dt · max(k_a, k_ω, k_v)` must stay below this: the alignment loop `δ̇ ≈ −k_a δ` sampled
/// with a zero-order hold is stable for `k_a·dt < 2` and monotone for `k_a·dt < 1`, and so are
/// the attitude loop with `k_ω` and the position loop `ṗ̃ ≈ −k_v p̃` near the goal.
pub const MAX_GAIN_STEP: f64 = 1.0;
/// `dt · barrier_rate` may be at most this: the safety barrier's guarantee needs it
/// ([`crate::safety`]).
pub const MAX_BARRIER_STEP: f64 = 0.5;
/// Coordinates, radii and gains must be at most this in magnitude.
pub const MAX_MAGNITUDE: f64 = 1e6;
/// `bounds` may reach this far: the default box around coordinates and rings of
/// [`MAX_MAGNITUDE`] plus its margin stays inside it, so a written scenario reads back.
pub const MAX_BOUNDS: f64 = 1e7;

/// One robot: where it starts and the pose it must reach.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RobotSpec {
    /// `[x, y, θ]` at time 0.
    pub start: [f64; 3],
    /// `[x_d, y_d, θ_d]`.
    pub goal: [f64; 3],
}

impl RobotSpec {
    /// The start pose.
    #[must_use]
    pub fn start_pose(&self) -> Pose {
        Pose::new(self.start[0], self.start[1], self.start[2])
    }
    /// The goal pose.
    #[must_use]
    pub fn goal_pose(&self) -> Pose {
        Pose::new(self.goal[0], self.goal[1], self.goal[2])
    }
}

/// A scenario as read from a file, with the defaults filled in.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scenario {
    /// Free text, shown to people (never interpreted).
    #[serde(default = "default_name")]
    pub name: String,
    /// The area to draw and to sample fields on. Default: the box around every start, goal
    /// and obstacle ring, with a margin of 10 % (at least 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bounds: Option<[f64; 4]>,
    /// Simulated seconds. Default 40.
    #[serde(default = "default_duration")]
    pub duration: f64,
    /// Step size (s). Default 0.01.
    #[serde(default = "default_dt")]
    pub dt: f64,
    /// The method's parameters; missing keys take the defaults of [`Params`].
    #[serde(default)]
    pub params: Params,
    /// Robots treated as independent runs drawn together (the paper's Examples 1 and 2): they
    /// neither sense nor avoid each other, and pair metrics are not reported. Default false.
    #[serde(default, skip_serializing_if = "is_false")]
    pub independent: bool,
    /// At least one robot.
    pub robots: Vec<RobotSpec>,
    /// Circular obstacles. Default none.
    #[serde(default)]
    pub obstacles: Vec<Obstacle>,
    /// The planner that drives the robots ([`crate::planner`]): a name (`"avf"`) or an object
    /// with its gains (`{"name": "avf", "lambda": 2}`). Default `"dvf"`, left out when written.
    #[serde(default, skip_serializing_if = "Spec::is_default")]
    pub planner: Spec,
}

fn default_name() -> String {
    "untitled".to_owned()
}
fn default_duration() -> f64 {
    40.0
}
fn default_dt() -> f64 {
    0.01
}
fn is_false(b: &bool) -> bool {
    !*b
}

impl Scenario {
    /// Parses and validates a scenario from JSON text.
    ///
    /// # Errors
    /// [`Error::Parse`] for text that is not a scenario (with the path of the offending field),
    /// [`Error::Invalid`] for values out of their documented range.
    pub fn from_json(text: &str) -> Result<Self, Error> {
        // Syntax first, so that a truncated file is reported as such (with line and column)
        // rather than as a type error somewhere inside it. `IgnoredAny` checks the syntax
        // without building the document.
        serde_json::from_str::<serde::de::IgnoredAny>(text).map_err(|e| Error::Parse {
            field: String::new(),
            message: format!("not valid JSON: {e}"),
        })?;
        if !text.trim_start().starts_with('{') {
            return Err(Error::Parse {
                field: String::new(),
                message: "expected a JSON object with a \"robots\" list".into(),
            });
        }
        // Then the types, straight from the text: the path names the field, so the position
        // serde_json appends to a type error adds nothing and is left out.
        let mut de = serde_json::Deserializer::from_str(text);
        let s: Scenario = serde_path_to_error::deserialize(&mut de).map_err(|e| {
            let path = e.path().to_string();
            let inner = e.into_inner();
            let mut message = inner.to_string();
            let at = format!(" at line {} column {}", inner.line(), inner.column());
            if inner.line() > 0 && message.ends_with(&at) {
                message.truncate(message.len() - at.len());
            }
            Error::Parse {
                field: if path == "." { String::new() } else { path },
                message,
            }
        })?;
        s.validate()?;
        Ok(s)
    }

    /// The scenario as pretty JSON, bounds resolved.
    #[must_use]
    pub fn to_json(&self) -> String {
        let mut s = self.clone();
        s.bounds = Some(self.resolved_bounds());
        serde_json::to_string_pretty(&s).unwrap_or_default()
    }

    /// `bounds`, or the default box when the file has none.
    #[must_use]
    pub fn resolved_bounds(&self) -> [f64; 4] {
        if let Some(b) = self.bounds {
            return b;
        }
        let mut lo = glam::DVec2::splat(f64::INFINITY);
        let mut hi = glam::DVec2::splat(f64::NEG_INFINITY);
        for r in &self.robots {
            for p in [r.start_pose().p, r.goal_pose().p] {
                lo = lo.min(p);
                hi = hi.max(p);
            }
        }
        for o in &self.obstacles {
            lo = lo.min(o.center - o.influence);
            hi = hi.max(o.center + o.influence);
        }
        if !lo.is_finite() {
            return [-10.0, -10.0, 10.0, 10.0];
        }
        let margin = ((hi - lo) * 0.1).max(glam::DVec2::ONE);
        let (lo, hi) = (lo - margin, hi + margin);
        [lo.x, lo.y, hi.x, hi.y]
    }

    /// Number of steps the run takes: `ceil(duration / dt)`, at least 1 (a quotient within
    /// 1e-9 of a whole number is taken as that number, so 40 s at 0.01 s is exactly 4000
    /// steps despite representation error).
    #[must_use]
    pub fn steps(&self) -> usize {
        let n = self.duration / self.dt;
        let r = n.round();
        let steps = if (n - r).abs() < 1e-9 * r.max(1.0) {
            r as usize
        } else {
            n.ceil() as usize
        };
        steps.max(1)
    }

    /// Checks every value against its documented range.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the first offending field.
    pub fn validate(&self) -> Result<(), Error> {
        let p = &self.params;
        // The duration and dt have limits of their own, below MAX_MAGNITUDE: each field's one
        // "at most" message is its own (2e6 s and 1e6 s are refused alike).
        finite_number("duration", self.duration)?;
        positive("duration", self.duration)?;
        if self.duration > MAX_DURATION {
            return invalid("duration", format!("must be at most {MAX_DURATION} s"));
        }
        finite_number("dt", self.dt)?;
        positive("dt", self.dt)?;
        if self.dt > MAX_DT {
            return invalid("dt", format!("must be at most {MAX_DT} s"));
        }
        if self.duration / self.dt > MAX_STEPS {
            return invalid(
                "dt",
                format!("duration / dt must be at most {MAX_STEPS} steps"),
            );
        }
        if let Some(b) = self.bounds {
            for (k, v) in b.iter().enumerate() {
                if !v.is_finite() || v.abs() > MAX_BOUNDS {
                    return invalid(
                        &format!("bounds[{k}]"),
                        format!(
                            "must be a finite number of magnitude at most {MAX_BOUNDS:e}, not {v}"
                        ),
                    );
                }
            }
            if !(b[0] < b[2] && b[1] < b[3]) {
                return invalid(
                    "bounds",
                    "must be [xmin, ymin, xmax, ymax] with xmin < xmax and ymin < ymax",
                );
            }
        }
        // The table's numbers first, then its optional numbers: the first offending one is named.
        let mut copy = self.params;
        for optional in [false, true] {
            for row in PARAMETERS {
                let v = match copy.slot(row.name) {
                    Some(Slot::Number(v)) if !optional => *v,
                    Some(Slot::Optional(Some(v))) if optional => *v,
                    _ => continue,
                };
                let field = format!("params.{}", row.name);
                finite(&field, v)?;
                positive(&field, v)?;
            }
        }
        if p.avoid_radius <= p.safe_radius {
            return invalid(
                "params.avoid_radius",
                format!(
                    "must exceed params.safe_radius ({}): the avoidance ring lies outside the safe disc",
                    p.safe_radius
                ),
            );
        }
        let fastest = p.k_a.max(p.k_omega).max(p.k_v);
        if self.dt * fastest >= MAX_GAIN_STEP {
            return invalid(
                "dt",
                format!(
                    "{} s is too large for the gains: dt · max(k_a, k_omega, k_v) must be below {MAX_GAIN_STEP} (use dt < {})",
                    self.dt,
                    MAX_GAIN_STEP / fastest
                ),
            );
        }
        if let Some(rate) = p.barrier_rate {
            if self.dt * rate > MAX_BARRIER_STEP {
                return invalid(
                    "dt",
                    format!(
                        "{} s is too large for params.barrier_rate ({rate}): dt · barrier_rate must be at most {MAX_BARRIER_STEP} (use dt ≤ {})",
                        self.dt,
                        MAX_BARRIER_STEP / rate
                    ),
                );
            }
        }
        self.planner.build()?;
        if self.robots.is_empty() {
            return invalid("robots", "needs at least one robot");
        }
        if self.robots.len() > MAX_ROBOTS {
            return invalid("robots", format!("at most {MAX_ROBOTS} robots"));
        }
        if self.obstacles.len() > MAX_OBSTACLES {
            return invalid("obstacles", format!("at most {MAX_OBSTACLES} obstacles"));
        }
        for (i, r) in self.robots.iter().enumerate() {
            for (key, v) in [("start", r.start), ("goal", r.goal)] {
                for (k, x) in v.iter().enumerate() {
                    finite(&format!("robots[{i}].{key}[{k}]"), *x)?;
                }
            }
        }
        for (i, o) in self.obstacles.iter().enumerate() {
            finite(&format!("obstacles[{i}].center[0]"), o.center.x)?;
            finite(&format!("obstacles[{i}].center[1]"), o.center.y)?;
            finite(&format!("obstacles[{i}].radius"), o.radius)?;
            positive(&format!("obstacles[{i}].radius"), o.radius)?;
            finite(&format!("obstacles[{i}].influence"), o.influence)?;
            if o.influence <= o.radius {
                return invalid(
                    &format!("obstacles[{i}].influence"),
                    format!("must exceed the radius ({})", o.radius),
                );
            }
        }
        for (i, r) in self.robots.iter().enumerate() {
            for (key, pose) in [("start", r.start_pose()), ("goal", r.goal_pose())] {
                for (j, o) in self.obstacles.iter().enumerate() {
                    if o.clearance(pose.p) <= 0.0 {
                        return invalid(
                            &format!("robots[{i}].{key}"),
                            format!("lies inside obstacles[{j}] (radius {})", o.radius),
                        );
                    }
                }
            }
            let goal = r.goal_pose().p;
            for (j, o) in self.obstacles.iter().enumerate() {
                if goal.distance(o.center) < o.influence {
                    return invalid(
                        &format!("robots[{i}].goal"),
                        format!(
                            "lies in the influence ring of obstacles[{j}] ({} from its centre, influence {}): the ring's circular field would keep the robot from settling there; move the goal out of the ring or shrink the ring",
                            goal.distance(o.center),
                            o.influence
                        ),
                    );
                }
            }
        }
        if !self.independent {
            let safe = 2.0 * p.safe_radius;
            let starts: Vec<DVec2> = self.robots.iter().map(|r| r.start_pose().p).collect();
            if let Some((i, j, d)) = crate::grid::closest_pair_below(&starts, safe) {
                return invalid(
                    &format!("robots[{j}].start"),
                    format!("is {d} from robots[{i}].start, closer than the safe distance 2 · safe_radius = {safe}: robots may not start in each other's safe disc"),
                );
            }
            let goals: Vec<DVec2> = self.robots.iter().map(|r| r.goal_pose().p).collect();
            if let Some((i, j, d)) = crate::grid::closest_pair_below(&goals, safe) {
                return invalid(
                    &format!("robots[{j}].goal"),
                    format!("is {d} from robots[{i}].goal, closer than the safe distance 2 · safe_radius = {safe}: both robots cannot settle there"),
                );
            }
        }
        Ok(())
    }

    /// [`Scenario::validate`] for a scenario that was valid before robot `index` changed:
    /// the checks that concern that robot alone (its numbers, the obstacles, its start's and
    /// goal's distances to the other robots'), O(robots + obstacles) without allocating; only
    /// when one fails does the whole validation run, so that the error is exactly the one
    /// [`Scenario::validate`] gives.
    ///
    /// # Errors
    /// An index out of range, or the first offending field as [`Scenario::validate`] names it.
    pub fn validate_robot(&self, index: usize) -> Result<(), Error> {
        let count = self.robots.len();
        let r = self
            .robots
            .get(index)
            .ok_or(Error::RobotIndex { index, count })?;
        let (start, goal) = (r.start_pose().p, r.goal_pose().p);
        let numbers = r.start.iter().chain(&r.goal).all(|v| in_range(*v));
        let obstacles = self.obstacles.iter().all(|o| clear_of(o, start, goal));
        let safe = 2.0 * self.params.safe_radius;
        let apart = self.independent
            || self.robots.iter().enumerate().all(|(k, q)| {
                k == index
                    || (q.start_pose().p.distance(start) >= safe
                        && q.goal_pose().p.distance(goal) >= safe)
            });
        if numbers && obstacles && apart {
            Ok(())
        } else {
            self.validate()
        }
    }

    /// [`Scenario::validate`] for a scenario that was valid before obstacle `index` changed:
    /// its numbers, and every robot's start and goal against it, O(robots); the whole
    /// validation runs only when one fails (see [`Scenario::validate_robot`]).
    ///
    /// # Errors
    /// An index out of range, or the first offending field as [`Scenario::validate`] names it.
    pub fn validate_obstacle(&self, index: usize) -> Result<(), Error> {
        let o = self.obstacles.get(index).ok_or_else(|| Error::Invalid {
            field: "obstacle".into(),
            message: format!(
                "no obstacle {index}: the scenario has {} (numbered from 0)",
                self.obstacles.len()
            ),
        })?;
        let numbers = [o.center.x, o.center.y, o.radius, o.influence]
            .into_iter()
            .all(in_range)
            && o.radius > 0.0
            && o.influence > o.radius;
        let clear = self
            .robots
            .iter()
            .all(|r| clear_of(o, r.start_pose().p, r.goal_pose().p));
        if numbers && clear {
            Ok(())
        } else {
            self.validate()
        }
    }
}

/// What `finite` accepts.
fn in_range(v: f64) -> bool {
    v.is_finite() && v.abs() <= MAX_MAGNITUDE
}

/// What [`Scenario::validate`] asks of a robot's `start` and `goal` and an obstacle: both
/// outside the disc, the goal outside the ring.
fn clear_of(o: &Obstacle, start: DVec2, goal: DVec2) -> bool {
    o.clearance(start) > 0.0 && o.clearance(goal) > 0.0 && goal.distance(o.center) >= o.influence
}

fn invalid<T>(field: &str, message: impl Into<String>) -> Result<T, Error> {
    Err(Error::Invalid {
        field: field.to_owned(),
        message: message.into(),
    })
}

/// `v` is a finite number (not NaN, not infinite).
fn finite_number(field: &str, v: f64) -> Result<(), Error> {
    if v.is_finite() {
        Ok(())
    } else {
        invalid(field, format!("must be a finite number, not {v}"))
    }
}

fn finite(field: &str, v: f64) -> Result<(), Error> {
    finite_number(field, v)?;
    if v.abs() > MAX_MAGNITUDE {
        return invalid(
            field,
            format!("must be at most {MAX_MAGNITUDE:e} in magnitude"),
        );
    }
    Ok(())
}

fn positive(field: &str, v: f64) -> Result<(), Error> {
    if v > 0.0 {
        Ok(())
    } else {
        invalid(field, format!("must be positive, not {v}"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::test;

    fn err(text: &str) -> String {
        Scenario::from_json(text).unwrap_err().to_string()
    }

    #[test]
    fn minimal_scenario_takes_the_defaults() {
        let s = Scenario::from_json(r#"{"robots":[{"start":[0,0,0],"goal":[1,2,3]}]}"#).unwrap();
        assert_eq!(s.dt, 0.01);
        assert_eq!(s.duration, 40.0);
        assert_eq!(s.params, Params::default());
        assert_eq!(s.steps(), 4000);
        let b = s.resolved_bounds();
        assert!(b[0] < 0.0 && b[2] > 1.0 && b[1] < 0.0 && b[3] > 2.0);
    }

    #[test]
    fn errors_name_the_field() {
        assert!(
            err(r#"{"robots":[{"start":[0,0,0],"goal":[1,2,3]}],"params":{"k_v":-1}}"#)
                .starts_with("params.k_v: must be positive")
        );
        assert!(
            err(r#"{"robots":[{"start":[0,0,0],"goal":[1,2,3]}],"params":{"kv":1}}"#)
                .starts_with("params.kv: unknown field `kv`")
        );
        assert!(
            err(r#"{"robots":[{"start":[0,0],"goal":[1,2,3]}]}"#).starts_with("robots[0].start:")
        );
        assert!(err(r#"{"robots":[]}"#).starts_with("robots: needs at least one robot"));
        assert!(err(r#"{"robots":[{"start":[0,0,0],"goal":[1,2,3]}],"obstacles":[{"center":[5,5],"radius":2,"influence":1}]}"#)
            .starts_with("obstacles[0].influence: must exceed the radius"));
        assert!(err(r#"{"robots":[{"start":[5,5,0],"goal":[1,2,3]}],"obstacles":[{"center":[5,5],"radius":2,"influence":3}]}"#)
            .starts_with("robots[0].start: lies inside obstacles[0]"));
        assert!(
            err(r#"{"robots":[{"start":[0,0,0],"goal":[1,2,3]}],"dt":0.5}"#)
                .starts_with("dt: must be at most")
        );
        // The duration's one limit, however far above it: 1e6 s and 2e6 s (above MAX_MAGNITUDE)
        // get the same message; so do dt's.
        for duration in ["1e6", "2e6"] {
            let e = err(&format!(
                r#"{{"robots":[{{"start":[0,0,0],"goal":[1,2,3]}}],"duration":{duration}}}"#
            ));
            assert_eq!(e, "duration: must be at most 3600 s", "{duration}");
        }
        for dt in ["1e6", "2e6"] {
            let e = err(&format!(
                r#"{{"robots":[{{"start":[0,0,0],"goal":[1,2,3]}}],"dt":{dt}}}"#
            ));
            assert_eq!(e, "dt: must be at most 0.1 s", "{dt}");
        }
        assert!(err(
            r#"{"robots":[{"start":[0,0,0],"goal":[1,2,3]}],"dt":0.09,"params":{"k_a":20}}"#
        )
        .contains("too large for the gains"));
        assert!(err("[1,2").starts_with("malformed scenario"));
        assert!(
            err(r#"{"robots":[{"start":[0,0,0],"goal":[1,2,3]}],"dt":"x"}"#).starts_with("dt:")
        );
        // A type error names its field, not a position in the text; a syntax error says where.
        let typed = err(r#"{"robots":[{"start":[0,0,"a"],"goal":[1,2,3]}]}"#);
        assert!(
            typed.starts_with("robots[0].start[2]: invalid type"),
            "{typed}"
        );
        assert!(!typed.contains("at line"), "{typed}");
        let syntax = err(r#"{"robots":[{"start":[0,0,0],"goal":[1,2,3]}]"#);
        assert!(
            syntax.contains("not valid JSON: EOF") && syntax.contains("at line 1"),
            "{syntax}"
        );
        // A key given twice is refused rather than the last one silently winning.
        let twice = err(r#"{"robots":[{"start":[0,0,0],"goal":[1,2,3]}],"dt":0.01,"dt":0.02}"#);
        assert!(twice.contains("duplicate field `dt`"), "{twice}");
    }

    #[test]
    fn round_trip_through_json() {
        let s = Scenario::from_json(r#"{"name":"a","robots":[{"start":[0,0,0],"goal":[1,2,3]}],"obstacles":[{"center":[5,5],"radius":1,"influence":2}]}"#).unwrap();
        let back = Scenario::from_json(&s.to_json()).unwrap();
        assert_eq!(back.robots, s.robots);
        assert_eq!(back.obstacles, s.obstacles);
        assert_eq!(back.bounds, Some(s.resolved_bounds()));
    }
}
