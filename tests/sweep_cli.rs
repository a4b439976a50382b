//! Sweeps that cannot mislead, tested on the built `dvf` binary: the merge refuses a set of
//! shard lines that is not one whole sweep, a sweep in which nothing ran fails, `--set` and
//! `--grid` reach every scenario with the scenario file's checks, the shard lines carry what a
//! notebook groups and plots by, and the documented GNU parallel recipe reruns failed jobs.
// The binary exists natively and with the `cli` feature only.
#![cfg(all(not(target_arch = "wasm32"), feature = "cli"))]

mod common;

use common::{dvf, ok, on_a_terminal, stderr, stdout};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// `dvf args`, which must fail with exit code 2 and one line on stderr containing every one of
/// `needles`: that line.
fn refused(args: &[&str], needles: &[&str]) -> String {
    let o = dvf(args);
    assert_eq!(o.status.code(), Some(2), "dvf {args:?}: {}", stderr(&o));
    let err = stderr(&o);
    assert_eq!(err.trim_end().lines().count(), 1, "dvf {args:?}: {err}");
    assert!(!err.contains("panicked"), "dvf {args:?}: {err}");
    for n in needles {
        assert!(err.contains(n), "dvf {args:?}: {err:?} lacks {n:?}");
    }
    err
}

/// An empty folder of this test binary's scratch space.
fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("sweep-cli")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("a scratch folder");
    dir
}

/// Writes `lines` to `dir/name`, returning the path as an argument.
fn file(dir: &Path, name: &str, lines: &[&str]) -> String {
    let path = dir.join(name);
    let mut text = lines.join("\n");
    text.push('\n');
    std::fs::write(&path, text).expect("write the lines");
    path.display().to_string()
}

/// The merge refuses a set that lost its first or its last seed, has a gap or a seed twice,
/// or mixes in lines of another sweep of neighbouring seeds, naming the seed and the shard to
/// rerun; lines without the sweep they belong to are refused with how to rerun them.
#[test]
fn merge_refuses_a_set_that_is_not_one_whole_sweep() {
    let dir = scratch("whole");
    let recipe = ["--seed", "0", "--count", "8", "--robots", "3..=4"];
    let shard = |k: &str| ok(&[&["sweep"][..], &recipe, &["--shard", k]].concat());
    let (one, two) = (shard("1/2"), shard("2/2"));
    let one: Vec<&str> = one.lines().collect();
    let two: Vec<&str> = two.lines().collect();
    assert_eq!((one.len(), two.len()), (4, 4));
    let whole = ok(&[&["sweep"][..], &recipe].concat());
    let (a, b) = (file(&dir, "1.jsonl", &one), file(&dir, "2.jsonl", &two));
    assert_eq!(ok(&["sweep", "merge", &b, &a]), whole);

    // Seed 0 (the first line of shard 1) and seed 7 (the last of shard 2) dropped.
    let no_first = file(&dir, "no-first.jsonl", &one[1..]);
    refused(
        &["sweep", "merge", &no_first, &b],
        &["seed 0 is missing", "shard 1/2"],
    );
    let no_last = file(&dir, "no-last.jsonl", &two[..3]);
    refused(
        &["sweep", "merge", &a, &no_last],
        &["seed 7 is missing", "shard 2/2"],
    );
    let gap = file(&dir, "gap.jsonl", &[one[0], one[2], one[3]]);
    refused(&["sweep", "merge", &gap, &b], &["seed 2 is missing"]);
    let twice = file(&dir, "twice.jsonl", &[one[1]]);
    refused(
        &["sweep", "merge", &a, &b, &twice],
        &["seed 2 appears twice"],
    );
    // Five lines of another sweep's neighbouring seeds (8 … 12): another first seed and count.
    let next = ok(&[
        "sweep", "--seed", "8", "--count", "5", "--robots", "3..=4", "--shard", "1/1",
    ]);
    let next = file(&dir, "next.jsonl", &next.lines().collect::<Vec<_>>());
    refused(
        &["sweep", "merge", &a, &b, &next],
        &["next.jsonl:1", "another sweep"],
    );
    // The same seeds with another count are another sweep too.
    let longer = ok(&[
        "sweep", "--seed", "0", "--count", "9", "--robots", "3..=4", "--shard", "2/2",
    ]);
    let longer = file(&dir, "longer.jsonl", &longer.lines().collect::<Vec<_>>());
    refused(&["sweep", "merge", &a, &longer], &["another sweep"]);
    // A line as shards wrote it before they named their sweep (tests/cli.rs wrote these).
    let old = r#"{"seed":0,"recipe":{"family":"random","robots":[3,4],"obstacles":[0,5],"avoidance":"exit","barrier_rate":5.0},"skipped":false,"robots":3,"converged_steps":[735,880,721],"violations":0,"smoothness":{"reversals":2,"steps":36000,"settled_reversals":0,"settled_steps":33705,"chattering":0,"max_omega_step":8.826,"settled_max_omega_step":0.0}}"#;
    let old = file(&dir, "old.jsonl", &[old]);
    refused(
        &["sweep", "merge", &old],
        &["old.jsonl:1", "rerun every shard"],
    );
    // A summary is not a shard's line.
    let summary = file(&dir, "summary.json", &[whole.trim_end()]);
    refused(
        &["sweep", "merge", &summary],
        &["summary.json:1", "summary"],
    );
}

