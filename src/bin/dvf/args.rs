//! The command line: its subcommands, their arguments and the parsers of their values.
//!
//! clap turns doc comments into help text, so the doc comment of a subcommand is on its variant
//! of [`Command`] and its argument structs carry plain comments.

use clap::{Args, Parser, Subcommand};
use dvf::planner::{entry, Spec};
use dvf::presets::preset;
use dvf::scenario::Scenario;
use std::io::Read;
use std::path::PathBuf;

#[derive(Parser)]
#[command(
    name = "dvf",
    version,
    about = "Dynamic vector field motion planning for nonholonomic robots (He & Li)"
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand)]
pub enum Command {
    /// Run a scenario and print a JSON report.
    Simulate(SimulateArgs),
    /// Sample robot I's obstacle-free goal field at its start attitude on an N×N grid.
    Field(FieldArgs),
    /// Run COUNT random scenarios from SEED and print the success rate, the violations and
    /// the distribution of convergence times (JSON); with `--grid`, COUNT at each point of
    /// the grid, one group each. With `--shard K/N`, run only every N-th scenario from the
    /// K-th and print one JSON line per scenario instead; `dvf sweep merge` checks that the
    /// shards' lines are one whole sweep and combines them into its summary.
    #[command(args_conflicts_with_subcommands = true)]
    Sweep {
        #[command(subcommand)]
        action: Option<SweepAction>,
        #[command(flatten)]
        args: Box<SweepArgs>,
    },
    /// Time the simulation of a crowd (N robots swapping across a circle at constant
    /// density, M obstacles on the way) and print
    /// `{"robots": N, "steps": S, "obstacles": M, "ms_per_step": x}`.
    Bench(BenchArgs),
    /// List the presets, or print one as a scenario file with `--preset NAME`.
    Presets(PresetsArgs),
    /// Run a scenario with each of several planners (all of them by default) on the same
    /// robots, limits and safety barrier, and print one row of metrics per planner: arrival
    /// with heading, time to the last arrival, path length, control effort, peak curvature,
    /// reversals, chattering, closest pair and clearance, violations and compute per step;
    /// with `--json`, the comparison as JSON.
    Compare(CompareArgs),
    /// List the planners (`dvf compare --list`): name, title, what each avoids on its own, and
    /// its source.
    Planners(PlannersArgs),
}

/// What `dvf sweep` can do besides running scenarios.
#[derive(Subcommand)]
pub enum SweepAction {
    /// Combine the JSON lines of `dvf sweep --shard` runs (files, or standard input when
    /// none is given) into the summary one unsharded sweep of the same scenarios prints;
    /// refuse a set that misses a scenario, has one twice or mixes sweeps.
    Merge {
        /// Files of JSON lines, in any order.
        files: Vec<PathBuf>,
    },
}

// The arguments of `dvf simulate`.
#[derive(Args)]
pub struct SimulateArgs {
    #[command(flatten)]
    pub source: Source,
    /// Also write the trajectories as CSV (t,robot,x,y,theta,v,omega), row by row as the run
    /// goes; the file is created before the run starts.
    #[arg(long, value_name = "PATH")]
    pub csv: Option<PathBuf>,
    /// With --csv: keep every K-th step (and the last) rather than every step.
    #[arg(long, value_name = "K", default_value_t = 1, requires = "csv", value_parser = clap::value_parser!(u64).range(1..))]
    pub every: u64,
    /// Run with this planner rather than the scenario's `planner` (see `dvf planners`): a
    /// name, or a JSON object with its gains (`{"name": "avf", "lambda": 2}`).
    #[arg(long, value_name = "NAME", value_parser = parse_planner)]
    pub planner: Option<Spec>,
}

// The arguments of `dvf compare`.
#[derive(Args)]
pub struct CompareArgs {
    /// A scenario file (JSON), or `-` for standard input.
    #[arg(value_name = "FILE", required_unless_present_any = ["preset", "list"], conflicts_with = "preset")]
    pub file: Option<PathBuf>,
    /// A built-in preset (see `dvf presets`).
    #[arg(long, value_name = "NAME")]
    pub preset: Option<String>,
    /// The planners to run, comma-separated (all of `dvf planners` by default).
    #[arg(long, value_name = "NAME,…", value_delimiter = ',')]
    pub planners: Vec<String>,
    /// Print the comparison as JSON rather than a table.
    #[arg(long)]
    pub json: bool,
    /// Set NAME to VALUE in the scenario (repeatable): a parameter by its scenario file name
    /// (v_max, omega_max, barrier_rate, k_v, …; `none` for no limit or no barrier), dt or
    /// duration.
    #[arg(long = "set", value_name = "NAME=VALUE", allow_hyphen_values = true)]
    pub set: Vec<String>,
    /// List the planners instead (as `dvf planners`).
    #[arg(long, conflicts_with_all = ["file", "preset", "planners", "set"])]
    pub list: bool,
}

