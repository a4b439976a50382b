//! The planners the simulator can step, DVF and the ones researchers compare it with, each on
//! the same unicycle, sensing, limits, safety barrier, metrics and report.
//!
//! A scenario names its planner (`"planner": "avf"`, or an object with its gains,
//! `{"name": "avf", "lambda": 2}`; [`Spec`]). DVF (`dvf`, and `dvf-paper` with the paper's
//! avoidance) is the simulator's own evaluation (`sim/evaluation.rs`); every other planner
//! implements [`Planner`]: from a snapshot of the scene ([`World`]) it gives every robot's
//! command at once, so that a joint planner (a QP over all robots, ORCA) sees every robot. The
//! simulator then applies the robot's limits ([`crate::controller::saturate`]) and, when the
//! parameters turn it on (`barrier_rate`, the default), the safety barrier
//! ([`crate::safety::filter`]) to each command, as it does to DVF's: every planner gets the
//! same safety net, or none (`barrier_rate: null`).
//!
//! # Adding a planner
//! One file in this folder with a `pub(super) const ENTRY: Entry` (its name, what it is, its
//! source and how to build it from its gains), and its module's name in the `planners!` line
//! below. A planner that steers each robot alone implements [`Alone`] rather than
//! [`Planner`].

use crate::controller::Evaluation;
use crate::error::Error;
use crate::grid::Neighbours;
use crate::obstacle::Obstacle;
use crate::params::{Avoidance, Params};
use crate::sim::Robot;
use serde::de::DeserializeOwned;
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use serde_json::{Map, Value};

mod dvf;

/// The planners, by module: each module's `ENTRY`, in the order the menus list them.
macro_rules! planners {
    ($($module:ident),* $(,)?) => {
        /// Every planner the simulator knows, in the order the menus list them.
        pub static PLANNERS: &[Entry] = &[dvf::DVF, dvf::DVF_PAPER, $($module::ENTRY),*];
        $(mod $module;)*
    };
}
planners!(avf, cvf, clf, clf_cbf, orca, move_to_pose);

/// A planner for every robot of a scene, one step at a time.
pub trait Planner: Send + Sync + std::fmt::Debug {
    /// Every robot's command from the snapshot `world`, into `out` (one per robot, in scenario
    /// order; `out[i]` holds robot `i`'s last evaluation on entry). Besides the command, an
    /// evaluation carries the direction the planner wants to go (`field`, which the barrier's
    /// turn away from a blocked direction reads and the playground draws); the rest may stay
    /// as [`Evaluation::default`] leaves it.
    fn plan(&mut self, world: &World<'_>, out: &mut [Evaluation]);

    /// A copy of this planner with its state (a [`crate::Simulation`] is `Clone`).
    fn clone_box(&self) -> Box<dyn Planner>;
}

/// A planner that steers each robot alone, from its own pose and goal (it senses nothing): its
/// [`Planner::plan`] evaluates every robot in turn.
pub trait Alone: Clone + std::fmt::Debug + Send + Sync + 'static {
    /// Robot `r`'s evaluation (see [`Planner::plan`]).
    fn evaluate(&self, r: &Robot) -> Evaluation;
}

impl<T: Alone> Planner for T {
    fn plan(&mut self, world: &World<'_>, out: &mut [Evaluation]) {
        for (e, r) in out.iter_mut().zip(world.robots) {
            *e = self.evaluate(r);
        }
    }

    fn clone_box(&self) -> Box<dyn Planner> {
        Box::new(self.clone())
    }
}

/// What a planner sees at a step: the whole scene, with each robot's sensed robots and
/// obstacles (within `R_s`, [`Params::sense_radius`]) found for it.
#[derive(Clone, Copy, Debug)]
pub struct World<'a> {
    /// Simulated time (s).
    pub time: f64,
    /// The step (s) over which each command is held.
    pub dt: f64,
    /// The scene's parameters: `r_ij`, `R_s`, the limits.
    pub params: &'a Params,
    /// Every robot, in scenario order.
    pub robots: &'a [Robot],
    /// Every obstacle.
    pub obstacles: &'a [Obstacle],
    /// Whether the robots are independent runs drawn together (they sense no robots).
    pub independent: bool,
    pub(crate) near: &'a Neighbours,
}

