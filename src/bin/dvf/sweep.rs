//! `dvf sweep`: run random scenarios and summarise them, or one shard of them as JSON lines;
//! `dvf sweep merge`: the summary of the shards' lines.

use crate::args::SweepArgs;
use dvf::scenario::Scenario;
use dvf::sweep::{label, nothing_ran, Merge, Plan, Request, Summaries, Values};
use dvf::Report;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// Runs the sweep `args` describe: the summary as one JSON line (one group per point of the
/// grid), or with `--shard` one line per scenario of the shard. Failing scenarios are written
/// to `--write`'s folder. A sweep in which no scenario ran prints its summary and fails.
pub fn run(out: &mut impl Write, args: SweepArgs) -> Result<(), String> {
    let plan = Plan::new(&Request {
        family: args.family,
        seed: args.seed,
        count: args.count,
        robots: args.robots,
        obstacles: args.obstacles,
        spacing: args.spacing,
        avoidance: args.avoidance,
        barrier_rate: parse_rate(&args.barrier_rate)?,
        set: args.set,
        grid: args.grid,
        planner: args.planner,
    })
    .map_err(|e| e.to_string())?;
    let write = args.write;
    if let Some(dir) = &write {
        std::fs::create_dir_all(dir)
            .map_err(|e| format!("{}: cannot create: {e}", dir.display()))?;
    }
    // A bar of the scenarios this process runs, on a terminal only.
    let bar = crate::progress::bar(
        args.shard.map_or(plan.total(), |(k, n)| {
            plan.total().saturating_sub(k - 1).div_ceil(n)
        }),
        "scenario",
    );
    // Scenarios run on every core: the first write error is kept for the end.
    let write_error = Mutex::new(None);
    let write_failure = |values: &Values, s: u64, scenario: &Scenario, report: &Report| {
        bar.inc(1);
        if let Some(dir) = &write {
            write_if_failed(dir, &file_name(s, values), scenario, report, &write_error);
        }
    };
    if let Some(shard) = args.shard {
        plan.shard(shard, write_failure, |outcome| {
            crate::write_json(out, &outcome).map_err(Failed)
        })
        .map_err(|Failed(e)| e)?;
    } else {
        let summaries = plan.summaries(write_failure);
        crate::write_json(out, &summaries)?;
        ran(&summaries)?;
    }
    bar.finish_and_clear();
    match write_error.into_inner().unwrap_or_else(|p| p.into_inner()) {
        Some(e) => Err(e),
        None => Ok(()),
    }
}

/// A message of a shard's run: its lines' writing, or the plan's own refusal.
struct Failed(String);

impl From<dvf::Error> for Failed {
    fn from(e: dvf::Error) -> Self {
        Self(e.to_string())
    }
}

/// An error unless some scenario ran at every point: a sweep of skipped scenarios has nothing
/// to report.
/// A sweep where only some were skipped succeeds, with a warning on standard error that says
/// how many, so that a rate over fewer scenarios than asked for is not read as the whole.
fn ran(summaries: &Summaries) -> Result<(), String> {
    if let Some(why) = nothing_ran(summaries) {
        return Err(why);
    }
    let (skipped, asked) = summaries.all().iter().fold((0, 0), |(k, n), (_, s)| {
        (k + s.skipped, n + s.skipped + s.scenarios)
    });
    if skipped > 0 {
        eprintln!(
            "warning: {skipped} of {asked} scenarios were skipped because their robots or obstacles could not be placed; the summary covers the other {}",
            asked - skipped
        );
    }
    Ok(())
}

/// The file a failing scenario is written to: `seed-S.json`, or with a grid
/// `seed-S-NAME=VALUE,….json`.
fn file_name(seed: u64, values: &Values) -> String {
    if values.is_empty() {
        format!("seed-{seed}.json")
    } else {
        format!("seed-{seed}-{}.json", label(values, ","))
    }
}

/// A positive barrier rate, or `none`.
fn parse_rate(text: &str) -> Result<Option<f64>, String> {
    if text == "none" {
        return Ok(None);
    }
    match text.parse::<f64>() {
        Ok(r) if r.is_finite() && r > 0.0 => Ok(Some(r)),
        _ => Err(format!(
            "barrier-rate: expected a positive rate or none, not {text:?}"
        )),
    }
}

/// Writes a scenario as `dir/name` if a robot did not converge or a violation occurred; the
/// first error of any call is kept in `first_error`.
fn write_if_failed(
    dir: &Path,
    name: &str,
    scenario: &Scenario,
    report: &Report,
    first_error: &Mutex<Option<String>>,
) {
    let failed = report.violations > 0 || report.robots.iter().any(|r| r.converged_at.is_none());
    if !failed {
        return;
    }
    let path = dir.join(name);
    if let Err(e) = std::fs::write(&path, scenario.to_json()) {
        let mut first = first_error.lock().unwrap_or_else(|p| p.into_inner());
        first.get_or_insert(format!("{}: cannot write: {e}", path.display()));
    }
}

/// Writes the summary of the shards' lines in `files` (standard input when there are none),
/// checked to be one whole sweep; fails after writing it if no scenario ran.
pub fn merge(out: &mut impl Write, files: &[PathBuf]) -> Result<(), String> {
    let mut texts = Vec::new();
    if files.is_empty() {
        let mut text = String::new();
        std::io::Read::read_to_string(&mut std::io::stdin(), &mut text)
            .map_err(|e| format!("standard input: {e}"))?;
        texts.push(("standard input".to_owned(), text));
    }
    for f in files {
        let text =
            std::fs::read_to_string(f).map_err(|e| format!("{}: cannot read: {e}", f.display()))?;
        texts.push((f.display().to_string(), text));
    }
    let mut merge = Merge::new();
    for (name, text) in &texts {
        for (k, line) in text.lines().enumerate() {
            merge
                .add(&format!("{name}:{}", k + 1), line)
                .map_err(|e| e.to_string())?;
        }
    }
    let summaries = merge.finish().map_err(|e| e.to_string())?;
    crate::write_json(out, &summaries)?;
    ran(&summaries)
}
