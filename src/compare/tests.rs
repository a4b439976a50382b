//! The comparison's metrics against independent computations, its refusals, and its numbers
//! against those stored from a native run (under `wasm-pack test`: the same bits in wasm).

use super::*;
use crate::sim::run_recorded;
use crate::testing::test;

/// Two robots swapping places past an obstacle: pairs, clearance and turns to measure.
fn two() -> Scenario {
    Scenario::from_json(
        r#"{"name": "two", "duration": 12,
            "robots": [{"start": [0, 0, 0], "goal": [8, 0, 0]},
                       {"start": [8, 0.5, 3.141592653589793], "goal": [0, 0.5, 3.141592653589793]}],
            "obstacles": [{"center": [4, 3], "radius": 1, "influence": 2}]}"#,
    )
    .expect("a valid scenario")
}

/// The path length, control effort and peak curvature are sums and maxima over the commands
/// the run held, step by step: the recorded samples (`run_recorded`, whose sample `k` holds
/// the command held over step `k + 1`) summed in the same order give the same bits. The run's
/// arrival, distances and violations are the simulator's report's. A robot's path is at least
/// the straight line from its start to where it ended (to 1e-9 m of round-off over 1,200 steps).
#[test]
fn the_metrics_are_the_runs_commands_and_report() {
    let s = two();
    let c = compare_with(&s, &[Spec::named("dvf")], || 0.0).unwrap();
    let run = &c.planners[0];
    let (report, samples) = run_recorded(&s, 1).unwrap();
    for (k, (r, m)) in samples.iter().zip(&run.robots).enumerate() {
        let held = &r[..r.len() - 1];
        assert_eq!(held.len(), s.steps());
        let path = held.iter().fold(0.0, |a, x| a + x[4].abs() * s.dt);
        let effort = held
            .iter()
            .fold(0.0, |a, x| a + (x[4] * x[4] + x[5] * x[5]) * s.dt);
        let curvature = held
            .iter()
            .filter(|x| x[4].abs() > CURVATURE_MIN_SPEED)
            .fold(0.0, |a: f64, x| a.max(x[5].abs() / x[4].abs()));
        assert_eq!(m.robot, k);
        assert_eq!(m.path_length, path);
        assert_eq!(m.control_effort, effort);
        assert_eq!(m.peak_curvature, curvature);
        let start = s.robots[k].start_pose().p;
        let end = glam::DVec2::new(
            report.robots[k].final_pose[0],
            report.robots[k].final_pose[1],
        );
        assert!(m.path_length >= start.distance(end) - 1e-9);
        assert_eq!(m.arrival_time, report.robots[k].converged_at);
        assert_eq!(m.reversals, report.robots[k].smoothness.reversals);
    }
    let m = &run.metrics;
    assert_eq!(m.arrived, 2, "both robots arrive under DVF");
    assert_eq!(m.arrival_rate, 1.0);
    let last = report
        .robots
        .iter()
        .filter_map(|r| r.converged_at)
        .fold(0.0, f64::max);
    assert_eq!(m.time_to_last_arrival, Some(last));
    assert_eq!(
        m.path_length,
        run.robots[0].path_length + run.robots[1].path_length
    );
    assert_eq!(m.min_pair_distance, report.min_pair_distance);
    assert_eq!(m.min_obstacle_clearance, report.min_obstacle_clearance);
    assert_eq!(m.violations, report.violations);
    assert_eq!(m.steps, s.steps());
    assert_eq!(c.conditions.robots, 2);
    assert!(c.conditions.barrier);
}

/// A robot that does not arrive leaves the time to the last arrival null (not the time of
/// those that did), and the arrival rate counts it.
#[test]
fn one_robot_short_leaves_no_last_arrival() {
    let mut s = two();
    s.duration = 2.0;
    let c = compare_with(&s, &[Spec::named("dvf")], || 0.0).unwrap();
    let m = &c.planners[0].metrics;
    assert_eq!(m.arrived, 0, "no robot arrives in 2 s");
    assert_eq!((m.arrival_rate, m.time_to_last_arrival), (0.0, None));
}

/// The compute time is the clock's: 60 ms over the run's 1,200 steps is 0.05 ms per step
/// (both exact in binary to within one rounding of the division).
#[test]
fn the_compute_time_is_read_from_the_clock_passed_in() {
    let mut ticks = [0.0, 60.0, 100.0, 160.0].into_iter();
    let c = compare_with(
        &two(),
        &[Spec::named("dvf"), Spec::named("dvf-paper")],
        || ticks.next().unwrap(),
    )
    .unwrap();
    for p in &c.planners {
        assert_eq!(p.metrics.ms_per_step, 60.0 / 1200.0);
    }
    assert_eq!(c.planners[1].planner, Spec::named("dvf-paper"));
    assert_eq!(c.planners[1].title, crate::planner::PLANNERS[1].title);
}

/// No planner, an unknown one or refused gains are named by the list's field; the message of
/// an unknown name lists the known ones.
#[test]
fn bad_planner_lists_are_refused_by_their_field() {
    let err = |planners: &[Spec]| compare(&two(), planners).unwrap_err().to_string();
    assert!(err(&[]).starts_with("planners: name at least one planner: dvf, dvf-paper"));
    let e = err(&[Spec::named("dvf"), Spec::named("rrt")]);
    assert!(
        e.starts_with("planners[1]: unknown planner \"rrt\": one of dvf"),
        "{e}"
    );
    let gains: Spec = serde_json::from_str(r#"{"name": "dvf", "lambda": 2}"#).unwrap();
    let e = err(&[gains]);
    assert!(e.starts_with("planners[0]"), "{e}");
    assert!(e.contains("lambda"), "{e}");
}

/// Example 4 for 10 s with `dvf` and `dvf-paper`, every number but the compute time, as
/// tests/data/compare/example4-10s.json holds it from a native run (rewritten with
/// `DVF_WRITE_REFERENCE=1`). Under `wasm-pack test` this shows that the wasm build compares
/// with the very same numbers.
#[test]
fn a_comparison_gives_the_stored_numbers_in_every_build() {
    use serde_json::Value;
    let mut s = crate::presets::preset("example4-obstacle-formation").unwrap();
    s.duration = 10.0;
    let c = compare_with(&s, &[Spec::named("dvf"), Spec::named("dvf-paper")], || 0.0).unwrap();
    let ours: Value = serde_json::from_str(&serde_json::to_string(&c).unwrap()).unwrap();
    #[cfg(not(target_arch = "wasm32"))]
    if std::env::var_os("DVF_WRITE_REFERENCE").is_some() {
        let path = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/data/compare/example4-10s.json"
        );
        std::fs::write(path, serde_json::to_string_pretty(&ours).unwrap() + "\n").unwrap();
    }
    let stored: Value =
        serde_json::from_str(include_str!("../../tests/data/compare/example4-10s.json")).unwrap();
    assert_eq!(stored, ours);
}
