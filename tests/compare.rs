//! Planners compared on the built `dvf` binary and through the library: `dvf compare` prints
//! the library's comparison (table or JSON), refuses bad options by their name; `dvf planners`
//! lists the registry; `--planner` reaches `dvf simulate` and `dvf sweep`, whose shard lines
//! and summary record it and whose merge refuses shards of different planners; the tables of
//! `make compare-table` have a row per planner.
// The binary exists natively and with the `cli` feature only.
#![cfg(all(not(target_arch = "wasm32"), feature = "cli"))]

mod common;

use common::{dvf, ok, stderr, TempFile};
use dvf::compare::table::{families_table, run_rows, FamilySweep};
use dvf::compare::{compare_with, Comparison};
use dvf::planner::{Spec, PLANNERS};
use dvf::sweep::Request;
use serde_json::Value;

/// `dvf args`, which must fail with exit code 2 and one line on stderr starting with `start`.
fn refused(args: &[&str], start: &str) -> String {
    let o = dvf(args);
    assert_eq!(o.status.code(), Some(2), "dvf {args:?}: {}", stderr(&o));
    let err = stderr(&o);
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(err.starts_with(start), "dvf {args:?}: {err}");
    err
}

/// A comparison's JSON with the compute times (the one number that differs from run to run)
/// taken out.
fn without_times(mut v: Value) -> Value {
    for p in v["planners"].as_array_mut().expect("planners") {
        p["metrics"]["ms_per_step"] = Value::Null;
    }
    v
}

/// `dvf compare --json` is the library's comparison, every number but the compute time; every
/// planner of the registry by default, each with a finite, non-negative compute time.
#[test]
fn compare_json_is_the_librarys_comparison() {
    let cli: Value = serde_json::from_str(&ok(&[
        "compare",
        "--preset",
        "table2-obstacles",
        "--planners",
        "dvf-paper,dvf",
        "--json",
    ]))
    .unwrap();
    let s = dvf::presets::preset("table2-obstacles").unwrap();
    let lib: Comparison =
        compare_with(&s, &[Spec::named("dvf-paper"), Spec::named("dvf")], || 0.0).unwrap();
    let lib = serde_json::to_value(&lib).unwrap();
    assert_eq!(without_times(cli.clone()), without_times(lib));
    assert_eq!(cli["scenario"], s.name.as_str());
    assert_eq!(cli["planners"][0]["planner"], "dvf-paper");
    let all: Value =
        serde_json::from_str(&ok(&["compare", "--preset", "table1-free-space", "--json"])).unwrap();
    let names: Vec<&str> = all["planners"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["planner"].as_str().unwrap())
        .collect();
    assert_eq!(names, PLANNERS.iter().map(|e| e.name).collect::<Vec<_>>());
    for p in all["planners"].as_array().unwrap() {
        let ms = p["metrics"]["ms_per_step"].as_f64().unwrap();
        assert!(ms.is_finite() && ms >= 0.0, "{ms}");
        assert_eq!(
            p["robots"].as_array().unwrap().len(),
            6,
            "Example 1's six robots"
        );
    }
}

/// The table has a header with the units and one row per planner, in the order asked for;
/// `--set` reaches the scenario (the conditions line says the limits).
#[test]
fn compare_prints_a_row_per_planner() {
    let f = TempFile::with_text(
        "two",
        r#"{"name": "two", "duration": 10,
            "robots": [{"start": [0, 0, 0], "goal": [6, 0, 0]},
                       {"start": [6, 0.4, 3.14159], "goal": [0, 0.4, 3.14159]}]}"#,
    );
    let out = ok(&[
        "compare",
        f.arg(),
        "--planners",
        "dvf,dvf-paper",
        "--set",
        "v_max=2",
        "--set",
        "omega_max=none",
    ]);
    assert!(out.starts_with("two: 2 robots, 0 obstacles, 10 s in steps of 0.01 s, v_max 2, ω_max none, safety barrier on"), "{out}");
    assert!(
        out.contains("| path (m) |") && out.contains("| µs/step |"),
        "{out}"
    );
    let rows: Vec<&str> = out.lines().skip(4).collect();
    assert_eq!(rows.len(), 2, "{out}");
    assert!(rows[0].starts_with("| dvf | "), "{out}");
    assert!(rows[1].starts_with("| dvf-paper | "), "{out}");
    assert!(
        out.lines()
            .nth(2)
            .unwrap()
            .starts_with("| planner | arrived |"),
        "{out}"
    );
}

