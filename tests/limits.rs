//! Robots with limits (docs/notes-on-the-paper.md §10, docs/book/src/safety.md): a turn rate
//! beyond `ω_max` slows the robot so that it keeps the curvature the field prescribes, no
//! command ever exceeds `v_max` or `ω_max`, and limited robots still arrive with their
//! heading, with no violation.
//!
//! Native only: these run a few thousand simulated seconds (seconds optimised).
#![cfg(not(target_arch = "wasm32"))]

use dvf::presets::{preset, PRESETS, REAL_ROBOT};
use dvf::scenario::Scenario;
use dvf::sweep::{scenario, sweep, Family, Recipe};
use dvf::{command, Command, Params, Pose, Simulation};

/// Runs `s` to its end and checks every command of every step against the limits (exactly:
/// the limits are clamps), then that every robot arrived and nothing collided.
fn assert_limited_run_arrives(s: &Scenario) {
    let (v_max, omega_max) = (s.params.v_max.unwrap(), s.params.omega_max.unwrap());
    let mut sim = Simulation::new(s).expect("a valid scenario");
    for _ in 0..s.steps() {
        sim.step();
        for (i, r) in sim.robots().iter().enumerate() {
            let c = r.last.command;
            assert!(
                c.v.abs() <= v_max && c.omega.abs() <= omega_max,
                "{}: robot {i} at {} s commands {c:?} beyond ({v_max}, {omega_max})",
                s.name,
                sim.time()
            );
        }
    }
    let report = sim.report();
    assert_eq!(report.violations, 0, "{}: violations", s.name);
    for (i, r) in report.robots.iter().enumerate() {
        assert!(
            r.converged_at.is_some(),
            "{}: robot {i} ended {:?} (position error {}, heading error {})",
            s.name,
            r.final_pose,
            r.position_error,
            r.heading_error
        );
    }
}

/// Where the field asks for a turn rate beyond `ω_max`, the limited command turns at `ω_max`
/// and keeps the curvature `ω/v` of the unlimited one (to a relative 1e-12: one division and
/// one product apart); where it does not, the command is the unlimited one, bit for bit.
#[test]
fn a_turn_beyond_the_limit_keeps_the_curvature() {
    let free = Params::default();
    let limited = Params {
        omega_max: Some(5.0),
        ..free
    };
    let goal = Pose::new(10.0, -3.0, 0.4);
    let (mut cut, mut kept) = (0, 0);
    for k in 0..400 {
        let a = k as f64 * 0.37;
        let pose = Pose::new(
            25.0 * (0.7 * a).cos(),
            25.0 * (1.3 * a).sin(),
            (2.9 * a) % 6.2 - 3.1,
        );
        let c = command(&free, pose, goal, &[], &[]);
        let l = command(&limited, pose, goal, &[], &[]);
        if c.omega.abs() > 5.0 {
            cut += 1;
            assert_eq!(l.omega, 5.0_f64.copysign(c.omega), "{pose:?}");
            let (k_free, k_limited) = (c.omega / c.v, l.omega / l.v);
            assert!(
                (k_limited - k_free).abs() <= 1e-12 * k_free.abs(),
                "{pose:?}: curvature {k_limited} against {k_free}"
            );
            assert!(l.v.abs() < c.v.abs() || c.v == 0.0, "{pose:?}: not slowed");
        } else {
            kept += 1;
            assert_eq!(l, c, "{pose:?}");
        }
    }
    assert!(
        cut > 50 && kept > 50,
        "{cut} cut, {kept} kept: both cases drawn"
    );
}

/// One robot in free space follows the path of the unlimited controller: the turn-rate limit
/// rescales time along the integral curve (docs/notes-on-the-paper.md §10). Every position of
/// the limited run lies within 0.02 of the unlimited run's path (as the polyline of its
/// positions), and it arrives later. Bound: with `dt = 0.01` a held command departs from the
/// continuous curve by `O(v·dt·ω·dt)` per step, which the unlimited run's `|ω| ≤ k_a·π/2 + k_ω·π`
/// and `|v| ≤ 60` keep to a few hundredths over the turns at the start.
#[test]
fn one_robot_keeps_its_path_under_the_turn_rate_limit() {
    let json = |limit: &str| {
        format!(
            r#"{{"duration": 120, "params": {{"omega_max": {limit}}},
                "robots": [{{"start": [0, 0, 2.5], "goal": [30, 20, -1.0]}}]}}"#
        )
    };
    let trace = |s: &Scenario| {
        let mut sim = Simulation::new(s).expect("a valid scenario");
        let mut points = vec![sim.robots()[0].pose.p];
        for _ in 0..s.steps() {
            sim.step();
            points.push(sim.robots()[0].pose.p);
        }
        (points, sim.report())
    };
    let (free, free_report) = trace(&Scenario::from_json(&json("null")).unwrap());
    let (limited, limited_report) = trace(&Scenario::from_json(&json("1")).unwrap());
    let distance_to_path = |p: glam::DVec2| {
        free.windows(2)
            .map(|w| {
                let (a, b) = (w[0], w[1]);
                let ab = b - a;
                let t = if ab.length_squared() == 0.0 {
                    0.0
                } else {
                    ((p - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0)
                };
                p.distance(a + t * ab)
            })
            .fold(f64::INFINITY, f64::min)
    };
    let worst = limited
        .iter()
        .step_by(10)
        .map(|&p| distance_to_path(p))
        .fold(0.0, f64::max);
    assert!(
        worst < 0.02,
        "the limited path strays {worst} from the free one"
    );
    let (tf, tl) = (
        free_report.robots[0].converged_at.expect("free arrives"),
        limited_report.robots[0]
            .converged_at
            .expect("limited arrives"),
    );
    assert!(
        tl > tf,
        "the limited robot arrives at {tl}, the free one at {tf}"
    );
}

