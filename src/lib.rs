#![doc = include_str!("../README.md")]
#![warn(missing_docs)]

// The paper's method: SE(2) and its log map, the goal field, circular obstacle fields and their
// blending, the swarm's virtual obstacles, the controller; the unicycle and the safety barrier
// every planner here shares.
pub mod controller;
pub mod field;
pub mod obstacle;
pub mod safety;
pub mod se2;
pub mod swarm;
pub mod unicycle;

// Scenes and their runs: the scenario format and its parameters, the paper's examples, the
// simulation and its metrics, the neighbourhood structures, random sweeps.
pub mod error;
pub mod grid;
pub mod params;
pub mod presets;
pub mod scenario;
pub mod sim;
pub mod sweep;

// The live, editable model behind the page, and the JavaScript facade (wasm32 only).
pub mod playground;
#[cfg(target_arch = "wasm32")]
pub mod wasm;

// Selects without a branch, for the hot loops; the sines, cosines and arctangents every build
// takes alike.
mod maths;
mod select;

#[cfg(test)]
mod testing;

pub use controller::{command, Command};
pub use error::Error;
pub use obstacle::Obstacle;
pub use params::Params;
pub use scenario::Scenario;
pub use se2::Pose;
pub use sim::{run, Neighbourhood, Report, Simulation};

#[cfg(doctest)]
mod doc_examples;
