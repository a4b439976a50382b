//! # dvf: the Dynamic Vector Field method for nonholonomic multi-robot planning
//!
//! dvf drives unicycle robots (`ṗ = v·(cos θ, sin θ)`, `θ̇ = ω`) to goal poses in SE(2) with
//! the method of "Simultaneous Position and Orientation Planning of Nonholonomic Multi-Robot
//! Systems: A Dynamic Vector Field Approach" (X. He and Z. Li): a vector field towards each
//! goal built from the logarithm map of SE(2), circular fields around obstacles blended into
//! it, a virtual obstacle between robots that come close, and a controller that turns the
//! field into `(v, ω)`. On top of the paper, a safety barrier bounds every robot's forward
//! speed so that no two robots and no robot and obstacle ever overlap. The same core runs
//! natively (this library and the `dvf` command line) and as WebAssembly (the browser
//! playground).
//!
//! ## A first run
//!
//! A scenario names its robots' starts and goals, its obstacles and the method's parameters;
//! [`run()`] checks it as the file reader does and simulates it to its end, returning a
//! [`Report`]. The paper's examples are
//! built in ([`presets`]):
//!
//! ```
//! let scenario = dvf::presets::preset("table1-free-space")?;
//! let report = dvf::run(&scenario)?;
//! // Every robot reached its goal pose and stayed there, and no two robots overlapped.
//! assert!(report.robots.iter().all(|r| r.converged_at.is_some()));
//! assert_eq!(report.violations, 0);
//! # Ok::<(), dvf::Error>(())
//! ```
//!
//! A scenario of one's own is JSON (the format is [`scenario`]'s) or built in code
//! ([`Scenario::builder`]), checked either way; a [`Simulation`] runs it step by step:
//!
//! ```
//! let scenario = dvf::Scenario::from_json(
//!     r#"{ "duration": 30.0,
//!          "robots": [ { "start": [0, 0, 0], "goal": [10, 0, 0] },
//!                      { "start": [10, 0, 3.14159], "goal": [0, 0, 3.14159] } ],
//!          "obstacles": [ { "center": [5, 4], "radius": 1, "influence": 2 } ] }"#,
//! )?;
//! let mut sim = dvf::Simulation::new(&scenario)?;
//! while sim.time() < 30.0 {
//!     sim.step();
//! }
//! // The two robots met head-on, went around each other and arrived; they never overlapped.
//! let report = sim.report();
//! assert!(report.robots.iter().all(|r| r.converged_at.is_some()));
//! assert_eq!(report.violations, 0);
//! # Ok::<(), dvf::Error>(())
//! ```
//!
//! ## Modules, in the paper's order
//!
//! The method:
//! - [`se2`]: poses in SE(2), their composition and the logarithm map (Section III);
//! - [`field`]: the dynamic vector field towards a goal pose (Section III);
//! - [`obstacle`]: circular obstacles and their avoidance field, blended into the goal's
//!   (Section IV);
//! - [`swarm`]: collision avoidance among robots through a virtual obstacle (Section V);
//! - [`controller`]: the controllers that turn the field into `(v, ω)` (Sections III to V);
//! - [`unicycle`]: the unicycle's kinematics, integrated over a step;
//! - [`safety`]: the safety barrier on the forward speed (not in the paper), and
//!   [`SafeRobot`]: one robot under the controller and the barrier, stepped from one's own
//!   loop.
//!
//! Scenes and their runs:
//! - [`params`]: the method's parameters and their defaults;
//! - [`scenario`]: the scenario format and its validation;
//! - [`presets`]: the paper's examples (Section VI) and crowds of any size;
//! - [`sim`]: the simulation, its metrics and its report;
//! - [`grid`]: the neighbourhood structures that keep a step O(N);
//! - [`sweep`]: random scenarios and their statistics;
//! - [`planner`]: the planners the simulator steps, DVF and the ones it is compared with;
//! - [`compare`]: a scenario run with each of several planners, the same metrics for each;
//! - [`error`]: the errors, each naming the field at fault.
//!
//! The browser:
//! - [`playground`]: the live, editable model behind the page;
//! - `wasm`: the JavaScript facade (wasm32 only).
//!
//! ## Features
//!
//! - `cli` (default): the `dvf` command line (`dvf simulate`, `dvf sweep`, `dvf bench`, …)
//!   and its argument parser, clap. A library user turns it off:
//!   `dvf = { version = "0.1", default-features = false }`.
//! - `python`: the Python module of the `dvf` wheel (pyo3 and numpy; built by maturin from
//!   `python/pyproject.toml`, docs/book/src/python.md).
//!
//! Natively the library runs a sweep's scenarios and a large crowd's step on rayon's
//! threads, with the same bits as on one thread; the wasm build runs them on one.
//!
//! ## More
//!
//! The book (`docs/book`, built by `make docs`) covers the playground, embedding it in a
//! page, the command line, the scenario format and the notes on the paper; the code, its
//! tests and benchmarks are at <https://github.com/dvf-rs/dvf>.

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
// simulation and its metrics, the neighbourhood structures, random sweeps, planners compared.
pub mod compare;
pub mod error;
pub mod grid;
pub mod params;
pub mod planner;
pub mod presets;
pub mod scenario;
pub mod sim;
pub mod sweep;

// The live, editable model behind the page, and the JavaScript facade (wasm32 only).
pub mod playground;
#[cfg(target_arch = "wasm32")]
pub mod wasm;
// The Python module `dvf._dvf` of the wheel (the `python` feature, native only).
#[cfg(all(feature = "python", not(target_arch = "wasm32")))]
mod python;

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
pub use safety::SafeRobot;
pub use scenario::Scenario;
pub use se2::Pose;
pub use sim::{run, Neighbourhood, Report, Simulation};

// The Rust blocks of the README and of the book, run as doctests.
#[cfg(doctest)]
mod doc_examples;
