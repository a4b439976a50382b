//! The live model's parts together: the prediction against playing, the trails across edits
//! and crowd sizes, the field view against a scan, edits refused and applied.

use super::*;
use crate::controller::evaluate;
use crate::presets::{preset, DEFAULT_PRESET};
use crate::scenario::RobotSpec;
use crate::se2::Pose;
use crate::testing::assert_close;
use crate::testing::test;
use std::f64::consts::FRAC_PI_2;

fn two() -> Scenario {
    Scenario::from_json(
        r#"{"duration":10,"robots":[{"start":[0,0,0],"goal":[10,0,0]},{"start":[10,0,3.14159],"goal":[0,0,3.14159]}],
            "obstacles":[{"center":[5,8],"radius":1,"influence":2}]}"#,
    )
    .unwrap()
}

/// The prediction from t = 0 is the run that playing produces, sample for sample.
#[test]
fn prediction_is_what_playing_shows() {
    let mut live = Live::new(preset(DEFAULT_PRESET).unwrap()).unwrap();
    let samples = live.prediction().samples();
    assert!((2..=PREDICTION_SAMPLES).contains(&samples));
    let n = live.scenario().robots.len();
    assert_eq!(live.prediction().poses().len(), n * samples * POSE_STRIDE);
    let times = live.prediction().times().to_vec();
    let predicted = live.prediction().poses().to_vec();
    let k = samples / 2;
    let target = ((times[k] - times[0]) / live.scenario().dt).round() as usize;
    live.step(target);
    for i in 0..n {
        let o = (i * samples + k) * POSE_STRIDE;
        assert_eq!(&predicted[o..o + 3], &live.poses()[i * 3..i * 3 + 3]);
    }
    // Predicting again from the middle changes nothing: the rest of the same run.
    let before = predicted[((samples - 1) * POSE_STRIDE)..][..2].to_vec();
    live.predict();
    let s2 = live.prediction().samples();
    assert_eq!(
        &live.prediction().poses()[(s2 - 1) * POSE_STRIDE..][..2],
        &before[..]
    );
}

#[test]
fn the_clock_stops_at_the_end_and_trails_stay_bounded() {
    let mut s = two();
    s.duration = 30.0;
    let mut live = Live::new(s).unwrap();
    let total = live.scenario().steps();
    assert_eq!(live.step(total + 50), total);
    assert!(live.finished());
    assert_eq!(live.step(1), 0);
    assert_close!(live.time(), 30.0, 1e-9);
    assert!(live.trails().history_len() <= MAX_TRAIL_SAMPLES);
    assert_eq!(
        live.trails().poses().len(),
        2 * MAX_TRAIL_SAMPLES * POSE_STRIDE
    );
    // The newest trail sample is the pose now.
    let last = (live.trails().head() + MAX_TRAIL_SAMPLES - 1) % MAX_TRAIL_SAMPLES;
    assert_eq!(
        &live.trails().poses()[last * 3..last * 3 + 3],
        &live.poses()[0..3]
    );
    assert_close!(live.trails().times()[last], 30.0, 1e-9);
    assert!(live.trails().min_pair()[last] > 0.0);
}

/// At t = 0 a move edits the start; at t > 0 the current pose, and reset forgets it.
#[test]
fn moving_a_robot_edits_the_start_only_at_time_zero() {
    let mut live = Live::new(two()).unwrap();
    live.move_robot(0, Pose::new(0.0, -3.0, FRAC_PI_2)).unwrap();
    assert_eq!(live.scenario().robots[0].start, [0.0, -3.0, FRAC_PI_2]);
    live.step(100);
    let t = live.time();
    live.move_robot(1, Pose::new(5.0, -5.0, 0.0)).unwrap();
    assert_eq!(live.time(), t);
    assert_eq!(&live.poses()[3..6], &[5.0, -5.0, 0.0]);
    assert_eq!(live.scenario().robots[1].start[0], 10.0);
    assert_eq!(
        live.prediction().poses()[live.prediction().samples() * 3],
        5.0
    );
    live.reset();
    assert_eq!(live.time(), 0.0);
    assert_eq!(&live.poses()[3..5], &[10.0, 0.0]);
}

