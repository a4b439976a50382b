//! The library's entry points, as a program that uses it sees them: every entry that takes a
//! scenario refuses what the file reader refuses, with its message; a scenario can be built in
//! code; one robot can be stepped with the barrier from one's own loop, with the simulator's
//! bits. They run natively, in Node (`wasm-pack test --node`) and in Chromium
//! (`make test-browser`).

#[path = "../src/testing.rs"]
mod testing;
use testing::test;

use dvf::presets::{circle_swap, preset};
use dvf::scenario::Scenario;
use dvf::sim::{run, run_recorded, run_streamed, run_with, step_time, Neighbourhood, Simulation};
use dvf::{Error, Obstacle, Params, Pose, SafeRobot};
use glam::DVec2;

/// A one-robot scene as JSON with `extra` keys.
fn json_with(extra: &str) -> String {
    format!(r#"{{ {extra} "robots": [ {{ "start": [0, 0, 0], "goal": [5, 1, 0.5] }} ] }}"#)
}

/// The message every entry that takes a scenario gives for `s`; they must all agree.
fn refusals(s: &Scenario) -> Vec<String> {
    let sink = |_: &Simulation, _: &[dvf::sim::Sample]| Ok::<(), Error>(());
    vec![
        s.validate().unwrap_err().to_string(),
        run(s).unwrap_err().to_string(),
        Simulation::new(s).unwrap_err().to_string(),
        Simulation::with_neighbourhood(s, Neighbourhood::AllPairs)
            .unwrap_err()
            .to_string(),
        run_recorded(s, 1).unwrap_err().to_string(),
        run_streamed(s, 1, sink).unwrap_err().to_string(),
        run_with(s, |_| Ok::<(), Error>(()))
            .unwrap_err()
            .to_string(),
    ]
}

/// `dt = 0` (which would never advance) and `dt < 0` (which would run backwards): the library
/// refuses them with the file reader's message, naming `dt`.
#[test]
fn a_step_that_is_not_positive_is_refused_with_the_file_readers_message() {
    for dt in ["0", "-0.01"] {
        let text = json_with(&format!(r#""dt": {dt},"#));
        let from_file = Scenario::from_json(&text).unwrap_err().to_string();
        assert_eq!(from_file, format!("dt: must be positive, not {dt}"));
        let mut s = Scenario::from_json(&json_with("")).unwrap();
        s.dt = dt.parse().unwrap();
        for message in refusals(&s) {
            assert_eq!(message, from_file);
        }
    }
}

/// A start or goal that is not a finite number (JSON has none: the library is the only way
/// in) is refused, naming the coordinate, rather than run to a NaN report with no violation.
#[test]
fn a_pose_that_is_not_finite_is_refused_naming_the_coordinate() {
    let valid = Scenario::from_json(&json_with("")).unwrap();
    let cases = [
        (0, "start", 0, f64::NAN, "NaN"),
        (0, "start", 2, f64::INFINITY, "inf"),
        (0, "goal", 1, f64::NEG_INFINITY, "-inf"),
    ];
    for (robot, key, k, value, shown) in cases {
        let mut s = valid.clone();
        let spec = &mut s.robots[robot];
        if key == "start" {
            spec.start[k] = value;
        } else {
            spec.goal[k] = value;
        }
        let expected = format!("robots[{robot}].{key}[{k}]: must be a finite number, not {shown}");
        for message in refusals(&s) {
            assert_eq!(message, expected);
        }
    }
    // The parameters are checked from the same table as a file's.
    let mut s = valid;
    s.params.k_v = f64::NAN;
    for message in refusals(&s) {
        assert_eq!(message, "params.k_v: must be a finite number, not NaN");
    }
}

/// The builder gives the scenario the file gives, and refuses what the file reader refuses.
#[test]
fn the_builder_reads_like_the_paper_and_validates_like_a_file() {
    let built = Scenario::builder()
        .name("Table II, first robot")
        .robot([0.0, 30.0, 0.0], [0.0, 0.0, 0.0])
        .obstacle([-9.2, 14.0], 1.5, 3.0)
        .dt(0.01)
        .duration(20.0)
        .build()
        .unwrap();
    let file = Scenario::from_json(
        r#"{ "name": "Table II, first robot", "duration": 20, "dt": 0.01,
             "robots": [ { "start": [0, 30, 0], "goal": [0, 0, 0] } ],
             "obstacles": [ { "center": [-9.2, 14], "radius": 1.5, "influence": 3 } ] }"#,
    )
    .unwrap();
    assert_eq!(built, file);
    // Nothing set but the robots: the file's defaults.
    let minimal = Scenario::builder()
        .robot([0.0, 0.0, 0.0], [5.0, 1.0, 0.5])
        .build()
        .unwrap();
    assert_eq!(minimal, Scenario::from_json(&json_with("")).unwrap());
    assert_eq!(
        Scenario {
            robots: minimal.robots.clone(),
            ..Scenario::default()
        },
        minimal
    );
    // Refused as the file is, field named.
    let no_robot = Scenario::builder().build().unwrap_err().to_string();
    assert_eq!(no_robot, "robots: needs at least one robot");
    let ring = Scenario::builder()
        .robot([0.0, 30.0, 0.0], [0.0, 0.0, 0.0])
        .obstacle([0.0, 14.0], 3.0, 2.0)
        .build()
        .unwrap_err()
        .to_string();
    assert_eq!(ring, "obstacles[0].influence: must exceed the radius (3)");
    let paper = Params {
        barrier_rate: None,
        ..Params::default()
    };
    let fast = Scenario::builder()
        .robot([0.0, 0.0, 0.0], [1.0, 0.0, 0.0])
        .params(paper)
        .dt(-1.0)
        .build()
        .unwrap_err();
    assert_eq!(fast.to_string(), "dt: must be positive, not -1");
}

/// `step_time` is `k·dt` in decimal: the number a person writes, read back, for every step
/// of runs at several step sizes; and the binary product where the decimal would not be
/// exact.
#[test]
fn step_times_are_the_decimals_of_k_dt() {
    for (dt, decimals) in [(0.01, 2), (0.001, 3), (0.005, 3), (0.1, 1), (0.025, 3)] {
        let units = (dt * 10f64.powi(decimals)).round() as u64;
        for k in 0..100_000u64 {
            let scaled = k * units;
            let p = 10u64.pow(decimals as u32);
            let text = format!(
                "{}.{:0width$}",
                scaled / p,
                scaled % p,
                width = decimals as usize
            );
            let expected: f64 = text.parse().unwrap();
            assert_eq!(step_time(k as usize, dt), expected, "step {k} at dt {dt}");
        }
    }
    assert_eq!(step_time(35, 0.01), 0.35);
    assert_ne!(35.0 * 0.01, 0.35);
    // One third has no short decimal: the binary product.
    let third = 1.0 / 3.0 / 10.0;
    assert_eq!(step_time(7, third), 7.0 * third);
}

/// A run through `run_streamed` hands on the same samples `run_recorded` keeps, step by step.
#[test]
fn streamed_samples_are_the_recorded_ones() {
    let s = preset("example3-circle-swap").unwrap();
    let (report, traj) = run_recorded(&s, 7).unwrap();
    let mut streamed: Vec<Vec<[f64; 6]>> = vec![Vec::new(); s.robots.len()];
    let mut calls = 0;
    let again = run_streamed(&s, 7, |sim, samples| {
        assert_eq!(sim.steps(), calls);
        calls += 1;
        for (k, q) in samples.iter().enumerate() {
            streamed[k].push(*q);
        }
        Ok::<(), Error>(())
    })
    .unwrap();
    assert_eq!(calls, s.steps() + 1);
    assert_eq!(streamed, traj);
    assert_eq!(again.robots, report.robots);
    // Steps 0, 7, 14, … and the last.
    let last = s.steps();
    let expected: Vec<f64> = (0..=last)
        .filter(|k| k % 7 == 0 || *k == last)
        .map(|k| step_time(k, s.dt))
        .collect();
    let times: Vec<f64> = traj[0].iter().map(|q| q[0]).collect();
    assert_eq!(times, expected);
}

/// Safe robots stepped from the same snapshot, each sensing the others in scenario order, take the
/// simulator's very steps: every pose and command the same bits, at every step.
fn safe_robots_take_the_simulators_steps(s: &Scenario) {
    let mut sim = Simulation::new(s).unwrap();
    let mut robots: Vec<SafeRobot> = s
        .robots
        .iter()
        .map(|r| SafeRobot::new(&s.params, s.dt, r.start_pose(), r.goal_pose()).unwrap())
        .collect();
    for step in 1..=s.steps() {
        let snapshot: Vec<_> = robots.iter().map(SafeRobot::as_neighbour).collect();
        let commands: Vec<_> = robots
            .iter_mut()
            .enumerate()
            .map(|(i, a)| {
                let others: Vec<_> = snapshot
                    .iter()
                    .enumerate()
                    .filter(|&(j, _)| j != i)
                    .map(|(_, n)| *n)
                    .collect();
                a.step(&others, &s.obstacles)
            })
            .collect();
        let held: Vec<_> = sim.robots().iter().map(|r| r.last.command).collect();
        sim.step();
        for (i, (a, r)) in robots.iter().zip(sim.robots()).enumerate() {
            let (ours, theirs) = (a.pose().to_array(), r.pose.to_array());
            assert_eq!(
                ours.map(f64::to_bits),
                theirs.map(f64::to_bits),
                "{}: robot {i} at step {step}: {ours:?} against {theirs:?}",
                s.name
            );
            assert_eq!(commands[i], held[i], "{}: robot {i} at step {step}", s.name);
        }
    }
    let report = sim.report();
    assert_eq!(report.violations, 0);
}

#[test]
fn one_safe_robot_with_an_obstacle_takes_the_simulators_steps() {
    let s = Scenario::builder()
        .robot([0.0, 30.0, 0.0], [0.0, 0.0, 0.0])
        .obstacle([-9.2, 14.0], 1.5, 3.0)
        .duration(20.0)
        .build()
        .unwrap();
    safe_robots_take_the_simulators_steps(&s);
}

#[test]
fn safe_robots_that_meet_take_the_simulators_steps() {
    // Two robots head-on past an obstacle, and the paper's circle swap of six.
    let pair = Scenario::builder()
        .robot([0.0, 0.0, 0.0], [10.0, 0.0, 0.0])
        .robot([10.0, 0.3, 3.0], [0.0, 0.3, 3.0])
        .obstacle([5.0, 4.0], 1.0, 2.0)
        .duration(30.0)
        .build()
        .unwrap();
    safe_robots_take_the_simulators_steps(&pair);
    safe_robots_take_the_simulators_steps(&circle_swap(6, 20.0));
}

/// A safe robot refuses what a scenario of its one robot would be refused for.
#[test]
fn a_safe_robot_refuses_a_step_or_pose_the_validation_refuses() {
    let p = Params::default();
    let (a, b) = (Pose::new(0.0, 0.0, 0.0), Pose::new(1.0, 0.0, 0.0));
    let err = |dt: f64, start: Pose| SafeRobot::new(&p, dt, start, b).unwrap_err().to_string();
    assert_eq!(err(0.0, a), "dt: must be positive, not 0");
    assert_eq!(err(-0.01, a), "dt: must be positive, not -0.01");
    assert_eq!(
        err(0.01, Pose::new(f64::NAN, 0.0, 0.0)),
        "robots[0].start[0]: must be a finite number, not NaN"
    );
    assert!(err(0.5, a).starts_with("dt: must be at most"));
}

/// The in-place edits of a new simulation refuse, changing nothing, the numbers the
/// validation refuses; a new simulation of the edited scenario then names the field.
#[test]
fn placing_a_robot_or_obstacle_refuses_numbers_the_validation_refuses() {
    let s = preset("table2-obstacles").unwrap();
    let mut sim = Simulation::new(&s).unwrap();
    let before = sim.robots().to_vec();
    let (pose, goal) = (s.robots[0].start_pose(), s.robots[0].goal_pose());
    let nan = Pose::new(f64::NAN, 0.0, 0.0);
    assert!(!sim.place_robot(0, nan, goal));
    assert!(!sim.place_robot(0, pose, Pose::new(0.0, 1e7, 0.0)));
    let obstacle = s.obstacles[0];
    for bad in [
        Obstacle {
            radius: 0.0,
            ..obstacle
        },
        Obstacle {
            influence: obstacle.radius,
            ..obstacle
        },
        Obstacle {
            center: DVec2::new(f64::INFINITY, 0.0),
            ..obstacle
        },
    ] {
        assert!(!sim.place_obstacle(0, bad));
    }
    assert_eq!(sim.robots(), &before[..]);
    assert_eq!(sim.obstacles(), &s.obstacles[..]);
    // A valid edit is taken.
    assert!(sim.place_robot(0, Pose::new(1.0, 30.0, 0.0), goal));
}
