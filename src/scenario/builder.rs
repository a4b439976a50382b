//! [`Scenario::builder`]: a scenario written in code the way the paper states its examples
//! (starts and goals, obstacles with `r_o` and `R_o`, the step and the duration), checked by
//! the same validation as a file.

use super::{default_dt, default_duration, default_name, RobotSpec, Scenario};
use crate::error::Error;
use crate::obstacle::Obstacle;
use crate::params::Params;
use glam::DVec2;

impl Default for Scenario {
    /// The defaults of a file that gives `robots` only, without the robots: named `untitled`,
    /// 40 s at `dt = 0.01`, the default parameters, no obstacles, bounds around the scene.
    /// Not valid as it is (a scenario needs a robot): [`Scenario::builder`] adds them.
    fn default() -> Self {
        Self {
            name: default_name(),
            bounds: None,
            duration: default_duration(),
            dt: default_dt(),
            params: Params::default(),
            independent: false,
            robots: Vec::new(),
            obstacles: Vec::new(),
            planner: crate::planner::Spec::default(),
        }
    }
}

impl Scenario {
    /// A builder starting from [`Scenario::default`]; [`ScenarioBuilder::build`] validates
    /// the result as [`Scenario::from_json`] does a file.
    ///
    /// ```
    /// use dvf::Scenario;
    /// // Table II's first robot, from (0, 30) heading east to the origin, around an obstacle.
    /// let s = Scenario::builder()
    ///     .robot([0.0, 30.0, 0.0], [0.0, 0.0, 0.0])
    ///     .obstacle([-9.2, 14.0], 1.5, 3.0)
    ///     .dt(0.01)
    ///     .duration(20.0)
    ///     .build()?;
    /// assert_eq!(s.steps(), 2000);
    /// # Ok::<(), dvf::Error>(())
    /// ```
    pub fn builder() -> ScenarioBuilder {
        ScenarioBuilder {
            scenario: Self::default(),
        }
    }
}

/// A [`Scenario`] under construction ([`Scenario::builder`]). Each method sets one field of
/// the file format or adds one robot or obstacle; nothing is checked before
/// [`ScenarioBuilder::build`].
#[derive(Clone, Debug)]
#[must_use]
pub struct ScenarioBuilder {
    scenario: Scenario,
}

impl ScenarioBuilder {
    /// Adds a robot from `start` to `goal`, each `[x, y, θ]` (θ in radians).
    pub fn robot(mut self, start: [f64; 3], goal: [f64; 3]) -> Self {
        self.scenario.robots.push(RobotSpec { start, goal });
        self
    }
    /// Adds a circular obstacle at `center` of radius `r_o` whose field acts within `R_o`
    /// (`influence`, greater than `radius`).
    pub fn obstacle(mut self, center: [f64; 2], radius: f64, influence: f64) -> Self {
        self.scenario.obstacles.push(Obstacle {
            center: DVec2::from_array(center),
            radius,
            influence,
        });
        self
    }
    /// The step size (s).
    pub fn dt(mut self, dt: f64) -> Self {
        self.scenario.dt = dt;
        self
    }
    /// The simulated seconds.
    pub fn duration(mut self, duration: f64) -> Self {
        self.scenario.duration = duration;
        self
    }
    /// The method's parameters.
    pub fn params(mut self, params: Params) -> Self {
        self.scenario.params = params;
        self
    }
    /// The name shown to people.
    pub fn name(mut self, name: impl Into<String>) -> Self {
        self.scenario.name = name.into();
        self
    }
    /// The area to draw, `[xmin, ymin, xmax, ymax]`.
    pub fn bounds(mut self, bounds: [f64; 4]) -> Self {
        self.scenario.bounds = Some(bounds);
        self
    }
    /// Whether the robots are independent runs drawn together (they neither sense nor avoid
    /// each other).
    pub fn independent(mut self, independent: bool) -> Self {
        self.scenario.independent = independent;
        self
    }
    /// The scenario, validated.
    ///
    /// # Errors
    /// The first offending field, with the message [`Scenario::from_json`] gives for a file.
    pub fn build(self) -> Result<Scenario, Error> {
        self.scenario.validate()?;
        Ok(self.scenario)
    }
}
