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
    use dvf::presets::{preset, PRESETS};
    use dvf::scenario::Scenario;
    use dvf::sim::run_recorded;
    use std::io::Write;
    use std::path::PathBuf;

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
