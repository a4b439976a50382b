//! The grid neighbour search ([`Neighbourhood::Grid`]) against the all-pairs reference
//! ([`Neighbourhood::AllPairs`]): the same bits at every step (poses, heading errors, the
//! controller's evaluations) and the same report, on every preset, on circle crowds and on
//! random scenarios. They run natively, in Node (`wasm-pack test --node`) and in Chromium
//! (`make test-browser`).

#[path = "../src/testing.rs"]
mod testing;
use testing::test;

use dvf::presets::{circle_swap, crowd, crowd_with_obstacles, PRESETS};
use dvf::sim::{Neighbourhood, Robot, Simulation};
use dvf::sweep::{random_scenario, Recipe};
use dvf::Scenario;

/// Every number of a robot's state and of the controller's last evaluation, as bits.
fn bits(r: &Robot) -> Vec<u64> {
    let e = &r.last;
    let mut v = vec![
        r.pose.p.x,
        r.pose.p.y,
        r.pose.theta,
        r.heading_error,
        e.command.v,
        e.command.omega,
        e.field.x,
        e.field.y,
        e.goal_field.x,
        e.goal_field.y,
        e.obstacle_keep,
        e.robot_keep,
    ];
    if let Some(o) = e.virtual_obstacle {
        v.extend([o.x, o.y]);
    }
    v.into_iter().map(f64::to_bits).collect()
}

/// Runs `s` for at most `steps` steps both ways and asserts the same bits at every step and
/// the same report.
fn same_bits(s: &Scenario, steps: usize) {
    let mut grid = Simulation::with_neighbourhood(s, Neighbourhood::Grid).unwrap();
    let mut all = Simulation::with_neighbourhood(s, Neighbourhood::AllPairs).unwrap();
    for k in 0..=steps.min(s.steps()) {
        if k > 0 {
            grid.step();
            all.step();
        }
        for (i, (a, b)) in grid.robots().iter().zip(all.robots()).enumerate() {
            assert_eq!(
                bits(a),
                bits(b),
                "{}: robot {i} differs at step {k}: grid {a:?}, all pairs {b:?}",
                s.name
            );
        }
    }
    // The report's floats as bits: serde_json writes the shortest string that reads back to
    // the same f64 (and keeps the sign of −0).
    let (a, b) = (grid.report(), all.report());
    assert_eq!(
        serde_json::to_string(&a).unwrap(),
        serde_json::to_string(&b).unwrap(),
        "{}: reports differ",
        s.name
    );
}

#[test]
fn every_preset_gives_the_same_bits() {
    for p in PRESETS {
        same_bits(&p.scenario(), usize::MAX);
    }
}

/// Crowds large enough for a grid of many cells, through the jam at the centre.
#[test]
fn crowds_give_the_same_bits() {
    same_bits(&crowd(60), 3000);
    same_bits(&circle_swap(24, 12.0), 2000);
    // A crowd of 150 at a spacing of 4: about 16 × 16 cells of the sensing radius.
    let mut s = crowd(150);
    s.duration = 20.0;
    same_bits(&s, usize::MAX);
}

/// A sensing radius shorter than the spacing of the starts: at first no pair lies within the
/// grid's reach, and the closest pair comes from the fallback over all pairs; violations are
/// counted (the barrier is off).
#[test]
fn short_sensing_and_violations_give_the_same_bits() {
    let mut s = circle_swap(30, 20.0);
    s.params.sense_radius = 2.5;
    s.params.barrier_rate = None;
    s.duration = 30.0;
    let r = dvf::run(&s).unwrap();
    assert!(r.violations > 0, "the scenario should violate: {r:?}");
    same_bits(&s, usize::MAX);
}

#[test]
fn random_scenarios_give_the_same_bits() {
    let recipe = Recipe {
        duration: 40.0,
        ..Recipe::default()
    };
    let mut done = 0;
    for seed in 0..12 {
        if let Some(s) = random_scenario(&recipe, seed) {
            same_bits(&s, usize::MAX);
            done += 1;
        }
    }
    assert!(done >= 10, "only {done} random scenarios could be placed");
}

/// Many obstacles (the obstacle cells hold a few per cell), and robots that enter discs whose
/// rings are too thin to turn them (the barrier is off): the same sensing, clearances and
/// violation events as the scan over every obstacle.
#[test]
fn obstacle_fields_give_the_same_bits() {
    let mut s = crowd_with_obstacles(150, 40);
    s.duration = 30.0;
    same_bits(&s, usize::MAX);
    let mut thin = Scenario::from_json(
        r#"{"duration": 8, "params": {"barrier_rate": null},
            "robots": [{"start": [-50, 0, 0], "goal": [50, 0, 0]},
                       {"start": [-50, 20, 0], "goal": [50, 20, 0]},
                       {"start": [50, -20, 3.14159], "goal": [-50, -20, 3.14159]}],
            "obstacles": [{"center": [0, 0], "radius": 5, "influence": 5.01},
                          {"center": [0, 20], "radius": 5, "influence": 5.01},
                          {"center": [0, -20], "radius": 5, "influence": 5.01},
                          {"center": [300, 300], "radius": 1, "influence": 2}]}"#,
    )
    .unwrap();
    let r = dvf::run(&thin).unwrap();
    assert!(r.violations >= 3, "every robot should enter a disc: {r:?}");
    same_bits(&thin, usize::MAX);
    // An obstacle larger than the cells allow is listed everywhere.
    thin.obstacles.push(dvf::Obstacle {
        center: glam::DVec2::new(0.0, 1e5),
        radius: 9e4,
        influence: 9.1e4,
    });
    same_bits(&thin, usize::MAX);
}

/// A step of a large crowd evaluates its robots on rayon's threads (natively): the same bits
/// on one thread as on two, as from outside a pool (the global pool, whose thread count is the
/// machine's: the step moves onto it) and as with the parallel step turned off, at every step,
/// and the same report. 100 robots more than `PARALLEL_FROM` among obstacles, through the
/// first 4 s.
#[cfg(not(target_arch = "wasm32"))]
#[test]
fn threads_give_the_same_bits() {
    let s = crowd_with_obstacles(dvf::sim::PARALLEL_FROM + 100, 12);
    let pool = |threads| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
    };
    let (one, two) = (pool(1), pool(2));
    let mut a = Simulation::new(&s).unwrap();
    let mut b = Simulation::new(&s).unwrap();
    let mut c = Simulation::new(&s).unwrap();
    c.set_parallel(false);
    let mut d = Simulation::new(&s).unwrap();
    for k in 1..=400 {
        one.install(|| a.step());
        two.install(|| b.step());
        c.step();
        d.step();
        for (i, (((x, y), z), w)) in a
            .robots()
            .iter()
            .zip(b.robots())
            .zip(c.robots())
            .zip(d.robots())
            .enumerate()
        {
            assert_eq!(
                bits(x),
                bits(w),
                "robot {i} at step {k}: one thread, global pool"
            );
            assert_eq!(
                bits(x),
                bits(y),
                "robot {i} at step {k}: one thread, two threads"
            );
            assert_eq!(
                bits(x),
                bits(z),
                "robot {i} at step {k}: one thread, serial"
            );
        }
    }
    let report = |sim: &Simulation| serde_json::to_string(&sim.report()).unwrap();
    assert_eq!(report(&a), report(&b));
    assert_eq!(report(&a), report(&c));
    assert_eq!(report(&a), report(&d));
}
