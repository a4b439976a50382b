//! DVF itself: the simulator's own evaluation (`sim/evaluation.rs`), with the scenario's
//! avoidance (`dvf`) or the paper's (`dvf-paper`). Its gains are the scenario's `params`; its
//! `planner` object takes none.

use super::{gains, Built, Entry};
use crate::error::Error;
use crate::params::Avoidance;
use serde::Deserialize;
use serde_json::{Map, Value};

/// DVF as the scenario's parameters set it (the default planner).
pub(super) const DVF: Entry = Entry {
    name: "dvf",
    title: "Dynamic vector field",
    source: "He & Li, Simultaneous Position and Orientation Planning of Nonholonomic \
             Multi-Robot Systems: A Dynamic Vector Field Approach",
    avoids: "robots and obstacles",
    build: |map| no_gains(map).map(|()| Built::Dvf(None)),
};

/// DVF with the paper's avoidance as written (`params.avoidance = "paper"`).
pub(super) const DVF_PAPER: Entry = Entry {
    name: "dvf-paper",
    title: "Dynamic vector field, the paper's avoidance",
    source: DVF.source,
    avoids: "robots and obstacles",
    build: |map| no_gains(map).map(|()| Built::Dvf(Some(Avoidance::Paper))),
};

/// DVF's gains are the scenario's `params`: its `planner` object has none.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct NoGains {}

fn no_gains(map: &Map<String, Value>) -> Result<(), Error> {
    gains::<NoGains>(map).map(|NoGains {}| ())
}