#[test]
fn bad_edits_are_refused_and_change_nothing() {
    let mut live = Live::new(two()).unwrap();
    live.step(10);
    let before = live.poses().to_vec();
    let e = live.move_robot(5, Pose::IDENTITY).unwrap_err().to_string();
    assert!(e.contains("index 5 is out of range"), "{e}");
    let e = live
        .move_robot(0, Pose::new(f64::NAN, 0.0, 0.0))
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("robots[0].pose[0]: must be a finite number"),
        "{e}"
    );
    let e = live
        .move_robot(0, Pose::new(5.0, 8.0, 0.0))
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("robots[0]: would be inside obstacles[0]"),
        "{e}"
    );
    // Onto the other robot, at t > 0: inside its safe disc.
    let other = live.simulation().robots()[1].pose;
    let e = live
        .move_robot(0, Pose::new(other.p.x + 0.5, other.p.y, 0.0))
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("robots[1]: would be 0.500 from robots[0]"),
        "{e}"
    );
    let mut s = live.scenario().clone();
    s.params.k_v = -1.0;
    let e = live.edit(s).unwrap_err().to_string();
    assert!(e.starts_with("params.k_v: must be positive"), "{e}");
    assert_eq!(live.poses(), &before[..]);
    assert!(live.sample_field(2, [0.0, 0.0, 1.0, 1.0], 4, 4).is_err());
    assert!(live.sample_field(0, [0.0, 0.0, 1.0, 1.0], 1, 4).is_err());
    assert!(live
        .sample_field(0, [0.0, 0.0, f64::NAN, 1.0], 4, 4)
        .is_err());
    assert!(live
        .integral_curves(0, f64::INFINITY, [0.0, 0.0, 1.0, 1.0], 4)
        .is_err());
    let many = Scenario {
        robots: (0..=MAX_LIVE_ROBOTS)
            .map(|k| RobotSpec {
                start: [10.0 * k as f64, -50.0, 0.0],
                goal: [10.0 * k as f64, 50.0, 0.0],
            })
            .collect(),
        ..live.scenario().clone()
    };
    let e = Live::new(many).unwrap_err().to_string();
    assert!(e.starts_with("robots: at most 10000"), "{e}");
    let mut long = live.scenario().clone();
    long.duration = 3_000.0;
    long.dt = 0.002;
    let e = Live::new(long).unwrap_err().to_string();
    assert!(
        e.starts_with("duration: the playground runs at most"),
        "{e}"
    );
}

/// A prediction runs at most PREDICTION_WORK robot-steps ahead, and none above
/// MAX_PREDICTED_ROBOTS robots; the simulation itself takes any count up to the limit.
#[test]
fn predictions_are_bounded_by_work_and_stop_above_the_robot_limit() {
    let line = |n: usize| Scenario {
        robots: (0..n)
            .map(|k| RobotSpec {
                start: [k as f64 * 3.0, 0.0, 0.0],
                goal: [k as f64 * 3.0, 500.0, 0.0],
            })
            .collect(),
        duration: 60.0,
        obstacles: vec![],
        // Too slow to arrive within the horizon: the prediction ends there, not at an
        // arrival.
        params: crate::params::Params {
            v_max: Some(1.0),
            ..two().params
        },
        ..two()
    };
    let live = Live::new(line(MAX_PREDICTED_ROBOTS)).unwrap();
    let horizon = PREDICTION_WORK / MAX_PREDICTED_ROBOTS;
    assert!(horizon < live.scenario().steps());
    let last = live.prediction().times()[live.prediction().samples() - 1];
    assert_close!(last, horizon as f64 * live.scenario().dt, 1e-9);
    let mut live = Live::new(line(MAX_PREDICTED_ROBOTS + 1)).unwrap();
    assert_eq!(live.prediction().samples(), 0);
    assert!(live.prediction().poses().is_empty() && live.prediction().times().is_empty());
    assert_eq!(live.step(10), 10);
    assert_eq!(live.poses().len(), (MAX_PREDICTED_ROBOTS + 1) * POSE_STRIDE);
}

