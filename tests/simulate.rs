//! `dvf simulate` on the built binary: the trajectories stream to their CSV as the run goes,
//! in bounded memory, thinned by `--every`, with times that read back as `k·dt`; a CSV path
//! that cannot be written is refused before the run; the scenario may come on standard input;
//! a run on a terminal shows its progress on standard error and a pipe gets none.
// The binary exists natively and with the `cli` feature only.
#![cfg(all(not(target_arch = "wasm32"), feature = "cli"))]

mod common;

use common::{dvf, on_a_terminal, TempFile, DVF};
use serde_json::Value;
use std::fs::File;
use std::io::Write;
use std::process::{Command, Stdio};

/// The crowd of `robots` (the preset `crowd-N`) run for `duration` seconds, as a file.
fn crowd_file(robots: usize, duration: f64) -> TempFile {
    let mut s = dvf::presets::crowd(robots);
    s.duration = duration;
    TempFile::with_text("crowd", &s.to_json())
}

/// Runs `dvf args` to its end and returns its exit code, its standard error and its peak
/// resident memory in KiB (`ru_maxrss` of the child, reaped with `wait4`).
fn peak_memory(args: &[&str]) -> (i32, String, i64) {
    let err = TempFile::new("stderr", "txt");
    let child = Command::new(DVF)
        .args(args)
        .stdout(Stdio::null())
        .stderr(File::create(&err.0).expect("a file for stderr"))
        .spawn()
        .expect("the dvf binary runs");
    let pid = libc::pid_t::try_from(child.id()).expect("a pid");
    let mut status = 0;
    // SAFETY: `rusage` is plain data that wait4 fills; the child is ours and reaped once,
    // here (`child` is dropped without a wait).
    let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
    let reaped = unsafe { libc::wait4(pid, &mut status, 0, &mut usage) };
    assert_eq!(reaped, pid, "wait4");
    drop(child);
    let code = if libc::WIFEXITED(status) {
        libc::WEXITSTATUS(status)
    } else {
        -1
    };
    let stderr = std::fs::read_to_string(&err.0).expect("stderr");
    (code, stderr, usage.ru_maxrss)
}

/// The trajectories of a run go to the file as the run goes: a run four times as long peaks
/// at the same memory. 40 robots of `[t, x, y, θ, v, ω]` at every one of 10,001 steps would
/// hold 40 · 10,001 · 48 B ≈ 18.3 MiB more than 2,501 steps (13.7 MiB); the tolerance, 2 MiB,
/// is far below that and far above the few pages by which two runs of one program differ.
#[test]
fn csv_streams_to_its_file_in_bounded_memory() {
    let (short, long) = (crowd_file(40, 25.0), crowd_file(40, 100.0));
    let mut peaks = Vec::new();
    for scenario in [&short, &long] {
        let (code, stderr, peak) = peak_memory(&["simulate", scenario.arg(), "--csv", "/dev/null"]);
        assert_eq!(code, 0, "{stderr}");
        assert!(stderr.is_empty(), "{stderr}");
        peaks.push(peak);
    }
    let (n, four_n) = (peaks[0], peaks[1]);
    assert!(
        four_n <= n + 2 * 1024,
        "2,501 steps peak at {n} KiB, 10,001 at {four_n} KiB: the trajectory is held"
    );
}

/// A CSV path that cannot be written is refused with the path named, exit code 2, and before
/// the run: nothing is simulated, so the program never holds a trajectory (1,000 robots over
/// 2,001 steps would be 1,000 · 2,001 · 48 B ≈ 92 MiB) nor prints a report.
#[test]
fn a_csv_path_that_cannot_be_written_is_refused_before_the_run() {
    let scenario = crowd_file(1000, 20.0);
    let path = "/nonexistent-dir-of-dvf/out.csv";
    let (code, stderr, peak) = peak_memory(&["simulate", scenario.arg(), "--csv", path]);
    assert_eq!(code, 2);
    assert!(
        stderr.starts_with(&format!("{path}: cannot write")),
        "{stderr}"
    );
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(peak < 48 * 1024, "peak {peak} KiB: the run went ahead");
}

