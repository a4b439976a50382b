//! `dvf sweep`: run random scenarios and summarise them, or one shard of them as JSON lines;
//! `dvf sweep merge`: the summary of the shards' lines.

use crate::args::SweepArgs;
use dvf::params::Avoidance;
use dvf::scenario::{Scenario, MAX_OBSTACLES, MAX_ROBOTS};
use dvf::sweep::{
    label, points, sweep_points, value_of, with, Axis, Family, Merge, Outcome, Recipe, Summaries,
    Sweep, Values,
};
use dvf::Report;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// Largest `--count` of `dvf sweep`.
const MAX_SWEEP: usize = 1_000_000;

/// Runs the sweep `args` describe: the summary as one JSON line (one group per point of the
/// grid), or with `--shard` one line per scenario of the shard. Failing scenarios are written
/// to `--write`'s folder. A sweep in which no scenario ran prints its summary and fails.
pub fn run(out: &mut impl Write, args: SweepArgs) -> Result<(), String> {
    let (recipe, set) = recipe(&args)?;
    let axes = args
        .grid
        .iter()
        .map(|t| Axis::parse(t))
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| e.to_string())?;
    if let Some(a) = axes.iter().find(|a| set.contains_key(&a.name)) {
        return Err(format!("{}: given by both --set and --grid", a.name));
    }
    let grid = points(&axes).map_err(|e| e.to_string())?;
    // Every point's values are read and checked before anything runs.
    let runs: Vec<(Values, Recipe)> = grid
        .iter()
        .map(|v| Ok((v.clone(), with(&recipe, v)?)))
        .collect::<Result<_, dvf::Error>>()
        .map_err(|e| e.to_string())?;
    let SweepArgs {
        shard,
        seed,
        count,
        write,
        ..
    } = args;
    let total = count * runs.len();
    if total > MAX_SWEEP {
        return Err(format!(
            "count: count × grid points must be at most {MAX_SWEEP}, not {count} × {}",
            runs.len()
        ));
    }
    if let Some(dir) = &write {
        std::fs::create_dir_all(dir)
            .map_err(|e| format!("{}: cannot create: {e}", dir.display()))?;
    }
    // Scenarios run on every core: the first write error is kept for the end.
    let write_error = Mutex::new(None);
    let write_failure = |values: &Values, s: u64, scenario: &Scenario, report: &Report| {
        if let Some(dir) = &write {
            write_if_failed(dir, &file_name(s, values), scenario, report, &write_error);
        }
    };
    if let Some((k, n)) = shard {
        // Every N-th scenario from the K-th, point by point and seed by seed, one line each as
        // it finishes: a shard cut short leaves whole lines, and merge names the missing seeds.
        let id = Sweep::id_of(&recipe, &grid, seed, count);
        for index in (k - 1..total).step_by(n) {
            let (point, (values, recipe)) = (index / count, &runs[index / count]);
            let s = seed.wrapping_add((index % count) as u64);
            let mut outcome = Outcome::run(recipe, s, |scenario, report| {
                write_failure(values, s, scenario, report);
            });
            outcome.sweep = Some(Sweep {
                id: id.clone(),
                seed,
                count,
                points: runs.len(),
                point,
                shard: [k, n],
            });
            outcome.values.clone_from(values);
            outcome.recipe.set.clone_from(&set);
            crate::write_json(out, &outcome)?;
        }
    } else {
        let summaries = sweep_points(&runs, seed, count, write_failure);
        crate::write_json(out, &summaries)?;
        ran(&summaries)?;
    }
    match write_error.into_inner().unwrap_or_else(|p| p.into_inner()) {
        Some(e) => Err(e),
        None => Ok(()),
    }
}

/// An error unless some scenario ran at every point: a sweep of skipped scenarios has nothing
/// to report.
fn ran(summaries: &Summaries) -> Result<(), String> {
    for (values, s) in summaries.all() {
        if s.scenarios == 0 {
            let at = values.map_or(String::new(), |v| format!(" at {}", label(v, " ")));
            return Err(format!(
                "no scenario ran{at}: all {} were skipped because their robots or obstacles could not be placed; ask for fewer robots (--robots) or obstacles (--obstacles), or a larger area (--set side=…)",
                s.skipped
            ));
        }
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

/// The recipe of `args`, its ranges and settings checked, and the values `--set` gave.
fn recipe(args: &SweepArgs) -> Result<(Recipe, Values), String> {
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
    let mut set = Values::new();
    for text in &args.set {
        let Some((name, value)) = text.split_once('=') else {
            return Err(format!("set: expected NAME=VALUE, not {text:?}"));
        };
        let name = name.trim();
        if set.insert(name.to_owned(), value_of(value)).is_some() {
            return Err(format!("set: {name} is given twice"));
        }
    }
    let recipe = with(&recipe, &set).map_err(|e| e.to_string())?;
    Ok((recipe, set))
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