/// Every "real robot" preset carries the small robot's limits scaled to its safe radius, and
/// every one arrives within its duration without exceeding them.
#[test]
fn real_robot_presets_arrive_within_their_limits() {
    let real: Vec<_> = PRESETS
        .iter()
        .filter(|p| p.name.starts_with("real-"))
        .collect();
    assert_eq!(
        real.len(),
        6,
        "the four examples (five scenes) and the formation"
    );
    for p in real {
        let s = preset(p.name).unwrap();
        let plain = preset(p.name.trim_start_matches("real-")).unwrap();
        let (v_max, omega_max) = REAL_ROBOT.limits(s.params.safe_radius);
        assert_eq!(
            (s.params.v_max, s.params.omega_max),
            (Some(v_max), Some(omega_max))
        );
        assert_eq!(
            (plain.robots, plain.obstacles),
            (s.robots.clone(), s.obstacles.clone())
        );
        assert_limited_run_arrives(&s);
    }
}

/// A sweep whose recipe fixes the limits (`Recipe::limited`): a few scenarios of each family
/// at `v_max = ω_max = 2` and at 1, 1 carry the limits, and all their robots arrive with no
/// violation. 900 s, so that no slow robot runs out of time. Not every scene arrives in full
/// (formation seed 1 at 1, 1 leaves three robots rocking at a switch,
/// docs/notes-on-the-paper.md §10): the formation family starts at seed 2 and the dense one at
/// seed 1, and the rates over hundreds of scenes are in docs/book/src/safety.md.
#[test]
fn limited_sweeps_arrive_without_violation() {
    for (family, first, count) in [
        (Family::Random, 0, 3),
        (Family::Formation, 2, 2),
        (Family::Dense, 1, 1),
    ] {
        for (v, w) in [(2.0, 2.0), (1.0, 1.0)] {
            let recipe = Recipe {
                duration: 900.0,
                ..Recipe::of(family).limited(v, w)
            };
            let s = scenario(&recipe, first).expect("a scene");
            assert_eq!((s.params.v_max, s.params.omega_max), (Some(v), Some(w)));
            let summary = sweep(&recipe, first, count, |_, _, _| {});
            assert_eq!(summary.violations, 0, "{family:?} at {v}, {w}");
            assert_eq!(
                summary.converged, summary.robots,
                "{family:?} at {v}, {w}: {:?}",
                summary.failures
            );
        }
    }
}

/// Only a limit that binds changes a command: with limits far above anything the field asks
/// for, the command is the unlimited one, bit for bit.
#[test]
fn limits_that_do_not_bind_change_nothing() {
    let free = Params::default();
    let loose = Params {
        v_max: Some(1e6),
        omega_max: Some(1e6),
        ..free
    };
    for k in 0..100 {
        let a = k as f64;
        let pose = Pose::new(
            40.0 * a.sin(),
            30.0 * (0.5 * a).cos(),
            (1.7 * a) % 6.0 - 3.0,
        );
        let goal = Pose::new(0.0, 0.0, 1.0);
        let c: Command = command(&free, pose, goal, &[], &[]);
        assert_eq!(command(&loose, pose, goal, &[], &[]), c);
    }
}