/// During a drag an edit looks DRAG_PREDICTION_WORK / robots steps ahead; the drag's end
/// predicts within PREDICTION_WORK again, the same bits as a prediction made afresh.
#[test]
fn a_drag_predicts_a_shorter_way_and_its_end_in_full() {
    let s = crate::presets::crowd(MAX_PREDICTED_ROBOTS);
    let dt = s.dt;
    let mut live = Live::new(s).unwrap();
    let last = |live: &Live| live.prediction().times()[live.prediction().samples() - 1];
    // In full the crowd is predicted to its arrival, past the drag's horizon.
    let full = last(&live);
    let drag_horizon = (DRAG_PREDICTION_WORK / MAX_PREDICTED_ROBOTS) as f64 * dt;
    assert!(full > 2.0 * drag_horizon, "{full} s");
    live.set_dragging(true);
    assert_eq!(
        last(&live),
        full,
        "a drag that has not moved keeps the prediction"
    );
    let [x, y, theta] = live.scenario().robots[0].start;
    live.move_robot(0, Pose::new(x - 0.5, y, theta)).unwrap();
    assert_close!(last(&live), drag_horizon, 1e-9);
    live.set_dragging(false);
    assert!(last(&live) > 2.0 * drag_horizon, "{} s", last(&live));
    let after = live.prediction().poses().to_vec();
    live.predict();
    assert_eq!(after, live.prediction().poses());
}

/// Trails share a fixed budget: fewer samples per robot in a crowd. When an edit changes
/// the capacity, the newest samples are kept in time order.
#[test]
fn trail_rings_shrink_with_the_crowd_and_keep_the_newest_samples() {
    let s = crate::presets::crowd(100);
    let mut live = Live::new(s).unwrap();
    assert_eq!(live.trails().capacity(), MAX_TRAIL_SAMPLES);
    while live.trails().history_len() < 1_500 {
        live.step(live.record_every);
        assert_eq!(
            live.trails().head(),
            live.trails().recorded() % MAX_TRAIL_SAMPLES
        );
    }
    let (t, pose0) = (live.time(), live.poses()[..3].to_vec());
    let times = live.trails().times().to_vec();
    let head = live.trails().head();
    // 100 more robots, far outside the crowd, at t > 0.
    let mut s = live.scenario().clone();
    for k in 0..100 {
        let x = 1_000.0 + 5.0 * k as f64;
        s.robots.push(RobotSpec {
            start: [x, 0.0, 0.0],
            goal: [x, 50.0, 0.0],
        });
    }
    live.edit(s).unwrap();
    let cap = TRAIL_BUDGET / 200;
    assert!(cap < 1_500);
    assert_eq!(live.trails().capacity(), cap);
    assert_eq!(live.trails().history_len(), cap);
    assert_eq!(live.trails().poses().len(), 200 * cap * POSE_STRIDE);
    assert_eq!(live.trails().times().len(), cap);
    assert_eq!(live.trails().len_of(0), cap);
    assert_eq!(live.trails().len_of(199), 0);
    assert_eq!(live.trails().recorded(), cap);
    assert_eq!(live.trails().head(), live.trails().recorded() % cap);
    // The newest sample is still the pose now, and the times are the newest, in order.
    let newest = (live.trails().head() + cap - 1) % cap;
    assert_eq!(
        &live.trails().poses()[newest * 3..newest * 3 + 3],
        &pose0[..]
    );
    assert_eq!(live.trails().times()[newest], t);
    for k in 0..cap {
        let old = (head + MAX_TRAIL_SAMPLES - cap + k) % MAX_TRAIL_SAMPLES;
        assert_eq!(live.trails().times()[k], times[old]);
    }
}

