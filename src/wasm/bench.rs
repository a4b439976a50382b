//! `CrowdBench`: the crowd of `dvf bench`, for timing the simulation in a JS engine
//! (`benches/wasm.mjs`).

use super::convert::whole;
use crate::presets;
use crate::scenario::{MAX_OBSTACLES, MAX_ROBOTS};
use crate::sim;
use wasm_bindgen::prelude::*;

/// The crowd of `dvf bench` (N robots swapping across a circle at constant density, M
/// obstacles on the way), for timing the simulation in a JS engine (`benches/wasm.mjs`): set up
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
        let robots = whole("robots", robots, MAX_ROBOTS)?.max(1);
        let obstacles = whole("obstacles", obstacles, MAX_OBSTACLES)?;
        Ok(CrowdBench {
            sim: sim::Simulation::new(&presets::crowd_with_obstacles(robots, obstacles))
                .map_err(|e| JsError::new(&e.to_string()))?,
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