/// A sweep in which every scenario was skipped fails and says why; its summary's success
/// rate is null, not 1. So does the merge of its shards.
#[test]
fn a_sweep_that_ran_nothing_fails() {
    let args = ["sweep", "--robots", "1000", "--count", "2"];
    let o = dvf(&args);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("no scenario ran"), "{}", stderr(&o));
    assert!(stderr(&o).contains("--robots"), "{}", stderr(&o));
    let v: Value = serde_json::from_str(&stdout(&o)).expect("the summary is still printed");
    assert_eq!(
        (v["scenarios"].as_u64(), v["skipped"].as_u64()),
        (Some(0), Some(2))
    );
    assert!(v["success_rate"].is_null(), "{v}");

    let dir = scratch("nothing");
    let lines = ok(&[&args[..], &["--shard", "1/1"]].concat());
    let path = file(&dir, "all.jsonl", &lines.lines().collect::<Vec<_>>());
    let o = dvf(&["sweep", "merge", &path]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("no scenario ran"), "{}", stderr(&o));
    // One grid point where nothing fits fails the sweep and is named.
    refused(
        &[
            "sweep",
            "--robots",
            "16",
            "--count",
            "1",
            "--grid",
            "side=8,100",
        ],
        &["no scenario ran at side=8"],
    );
}