/// The field samples bin the robots by cell; they are those of a scan over all robots,
/// bit for bit, in a crowd and at a zoom that puts many cells in view.
#[test]
fn binned_field_samples_equal_the_scan() {
    let mut live = Live::new(crate::presets::crowd(300)).unwrap();
    live.step(150);
    for (bounds, side) in [
        ([-200.0, -200.0, 200.0, 200.0], 40),
        ([150.0, -30.0, 230.0, 30.0], 23),
        ([-5e6, -5e6, 5e6, 5e6], 7),
    ] {
        let index = 17;
        let got = live
            .sample_field(index, bounds, side, side)
            .unwrap()
            .to_vec();
        let sim = live.simulation();
        let robot = &sim.robots()[index];
        let params = *sim.params();
        let rs = params.sense_radius;
        for k in 0..side * side {
            let pose = Pose::new(got[4 * k], got[4 * k + 1], robot.pose.theta);
            let neighbours: Vec<Neighbour> = sim
                .robots()
                .iter()
                .enumerate()
                .filter(|&(j, o)| j != index && o.pose.p.distance_squared(pose.p) <= rs * rs)
                .map(|(_, o)| Neighbour {
                    position: o.pose.p,
                    speed: o.last.command.v.abs(),
                    slowest_near: crate::swarm::SLOWEST_UNKNOWN,
                })
                .collect();
            let e = evaluate(
                &params,
                pose,
                pose.error_to(robot.goal),
                robot.last.command.v.abs(),
                sim.obstacles().iter(),
                neighbours.iter().copied(),
            );
            assert_eq!(
                [got[4 * k + 2], got[4 * k + 3]],
                [e.field.x, e.field.y],
                "{bounds:?} {k}"
            );
        }
    }
}

/// Editing a goal at t > 0 keeps the clock and the poses, adds a robot at its start, and
/// keeps the trails of the robots that remain.
#[test]
fn edits_apply_live() {
    let mut live = Live::new(two()).unwrap();
    live.step(200);
    let (t, poses, len) = (live.time(), live.poses().to_vec(), live.trails().len_of(0));
    let mut s = live.scenario().clone();
    s.robots[0].goal = [0.0, 10.0, 0.0];
    s.robots.push(RobotSpec {
        start: [-5.0, -5.0, 0.0],
        goal: [-5.0, 5.0, 0.0],
    });
    live.edit(s).unwrap();
    assert_eq!(live.time(), t);
    assert_eq!(&live.poses()[..6], &poses[..]);
    assert_eq!(&live.poses()[6..8], &[-5.0, -5.0]);
    assert_eq!(live.trails().len_of(0), len);
    assert_eq!(live.trails().len_of(2), 0);
    live.step(1);
    assert_eq!(
        live.trails().len_of(2),
        usize::from(live.steps().is_multiple_of(live.record_every))
    );
    assert_eq!(live.status().len(), 3 * STATUS_STRIDE);
    // Removing a robot drops it.
    let mut s = live.scenario().clone();
    s.robots.truncate(1);
    live.edit(s).unwrap();
    assert_eq!(live.poses().len(), 3);
    assert!(live.prediction().min_pair()[0].is_nan());
}

/// The field at the robot's own position is the field it follows, and it turns with the
/// robot's attitude.
#[test]
fn field_samples_follow_the_robot() {
    let mut live = Live::new(two()).unwrap();
    let e = live.simulation().robots()[0].last.field;
    let grid = live
        .sample_field(0, [0.0, 0.0, 10.0, 10.0], 11, 11)
        .unwrap()
        .to_vec();
    assert_eq!(grid.len(), 11 * 11 * FIELD_STRIDE);
    assert_eq!(&grid[..2], &[0.0, 0.0]);
    assert_close!(grid[2], e.x, 1e-12);
    assert_close!(grid[3], e.y, 1e-12);
    live.move_robot(0, Pose::new(0.0, 0.0, FRAC_PI_2)).unwrap();
    let turned = live
        .sample_field(0, [0.0, 0.0, 10.0, 10.0], 11, 11)
        .unwrap();
    assert!((turned[2] - grid[2]).abs() + (turned[3] - grid[3]).abs() > 0.1);
}

#[test]
fn integral_curves_end_at_the_goal() {
    let mut live = Live::new(two()).unwrap();
    let c = live
        .integral_curves(0, FRAC_PI_2, [-20.0, -20.0, 20.0, 20.0], 3)
        .unwrap();
    assert_eq!(c.len(), 9 * CURVE_POINTS * 2);
    let end = (CURVE_POINTS - 1) * 2;
    assert_close!(
        DVec2::new(c[end], c[end + 1]).distance(DVec2::new(10.0, 0.0)),
        0.0,
        0.1
    );
}
