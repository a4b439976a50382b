//! `dvf field`: sample one robot's obstacle-free goal field on a grid.

use crate::args::FieldArgs;
use dvf::field::sample_grid;
use std::io::Write;

/// Largest `--grid` accepted: 1000 × 1000 samples.
const MAX_GRID: usize = 1000;

/// Samples robot `args.robot`'s goal field at its start attitude and writes
/// `{"theta": …, "points": […]}` as one JSON line.
pub fn run(out: &mut impl Write, args: &FieldArgs) -> Result<(), String> {
    let s = args.source.load()?;
    let (robot, grid) = (args.robot, args.grid);
    if robot >= s.robots.len() {
        return Err(dvf::Error::RobotIndex {
            index: robot,
            count: s.robots.len(),
        }
        .to_string());
    }
    if !(2..=MAX_GRID).contains(&grid) {
        return Err(format!(
            "grid: must be between 2 and {MAX_GRID}, not {grid}"
        ));
    }
    let r = &s.robots[robot];
    let theta = r.start_pose().theta;
    let points = sample_grid(r.goal_pose(), theta, s.resolved_bounds(), grid);
    crate::write_json(
        out,
        &serde_json::json!({ "theta": theta, "points": points }),
    )
}
