//! The planner's promises (docs/book/src/safety.md): robots that meet go round each other and on to
//! their goals, never closer than `2·r_ij`, never inside an obstacle; scenarios that break a
//! promise from the start are refused with a message naming the field; every step size the
//! validation accepts converges.
//!
//! Native only: these run thousands of simulated seconds (a few seconds optimised).
#![cfg(not(target_arch = "wasm32"))]

use dvf::presets::{circle_swap, line_swap, preset, PRESETS};
use dvf::scenario::Scenario;
use dvf::sim::{run, Report};
use dvf::sweep::{sweep, Recipe};
use dvf::Obstacle;
use glam::DVec2;

/// Every robot within tolerance at the end and no violation event.
fn assert_kept(name: &str, report: &Report) {
    assert_eq!(report.violations, 0, "{name}: violations");
    for (i, r) in report.robots.iter().enumerate() {
        assert!(
            r.converged_at.is_some(),
            "{name}: robot {i} ended {:?} (position error {}, heading error {})",
            r.final_pose,
            r.position_error,
            r.heading_error
        );
    }
}

/// Antipodal swaps of 2 … 24 robots on the paper's circle (radius 20), on a wider one, and on
/// the narrowest that keeps 24 goals `3·r_ij` apart (radius 12): all robots of a swap meet in
/// the middle at once, the hardest case for a cluster, and on the narrow circle each robot
/// must then slip into a slot between robots already parked.
#[test]
fn antipodal_circle_swaps_of_2_to_24_robots_all_arrive() {
    for radius in [12.0, 20.0, 30.0] {
        for n in 2..=24 {
            let s = circle_swap(n, radius);
            assert_kept(&s.name, &run(&s).unwrap());
        }
    }
}

/// Line-to-line swaps of 2 … 10 robots, 10 apart (the paper's spacing) and 5 apart.
#[test]
fn line_swaps_of_2_to_10_robots_all_arrive() {
    for spacing in [10.0, 5.0] {
        for n in 2..=10 {
            let s = line_swap(n, spacing);
            assert_kept(&s.name, &run(&s).unwrap());
        }
    }
}

/// A fixed-seed sample of the random scenarios of `dvf sweep` (4 … 16 robots, 0 … 5
/// obstacles, 100 × 100, 120 s, default parameters): at least 99 % of robots converge and no
/// violation happens. docs/book/src/safety.md quotes the full 1,000-scenario sweep.
#[test]
fn random_scenarios_converge_without_violation() {
    let summary = sweep(&Recipe::default(), 0, 200, |_, _, _| {});
    assert_eq!(summary.skipped, 0);
    assert_eq!(summary.violations, 0, "{:?}", summary.failures);
    assert!(
        summary.success_rate >= Some(0.99),
        "{} of {} converged: {:?}",
        summary.converged,
        summary.robots,
        summary.failures
    );
}

/// With the barrier off the field alone is the paper's promise, which random scenarios break:
/// the barrier is what the zero above rests on.
#[test]
fn without_the_barrier_random_scenarios_collide() {
    let mut recipe = Recipe::default();
    recipe.params.barrier_rate = None;
    let summary = sweep(&recipe, 0, 200, |_, _, _| {});
    assert!(summary.violations > 0, "{summary:?}");
}

/// Every step size from 0.001 s up to the largest the gains allow converges on the paper's
/// examples with no violation; 0.1 s is refused, and the message says why and what to use.
/// The formation preset, not one of the paper's examples, is left out: at dt = 0.02 one of
/// its robots stays outside the grid (docs/book/src/known-limits.md); every step size keeps it safe.
#[test]
fn step_sizes_from_a_millisecond_to_the_limit_converge() {
    for dt in [0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.08, 0.099] {
        for p in PRESETS.iter().filter(|p| !p.name.starts_with("formation")) {
            let mut s = p.scenario();
            s.dt = dt;
            s.duration = s.duration.max(40.0);
            s.validate()
                .unwrap_or_else(|e| panic!("{} at dt {dt}: {e}", p.name));
            assert_kept(&format!("{} at dt {dt}", p.name), &run(&s).unwrap());
        }
    }
    let mut s = preset("example4-obstacle-formation").unwrap();
    s.dt = 0.1;
    let e = s.validate().unwrap_err().to_string();
    assert!(e.starts_with("dt: 0.1 s is too large for the gains"), "{e}");
    assert!(e.contains("use dt < 0.1"), "{e}");
}