/// With `ω_max` set, the virtual obstacle's exit asks where the robot's field leads, not where
/// its heading points (src/controller.rs, docs/notes-on-the-paper.md §10). Hand-worked scene:
/// a robot at the origin heading `θ = −1.4` (down, a little right), its goal 20 ahead along
/// +x, a neighbour at (2, 2) moving as fast as it does. The heading leads away from the
/// neighbour and the goal field towards it. Without limits the neighbour is no candidate (the
/// heading is what the exit asks) and the robot follows its goal field; with `ω_max = 2` it
/// circles the midpoint (1, 1): `keep_c = 0` (1.41 from it, inside `R_c = 3`), its field is the
/// tangent `Γ_r⊥ = R(π/2)(p − p̃_o) = (1, −1)` (the one with a positive projection on the body
/// Y axis), `δ = −π/4 − θ = 0.6146`, `ω = k_a·δ = 6.146` cut to `ω_max = 2`, and
/// `v = v_c·ω_max/|ω| = 2·2/6.146`. Tolerance 1e-12: a few roundings of the same formulas.
#[test]
fn with_a_turn_rate_limit_the_exit_follows_the_field() {
    use dvf::controller::evaluate;
    use dvf::swarm::{Neighbour, SLOWEST_UNKNOWN};
    use glam::DVec2;
    let theta = -1.4;
    let pose = Pose::new(0.0, 0.0, theta);
    let goal = Pose::new(20.0, 0.0, 0.0);
    let neighbour = Neighbour {
        position: DVec2::new(2.0, 2.0),
        speed: 1.0,
        slowest_near: SLOWEST_UNKNOWN,
    };
    let to = neighbour.position - pose.p;
    let run = |params: &Params| evaluate(params, pose, pose.error_to(goal), 1.0, &[], [neighbour]);
    let free = run(&Params::default());
    let limited = run(&Params {
        omega_max: Some(2.0),
        ..Params::default()
    });
    // The premises: the goal field leads towards the neighbour, the direction of motion (the
    // heading, reversed for a goal behind) away from it.
    let h = DVec2::new(theta.cos(), theta.sin());
    let motion = if h.dot(free.goal_field) < 0.0 { -h } else { h };
    assert!(free.goal_field.dot(to) > 0.0, "{:?}", free.goal_field);
    assert!(motion.dot(to) < 0.0, "{motion:?}");

    assert_eq!(free.virtual_obstacle, None, "unlimited: heading leads away");
    assert_eq!(free.robot_keep, 1.0);
    assert_eq!(limited.virtual_obstacle, Some(DVec2::new(1.0, 1.0)));
    assert_eq!(limited.robot_keep, 0.0);
    assert!(
        (limited.field - DVec2::new(1.0, -1.0)).length() < 1e-12,
        "the tangent: {:?}",
        limited.field
    );
    let delta = -std::f64::consts::FRAC_PI_4 - theta;
    let asked = Params::default().k_a * delta;
    let expected = Command {
        v: Params::default().avoid_speed * 2.0 / asked,
        omega: 2.0,
    };
    let c = limited.command;
    assert_eq!(c.omega, expected.omega, "{c:?}");
    assert!(
        (c.v - expected.v).abs() < 1e-12,
        "{c:?} against {expected:?}"
    );
}

/// The barrier's left turn (src/safety/mod.rs, `filter`), cut by `ω_max`, slows the robot by
/// the same factor: the command keeps the curvature `ω/v` the turn asks for. Scene: a robot at
/// the origin heading +y with `(v, ω) = (1, 0.5)`, its field `(1, 0)` pointing at a neighbour
/// at (2.05, 0), 0.05 beyond the safe distance 2. The barrier (`α = 5`, `dt = 0.01`) allows
/// `½α·0.05 = 0.125` along the field of the speed `k_v|Γ| = 1` wanted: held by 0.875, it turns
/// the robot left by `k_a·0.875·π/2 = 13.74`, and the step (to the left, away from the
/// neighbour) is not braked. With `ω_max = 2` the turn rate is 2 and the speed
/// `1·2/14.24`: the same curvature as the unlimited command, to a relative 1e-12 (one
/// division and one product apart).
#[test]
fn a_barrier_turn_cut_by_the_limit_keeps_its_curvature() {
    use dvf::safety::{filter, Constraints};
    use glam::DVec2;
    let pose = Pose::new(0.0, 0.0, std::f64::consts::FRAC_PI_2);
    let c = Command { v: 1.0, omega: 0.5 };
    let field = DVec2::X;
    let neighbour = DVec2::new(2.05, 0.0);
    let run = |params: &Params| {
        filter(
            &mut Constraints::new(),
            params,
            0.01,
            pose,
            c,
            field,
            [neighbour],
            [],
        )
        .0
    };
    let free = run(&Params::default());
    let limited = run(&Params {
        omega_max: Some(2.0),
        ..Params::default()
    });
    // Hand-worked turn, to 1e-6: the barrier keeps distances a relative 1e-9 beyond the
    // limit, 2e-9 of the 0.05 left, which moves the held part by 5e-9 and the turn by 8e-8.
    let turned = 0.5 + 10.0 * 0.875 * std::f64::consts::FRAC_PI_2;
    assert!(
        (free.omega - turned).abs() < 1e-6,
        "{free:?} against {turned}"
    );
    assert_eq!(free.v, c.v, "the left turn is not braked");
    assert_eq!(limited.omega, 2.0, "{limited:?}");
    let (k_free, k_limited) = (free.omega / free.v, limited.omega / limited.v);
    assert!(
        (k_limited - k_free).abs() <= 1e-12 * k_free.abs(),
        "curvature {k_limited} against {k_free}"
    );
}
