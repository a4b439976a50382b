//! `dvf`: simulate scenarios, sample fields, run sweeps, compare planners, time crowds and list
//! presets from the command line.
//!
//! Output is JSON on stdout. Invalid input exits with code 2 and one line on stderr that names
//! the offending field; the program never panics on input.
//!
//! One module per subcommand ([`simulate`], [`field`], [`sweep`], [`bench`], [`presets`],
//! [`compare`] with `dvf planners`), each with one `run` that writes its output; [`args`]
//! declares the command line.

#[cfg(target_arch = "wasm32")]
fn main() {}

#[cfg(not(target_arch = "wasm32"))]
mod args;
#[cfg(not(target_arch = "wasm32"))]
mod bench;
#[cfg(not(target_arch = "wasm32"))]
mod compare;
#[cfg(not(target_arch = "wasm32"))]
mod field;
#[cfg(not(target_arch = "wasm32"))]
mod presets;
#[cfg(not(target_arch = "wasm32"))]
mod progress;
#[cfg(not(target_arch = "wasm32"))]
mod simulate;
#[cfg(not(target_arch = "wasm32"))]
mod sweep;

#[cfg(not(target_arch = "wasm32"))]
fn main() {
    std::process::exit(exit_code());
}

/// Parses the command line and runs its subcommand: 0 on success, 2 on invalid input (with one
/// line on stderr).
#[cfg(not(target_arch = "wasm32"))]
fn exit_code() -> i32 {
    use clap::Parser;
    let cli = match args::Cli::try_parse() {
        Ok(c) => c,
        Err(e) => return refused(&e),
    };
    match run(cli.command) {
        Ok(()) => 0,
        Err(msg) => {
            eprintln!("{}", msg.replace('\n', " "));
            2
        }
    }
}

/// What a command line that clap did not accept exits with: help and version print as clap
/// writes them; an error prints as one line, without the usage block.
#[cfg(not(target_arch = "wasm32"))]
fn refused(e: &clap::Error) -> i32 {
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
    // One line: clap's message ("error: …" and, for missing arguments, their names on the
    // following lines), without the usage block.
    let text = e.render().to_string();
    let message: Vec<&str> = text
        .lines()
        .map(str::trim)
        .take_while(|l| !l.starts_with("Usage:") && !l.starts_with("For more information"))
        .filter(|l| !l.is_empty())
        .collect();
    let line = message.join(" ");
    eprintln!("{}", line.trim_start_matches("error: "));
    2
}

/// Runs one subcommand, its output on stdout; an error is the message for stderr.
#[cfg(not(target_arch = "wasm32"))]
fn run(command: args::Command) -> Result<(), String> {
    use args::{Command, SweepAction};
    let mut out = std::io::stdout().lock();
    match command {
        Command::Simulate(a) => simulate::run(&mut out, &a),
        Command::Field(a) => field::run(&mut out, &a),
        Command::Sweep {
            action: Some(SweepAction::Merge { files }),
            ..
        } => sweep::merge(&mut out, &files),
        Command::Sweep { action: None, args } => sweep::run(&mut out, *args),
        Command::Bench(a) => bench::run(&mut out, &a),
        Command::Presets(a) => presets::run(&mut out, &a),
        Command::Compare(a) => compare::run(&mut out, &a),
        Command::Planners(a) => compare::list(&mut out, a.json),
    }
}

/// `value` as one JSON line on `out`.
#[cfg(not(target_arch = "wasm32"))]
fn write_json(out: &mut impl std::io::Write, value: &impl serde::Serialize) -> Result<(), String> {
    let json = serde_json::to_string(value).map_err(|e| e.to_string())?;
    writeln!(out, "{json}").map_err(|e| e.to_string())
}
