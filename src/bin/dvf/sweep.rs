//! `dvf sweep`: run random scenarios and summarise them, or one shard of them as JSON lines;
//! `dvf sweep merge`: the summary of the shards' lines.

use crate::args::SweepArgs;
use dvf::params::Avoidance;
use dvf::scenario::{Scenario, MAX_OBSTACLES, MAX_ROBOTS};
use dvf::sweep::{sweep, Family, Outcome, Recipe, Summary};
use dvf::Report;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// Largest `--count` of `dvf sweep`.
const MAX_SWEEP: usize = 1_000_000;

/// Runs the sweep `args` describe: the summary as one JSON line, or with `--shard` one line
/// per scenario of the shard. Failing scenarios are written to `--write`'s folder.
pub fn run(out: &mut impl Write, args: SweepArgs) -> Result<(), String> {
    let recipe = recipe(&args)?;
    let SweepArgs {
        shard,
        seed,
        count,
        write,
        ..
    } = args;
    // The parameters are the same for every scenario: check them once.
    if let Some(first) = dvf::sweep::scenario(&recipe, seed) {
        first.validate().map_err(|e| e.to_string())?;
    }
    if let Some(dir) = &write {
        std::fs::create_dir_all(dir)
            .map_err(|e| format!("{}: cannot create: {e}", dir.display()))?;
    }
    // Scenarios run on every core: the first write error is kept for the end.
    let write_error = Mutex::new(None);
    let write_failure = |s: u64, scenario: &Scenario, report: &Report| {
        if let Some(dir) = &write {
            write_if_failed(dir, s, scenario, report, &write_error);
        }
    };
    if let Some((k, n)) = shard {
        // Every N-th scenario from the K-th, one line each as it finishes: a shard cut short
        // leaves whole lines, and merge names the missing seeds.
        for index in (k - 1..count).step_by(n) {
            let s = seed.wrapping_add(index as u64);
            let outcome = Outcome::run(&recipe, s, |scenario, report| {
                write_failure(s, scenario, report);
            });
            crate::write_json(out, &outcome)?;
        }
    } else {
        let summary = sweep(&recipe, seed, count, write_failure);
        crate::write_json(out, &summary)?;
    }
    match write_error.into_inner().unwrap_or_else(|p| p.into_inner()) {
        Some(e) => Err(e),
        None => Ok(()),
    }
}

/// The recipe of `args`, its ranges and settings checked.
fn recipe(args: &SweepArgs) -> Result<Recipe, String> {
    let family = match args.family.as_str() {
        "dense" => Family::Dense,
        "formation" => Family::Formation,
        _ => Family::Random,
    };
    let mut recipe = Recipe::of(family);
    let robots = args
        .robots
        .unwrap_or((*recipe.robots.start(), *recipe.robots.end()));
    let obstacles = args
        .obstacles
        .unwrap_or((*recipe.obstacles.start(), *recipe.obstacles.end()));
    if let Some((a, b)) = args.spacing {
        if family != Family::Formation {
            return Err("spacing: only the formation family has goal slots".into());
        }
        recipe.spacing = a..=b;
    }
    let count = args.count;
    if !(1..=MAX_SWEEP).contains(&count) {
        return Err(format!(
            "count: must be between 1 and {MAX_SWEEP}, not {count}"
        ));
    }
    if robots.1 > MAX_ROBOTS || robots.0 == 0 {
        return Err(format!(
            "robots: must be between 1 and {MAX_ROBOTS}, not {}..={}",
            robots.0, robots.1
        ));
    }
    if obstacles.1 > MAX_OBSTACLES {
        return Err(format!(
            "obstacles: at most {MAX_OBSTACLES}, not {}",
            obstacles.1
        ));
    }
    recipe.robots = robots.0..=robots.1;
    recipe.obstacles = obstacles.0..=obstacles.1;
    recipe.params.avoidance = if args.avoidance == "paper" {
        Avoidance::Paper
    } else {
        Avoidance::Exit
    };
    recipe.params.barrier_rate = parse_rate(&args.barrier_rate)?;
    Ok(recipe)
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

/// Writes scenario `seed` as `dir/seed-S.json` if a robot did not converge or a violation
/// occurred; the first error of any call is kept in `first_error`.
fn write_if_failed(
    dir: &Path,
    seed: u64,
    scenario: &Scenario,
    report: &Report,
    first_error: &Mutex<Option<String>>,
) {
    let failed = report.violations > 0 || report.robots.iter().any(|r| r.converged_at.is_none());
    if !failed {
        return;
    }
    let path = dir.join(format!("seed-{seed}.json"));
    if let Err(e) = std::fs::write(&path, scenario.to_json()) {
        let mut first = first_error.lock().unwrap_or_else(|p| p.into_inner());
        first.get_or_insert(format!("{}: cannot write: {e}", path.display()));
    }
}

/// Writes the summary of the shards' lines in `files` (standard input when there are none).
pub fn merge(out: &mut impl Write, files: &[PathBuf]) -> Result<(), String> {
    let summary = merged(files)?;
    crate::write_json(out, &summary)
}

/// The summary of the outcomes in `files` (standard input when there are none), checked to
/// cover one recipe's seeds from the smallest, each once.
fn merged(files: &[PathBuf]) -> Result<Summary, String> {
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
    let mut outcomes: Vec<Outcome> = Vec::new();
    for (name, text) in &texts {
        for (k, line) in text.lines().enumerate() {
            if line.trim().is_empty() {
                continue;
            }
            let o: Outcome = serde_json::from_str(line)
                .map_err(|e| format!("{name}:{}: not a line of dvf sweep --shard: {e}", k + 1))?;
            if let Some(first) = outcomes.first() {
                if first.recipe != o.recipe {
                    return Err(format!(
                        "{name}:{}: seed {} was drawn from another recipe than seed {} (shards of different sweeps)",
                        k + 1,
                        o.seed,
                        first.seed
                    ));
                }
            }
            outcomes.push(o);
        }
    }
    outcomes.sort_by_key(|o| o.seed);
    let Some(first) = outcomes.first().map(|o| o.seed) else {
        return Err("no outcomes to merge".into());
    };
    for (k, o) in outcomes.iter().enumerate() {
        let want = first.wrapping_add(k as u64);
        if o.seed != want {
            return Err(if o.seed < want {
                format!("seed {} appears twice (a shard merged twice?)", o.seed)
            } else {
                format!("seed {want} is missing (a shard not finished or not given?)")
            });
        }
    }
    Ok(Summary::of(first, &outcomes))
}