impl World<'_> {
    /// The robots robot `i` senses: within `R_s` of it, never itself, in ascending index; none
    /// when the robots are independent.
    pub fn sensed(&self, i: usize) -> impl Iterator<Item = usize> + '_ {
        let p = self.robots[i].pose.p;
        let rs2 = self.params.sense_radius * self.params.sense_radius;
        let list = if self.independent {
            &[][..]
        } else {
            self.near.of(i)
        };
        list.iter()
            .map(|&j| j as usize)
            .filter(move |&j| self.robots[j].pose.p.distance_squared(p) <= rs2)
    }

    /// The obstacles robot `i` senses: those whose surface lies within `R_s` of it.
    pub fn sensed_obstacles(&self, i: usize) -> impl Iterator<Item = &Obstacle> + '_ {
        let p = self.robots[i].pose.p;
        let rs = self.params.sense_radius;
        self.obstacles.iter().filter(move |o| o.clearance(p) <= rs)
    }
}

/// A planner as the menus and the command line list it.
#[derive(Clone, Copy, Debug)]
pub struct Entry {
    /// Its name in a scenario and on the command line (`avf`).
    pub name: &'static str,
    /// What it is, in a few words.
    pub title: &'static str,
    /// Where it comes from: the paper or repository it follows.
    pub source: &'static str,
    /// What it avoids on its own (robots, obstacles, nothing), before the shared barrier.
    pub avoids: &'static str,
    /// Builds it from its gains (a scenario's `planner` object without its `name`).
    pub build: fn(&Map<String, Value>) -> Result<Built, Error>,
}

/// A planner built from its gains.
#[derive(Debug)]
pub enum Built {
    /// The simulator's own DVF evaluation, with the avoidance it runs with (`None`: the
    /// scenario's `params.avoidance`).
    Dvf(Option<Avoidance>),
    /// Another planner.
    Other(Box<dyn Planner>),
}

/// The entry of the planner named `name`.
///
/// # Errors
/// [`Error::Invalid`] naming `planner` and listing the known names.
pub fn entry(name: &str) -> Result<&'static Entry, Error> {
    PLANNERS
        .iter()
        .find(|e| e.name == name)
        .ok_or_else(|| Error::Invalid {
            field: "planner".to_owned(),
            message: format!(
                "unknown planner \"{name}\": one of {}",
                PLANNERS
                    .iter()
                    .map(|e| e.name)
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        })
}

/// A planner's gains read from its `planner` object: missing keys take `G`'s defaults, an
/// unknown key or a wrong type is refused naming the field (`planner.lambda`).
///
/// # Errors
/// [`Error::Invalid`] naming the field.
pub fn gains<G: DeserializeOwned>(map: &Map<String, Value>) -> Result<G, Error> {
    let value = Value::Object(map.clone());
    serde_path_to_error::deserialize(value).map_err(|e| {
        let path = e.path().to_string();
        Error::Invalid {
            field: if path == "." {
                "planner".to_owned()
            } else {
                format!("planner.{path}")
            },
            message: e.into_inner().to_string(),
        }
    })
}

/// A gain that must be a finite positive number.
///
/// # Errors
/// [`Error::Invalid`] naming `planner.{name}`.
pub fn positive(name: &str, v: f64) -> Result<(), Error> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(Error::Invalid {
            field: format!("planner.{name}"),
            message: format!("must be a finite number > 0, not {v}"),
        })
    }
}

