//! `dvf`: simulate scenarios, sample fields and list presets from the command line.
//!
//! Output is JSON on stdout. Invalid input exits with code 2 and one line on stderr that names
//! the offending field; the program never panics on input.

#[cfg(target_arch = "wasm32")]
fn main() {}

#[cfg(not(target_arch = "wasm32"))]
fn main() {
    std::process::exit(cli::main());
}

#[cfg(not(target_arch = "wasm32"))]
mod cli {
    use clap::{Args, Parser, Subcommand};
    use dvf::field::sample_grid;
    use dvf::params::Avoidance;
    use dvf::presets::{preset, PRESETS};
    use dvf::scenario::Scenario;
    use dvf::sim::{run_recorded, Neighbourhood, Simulation};
    use dvf::sweep::{sweep, Family, Outcome, Recipe, Summary};
    use std::io::Write;
    use std::path::PathBuf;

    /// What `dvf sweep` can do besides running scenarios.
    #[derive(Subcommand)]
    enum SweepAction {
        /// Combine the JSON lines of `dvf sweep --shard` runs (files, or standard input when
        /// none is given) into the summary one unsharded sweep of the same scenarios prints.
        Merge {
            /// Files of JSON lines, in any order.
            files: Vec<PathBuf>,
        },
    }

    /// Largest `--grid` accepted: 1000 × 1000 samples.
    const MAX_GRID: usize = 1000;

