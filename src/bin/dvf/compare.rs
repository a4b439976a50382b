//! `dvf compare`: a scenario run with each of several planners, one row of metrics per planner
//! (or the comparison as JSON); `dvf planners` (and `dvf compare --list`): the planners.

use crate::args::{CompareArgs, Source};
use dvf::compare::{all_planners, compare, table::run_rows};
use dvf::params::PARAMETERS;
use dvf::planner::{Spec, PLANNERS};
use dvf::scenario::Scenario;
use dvf::sweep::value_of;
use serde_json::Value;
use std::io::Write;

/// Runs the comparison `args` ask for and writes its table, or its JSON as one line.
pub fn run(out: &mut impl Write, args: &CompareArgs) -> Result<(), String> {
    if args.list {
        return list(out, false);
    }
    let source = Source {
        file: args.file.clone(),
        preset: args.preset.clone(),
    };
    let s = with_set(source.load()?, &args.set)?;
    let planners: Vec<Spec> = if args.planners.is_empty() {
        all_planners()
    } else {
        args.planners
            .iter()
            .map(|name| Spec::named(name.trim()))
            .collect()
    };
    let comparison = compare(&s, &planners).map_err(|e| e.to_string())?;
    if args.json {
        return crate::write_json(out, &comparison);
    }
    let c = &comparison.conditions;
    let limit = |v: Option<f64>| v.map_or_else(|| "none".to_owned(), |v| v.to_string());
    writeln!(
        out,
        "{}: {} robots, {} obstacles, {} s in steps of {} s, v_max {}, ω_max {}, safety barrier {}\n",
        comparison.scenario,
        c.robots,
        c.obstacles,
        c.duration,
        c.dt,
        limit(c.v_max),
        limit(c.omega_max),
        if c.barrier { "on" } else { "off" },
    )
    .map_err(|e| e.to_string())?;
    write!(out, "{}", run_rows(None, &comparison, true)).map_err(|e| e.to_string())
}

/// `s` with each `NAME=VALUE` of `set`: a parameter of the table (`params.NAME`), `dt` or
/// `duration`, checked as the scenario file is.
fn with_set(s: Scenario, set: &[String]) -> Result<Scenario, String> {
    if set.is_empty() {
        return Ok(s);
    }
    let mut doc: Value = serde_json::from_str(&s.to_json()).map_err(|e| e.to_string())?;
    for text in set {
        let Some((name, value)) = text.split_once('=') else {
            return Err(format!("set: expected NAME=VALUE, not {text:?}"));
        };
        let name = name.trim();
        let value = value_of(value);
        if PARAMETERS.iter().any(|p| p.name == name) {
            if doc.get("params").is_none_or(|p| !p.is_object()) {
                doc["params"] = Value::Object(serde_json::Map::new());
            }
            doc["params"][name] = value;
        } else if name == "dt" || name == "duration" {
            doc[name] = value;
        } else {
            let names: Vec<&str> = PARAMETERS
                .iter()
                .map(|p| p.name)
                .chain(["dt", "duration"])
                .collect();
            return Err(format!(
                "set: {name} is not a parameter of a scenario; expected one of {}",
                names.join(", ")
            ));
        }
    }
    Scenario::from_json(&doc.to_string()).map_err(|e| e.to_string())
}

/// Writes the planners: one line each (name, title, what it avoids, source), or `--json`'s
/// array of `{name, title, source, avoids}`.
pub fn list(out: &mut impl Write, json: bool) -> Result<(), String> {
    if json {
        let list: Vec<Value> = PLANNERS
            .iter()
            .map(|e| {
                serde_json::json!({
                    "name": e.name, "title": e.title, "source": e.source, "avoids": e.avoids,
                })
            })
            .collect();
        return crate::write_json(out, &list);
    }
    for e in PLANNERS {
        writeln!(
            out,
            "{:<12} {}; avoids {}. Source: {}",
            e.name, e.title, e.avoids, e.source
        )
        .map_err(|e| e.to_string())?;
    }
    Ok(())
}
