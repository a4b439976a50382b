//! `dvf bench`: time the steps of a crowd.

use crate::args::BenchArgs;
use dvf::presets::crowd_with_obstacles;
use dvf::scenario::{MAX_OBSTACLES, MAX_ROBOTS};
use dvf::sim::{Neighbourhood, Simulation};
use std::io::Write;

/// Largest `--steps` of `dvf bench`.
const MAX_BENCH_STEPS: usize = 1_000_000;

/// Sets up the crowd, times `args.steps` steps and writes
/// `{"robots": N, "steps": S, "obstacles": M, "ms_per_step": x}`.
pub fn run(out: &mut impl Write, args: &BenchArgs) -> Result<(), String> {
    let &BenchArgs {
        robots,
        steps,
        obstacles,
        all_pairs,
    } = args;
    if !(1..=MAX_ROBOTS).contains(&robots) {
        return Err(format!(
            "robots: must be between 1 and {MAX_ROBOTS}, not {robots}"
        ));
    }
    if !(1..=MAX_BENCH_STEPS).contains(&steps) {
        return Err(format!(
            "steps: must be between 1 and {MAX_BENCH_STEPS}, not {steps}"
        ));
    }
    if obstacles > MAX_OBSTACLES {
        return Err(format!(
            "obstacles: at most {MAX_OBSTACLES}, not {obstacles}"
        ));
    }
    let s = crowd_with_obstacles(robots, obstacles);
    let way = if all_pairs {
        Neighbourhood::AllPairs
    } else {
        Neighbourhood::Grid
    };
    let mut sim = Simulation::with_neighbourhood(&s, way).map_err(|e| e.to_string())?;
    let start = std::time::Instant::now();
    for _ in 0..steps {
        sim.step();
    }
    let ms = start.elapsed().as_secs_f64() * 1e3 / steps as f64;
    // Keys in the documented order (serde_json's map would sort them).
    writeln!(
        out,
        r#"{{"robots": {robots}, "steps": {steps}, "obstacles": {obstacles}, "ms_per_step": {ms}}}"#
    )
    .map_err(|e| e.to_string())
}