/// Bad options are refused naming the option or the field: an unknown planner (with the
/// known ones), a bad `--set`, a parameter out of range, a scenario missing.
#[test]
fn compare_refuses_bad_options_by_name() {
    let e = refused(
        &[
            "compare",
            "--preset",
            "table1-free-space",
            "--planners",
            "dvf,rrt",
        ],
        "planners[1]: unknown planner \"rrt\": one of dvf, dvf-paper",
    );
    assert!(e.contains("dvf-paper"), "{e}");
    refused(
        &[
            "compare",
            "--preset",
            "table1-free-space",
            "--set",
            "k_v=-1",
        ],
        "params.k_v: ",
    );
    refused(
        &[
            "compare",
            "--preset",
            "table1-free-space",
            "--set",
            "swirl=1",
        ],
        "set: swirl is not a parameter of a scenario",
    );
    refused(
        &["compare", "--preset", "table1-free-space", "--set", "k_v"],
        "set: expected NAME=VALUE",
    );
    refused(
        &["compare"],
        "the following required arguments were not provided",
    );
}

/// `dvf planners` and `dvf compare --list` list every entry of the registry with its title,
/// what it avoids and its source; `--json` as objects.
#[test]
fn planners_lists_the_registry() {
    let text = ok(&["planners"]);
    assert_eq!(ok(&["compare", "--list"]), text);
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), PLANNERS.len());
    for (line, e) in lines.iter().zip(PLANNERS) {
        assert!(line.starts_with(e.name), "{line}");
        for part in [e.title, e.avoids, e.source] {
            assert!(line.contains(part), "{line}");
        }
    }
    let json: Value = serde_json::from_str(&ok(&["planners", "--json"])).unwrap();
    assert_eq!(json[1]["name"], PLANNERS[1].name);
    assert_eq!(json[1]["source"], PLANNERS[1].source);
    assert_eq!(json.as_array().unwrap().len(), PLANNERS.len());
}

/// `dvf simulate --planner` overrides the scenario's planner: the report names it and is the
/// report of the scenario with that `planner`; an unknown name is refused by the option.
#[test]
fn simulate_runs_the_planner_asked_for() {
    let base = ok(&["presets", "--preset", "table2-obstacles"]);
    let mut doc: Value = serde_json::from_str(&base).unwrap();
    doc["duration"] = 5.into();
    doc["planner"] = "dvf-paper".into();
    let with_key = TempFile::with_text("paper", &doc.to_string());
    doc["planner"] = "dvf".into();
    let without = TempFile::with_text("dvf", &doc.to_string());
    let a = ok(&["simulate", with_key.arg()]);
    let b = ok(&["simulate", without.arg(), "--planner", "dvf-paper"]);
    assert_eq!(a, b);
    let report: Value = serde_json::from_str(&a).unwrap();
    assert_eq!(report["planner"], "dvf-paper");
    let c = ok(&["simulate", with_key.arg(), "--planner", "dvf"]);
    assert_ne!(a, c);
    assert!(serde_json::from_str::<Value>(&c)
        .unwrap()
        .get("planner")
        .is_none());
    refused(
        &["simulate", without.arg(), "--planner", "rrt"],
        "invalid value 'rrt' for '--planner <NAME>': planner: unknown planner \"rrt\"",
    );
    refused(
        &[
            "simulate",
            without.arg(),
            "--planner",
            r#"{"name": "dvf", "lambda": 2}"#,
        ],
        "planner",
    );
}