/// `--set NAME=VALUE` reaches every scenario: the parameters of the table, dt, duration and
/// the area; out-of-range values and unknown names are refused with the scenario file
/// reader's messages.
#[test]
fn set_changes_every_scenario_and_is_checked_as_a_file_is() {
    let base = ["sweep", "--seed", "4", "--count", "2", "--robots", "3..=5"];
    let plain = ok(&base);
    // The default gain set explicitly is the same sweep; another gain is another sweep.
    assert_eq!(ok(&[&base[..], &["--set", "k_a=10"]].concat()), plain);
    assert_ne!(ok(&[&base[..], &["--set", "k_a=5"]].concat()), plain);
    assert_ne!(ok(&[&base[..], &["--set", "v_max=1.5"]].concat()), plain);
    // dt and duration: each line's dt, and its robots' steps sum to robots × duration / dt.
    let lines = ok(&[
        &base[..],
        &[
            "--set",
            "dt=0.005",
            "--set",
            "duration=20",
            "--shard",
            "1/1",
        ],
    ]
    .concat());
    for line in lines.lines() {
        let v: Value = serde_json::from_str(line).unwrap();
        assert_eq!(v["dt"].as_f64(), Some(0.005), "{line}");
        let robots = v["robots"].as_array().unwrap().len() as u64;
        assert_eq!(
            v["smoothness"]["steps"].as_u64(),
            Some(robots * 4000),
            "{line}"
        );
        assert_eq!(v["recipe"]["set"]["dt"].as_f64(), Some(0.005), "{line}");
    }
    // The area: 16 robots 3 safe radii apart do not fit in a 5 × 5 square.
    refused(
        &["sweep", "--count", "1", "--robots", "16", "--set", "side=5"],
        &["no scenario ran"],
    );

    // The same message as the scenario file reader's, without the file's name.
    let dir = scratch("set");
    for (name, value, json) in [
        ("k_a", "-1", r#""params": {"k_a": -1}"#),
        ("sense_radius", "0", r#""params": {"sense_radius": 0}"#),
        ("avoidance", "orbit", r#""params": {"avoidance": "orbit"}"#),
        ("v_max", "fast", r#""params": {"v_max": "fast"}"#),
        ("dt", "0.5", r#""dt": 0.5"#),
        ("duration", "7200", r#""duration": 7200"#),
    ] {
        let scene = dir.join(format!("{name}.json"));
        let text = format!(r#"{{{json}, "robots": [{{"start": [0, 0, 0], "goal": [5, 5, 0]}}]}}"#);
        std::fs::write(&scene, text).unwrap();
        let path = scene.display().to_string();
        let from_file = refused(&["simulate", &path], &[name]);
        let from_file = from_file.strip_prefix(&format!("{path}: ")).unwrap();
        let set = format!("{name}={value}");
        assert_eq!(refused(&["sweep", "--set", &set], &[]), from_file, "{set}");
        let grid = format!("{name}={value}");
        assert_eq!(
            refused(&["sweep", "--grid", &grid], &[]),
            from_file,
            "{grid}"
        );
    }
    refused(
        &["sweep", "--set", "kv=1"],
        &["kv", "`k_v`", "`dt`", "`side`"],
    );
    refused(&["sweep", "--set", "k_a"], &["NAME=VALUE"]);
    refused(
        &["sweep", "--set", "k_a=5", "--set", "k_a=6"],
        &["k_a", "twice"],
    );
    refused(
        &["sweep", "--set", "k_a=5", "--grid", "k_a=5,6"],
        &["k_a", "given by both set and grid"],
    );
    refused(
        &["sweep", "--family", "formation", "--set", "side=50"],
        &["side", "formation"],
    );
}

/// `--grid` runs the sweep at every point of the product of its axes (lists and ranges), one
/// group each with its values; the group at the default value is the plain sweep, and the
/// shards of a grid sweep record their values and merge to the same bytes.
#[test]
fn a_grid_sweep_has_one_group_per_point_and_shards_merge_to_it() {
    let base = ["sweep", "--seed", "2", "--count", "3", "--robots", "3..=4"];
    let grid = ["--grid", "k_a=5:15:5", "--grid", "avoidance=exit,paper"];
    let whole = ok(&[&base[..], &grid].concat());
    let v: Value = serde_json::from_str(&whole).unwrap();
    let groups = v["groups"].as_array().expect("groups");
    assert_eq!(groups.len(), 6);
    let values: Vec<String> = groups.iter().map(|g| g["values"].to_string()).collect();
    assert_eq!(values[0], r#"{"avoidance":"exit","k_a":5.0}"#);
    assert_eq!(values[1], r#"{"avoidance":"paper","k_a":5.0}"#);
    assert_eq!(values[4], r#"{"avoidance":"exit","k_a":15.0}"#);
    // k_a = 10 with exit avoidance is the default recipe: its group is the plain summary.
    let mut plain: Value = serde_json::from_str(&ok(&base)).unwrap();
    let mut group = groups[2].clone();
    group.as_object_mut().unwrap().remove("values");
    plain.as_object_mut().unwrap().sort_keys();
    group.as_object_mut().unwrap().sort_keys();
    assert_eq!(group, plain);
    assert_ne!(groups[0]["convergence_time"], groups[2]["convergence_time"]);

    let dir = scratch("grid");
    let mut files = Vec::new();
    for k in 1..=4 {
        let shard = format!("{k}/4");
        let lines = ok(&[&base[..], &grid, &["--shard", &shard]].concat());
        for line in lines.lines() {
            let l: Value = serde_json::from_str(line).unwrap();
            let point = l["sweep"]["point"].as_u64().unwrap_or(0) as usize;
            assert_eq!(l["values"].to_string(), values[point], "{line}");
            assert_eq!(l["sweep"]["points"].as_u64(), Some(6), "{line}");
        }
        let lines: Vec<&str> = lines.lines().collect();
        files.push(file(&dir, &format!("{k}.jsonl"), &lines));
    }
    let merged = ok(&[
        &["sweep", "merge"][..],
        &files.iter().map(String::as_str).collect::<Vec<_>>(),
    ]
    .concat());
    assert_eq!(merged, whole);
    // A missing scenario of a grid sweep is named with its point.
    let first: Vec<String> = std::fs::read_to_string(&files[0])
        .unwrap()
        .lines()
        .skip(1)
        .map(str::to_owned)
        .collect();
    let cut = file(
        &dir,
        "cut.jsonl",
        &first.iter().map(String::as_str).collect::<Vec<_>>(),
    );
    refused(
        &["sweep", "merge", &cut, &files[1], &files[2], &files[3]],
        &["seed 2 at avoidance=exit k_a=5.0 is missing", "shard 1/4"],
    );
    for bad in ["k_a", "k_a=5:1:1", "k_a=1:5:0", "k_a=1:2:3:4"] {
        refused(&["sweep", "--grid", bad], &["grid"]);
    }
    refused(
        &["sweep", "--grid", "k_a=5,6", "--grid", "k_a=7"],
        &["k_a", "twice"],
    );
}

/// A shard line is one compact JSON object with what a notebook groups and plots by: the
/// obstacle count, dt, every robot's index, arrival and arrival time (null if it did not
/// arrive), and the closest pair with its clearance; times print as the multiples of the
/// step they are.
#[test]
fn shard_lines_carry_what_a_notebook_needs() {
    // Seed 42 of the narrowest formations leaves robots short of their slots
    // (tests/cli.rs, a_scenario_written_by_sweep_runs_the_same_under_simulate).
    let lines = ok(&[
        "sweep",
        "--family",
        "formation",
        "--spacing",
        "3..=3.5",
        "--seed",
        "40",
        "--count",
        "3",
        "--shard",
        "1/1",
    ]);
    let mut short = 0;
    for line in lines.lines() {
        assert!(line.len() < 4000, "a compact line: {} bytes", line.len());
        let v: Value = serde_json::from_str(line).unwrap();
        let keys: Vec<&str> = v.as_object().unwrap().keys().map(String::as_str).collect();
        for key in [
            "sweep",
            "seed",
            "recipe",
            "skipped",
            "dt",
            "obstacles",
            "robots",
            "violations",
            "closest",
            "smoothness",
        ] {
            assert!(keys.contains(&key), "{key} in {line}");
        }
        assert_eq!(v["dt"].as_f64(), Some(0.01));
        assert!(v["obstacles"].as_u64().unwrap() <= 3, "{line}");
        let robots = v["robots"].as_array().unwrap();
        assert!((9..=25).contains(&robots.len()), "{line}");
        for (k, r) in robots.iter().enumerate() {
            assert_eq!(r["robot"].as_u64(), Some(k as u64), "{line}");
            let arrived = r["arrived"].as_bool().unwrap();
            assert_eq!(arrived, !r["time"].is_null(), "{line}");
            short += usize::from(!arrived);
            if let Some(t) = r["time"].as_f64() {
                // The time is a multiple of 0.01 s printed with at most two decimals.
                let text = r["time"].to_string();
                let decimals = text.split_once('.').map_or(0, |(_, d)| d.len());
                assert!(decimals <= 2, "{text}");
                assert!(t > 0.0 && t <= 300.0, "{text}");
            }
        }
        let pair = v["closest"]["pair"].as_array().unwrap();
        let (i, j) = (pair[0].as_u64().unwrap(), pair[1].as_u64().unwrap());
        assert!(i < j && (j as usize) < robots.len(), "{line}");
        let clearance = v["closest"]["clearance"].as_f64().unwrap();
        // The barrier keeps every pair apart: a clearance of at least 0 (no violation).
        assert!(
            clearance >= 0.0 || v["violations"].as_u64() > Some(0),
            "{line}"
        );
    }
    assert!(short > 0, "seed 42 leaves robots short: {lines}");
}

/// The GNU parallel recipe of the docs resumes with `--resume-failed`, which reruns a failed
/// job (`--resume` alone skips every job in the log, failed or not).
#[test]
fn the_parallel_recipe_reruns_failed_jobs() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut found = 0;
    for doc in ["README.md", "docs/book/src/command-line.md"] {
        let text = std::fs::read_to_string(root.join(doc)).unwrap();
        for line in text
            .lines()
            .filter(|l| l.trim_start().starts_with("parallel "))
        {
            found += 1;
            let words: Vec<&str> = line.split_whitespace().collect();
            assert!(words.contains(&"--joblog"), "{doc}: {line}");
            assert!(words.contains(&"--resume-failed"), "{doc}: {line}");
            assert!(!words.contains(&"--resume"), "{doc}: {line}");
        }
    }
    assert!(found > 0, "the recipe is in the docs");
}

/// `--write` names a grid point's failing scenario by its seed and values, and the file runs
/// under `dvf simulate` (seed 42 of the narrowest formations fails, as in tests/cli.rs).
#[test]
fn a_grid_sweep_writes_failures_by_seed_and_values() {
    let dir = scratch("write");
    let out = dir.display().to_string();
    let args = [
        "sweep",
        "--family",
        "formation",
        "--spacing",
        "3..=3.5",
        "--seed",
        "42",
        "--count",
        "1",
        "--grid",
        "k_a=10",
        "--write",
        &out,
    ];
    let v: Value = serde_json::from_str(&ok(&args)).unwrap();
    assert_eq!(
        v["groups"][0]["failures"].as_array().map(Vec::len),
        Some(1),
        "{v}"
    );
    let file = dir.join("seed-42-k_a=10.0.json");
    let report: Value = serde_json::from_str(&ok(&["simulate", file.to_str().unwrap()])).unwrap();
    let arrived = report["robots"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|r| !r["converged_at"].is_null())
        .count();
    assert_eq!(Some(arrived as u64), v["groups"][0]["converged"].as_u64());
}

/// A sweep on a terminal shows how many of its scenarios have run, on standard error; on a
/// pipe it writes nothing there.
#[test]
fn a_sweep_shows_its_progress_on_a_terminal_only() {
    let args = [
        "sweep",
        "--count",
        "3",
        "--robots",
        "2..=3",
        "--obstacles",
        "0..=0",
    ];
    let o = dvf(&args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(o.stderr.is_empty(), "{}", stderr(&o));
    let screen = on_a_terminal(&args);
    assert!(screen.contains(" scenario "), "no progress bar: {screen:?}");
    assert!(screen.contains("/3"), "no scenario count: {screen:?}");
    assert!(
        screen.contains(r#""success_rate""#),
        "no summary: {screen:?}"
    );
}

/// A sweep where some scenarios were skipped succeeds, and says on standard error how many of
/// those asked for its summary leaves out.
#[test]
fn a_sweep_that_skipped_some_says_how_many() {
    let o = dvf(&[
        "sweep",
        "--count",
        "4",
        "--robots",
        "200..=1000",
        "--set",
        "duration=1",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let summary: Value = serde_json::from_str(stdout(&o).trim()).expect("one JSON summary");
    let skipped = summary["skipped"].as_u64().expect("skipped is a count");
    let ran = summary["scenarios"].as_u64().expect("scenarios is a count");
    assert!(skipped > 0 && ran > 0, "this sweep skips some: {summary}");
    let warning = stderr(&o);
    assert!(
        warning.contains(&format!(
            "{skipped} of {} scenarios were skipped",
            skipped + ran
        )),
        "{warning}"
    );
}
