//! `dvf simulate`: run a scenario, print its report, write its trajectories as CSV on request.
//!
//! The CSV is written as the run goes ([`dvf::sim::run_streamed`]): one step's rows in memory
//! at a time, whatever the run's length. A run on a terminal shows its progress on standard
//! error.

use crate::args::SimulateArgs;
use dvf::sim::{run_streamed, Sample, Simulation};
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;

/// Runs the scenario and writes its report as one JSON line.
pub fn run(out: &mut impl Write, args: &SimulateArgs) -> Result<(), String> {
    let mut s = args.source.load()?;
    if let Some(planner) = &args.planner {
        s.planner = planner.clone();
        s.validate().map_err(|e| e.to_string())?;
    }
    // The file is created (and its header written) before the run, so that a path that
    // cannot be written is refused at once rather than after hours of simulation.
    let mut csv = match &args.csv {
        Some(path) => Some(Csv::create(path)?),
        None => None,
    };
    // Without a CSV only the first and last steps are sampled, which nothing reads.
    let every = match csv {
        Some(_) => usize::try_from(args.every).unwrap_or(usize::MAX),
        None => usize::MAX,
    };
    let bar = crate::progress::bar(s.steps(), "step");
    let report = run_streamed(&s, every, |sim: &Simulation, samples: &[Sample]| {
        bar.set_position(sim.steps() as u64);
        match &mut csv {
            Some(csv) if !samples.is_empty() => csv.rows(samples),
            _ => Ok(()),
        }
    })
    .map_err(|e| e.0);
    bar.finish_and_clear();
    let report = report?;
    if let Some(csv) = csv {
        csv.finish()?;
    }
    crate::write_json(out, &report)
}

/// What stops a run early: the message for standard error (a CSV that cannot be written, or
/// the scenario).
struct Stop(String);

impl From<dvf::Error> for Stop {
    fn from(e: dvf::Error) -> Self {
        Stop(e.to_string())
    }
}

/// The CSV file of the trajectories: the header, then one row per robot and sample, in time
/// order.
struct Csv<'a> {
    path: &'a Path,
    w: BufWriter<File>,
}

impl<'a> Csv<'a> {
    /// Creates the file at `path` and writes the header.
    fn create(path: &'a Path) -> Result<Self, String> {
        let file = File::create(path).map_err(|e| cannot_write(path, &e))?;
        let mut csv = Csv {
            path,
            w: BufWriter::new(file),
        };
        writeln!(csv.w, "t,robot,x,y,theta,v,omega").map_err(|e| cannot_write(path, &e))?;
        Ok(csv)
    }

    /// One step's rows. `t` is the step's time as [`dvf::sim::step_time`] gives it, which
    /// prints as the short decimal of `steps·dt` (`0.35`, not `0.35000000000000003`).
    fn rows(&mut self, samples: &[Sample]) -> Result<(), Stop> {
        for (i, [t, x, y, th, v, om]) in samples.iter().enumerate() {
            writeln!(self.w, "{t},{i},{x},{y},{th},{v},{om}")
                .map_err(|e| Stop(cannot_write(self.path, &e)))?;
        }
        Ok(())
    }

    /// Writes what is buffered.
    fn finish(mut self) -> Result<(), String> {
        self.w.flush().map_err(|e| cannot_write(self.path, &e))
    }
}

fn cannot_write(path: &Path, e: &std::io::Error) -> String {
    format!("{}: cannot write: {e}", path.display())
}