fn two_robots(a: [f64; 3], b: [f64; 3], ga: [f64; 3], gb: [f64; 3]) -> Scenario {
    let text = serde_json::json!({
        "robots": [{"start": a, "goal": ga}, {"start": b, "goal": gb}],
    })
    .to_string();
    Scenario::from_json(&text).expect("two well separated robots")
}

/// Scenarios that break a promise before the first step are refused, naming the field.
#[test]
fn broken_promises_at_the_start_are_refused() {
    let ok = two_robots(
        [0.0, 0.0, 0.0],
        [10.0, 0.0, 0.0],
        [0.0, 30.0, 0.0],
        [10.0, 30.0, 0.0],
    );
    ok.validate().unwrap();
    let message = |s: Scenario| s.validate().unwrap_err().to_string();

    // Starting inside another robot's safe disc (2·r_ij = 2).
    let mut s = ok.clone();
    s.robots[1].start = [1.5, 0.0, 0.0];
    let e = message(s);
    assert!(
        e.starts_with("robots[1].start: is 1.5 from robots[0].start"),
        "{e}"
    );
    // Goals closer than the safe distance: both cannot settle.
    let mut s = ok.clone();
    s.robots[1].goal = [0.0, 31.0, 0.0];
    let e = message(s);
    assert!(
        e.starts_with("robots[1].goal: is 1 from robots[0].goal"),
        "{e}"
    );
    // The same goals are fine for independent runs (the robots never meet).
    let mut s = ok.clone();
    s.robots[1].goal = [0.0, 31.0, 0.0];
    s.independent = true;
    s.validate().unwrap();
    // A goal inside an obstacle's influence ring, and inside its disc.
    let mut s = ok.clone();
    s.obstacles.push(Obstacle {
        center: DVec2::new(0.0, 20.0),
        radius: 3.0,
        influence: 12.0,
    });
    let e = message(s.clone());
    assert!(
        e.starts_with("robots[0].goal: lies in the influence ring of obstacles[0]"),
        "{e}"
    );
    s.obstacles[0].radius = 11.0;
    let e = message(s);
    assert!(
        e.starts_with("robots[0].goal: lies inside obstacles[0]"),
        "{e}"
    );
    // A start inside an obstacle.
    let mut s = ok.clone();
    s.obstacles.push(Obstacle {
        center: DVec2::new(10.0, 1.0),
        radius: 2.0,
        influence: 3.0,
    });
    let e = message(s);
    assert!(
        e.starts_with("robots[1].start: lies inside obstacles[0]"),
        "{e}"
    );
    // A barrier too fast for the step.
    let mut s = ok.clone();
    s.params.barrier_rate = Some(60.0);
    let e = message(s);
    assert!(
        e.starts_with("dt: 0.01 s is too large for params.barrier_rate"),
        "{e}"
    );
}

/// A goal just outside a ring, inside its transition band (a case `dvf sweep` found): the
/// obstacle lets the robot go once the goal is nearer than its surface. With the paper's blend
/// the robot stalls at the goal position with its heading 1.3 rad off, held by the circular
/// field, which does not vanish at the goal as the goal field does.
#[test]
fn a_goal_in_the_transition_band_is_reached() {
    let text = serde_json::json!({
        "robots": [{"start": [7.333, 83.354, 0.319], "goal": [4.4743, 43.4466, 2.1195]}],
        "obstacles": [{"center": [14.7634, 45.1825], "radius": 7.5616, "influence": 9.8337}],
        "duration": 60.0,
    })
    .to_string();
    let s = Scenario::from_json(&text).unwrap();
    assert_kept("goal in the band", &run(&s).unwrap());
    let mut paper = s.clone();
    paper.params.avoidance = dvf::params::Avoidance::Paper;
    let r = run(&paper).unwrap();
    assert!(r.robots[0].heading_error > 1.0, "{:?}", r.robots[0]);
}
