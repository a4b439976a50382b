//! `dvf simulate`: run a scenario, print its report, write its trajectories as CSV on request.

use crate::args::SimulateArgs;
use dvf::sim::{run_recorded, Sample};
use std::io::Write;
use std::path::Path;

/// Runs the scenario and writes its report as one JSON line.
pub fn run(out: &mut impl Write, args: &SimulateArgs) -> Result<(), String> {
    let s = args.source.load()?;
    let report = match &args.csv {
        Some(path) => {
            let (report, traj) = run_recorded(&s, 1).map_err(|e| e.to_string())?;
            write_csv(path, &traj).map_err(|e| format!("{}: cannot write: {e}", path.display()))?;
            report
        }
        None => dvf::run(&s).map_err(|e| e.to_string())?,
    };
    crate::write_json(out, &report)
}

/// The trajectories as CSV, one row per robot and sample, in time order.
fn write_csv(path: &Path, traj: &[Vec<Sample>]) -> std::io::Result<()> {
    let mut w = std::io::BufWriter::new(std::fs::File::create(path)?);
    writeln!(w, "t,robot,x,y,theta,v,omega")?;
    let len = traj.first().map_or(0, Vec::len);
    for k in 0..len {
        for (i, samples) in traj.iter().enumerate() {
            let [t, x, y, th, v, om] = samples[k];
            writeln!(w, "{t},{i},{x},{y},{th},{v},{om}")?;
        }
    }
    w.flush()
}
