//! What a sweep draws from: the family of scenes, the ranges of counts and sizes, the area,
//! the duration, the step and the method's parameters.

use crate::error::Error;
use crate::params::Params;
use crate::planner::Spec;
use crate::scenario::{RobotSpec, Scenario, MAX_MAGNITUDE};
use serde::{Deserialize, Serialize};
use std::ops::RangeInclusive;

/// The step of a sweep's scenarios unless the recipe sets another (s).
pub const DT: f64 = 0.01;

/// The kind of scene a sweep draws.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Family {
    /// Robots and obstacles anywhere in the area ([`random_scenario`](super::random_scenario)).
    #[default]
    Random,
    /// Robots from a column on the left through a row of obstacles into a grid, a line or a
    /// ring of goal slots ([`formation_scenario`](super::formation_scenario)).
    Formation,
    /// [`random_scenario`](super::random_scenario) with more robots and obstacles ([`Recipe::dense`]).
    Dense,
}

/// What [`random_scenario`](super::random_scenario) and [`formation_scenario`](super::formation_scenario) draw from.
///
/// It serialises (ranges as `{"start", "end"}`) for the identity of a sweep's shards
/// ([`super::Sweep::id_of`]): every field is part of what a scenario is drawn from.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Recipe {
    /// The kind of scene.
    pub family: Family,
    /// Number of robots, drawn uniformly from this range.
    pub robots: RangeInclusive<usize>,
    /// Number of obstacles, drawn uniformly from this range.
    pub obstacles: RangeInclusive<usize>,
    /// Side of the square area `[0, side]²` (m) that holds starts, goals and obstacle centres.
    pub side: f64,
    /// Obstacle disc radius `r_o` (m), uniform.
    pub obstacle_radius: RangeInclusive<f64>,
    /// Width of the influence ring `R_o − r_o` (m), uniform.
    pub ring_width: RangeInclusive<f64>,
    /// Least distance between two starts and between two goals, in units of `safe_radius`.
    pub separation: f64,
    /// [`Family::Formation`]: the distance between neighbouring goal slots, in units of
    /// `safe_radius`, uniform (at least 2, so that the goals can be held apart).
    pub spacing: RangeInclusive<f64>,
    /// Simulated seconds.
    pub duration: f64,
    /// The step (s).
    pub dt: f64,
    /// The method's parameters.
    pub params: Params,
    /// The robots' limits `v_max` and `ω_max`, drawn for each scenario; `None` keeps those of
    /// `params`.
    pub limits: Option<Limits>,
    /// The planner every scenario runs with; left out of the identity when it is DVF, so
    /// that a DVF sweep keeps the identity it had before recipes named a planner.
    #[serde(skip_serializing_if = "Spec::is_default")]
    pub planner: Spec,
}

/// The ranges a sweep draws the robots' limits from ([`Recipe::limits`]), uniformly and for
/// each scenario (all its robots alike). A range of one value fixes the limit.
///
/// They are drawn from a generator of their own, seeded by the scenario's seed, after the scene:
/// scenario `k` of a recipe with limits is scenario `k` of the same recipe without them, but
/// for `params.v_max` and `params.omega_max`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Limits {
    /// `v_max` (m/s), greater than 0.
    pub v_max: RangeInclusive<f64>,
    /// `ω_max` (rad/s), greater than 0.
    pub omega_max: RangeInclusive<f64>,
}

impl Limits {
    /// `v_max` and `ω_max` fixed at these values.
    #[must_use]
    pub fn fixed(v_max: f64, omega_max: f64) -> Self {
        Self {
            v_max: v_max..=v_max,
            omega_max: omega_max..=omega_max,
        }
    }
}

impl Default for Recipe {
    /// 4 to 16 robots and 0 to 5 obstacles (`r_o` 1 … 8, rings 1 … 5 wide) in a 100 × 100
    /// area, poses `3·safe_radius` apart, 120 s in steps of [`DT`], default parameters.
    fn default() -> Self {
        Self {
            family: Family::Random,
            spacing: 3.0..=6.0,
            robots: 4..=16,
            obstacles: 0..=5,
            side: 100.0,
            obstacle_radius: 1.0..=8.0,
            ring_width: 1.0..=5.0,
            separation: 3.0,
            duration: 120.0,
            dt: DT,
            params: Params::default(),
            limits: None,
            planner: Spec::default(),
        }
    }
}

impl Recipe {
    /// The dense family: 24 to 64 robots and 0 to 8 obstacles in the same area, poses
    /// `3·safe_radius` apart, 200 s.
    #[must_use]
    pub fn dense() -> Self {
        Self {
            family: Family::Dense,
            robots: 24..=64,
            obstacles: 0..=8,
            duration: 200.0,
            ..Self::default()
        }
    }

    /// The formation family: 9 to 25 robots, 0 to 3 obstacles on the way, goal slots 3 to 6
    /// safe radii apart, 300 s (see [`formation_scenario`](super::formation_scenario)).
    #[must_use]
    pub fn formation() -> Self {
        Self {
            family: Family::Formation,
            robots: 9..=25,
            obstacles: 0..=3,
            obstacle_radius: 1.0..=4.0,
            ring_width: 1.0..=3.0,
            duration: 300.0,
            ..Self::default()
        }
    }

    /// This recipe with the robots' limits fixed at `v_max` and `omega_max` ([`Limits::fixed`]).
    #[must_use]
    pub fn limited(self, v_max: f64, omega_max: f64) -> Self {
        Self {
            limits: Some(Limits::fixed(v_max, omega_max)),
            ..self
        }
    }

    /// The recipe of `family` with its default ranges.
    #[must_use]
    pub fn of(family: Family) -> Self {
        match family {
            Family::Random => Self::default(),
            Family::Formation => Self::formation(),
            Family::Dense => Self::dense(),
        }
    }

    /// Checks the settings every scenario of the recipe shares (its duration, step and
    /// parameters) with the scenario file's own checks ([`Scenario::validate`], on a scene of
    /// one robot with them), so that a value is refused with the file reader's message even
    /// when no scene can be placed; and the area's side.
    ///
    /// # Errors
    /// The first offending field, named as a scenario file names it (`params.k_a`, `dt`,
    /// `duration`), or `side`.
    pub fn check(&self) -> Result<(), Error> {
        if !(self.side.is_finite() && self.side > 0.0 && self.side <= MAX_MAGNITUDE) {
            return Err(Error::Invalid {
                field: "side".into(),
                message: format!(
                    "must be a finite number greater than 0 and at most {MAX_MAGNITUDE:e}, not {}",
                    self.side
                ),
            });
        }
        Scenario {
            planner: self.planner.clone(),
            name: String::new(),
            bounds: None,
            duration: self.duration,
            dt: self.dt,
            params: self.params,
            independent: false,
            robots: vec![RobotSpec {
                start: [0.0, 0.0, 0.0],
                goal: [self.side, self.side, 0.0],
            }],
            obstacles: Vec::new(),
        }
        .validate()
    }
}