/// `dvf sweep --planner`: the summary and every shard line record the planner, the shards
/// merge to the summary, and shards of another planner are refused by the merge. A DVF sweep
/// records none (its lines and identity are those of a sweep without the option).
#[test]
fn sweep_records_its_planner_and_merge_refuses_mixed_planners() {
    let args = |planner: &str, shard: Option<&str>| {
        let mut a = vec![
            "sweep",
            "--count",
            "3",
            "--robots",
            "2..=3",
            "--obstacles",
            "0..=1",
            "--set",
            "duration=8",
            "--planner",
        ];
        a.push(planner);
        if let Some(s) = shard {
            a.extend(["--shard", s]);
        }
        a.iter().map(|s| (*s).to_owned()).collect::<Vec<_>>()
    };
    let run = |a: Vec<String>| ok(&a.iter().map(String::as_str).collect::<Vec<_>>());
    let summary: Value = serde_json::from_str(&run(args("dvf-paper", None))).unwrap();
    assert_eq!(summary["planner"], "dvf-paper");
    let paper1 = run(args("dvf-paper", Some("1/2")));
    let paper2 = run(args("dvf-paper", Some("2/2")));
    for line in paper1.lines().chain(paper2.lines()) {
        let o: Value = serde_json::from_str(line).unwrap();
        assert_eq!(o["recipe"]["planner"], "dvf-paper", "{line}");
    }
    let (f1, f2) = (TempFile::new("p1", "jsonl"), TempFile::new("p2", "jsonl"));
    std::fs::write(f1.path(), &paper1).unwrap();
    std::fs::write(f2.path(), &paper2).unwrap();
    let merged: Value = serde_json::from_str(&ok(&["sweep", "merge", f1.arg(), f2.arg()])).unwrap();
    assert_eq!(merged, summary);
    let dvf2 = run(args("dvf", Some("2/2")));
    assert!(!dvf2.contains("planner"), "{dvf2}");
    let plain = ok(&[
        "sweep",
        "--count",
        "3",
        "--robots",
        "2..=3",
        "--obstacles",
        "0..=1",
        "--set",
        "duration=8",
        "--shard",
        "2/2",
    ]);
    assert_eq!(dvf2, plain);
    let f3 = TempFile::new("d2", "jsonl");
    std::fs::write(f3.path(), &dvf2).unwrap();
    let e = refused(&["sweep", "merge", f1.arg(), f3.arg()], "");
    assert!(
        e.contains("another recipe or belongs to another sweep"),
        "{e}"
    );
    refused(
        &["sweep", "--count", "1", "--planner", "rrt"],
        "invalid value 'rrt' for '--planner <NAME>'",
    );
}

/// The tables of `make compare-table`: a row per family and planner with its scenes and
/// arrivals, and a row per scene and planner of the run metrics.
#[test]
fn the_compare_tables_have_a_row_per_planner() {
    let planners = [Spec::named("dvf"), Spec::named("dvf-paper")];
    let sweeps = [FamilySweep {
        label: "random, small".into(),
        request: Request {
            count: 2,
            robots: Some((2, 3)),
            obstacles: Some((0, 1)),
            set: vec!["duration=6".into()],
            ..Request::default()
        },
    }];
    let table = families_table(&planners, &sweeps).unwrap();
    let rows: Vec<&str> = table.lines().skip(2).collect();
    assert_eq!(rows.len(), 2, "{table}");
    assert!(
        rows[0].starts_with("| random, small | dvf | 2 | "),
        "{table}"
    );
    assert!(
        rows[1].starts_with("| random, small | dvf-paper | 2 | "),
        "{table}"
    );
    assert!(table.starts_with("| family | planner | scenes | arrived | rate |"));
    let s = dvf::presets::preset("table1-free-space").unwrap();
    let c = compare_with(&s, &planners, || 0.0).unwrap();
    let rows = run_rows(Some("ex1"), &c, true);
    assert_eq!(rows.lines().count(), 4, "{rows}");
    assert!(
        rows.lines()
            .nth(2)
            .unwrap()
            .starts_with("| ex1 | dvf | 6/6 | "),
        "{rows}"
    );
}