/// A scenario's planner: its name and its gains (the keys its entry reads; none for its
/// defaults). Written as the bare name when it has no gains, read from either form.
#[derive(Clone, Debug, PartialEq)]
pub struct Spec {
    /// The planner's [`Entry::name`].
    pub name: String,
    /// Its gains, by name.
    pub gains: Map<String, Value>,
}

impl Default for Spec {
    fn default() -> Self {
        Self::named("dvf")
    }
}

impl Spec {
    /// The planner `name` with its default gains.
    #[must_use]
    pub fn named(name: &str) -> Self {
        Self {
            name: name.to_owned(),
            gains: Map::new(),
        }
    }

    /// Whether this is DVF with its defaults (a scenario then leaves the key out).
    #[must_use]
    pub fn is_default(&self) -> bool {
        *self == Self::default()
    }

    /// Builds the planner.
    ///
    /// # Errors
    /// [`Error::Invalid`] for an unknown name or gains its entry refuses, naming the field.
    pub fn build(&self) -> Result<Built, Error> {
        (entry(&self.name)?.build)(&self.gains)
    }
}

impl Serialize for Spec {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        if self.gains.is_empty() {
            return s.serialize_str(&self.name);
        }
        let mut map = Map::new();
        map.insert("name".to_owned(), Value::String(self.name.clone()));
        map.extend(self.gains.clone());
        map.serialize(s)
    }
}

impl<'de> Deserialize<'de> for Spec {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        use serde::de::Error as _;
        match Value::deserialize(d)? {
            Value::String(name) => Ok(Self::named(&name)),
            Value::Object(mut gains) => match gains.remove("name") {
                Some(Value::String(name)) => Ok(Self { name, gains }),
                _ => Err(D::Error::custom(
                    "a planner object needs a \"name\" string (\"avf\", …)",
                )),
            },
            _ => Err(D::Error::custom(
                "a planner is a name (\"avf\") or an object {\"name\": \"avf\", gains…}",
            )),
        }
    }
}

/// The message `entry` refuses `gains` with (a JSON object), for the planners' tests.
#[cfg(test)]
pub(crate) fn refused(entry: &Entry, gains: Value) -> String {
    let Value::Object(map) = gains else {
        unreachable!("gains are an object")
    };
    match (entry.build)(&map) {
        Ok(_) => panic!("{} accepted {map:?}", entry.name),
        Err(e) => e.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::test;

    #[test]
    fn a_spec_reads_a_name_or_an_object_and_writes_the_name_alone_without_gains() {
        let bare: Spec = serde_json::from_str(r#""dvf-paper""#).unwrap();
        assert_eq!(bare, Spec::named("dvf-paper"));
        assert_eq!(serde_json::to_string(&bare).unwrap(), r#""dvf-paper""#);
        let object: Spec = serde_json::from_str(r#"{"name": "dvf", "x": 1}"#).unwrap();
        assert_eq!(object.name, "dvf");
        assert_eq!(object.gains["x"], 1);
        assert_eq!(
            serde_json::to_string(&object).unwrap(),
            r#"{"name":"dvf","x":1}"#
        );
        assert!(serde_json::from_str::<Spec>(r#"{"lambda": 2}"#).is_err());
        assert!(serde_json::from_str::<Spec>("3").is_err());
    }

    #[test]
    fn an_unknown_planner_is_refused_with_the_known_names() {
        let e = Spec::named("rrt").build().unwrap_err().to_string();
        assert!(e.starts_with("planner: unknown planner \"rrt\""), "{e}");
        assert!(e.contains("dvf, dvf-paper"), "{e}");
    }

    #[test]
    fn every_entry_builds_from_its_defaults() {
        for e in PLANNERS {
            assert!((e.build)(&Map::new()).is_ok(), "{}", e.name);
        }
        let names: Vec<_> = PLANNERS.iter().map(|e| e.name).collect();
        let mut unique = names.clone();
        unique.sort_unstable();
        unique.dedup();
        assert_eq!(unique.len(), names.len(), "{names:?}");
    }
}