// The arguments of `dvf planners`.
#[derive(Args)]
pub struct PlannersArgs {
    /// Print the list as JSON: `[{name, title, source, avoids}]`.
    #[arg(long)]
    pub json: bool,
}

// The arguments of `dvf field`.
#[derive(Args)]
pub struct FieldArgs {
    #[command(flatten)]
    pub source: Source,
    /// Robot index (0-based).
    #[arg(long, default_value_t = 0)]
    pub robot: usize,
    /// Grid size N (2 … 1000).
    #[arg(long, default_value_t = 21)]
    pub grid: usize,
}

// The arguments of `dvf sweep` (without `merge`).
#[derive(Args)]
pub struct SweepArgs {
    /// Run only scenarios K, K + N, K + 2N, … (counted from 1) of the COUNT (of COUNT times
    /// the grid's points) and print one JSON line per scenario (its sweep, seed, recipe,
    /// outcome), for `dvf sweep merge`.
    #[arg(long, value_name = "K/N", value_parser = parse_shard)]
    pub shard: Option<(usize, usize)>,
    /// Scenario k uses seed SEED + k, so any failure is rerun with `--seed S --count 1`.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Number of scenarios (1 … 1000000).
    #[arg(long, default_value_t = 100)]
    pub count: usize,
    /// The kind of scene: random (the default), dense (24 to 64 robots, 0 to 8
    /// obstacles) or formation (a column of robots through a row of obstacles into a
    /// grid, a line or a ring of goal slots).
    #[arg(long, value_name = "FAMILY", default_value = "random", value_parser = ["random", "dense", "formation"])]
    pub family: String,
    /// Robots per scenario, drawn from MIN..=MAX (the family's range by default:
    /// random 4..=16, dense 24..=64, formation 9..=25).
    #[arg(long, value_name = "MIN..=MAX", value_parser = parse_range)]
    pub robots: Option<(usize, usize)>,
    /// Obstacles per scenario, drawn from MIN..=MAX (random 0..=5, dense 0..=8,
    /// formation 0..=3).
    #[arg(long, value_name = "MIN..=MAX", value_parser = parse_range)]
    pub obstacles: Option<(usize, usize)>,
    /// Formation family: the distance between neighbouring goal slots in units of
    /// safe_radius, drawn from MIN..=MAX (at least 2; 3..=6 by default).
    #[arg(long, value_name = "MIN..=MAX", value_parser = parse_spacing)]
    pub spacing: Option<(f64, f64)>,
    /// Robot avoidance: exit (the default) or paper.
    #[arg(long, value_name = "MODE", default_value = "exit", value_parser = ["exit", "paper"])]
    pub avoidance: String,
    /// The safety barrier's rate α (1/s), or `none` to run without the barrier.
    #[arg(
        long,
        value_name = "RATE|none",
        default_value = "5",
        allow_hyphen_values = true
    )]
    pub barrier_rate: String,
    /// Set NAME to VALUE in every scenario (repeatable): a parameter by its scenario file
    /// name (k_v, k_omega, k_a, sense_radius, safe_radius, v_max, omega_max, barrier_rate,
    /// avoidance, …; `none` for no limit), dt, duration, or side (the area's side).
    #[arg(long = "set", value_name = "NAME=VALUE", allow_hyphen_values = true)]
    pub set: Vec<String>,
    /// Run the sweep at each value of NAME (repeatable: at every combination), each point a
    /// group of the summary: a list `NAME=a,b,c` or a range `NAME=start:stop:step`.
    #[arg(long = "grid", value_name = "NAME=VALUES", allow_hyphen_values = true)]
    pub grid: Vec<String>,
    /// Write every failing scenario as DIR/seed-S.json (with a grid,
    /// DIR/seed-S-NAME=VALUE,….json).
    #[arg(long, value_name = "DIR")]
    pub write: Option<PathBuf>,
    /// Run every scenario with this planner (see `dvf planners`): a name, or a JSON object
    /// with its gains. The shard lines and the summary record it; shards of different
    /// planners do not merge.
    #[arg(long, value_name = "NAME", default_value = "dvf", value_parser = parse_planner)]
    pub planner: Spec,
}

