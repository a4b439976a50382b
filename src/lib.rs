#![doc = include_str!("../README.md")]
#![warn(missing_docs)]

#[doc(hidden)]
pub mod approx;
pub mod controller;
pub mod error;
pub mod field;
pub mod grid;
pub mod live;
pub mod obstacle;
pub mod params;
pub mod presets;
pub mod safety;
pub mod scenario;
pub mod se2;
pub mod sim;
pub mod swarm;
pub mod sweep;
#[cfg(target_arch = "wasm32")]
pub mod wasm;
#[doc(hidden)]
pub mod xorshift;

pub use controller::{command, Command};
pub use error::Error;
pub use obstacle::Obstacle;
pub use params::Params;
pub use scenario::Scenario;
pub use se2::Pose;
pub use sim::{run, Neighbourhood, Report, Simulation};

#[cfg(all(test, target_arch = "wasm32"))]
wasm_bindgen_test::wasm_bindgen_test_configure!(run_in_browser);