    #[derive(Parser)]
    #[command(
        name = "dvf",
        version,
        about = "Dynamic vector field motion planning for nonholonomic robots (He & Li)"
    )]
    struct Cli {
        #[command(subcommand)]
        command: Command,
    }

    #[derive(Subcommand)]
    enum Command {
        /// Run a scenario and print a JSON report.
        Simulate {
            #[command(flatten)]
            source: Source,
            /// Also write the trajectories as CSV (t,robot,x,y,theta,v,omega).
            #[arg(long, value_name = "PATH")]
            csv: Option<PathBuf>,
        },
        /// Sample robot I's obstacle-free goal field at its start attitude on an N×N grid.
        Field {
            #[command(flatten)]
            source: Source,
            /// Robot index (0-based).
            #[arg(long, default_value_t = 0)]
            robot: usize,
            /// Grid size N (2 … 1000).
            #[arg(long, default_value_t = 21)]
            grid: usize,
        },
        /// Run COUNT random scenarios from SEED and print the success rate, the violations and
        /// the distribution of convergence times (JSON). With `--shard K/N`, run only every
        /// N-th scenario from the K-th and print one JSON line per scenario instead; `dvf sweep
        /// merge` combines the shards' lines into the summary of the whole sweep.
        #[command(args_conflicts_with_subcommands = true)]
        Sweep {
            #[command(subcommand)]
            action: Option<SweepAction>,
            /// Run only scenarios K, K + N, K + 2N, … (counted from 1) of the COUNT and print
            /// one JSON line per scenario (seed, recipe, outcome), for `dvf sweep merge`.
            #[arg(long, value_name = "K/N", value_parser = parse_shard)]
            shard: Option<(usize, usize)>,
            /// Scenario k uses seed SEED + k, so any failure is rerun with `--seed S --count 1`.
            #[arg(long, default_value_t = 0)]
            seed: u64,
            /// Number of scenarios (1 … 1000000).
            #[arg(long, default_value_t = 100)]
            count: usize,
            /// The kind of scene: random (the default), dense (24 to 64 robots, 0 to 8
            /// obstacles) or formation (a column of robots through a row of obstacles into a
            /// grid, a line or a ring of goal slots).
            #[arg(long, value_name = "FAMILY", default_value = "random", value_parser = ["random", "dense", "formation"])]
            family: String,
            /// Robots per scenario, drawn from MIN..=MAX (the family's range by default:
            /// random 4..=16, dense 24..=64, formation 9..=25).
            #[arg(long, value_name = "MIN..=MAX", value_parser = parse_range)]
            robots: Option<(usize, usize)>,
            /// Obstacles per scenario, drawn from MIN..=MAX (random 0..=5, dense 0..=8,
            /// formation 0..=3).
            #[arg(long, value_name = "MIN..=MAX", value_parser = parse_range)]
            obstacles: Option<(usize, usize)>,
            /// Formation family: the distance between neighbouring goal slots in units of
            /// safe_radius, drawn from MIN..=MAX (at least 2; 3..=6 by default).
            #[arg(long, value_name = "MIN..=MAX", value_parser = parse_spacing)]
            spacing: Option<(f64, f64)>,
            /// Robot avoidance: exit (the default) or paper.
            #[arg(long, value_name = "MODE", default_value = "exit", value_parser = ["exit", "paper"])]
            avoidance: String,
            /// The safety barrier's rate α (1/s), or `none` to run without the barrier.
            #[arg(
                long,
                value_name = "RATE|none",
                default_value = "5",
                allow_hyphen_values = true
            )]
            barrier_rate: String,
            /// Write every failing scenario as DIR/seed-S.json.
            #[arg(long, value_name = "DIR")]
            write: Option<PathBuf>,
        },
        /// Time the simulation of a crowd (N robots swapping across a circle at constant
        /// density, M obstacles on the way) and print
        /// `{"robots": N, "steps": S, "obstacles": M, "ms_per_step": x}`.
        Bench {
            /// Robots N (1 … 10000).
            #[arg(long, default_value_t = 1000)]
            robots: usize,
            /// Steps S timed (1 … 1000000), after the simulation is set up.
            #[arg(long, default_value_t = 100)]
            steps: usize,
            /// Obstacles M on the circle of half the crowd's radius.
            #[arg(long, default_value_t = 0)]
            obstacles: usize,
            /// Find neighbours by comparing all pairs (the O(N²) reference) instead of a grid.
            #[arg(long)]
            all_pairs: bool,
        },
        /// List the presets, or print one as a scenario file with `--preset NAME`.
        Presets {
            /// Print this preset's scenario JSON (a starting point for a file of your own).
            #[arg(long, value_name = "NAME")]
            preset: Option<String>,
        },
    }

    #[derive(Args)]
    struct Source {
        /// A scenario file (JSON).
        #[arg(
            value_name = "FILE",
            required_unless_present = "preset",
            conflicts_with = "preset"
        )]
        file: Option<PathBuf>,
        /// A built-in preset (see `dvf presets`).
        #[arg(long, value_name = "NAME")]
        preset: Option<String>,
    }

    /// Largest `--steps` of `dvf bench`.
    const MAX_BENCH_STEPS: usize = 1_000_000;
    /// Largest `--count` of `dvf sweep`.
    const MAX_SWEEP: usize = 1_000_000;
    /// Largest robot count of `dvf sweep` (the scenario limit).
    const MAX_SWEEP_ROBOTS: usize = dvf::scenario::MAX_ROBOTS;

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

    /// The summary of the outcomes in `files` (standard input when there are none), checked to
    /// cover one recipe's seeds from the smallest, each once.
    fn merge(files: &[PathBuf]) -> Result<Summary, String> {
        let mut texts = Vec::new();
        if files.is_empty() {
            let mut text = String::new();
            std::io::Read::read_to_string(&mut std::io::stdin(), &mut text)
                .map_err(|e| format!("standard input: {e}"))?;
            texts.push(("standard input".to_owned(), text));
        }
        for f in files {
            let text = std::fs::read_to_string(f)
                .map_err(|e| format!("{}: cannot read: {e}", f.display()))?;
            texts.push((f.display().to_string(), text));
        }
        let mut outcomes: Vec<Outcome> = Vec::new();
        for (name, text) in &texts {
            for (k, line) in text.lines().enumerate() {
                if line.trim().is_empty() {
                    continue;
                }
                let o: Outcome = serde_json::from_str(line).map_err(|e| {
                    format!("{name}:{}: not a line of dvf sweep --shard: {e}", k + 1)
                })?;
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

    impl Source {
        fn load(&self) -> Result<Scenario, String> {
            match (&self.file, &self.preset) {
                (_, Some(name)) => preset(name).map_err(|e| e.to_string()),
                (Some(path), None) => {
                    let text = std::fs::read_to_string(path)
                        .map_err(|e| format!("{}: cannot read: {e}", path.display()))?;
                    Scenario::from_json(&text).map_err(|e| format!("{}: {e}", path.display()))
                }
                (None, None) => Err("give a scenario FILE or --preset NAME".into()),
            }
        }
    }

    pub fn main() -> i32 {
        let cli = match Cli::try_parse() {
            Ok(c) => c,
            Err(e) => {
                use clap::error::ErrorKind;
                if matches!(
                    e.kind(),
                    ErrorKind::DisplayHelp
                        | ErrorKind::DisplayVersion
                        | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand
                ) {
                    let _ = e.print();
                    return if e.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand {
                        2
                    } else {
                        0
                    };
                }
                // One line: clap's message ("error: …" and, for missing arguments, their
                // names on the following lines), without the usage block.
                let text = e.render().to_string();
                let message: Vec<&str> = text
                    .lines()
                    .map(str::trim)
                    .take_while(|l| {
                        !l.starts_with("Usage:") && !l.starts_with("For more information")
                    })
                    .filter(|l| !l.is_empty())
                    .collect();
                let line = message.join(" ");
                eprintln!("{}", line.trim_start_matches("error: "));
                return 2;
            }
        };
        match run(cli.command) {
            Ok(()) => 0,
            Err(msg) => {
                eprintln!("{}", msg.replace('\n', " "));
                2
            }
        }
    }

    fn run(cmd: Command) -> Result<(), String> {
        let mut out = std::io::stdout().lock();
        match cmd {
            Command::Presets { preset: Some(name) } => {
                let s = preset(&name).map_err(|e| e.to_string())?;
                writeln!(out, "{}", s.to_json()).map_err(|e| e.to_string())?;
            }
            Command::Presets { preset: None } => {
                for p in PRESETS {
                    writeln!(out, "{:<30} {}", p.name, p.summary).map_err(|e| e.to_string())?;
                }
            }
            Command::Sweep {
                action: Some(SweepAction::Merge { files }),
                ..
            } => {
                let summary = merge(&files)?;
                let json = serde_json::to_string(&summary).map_err(|e| e.to_string())?;
                writeln!(out, "{json}").map_err(|e| e.to_string())?;
            }
            Command::Sweep {
                action: None,
                shard,
                seed,
                count,
                family,
                robots,
                obstacles,
                spacing,
                avoidance,
                barrier_rate,
                write,
            } => {
                let family = match family.as_str() {
                    "dense" => Family::Dense,
                    "formation" => Family::Formation,
                    _ => Family::Random,
                };
                let mut recipe = Recipe::of(family);
                let robots = robots.unwrap_or((*recipe.robots.start(), *recipe.robots.end()));
                let obstacles =
                    obstacles.unwrap_or((*recipe.obstacles.start(), *recipe.obstacles.end()));
                if let Some((a, b)) = spacing {
                    if family != Family::Formation {
                        return Err("spacing: only the formation family has goal slots".into());
                    }
                    recipe.spacing = a..=b;
                }
                if !(1..=MAX_SWEEP).contains(&count) {
                    return Err(format!(
                        "count: must be between 1 and {MAX_SWEEP}, not {count}"
                    ));
                }
                if robots.1 > MAX_SWEEP_ROBOTS || robots.0 == 0 {
                    return Err(format!(
                        "robots: must be between 1 and {MAX_SWEEP_ROBOTS}, not {}..={}",
                        robots.0, robots.1
                    ));
                }
                if obstacles.1 > dvf::scenario::MAX_OBSTACLES {
                    return Err(format!(
                        "obstacles: at most {}, not {}",
                        dvf::scenario::MAX_OBSTACLES,
                        obstacles.1
                    ));
                }
                recipe.robots = robots.0..=robots.1;
                recipe.obstacles = obstacles.0..=obstacles.1;
                recipe.params.avoidance = if avoidance == "paper" {
                    Avoidance::Paper
                } else {
                    Avoidance::Exit
                };
                recipe.params.barrier_rate = parse_rate(&barrier_rate)?;
                // The parameters are the same for every scenario: check them once.
                if let Some(first) = dvf::sweep::scenario(&recipe, seed) {
                    first.validate().map_err(|e| e.to_string())?;
                }
                if let Some(dir) = &write {
                    std::fs::create_dir_all(dir)
                        .map_err(|e| format!("{}: cannot create: {e}", dir.display()))?;
                }
                // Scenarios run on every core: the first write error is kept for the end.
                let write_error = std::sync::Mutex::new(None);
                let write_failure = |s: u64, scenario: &Scenario, report: &dvf::Report| {
                    let failed = report.violations > 0
                        || report.robots.iter().any(|r| r.converged_at.is_none());
                    if let (true, Some(dir)) = (failed, &write) {
                        let path = dir.join(format!("seed-{s}.json"));
                        if let Err(e) = std::fs::write(&path, scenario.to_json()) {
                            let mut first = write_error.lock().unwrap_or_else(|p| p.into_inner());
                            first.get_or_insert(format!("{}: cannot write: {e}", path.display()));
                        }
                    }
                };
                if let Some((k, n)) = shard {
                    // Every N-th scenario from the K-th, one line each as it finishes: a shard
                    // cut short leaves whole lines, and merge names the missing seeds.
                    for index in (k - 1..count).step_by(n) {
                        let s = seed.wrapping_add(index as u64);
                        let outcome = Outcome::run(&recipe, s, |scenario, report| {
                            write_failure(s, scenario, report);
                        });
                        let json = serde_json::to_string(&outcome).map_err(|e| e.to_string())?;
                        writeln!(out, "{json}").map_err(|e| e.to_string())?;
                    }
                } else {
                    let summary = sweep(&recipe, seed, count, write_failure);
                    let json = serde_json::to_string(&summary).map_err(|e| e.to_string())?;
                    writeln!(out, "{json}").map_err(|e| e.to_string())?;
                }
                if let Some(e) = write_error.into_inner().unwrap_or_else(|p| p.into_inner()) {
                    return Err(e);
                }
            }
            Command::Bench {
                robots,
                steps,
                obstacles,
                all_pairs,
            } => {
                if !(1..=dvf::scenario::MAX_ROBOTS).contains(&robots) {
                    return Err(format!(
                        "robots: must be between 1 and {}, not {robots}",
                        dvf::scenario::MAX_ROBOTS
                    ));
                }
                if !(1..=MAX_BENCH_STEPS).contains(&steps) {
                    return Err(format!(
                        "steps: must be between 1 and {MAX_BENCH_STEPS}, not {steps}"
                    ));
                }
                if obstacles > dvf::scenario::MAX_OBSTACLES {
                    return Err(format!(
                        "obstacles: at most {}, not {obstacles}",
                        dvf::scenario::MAX_OBSTACLES
                    ));
                }
                let s = dvf::presets::crowd_with_obstacles(robots, obstacles);
                let way = if all_pairs {
                    Neighbourhood::AllPairs
                } else {
                    Neighbourhood::Grid
                };
                let mut sim = Simulation::with_neighbourhood(&s, way);
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
                .map_err(|e| e.to_string())?;
            }
            Command::Simulate { source, csv } => {
                let s = source.load()?;
                let report = match csv {
                    Some(path) => {
                        let (report, traj) = run_recorded(&s, 1);
                        write_csv(&path, &traj)
                            .map_err(|e| format!("{}: cannot write: {e}", path.display()))?;
                        report
                    }
                    None => dvf::run(&s),
                };
                let json = serde_json::to_string(&report).map_err(|e| e.to_string())?;
                writeln!(out, "{json}").map_err(|e| e.to_string())?;
            }
            Command::Field {
                source,
                robot,
                grid,
            } => {
                let s = source.load()?;
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
                let json = serde_json::json!({ "theta": theta, "points": points });
                writeln!(out, "{json}").map_err(|e| e.to_string())?;
            }
        }
        Ok(())
    }

    fn write_csv(path: &std::path::Path, traj: &[Vec<dvf::sim::Sample>]) -> std::io::Result<()> {
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
}
