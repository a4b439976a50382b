//! Reports byte-identical to the stored ones: the JSON that `dvf simulate` and `dvf sweep`
//! print for these inputs (`tests/data/reports/`, written by the same commands). A change of
//! layout or of internal structure must not change one bit of what the method computes; a
//! change of the method itself shows up here first, and then the data are rewritten on
//! purpose, with the reason in the commit.
//!
//! To rewrite one: `cargo run --release -- simulate --preset NAME > tests/data/reports/NAME.json`
//! (the sweeps: the arguments in [`SWEEPS`]).

// The reports come from the binary, which exists with the `cli` feature only.
#![cfg(feature = "cli")]

use std::path::PathBuf;
use std::process::Command;

/// Every preset of the paper's examples and crowds of several sizes (each side of the grid's
/// "few robots" threshold, with and without pairs in reach).
const PRESETS: &[&str] = &[
    "example4-obstacle-formation",
    "table1-free-space",
    "table2-obstacles",
    "example3-line-swap",
    "example3-circle-swap",
    "formation-gap-grid",
    "crowd-1",
    "crowd-2",
    "crowd-7",
    "crowd-33",
    "crowd-100",
    "crowd-300",
];

/// Random scenes with obstacles, with the barrier and without, with both avoidance modes:
/// `(file stem, arguments of dvf sweep)`.
const SWEEPS: &[(&str, &[&str])] = &[
    ("sweep-seed7-count40", &["--count", "40", "--seed", "7"]),
    (
        "sweep-seed3-count20-paper-nobarrier",
        &[
            "--count",
            "20",
            "--seed",
            "3",
            "--barrier-rate",
            "none",
            "--avoidance",
            "paper",
        ],
    ),
];

fn stored(stem: &str) -> String {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/reports")
        .join(format!("{stem}.json"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn dvf(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_dvf"))
        .args(args)
        .output()
        .expect("dvf runs");
    assert!(
        out.status.success(),
        "dvf {args:?} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("UTF-8 output")
}

/// The first byte where two texts differ, with some context, for the failure message.
fn first_difference(a: &str, b: &str) -> String {
    let at = a
        .bytes()
        .zip(b.bytes())
        .position(|(x, y)| x != y)
        .unwrap_or(a.len().min(b.len()));
    let lo = at.saturating_sub(60);
    let window = |s: &str| s.get(lo..(at + 60).min(s.len())).unwrap_or("").to_owned();
    format!(
        "first difference at byte {at}:\n  now:    …{}…\n  stored: …{}…",
        window(a),
        window(b)
    )
}

#[test]
fn preset_reports_are_byte_identical_to_the_stored_ones() {
    for name in PRESETS {
        let now = dvf(&["simulate", "--preset", name]);
        let was = stored(name);
        assert!(now == was, "{name}: {}", first_difference(&now, &was));
    }
}

#[test]
fn sweep_summaries_are_byte_identical_to_the_stored_ones() {
    for (stem, args) in SWEEPS {
        let mut all = vec!["sweep"];
        all.extend_from_slice(args);
        let now = dvf(&all);
        let was = stored(stem);
        assert!(now == was, "{stem}: {}", first_difference(&now, &was));
    }
}