/// Every `t` of the CSV reads back as `k·dt` written as a decimal (`0.35`, never
/// `0.35000000000000003`), at every step of a run and with `--every`, at two step sizes.
#[test]
fn csv_times_are_the_decimals_of_k_dt_and_every_thins_the_rows() {
    for (dt, decimals, every) in [("0.01", 2u32, 1usize), ("0.005", 3, 7)] {
        let scenario = TempFile::with_text(
            "times.json",
            &format!(
                r#"{{ "duration": 12, "dt": {dt},
                     "robots": [ {{ "start": [0, 0, 0], "goal": [10, 5, 1] }},
                                 {{ "start": [10, 0, 3], "goal": [0, 5, 1] }} ] }}"#
            ),
        );
        let csv = TempFile::new("times", "csv");
        let every_arg = every.to_string();
        let mut args = vec!["simulate", scenario.arg(), "--csv", csv.arg()];
        // Every step by default.
        if every > 1 {
            args.extend(["--every", &every_arg]);
        }
        let o = dvf(&args);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&o.stderr)
        );
        let report: Value = serde_json::from_slice(&o.stdout).expect("one JSON report");
        let steps = report["steps"].as_u64().expect("steps") as usize;
        let text = std::fs::read_to_string(&csv.0).expect("the CSV");
        let mut lines = text.lines();
        assert_eq!(lines.next(), Some("t,robot,x,y,theta,v,omega"));
        let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
        let kept: Vec<usize> = (0..=steps)
            .filter(|k| k % every == 0 || *k == steps)
            .collect();
        assert_eq!(rows.len(), 2 * kept.len(), "dt {dt}, every {every}");
        let units: u64 = dt.replace("0.", "").parse().expect("dt's digits");
        let p = 10u64.pow(decimals);
        for (row, k) in rows.chunks(2).zip(&kept) {
            let scaled = *k as u64 * units;
            let decimal = format!("{}.{:0w$}", scaled / p, scaled % p, w = decimals as usize);
            let expected: f64 = decimal.parse().expect("a decimal");
            for (robot, cells) in row.iter().enumerate() {
                let t: f64 = cells[0].parse().expect("t is a number");
                assert_eq!(t, expected, "step {k}: t written as {}", cells[0]);
                assert!(cells[0].len() <= decimal.len(), "step {k}: {}", cells[0]);
                assert_eq!(cells[1], robot.to_string());
            }
        }
    }
    // --every needs --csv, and a K of at least 1.
    let o = dvf(&["simulate", "--preset", "table1-free-space", "--every", "2"]);
    assert_eq!(o.status.code(), Some(2));
    let o = dvf(&[
        "simulate",
        "--preset",
        "table1-free-space",
        "--csv",
        "/dev/null",
        "--every",
        "0",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--every"));
}

/// `dvf simulate -` reads the scenario from standard input: the report of the file, and a bad
/// scenario is refused naming standard input and the field.
#[test]
fn simulate_reads_the_scenario_from_standard_input() {
    let text = r#"{ "duration": 10, "robots": [ { "start": [0, 0, 0], "goal": [5, 2, 1] } ] }"#;
    let file = TempFile::with_text("stdin", text);
    let from_file = dvf(&["simulate", file.arg()]);
    assert_eq!(from_file.status.code(), Some(0));
    let piped = |input: &str| {
        let mut child = Command::new(DVF)
            .args(["simulate", "-"])
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("the dvf binary runs");
        child
            .stdin
            .take()
            .expect("stdin")
            .write_all(input.as_bytes())
            .expect("write the scenario");
        child.wait_with_output().expect("dvf ends")
    };
    let o = piped(text);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert_eq!(o.stdout, from_file.stdout);
    let o = piped(r#"{ "dt": 0, "robots": [ { "start": [0, 0, 0], "goal": [5, 2, 1] } ] }"#);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(
        String::from_utf8_lossy(&o.stderr),
        "standard input: dt: must be positive, not 0\n"
    );
}

/// On a terminal (a pseudo-terminal from util-linux's `script`) a run draws its progress bar
/// on standard error, and clears it before the report; on a pipe it writes no byte there.
#[test]
fn progress_shows_on_a_terminal_and_never_on_a_pipe() {
    let args = ["simulate", "--preset", "example4-obstacle-formation"];
    let o = dvf(&args);
    assert_eq!(o.status.code(), Some(0));
    assert!(
        o.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let screen = on_a_terminal(&args);
    assert!(screen.contains(" step "), "no progress bar: {screen:?}");
    assert!(screen.contains("/2500"), "no step count: {screen:?}");
    assert!(
        screen.contains(r#""violations":0"#),
        "no report: {screen:?}"
    );
}