// The arguments of `dvf bench`.
#[derive(Args)]
pub struct BenchArgs {
    /// Robots N (1 … 10000).
    #[arg(long, default_value_t = 1000)]
    pub robots: usize,
    /// Steps S timed (1 … 1000000), after the simulation is set up.
    #[arg(long, default_value_t = 100)]
    pub steps: usize,
    /// Obstacles M on the circle of half the crowd's radius.
    #[arg(long, default_value_t = 0)]
    pub obstacles: usize,
    /// Find neighbours by comparing all pairs (the O(N²) reference) instead of a grid.
    #[arg(long)]
    pub all_pairs: bool,
}

// The arguments of `dvf presets`.
#[derive(Args)]
pub struct PresetsArgs {
    /// Print this preset's scenario JSON (a starting point for a file of your own).
    #[arg(long, value_name = "NAME")]
    pub preset: Option<String>,
}

/// The scenario a subcommand runs: a file or a preset.
#[derive(Args)]
pub struct Source {
    /// A scenario file (JSON), or `-` for standard input.
    #[arg(
        value_name = "FILE",
        required_unless_present = "preset",
        conflicts_with = "preset"
    )]
    pub file: Option<PathBuf>,
    /// A built-in preset (see `dvf presets`).
    #[arg(long, value_name = "NAME")]
    pub preset: Option<String>,
}

impl Source {
    /// The scenario of the preset or of the file, read and checked.
    pub fn load(&self) -> Result<Scenario, String> {
        match (&self.file, &self.preset) {
            (_, Some(name)) => preset(name).map_err(|e| e.to_string()),
            (Some(path), None) if path.as_os_str() == "-" => {
                let mut text = String::new();
                std::io::stdin()
                    .read_to_string(&mut text)
                    .map_err(|e| format!("standard input: cannot read: {e}"))?;
                Scenario::from_json(&text).map_err(|e| format!("standard input: {e}"))
            }
            (Some(path), None) => {
                let text = std::fs::read_to_string(path)
                    .map_err(|e| format!("{}: cannot read: {e}", path.display()))?;
                Scenario::from_json(&text).map_err(|e| format!("{}: {e}", path.display()))
            }
            (None, None) => Err("give a scenario FILE or --preset NAME".into()),
        }
    }
}

/// A planner: a name of `dvf planners`, or a JSON object `{"name": …, gains…}` whose name is
/// one; its gains are checked when it is built.
fn parse_planner(text: &str) -> Result<Spec, String> {
    let spec = if text.trim_start().starts_with('{') {
        serde_json::from_str::<Spec>(text).map_err(|e| e.to_string())?
    } else {
        Spec::named(text.trim())
    };
    entry(&spec.name).map_err(|e| e.to_string())?;
    Ok(spec)
}

/// `A..=B` (or a single number) as an inclusive range.
fn parse_range(text: &str) -> Result<(usize, usize), String> {
    let (a, b) = text.split_once("..=").unwrap_or((text, text));
    let num = |t: &str| {
        t.trim()
            .parse::<usize>()
            .map_err(|_| format!("expected MIN..=MAX or a count, not {text:?}"))
    };
    let (a, b) = (num(a)?, num(b)?);
    if a > b {
        return Err(format!("{text:?}: MIN is larger than MAX"));
    }
    Ok((a, b))
}

/// `A..=B` (or a single number) of goal spacings, each at least 2 and at most 100.
fn parse_spacing(text: &str) -> Result<(f64, f64), String> {
    let (a, b) = text.split_once("..=").unwrap_or((text, text));
    let num = |t: &str| match t.trim().parse::<f64>() {
        Ok(x) if (2.0..=100.0).contains(&x) => Ok(x),
        _ => Err(format!(
            "expected MIN..=MAX of spacings between 2 and 100, not {text:?}"
        )),
    };
    let (a, b) = (num(a)?, num(b)?);
    if a > b {
        return Err(format!("{text:?}: MIN is larger than MAX"));
    }
    Ok((a, b))
}

/// `K/N` with `1 ≤ K ≤ N`.
fn parse_shard(text: &str) -> Result<(usize, usize), String> {
    let parsed = text
        .split_once('/')
        .and_then(|(k, n)| Some((k.trim().parse().ok()?, n.trim().parse().ok()?)));
    match parsed {
        Some((k, n)) if n >= 1 && (1..=n).contains(&k) => Ok((k, n)),
        _ => Err(format!(
            "expected K/N with 1 ≤ K ≤ N (shard K of N), not {text:?}"
        )),
    }
}
