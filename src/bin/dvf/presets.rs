//! `dvf presets`: list the built-in scenarios, or print one as a scenario file.

use crate::args::PresetsArgs;
use dvf::presets::{preset, PRESETS};
use std::io::Write;

/// Writes the named preset's scenario JSON, or one line per preset (its name and summary).
pub fn run(out: &mut impl Write, args: &PresetsArgs) -> Result<(), String> {
    match &args.preset {
        Some(name) => {
            let s = preset(name).map_err(|e| e.to_string())?;
            writeln!(out, "{}", s.to_json()).map_err(|e| e.to_string())
        }
        None => {
            for p in PRESETS {
                writeln!(out, "{:<30} {}", p.name, p.summary).map_err(|e| e.to_string())?;
            }
            Ok(())
        }
    }
}
