//! Properties of the method over many random inputs: convergence statistics from random pose
//! pairs (seeded, so every run sees the same pairs), finiteness among random obstacles, the
//! SE(2) log map, and the scenario parser on arbitrary text.
#![cfg(not(target_arch = "wasm32"))]

use dvf::params::Params;
use dvf::scenario::{RobotSpec, Scenario};
use dvf::se2::{exp, log, phi, Pose};
use dvf::sim::Simulation;
#[path = "../src/testing.rs"]
mod testing;
use dvf::Obstacle;
use glam::DVec2;
use proptest::prelude::*;
use proptest::test_runner::{Config, FileFailurePersistence, RngAlgorithm, TestRng, TestRunner};
use std::f64::consts::PI;
use testing::XorShift;

/// Convergence as the acceptance criteria define it: position error ≤ 0.05 and heading error ≤ 0.02 rad
/// (the crate's default `tol_position` / `tol_heading`, restated here so that a change of the
/// defaults does not silently loosen this test).
const TOL_POSITION: f64 = 0.05;
const TOL_HEADING: f64 = 0.02;

fn is_finite_pose(p: Pose) -> bool {
    p.p.is_finite() && p.theta.is_finite()
}

/// Outcome of one batch of random pose pairs.
struct Stats {
    pairs: usize,
    converged: usize,
    worst_position: f64,
    worst_heading: f64,
    /// Pairs that failed, for the failure message: (start, goal, position error, heading error).
    failures: Vec<([f64; 3], [f64; 3], f64, f64)>,
}

/// Runs `pairs` random pose pairs (start and goal uniform in [0, 100]², headings uniform in
/// (−π, π]) for 60 s at dt 0.01 under `params`, checking after every step that every pose and
/// command is finite.
fn random_pairs(seed: u64, pairs: usize, params: Params) -> Stats {
    // Independent robots do not sense each other, so one scenario of many robots is many
    // single-robot runs; batches keep the per-step bookkeeping small.
    const BATCH: usize = 100;
    let mut rng = XorShift(seed);
    let mut stats = Stats {
        pairs,
        converged: 0,
        worst_position: 0.0,
        worst_heading: 0.0,
        failures: Vec::new(),
    };
    let mut left = pairs;
    while left > 0 {
        let n = left.min(BATCH);
        left -= n;
        let robots: Vec<RobotSpec> = (0..n)
            .map(|_| {
                let start = [rng.range(0.0, 100.0), rng.range(0.0, 100.0), rng.heading()];
                let goal = [rng.range(0.0, 100.0), rng.range(0.0, 100.0), rng.heading()];
                RobotSpec { start, goal }
            })
            .collect();
        let s = Scenario {
            planner: dvf::planner::Spec::default(),
            name: "random pairs".into(),
            bounds: None,
            duration: 60.0,
            dt: 0.01,
            params,
            independent: true,
            robots: robots.clone(),
            obstacles: vec![],
        };
        s.validate().expect("a valid scenario");
        assert_eq!(s.steps(), 6000);
        let mut sim = Simulation::new(&s).unwrap();
        for step in 1..=s.steps() {
            sim.step();
            for (i, r) in sim.robots().iter().enumerate() {
                let c = r.last.command;
                assert!(
                    is_finite_pose(r.pose) && c.v.is_finite() && c.omega.is_finite(),
                    "step {step}: robot {:?} reached {:?} with command {c:?}",
                    robots[i],
                    r.pose
                );
            }
        }
        for (spec, r) in robots.iter().zip(sim.robots()) {
            let (ep, eh) = (r.position_error(), r.heading_error_abs());
            stats.worst_position = stats.worst_position.max(ep);
            stats.worst_heading = stats.worst_heading.max(eh);
            if ep <= TOL_POSITION && eh <= TOL_HEADING {
                stats.converged += 1;
            } else {
                stats.failures.push((spec.start, spec.goal, ep, eh));
            }
        }
    }
    stats
}

fn check_convergence(label: &str, seed: u64, pairs: usize, params: Params) {
    let s = random_pairs(seed, pairs, params);
    let rate = s.converged as f64 / s.pairs as f64;
    println!(
        "{label}: {}/{} converged ({:.2} %), worst position error {:.3e}, worst heading error {:.3e} rad",
        s.converged,
        s.pairs,
        100.0 * rate,
        s.worst_position,
        s.worst_heading
    );
    for f in &s.failures {
        println!(
            "  not converged: start {:?} goal {:?}: errors {:.3e}, {:.3e}",
            f.0, f.1, f.2, f.3
        );
    }
    // The acceptance rate of the issue. With the seed fixed this is a deterministic check of
    // these pairs, not a statistical one.
    assert!(
        rate >= 0.995,
        "{label}: only {}/{} converged; first failures (start, goal, errors): {:?}",
        s.converged,
        s.pairs,
        &s.failures[..s.failures.len().min(3)]
    );
}

/// Pose pairs per gain set: 99.5 % of 4000 allows 20 failures, so a single unlucky pair
/// cannot decide the outcome, and the run still takes about a second.
const PAIRS: usize = 4000;

#[test]
fn random_pose_pairs_converge_with_default_gains() {
    check_convergence("default gains", 0x5EED_0001, PAIRS, Params::default());
}

#[test]
fn random_pose_pairs_converge_with_unit_position_gains() {
    let params = Params {
        k_v: 1.0,
        k_omega: 1.0,
        k_a: 10.0,
        ..Params::default()
    };
    check_convergence("k_v = 1, k_omega = 1, k_a = 10", 0x5EED_0002, PAIRS, params);
}

/// The default fade `g = 1e-6` also finishes the heading for an alignment gain only 2.5 times
/// the attitude gain, where the residual equilibrium `k_ω θ̃ = k_a·fade·atan(…)` of a larger
/// `g` leaves pairs above the heading tolerance (docs/notes-on-the-paper.md §3: `g = 1e-3` left
/// 52 of 500 such pairs unconverged).
#[test]
fn random_pose_pairs_converge_with_a_low_alignment_gain() {
    let params = Params {
        k_a: 2.5,
        ..Params::default()
    };
    check_convergence("k_a = 2.5 k_omega", 0x5EED_0003, 1000, params);
}

// ---------------------------------------------------------------------------------------------
// Random obstacle fields.

#[derive(Clone, Debug)]
struct Field {
    start: [f64; 3],
    goal: [f64; 3],
    obstacles: Vec<Obstacle>,
}

/// One robot from the left of a 60 × 20 strip to its right, 0–5 obstacles in between
/// (overlaps allowed: the paper does not cover them, the simulation must still stay finite).
fn obstacle_field() -> impl Strategy<Value = Field> {
    let obstacle =
        (-15.0..15.0f64, -10.0..10.0f64, 0.5..3.0f64, 0.5..3.0f64).prop_map(|(x, y, r, extra)| {
            Obstacle {
                center: DVec2::new(x, y),
                radius: r,
                influence: r + extra,
            }
        });
    let pose = |x0: f64, x1: f64| (x0..x1, -10.0..10.0f64, -PI..=PI);
    (
        pose(-30.0, -15.0),
        pose(15.0, 30.0),
        proptest::collection::vec(obstacle, 0..=5),
    )
        .prop_map(|((sx, sy, st), (gx, gy, gt), obstacles)| Field {
            start: [sx, sy, st],
            goal: [gx, gy, gt],
            obstacles,
        })
        .prop_filter(
            "start and goal outside every influence ring and transition band",
            |f| {
                let eps = Params::default().transition_width;
                f.obstacles.iter().all(|o| {
                    [f.start, f.goal]
                        .iter()
                        .all(|p| DVec2::new(p[0], p[1]).distance(o.center) > o.influence + eps)
                })
            },
        )
}

/// Whether two influence rings (with their transition bands) intersect: the case the paper
/// does not cover, where two circular fields and the goal field are blended at once.
fn rings_overlap(obstacles: &[Obstacle]) -> bool {
    let eps = Params::default().transition_width;
    obstacles.iter().enumerate().any(|(i, a)| {
        obstacles[i + 1..]
            .iter()
            .any(|b| a.center.distance(b.center) < a.influence + b.influence + 2.0 * eps)
    })
}

#[test]
fn random_obstacle_fields_never_produce_non_finite_states() {
    let config = Config {
        cases: 256,
        // The seed is fixed: a failure reproduces by running the test again.
        failure_persistence: None,
        ..Config::default()
    };
    // A fixed seed: the cases, and the reach rate printed below, are the same on every run.
    let mut runner =
        TestRunner::new_with_rng(config, TestRng::deterministic_rng(RngAlgorithm::ChaCha));
    let reached = std::cell::Cell::new(0usize);
    let runs = std::cell::Cell::new(0usize);
    let min_clearance = std::cell::Cell::new(f64::INFINITY);
    let entered = std::cell::Cell::new(0usize);
    let entered_disjoint = std::cell::Cell::new(0usize);
    let worst = std::cell::RefCell::new(None);
    let result = runner.run(&obstacle_field(), |f| {
        let s = Scenario {
            planner: dvf::planner::Spec::default(),
            name: "random obstacles".into(),
            bounds: None,
            duration: 40.0,
            dt: 0.01,
            params: Params::default(),
            independent: false,
            robots: vec![RobotSpec {
                start: f.start,
                goal: f.goal,
            }],
            obstacles: f.obstacles.clone(),
        };
        prop_assert!(s.validate().is_ok(), "{:?}", s.validate());
        let mut sim = Simulation::new(&s).unwrap();
        for step in 1..=s.steps() {
            sim.step();
            let r = sim.robots()[0];
            let c = r.last.command;
            prop_assert!(
                is_finite_pose(r.pose) && c.v.is_finite() && c.omega.is_finite(),
                "step {}: pose {:?}, command {:?}",
                step,
                r.pose,
                c
            );
        }
        let rep = sim.report();
        runs.set(runs.get() + 1);
        if rep.robots[0].position_error <= TOL_POSITION
            && rep.robots[0].heading_error <= TOL_HEADING
        {
            reached.set(reached.get() + 1);
        }
        if let Some(c) = rep.min_obstacle_clearance {
            if c < min_clearance.get() {
                min_clearance.set(c);
                worst.replace(Some(f.clone()));
            }
            if c < 0.0 {
                entered.set(entered.get() + 1);
                if !rings_overlap(&f.obstacles) {
                    entered_disjoint.set(entered_disjoint.get() + 1);
                }
            }
        }
        Ok(())
    });
    // Reaching the goal is recorded, not asserted: where rings overlap a robot may be trapped
    // in a notch. Entering a disc is asserted: the safety barrier forbids it wherever the
    // rings are.
    println!(
        "random obstacle fields: {}/{} runs reached the goal in 40 s; {} entered an obstacle \
         disc ({} of them with pairwise disjoint influence rings); smallest clearance {:.3} \
         in {:?}",
        reached.get(),
        runs.get(),
        entered.get(),
        entered_disjoint.get(),
        min_clearance.get(),
        worst.borrow()
    );
    if let Err(e) = result {
        panic!("{e}");
    }
    assert_eq!(entered.get(), 0, "worst: {:?}", worst.borrow());
}

// ---------------------------------------------------------------------------------------------
// The step function over arbitrary finite states.

/// Cases of [`the_step_never_panics_nor_leaves_finite_numbers`]; docs/book/src/tests.md quotes it.
const STATE_CASES: u32 = 20_000;

/// A finite number anywhere from round-off to the validation's magnitude limit, either sign.
fn magnitude() -> impl Strategy<Value = f64> {
    prop_oneof![
        -1e6..1e6f64,
        -10.0..10.0f64,
        (-12.0..6.0f64, any::<bool>())
            .prop_map(|(e, neg)| if neg { -1.0 } else { 1.0 } * 10f64.powf(e)),
        Just(0.0),
    ]
}

/// A positive number from tiny to huge.
fn positive() -> impl Strategy<Value = f64> {
    prop_oneof![(-6.0..6.0f64).prop_map(|e| 10f64.powf(e)), 0.1..20.0f64]
}

prop_compose! {
    fn any_state()(
        robots in prop::collection::vec((magnitude(), magnitude(), magnitude(), magnitude(), magnitude(), magnitude()), 1..6),
        obstacles in prop::collection::vec((magnitude(), magnitude(), positive(), positive()), 0..4),
        gains in (positive(), positive(), positive(), positive(), positive()),
        radii in (positive(), positive(), positive(), positive()),
        saturation in (prop::option::of(positive()), prop::option::of(positive())),
        dt in prop_oneof![Just(0.01), 1e-4..0.1f64],
        paper in any::<bool>(),
        barrier in any::<bool>(),
    ) -> Scenario {
        // Gains within the validation's bound `dt · k < 1`, so that most cases are valid.
        let stable = |k: f64| k.min(0.99 / dt);
        let (k_v, k_omega, k_a, eps, v_c) = gains;
        let (k_v, k_omega, k_a) = (stable(k_v), stable(k_omega), stable(k_a));
        let (r_c, r_ij, r_s, _) = radii;
        let r_ij = r_ij.min(10.0);
        Scenario {
            planner: dvf::planner::Spec::default(),
            name: "arbitrary state".into(),
            bounds: None,
            duration: 50.0 * dt,
            dt,
            params: Params {
                k_v,
                k_omega,
                k_a,
                transition_width: eps,
                avoid_speed: v_c,
                avoid_radius: r_c + r_ij,
                safe_radius: r_ij,
                sense_radius: r_s,
                v_max: saturation.0,
                omega_max: saturation.1,
                avoidance: if paper { dvf::params::Avoidance::Paper } else { dvf::params::Avoidance::Exit },
                barrier_rate: barrier.then_some(0.5 / dt),
                ..Params::default()
            },
            independent: false,
            robots: robots
                .into_iter()
                .map(|(x, y, t, gx, gy, gt)| RobotSpec { start: [x, y, t], goal: [gx, gy, gt] })
                .collect(),
            obstacles: obstacles
                .into_iter()
                .map(|(x, y, r, w)| Obstacle { center: DVec2::new(x, y), radius: r.min(20.0), influence: r.min(20.0) + w.min(20.0) })
                .collect(),
        }
    }
}

proptest! {
    #![proptest_config(Config { max_global_rejects: 20 * STATE_CASES, ..config(STATE_CASES) })]

    /// Any state the validation accepts — poses and goals anywhere within its limits, any
    /// gains, radii, saturation and step — steps without a panic, and every pose, command and
    /// metric stays finite: no NaN or infinity leaves the core.
    #[test]
    fn the_step_never_panics_nor_leaves_finite_numbers(s in any_state()) {
        prop_assume!(s.validate().is_ok());
        let mut sim = Simulation::new(&s).unwrap();
        for _ in 0..s.steps() {
            sim.step();
            for r in sim.robots() {
                let c = r.last.command;
                prop_assert!(is_finite_pose(r.pose) && c.v.is_finite() && c.omega.is_finite()
                    && r.last.field.is_finite() && r.heading_error.is_finite(),
                    "{:?}", r);
            }
        }
        let rep = sim.report();
        prop_assert!(rep.min_pair_distance.is_none_or(f64::is_finite));
        prop_assert!(rep.min_obstacle_clearance.is_none_or(f64::is_finite));
        for r in &rep.robots {
            prop_assert!(r.position_error.is_finite() && r.heading_error.is_finite());
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The SE(2) log map (eqs. `eq_Upsi_log_h_def`, `eq_phi_def`).

/// proptest's configuration for the `proptest!` blocks: `cases` cases, and failing cases
/// saved next to this file (`tests/properties.proptest-regressions`; the default location
/// looks for a lib.rs or main.rs, which tests/ does not have) and replayed first.
fn config(cases: u32) -> Config {
    Config {
        cases,
        failure_persistence: Some(Box::new(FileFailurePersistence::WithSource(
            "proptest-regressions",
        ))),
        ..Config::default()
    }
}

fn angle() -> impl Strategy<Value = f64> {
    // The principal range, its end points exactly, and the neighbourhood of 0 where α(θ) is
    // taken from its series.
    prop_oneof![
        4 => -PI..=PI,
        1 => Just(PI),
        1 => Just(-PI),
        1 => Just(0.0),
        2 => -1e-3..1e-3f64,
    ]
}

/// Signed magnitudes from 1e-100 to 1e3 (log-uniform) and exact zero.
fn coordinate() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => -100.0..100.0f64,
        2 => (-100.0..3.0f64, any::<bool>()).prop_map(|(e, neg)| {
            let m = 10f64.powf(e);
            if neg { -m } else { m }
        }),
        1 => Just(0.0),
    ]
}

fn wrap(a: f64) -> f64 {
    let r = a.rem_euclid(2.0 * PI);
    if r > PI {
        r - 2.0 * PI
    } else {
        r
    }
}

proptest! {
    #![proptest_config(config(512))]

    /// exp(log(h)) = h. Tolerance 1e-9 (absolute, |p| ≤ 142): each map is a 2×2 product with
    /// a few rounding errors of order 1e-16·|p| ≈ 1e-14; 1e-9 leaves five orders for the
    /// condition of V(θ)Ξ(θ) = I near ±π yet catches any wrong coefficient.
    #[test]
    fn exp_inverts_log(x in coordinate(), y in coordinate(), t in angle()) {
        let h = Pose::new(x, y, t);
        let u = log(h);
        prop_assert!(u.phi.is_finite() && u.theta.is_finite());
        prop_assert!(u.theta > -PI && u.theta <= PI, "log angle {} not principal", u.theta);
        let back = exp(u);
        prop_assert!(back.p.distance(h.p) <= 1e-9, "{:?} -> {:?} -> {:?}", h, u, back);
        prop_assert!(wrap(back.theta - t).abs() <= 1e-12, "{:?} -> {:?}", h, back);
    }

    /// φ = Ξ(θ)p vanishes only at p = 0: Ξ is a scaled rotation with
    /// det Ξ = (θ/2)²/sin²(θ/2) ≥ 1 on the branch range |θ| ≤ 3π/2 the simulator uses
    /// (π + `BRANCH_HYSTERESIS`), so |φ| ≥ |p|. Lengths by `hypot` so that tiny p do not
    /// underflow in the check itself; 1e-12 relative covers the rounding of the products.
    #[test]
    fn phi_vanishes_exactly_at_the_origin(
        x in coordinate(),
        y in coordinate(),
        t in -1.5 * PI..=1.5 * PI,
    ) {
        let f = phi(DVec2::new(x, y), t);
        if x == 0.0 && y == 0.0 {
            prop_assert_eq!(f, DVec2::ZERO);
        } else {
            let (nf, np) = (f.x.hypot(f.y), x.hypot(y));
            prop_assert!(nf > 0.0, "φ({}, {}, {}) = 0", x, y, t);
            prop_assert!(nf >= np * (1.0 - 1e-12), "|φ| = {} < |p| = {} at θ = {}", nf, np, t);
        }
    }

    /// Near θ = 0 the log map is the identity on the translation: φ − p = (θ/2)(y, −x) + O(θ²)p,
    /// at most 5e-7·|p| for |θ| < 1e-6, inside the 1e-6 relative tolerance; a wrong limit of
    /// (1 + cos θ)/sin θ · θ/2 (NaN, 0, 2) fails it by O(1).
    #[test]
    fn phi_is_the_position_near_zero_angle(
        x in coordinate(),
        y in coordinate(),
        t in prop_oneof![Just(0.0), Just(-0.0), -1e-6..1e-6f64, Just(1e-300)],
    ) {
        let p = DVec2::new(x, y);
        let f = phi(p, t);
        let d = f - p;
        prop_assert!(
            d.x.hypot(d.y) <= 1e-6 * x.hypot(y),
            "φ({:?}, {}) = {:?}",
            p,
            t,
            f
        );
    }
}

// ---------------------------------------------------------------------------------------------
// The scenario parser never panics.

const VALID: &str = r#"{
  "name": "valid",
  "bounds": [-20, -20, 20, 20],
  "duration": 10,
  "dt": 0.01,
  "params": {"k_v": 0.5, "k_omega": 1, "k_a": 10, "v_max": 3},
  "independent": false,
  "robots": [
    {"start": [-10, 0, 0], "goal": [10, 0, 1.5]},
    {"start": [0, -10, 3.14], "goal": [0, 10, -1]}
  ],
  "obstacles": [{"center": [0, 0], "radius": 1.5, "influence": 3}]
}"#;

/// Every path into a JSON value (keys and indices), the root included.
fn paths(v: &serde_json::Value, here: &mut Vec<PathStep>, out: &mut Vec<Vec<PathStep>>) {
    out.push(here.clone());
    match v {
        serde_json::Value::Object(m) => {
            for (k, c) in m {
                here.push(PathStep::Key(k.clone()));
                paths(c, here, out);
                here.pop();
            }
        }
        serde_json::Value::Array(a) => {
            for (i, c) in a.iter().enumerate() {
                here.push(PathStep::Index(i));
                paths(c, here, out);
                here.pop();
            }
        }
        _ => {}
    }
}

#[derive(Clone, Debug)]
enum PathStep {
    Key(String),
    Index(usize),
}

fn at<'a>(v: &'a mut serde_json::Value, path: &[PathStep]) -> &'a mut serde_json::Value {
    path.iter().fold(v, |v, s| match s {
        PathStep::Key(k) => &mut v[k.as_str()],
        PathStep::Index(i) => &mut v[*i],
    })
}

/// Replacement values: every JSON type, and numbers at and past each documented limit.
fn replacement() -> impl Strategy<Value = serde_json::Value> {
    use serde_json::json;
    prop_oneof![
        Just(json!(null)),
        Just(json!(true)),
        Just(json!("x")),
        Just(json!([])),
        Just(json!({})),
        Just(json!([1, 2])),
        Just(json!([0, 0, 0])),
        Just(json!({"start": [0, 0, 0], "goal": [1, 1, 1]})),
        Just(json!(0)),
        Just(json!(-0.0)),
        Just(json!(-1)),
        Just(json!(1e-320)),
        Just(json!(1e308)),
        Just(json!(-1e308)),
        Just(json!(u64::MAX)),
        Just(json!(i64::MIN)),
        Just(json!(0.1)),
        Just(json!(3600)),
        Just(json!(1e5)),
        (-1e4..1e4f64).prop_map(|x| json!(x)),
        "[a-z_]{1,8}".prop_map(|s| json!(s)),
    ]
}

#[derive(Clone, Debug)]
enum Mutation {
    Replace(usize, serde_json::Value),
    Remove(usize),
    AddKey(usize, String, serde_json::Value),
    Truncate(usize),
    Duplicate(usize),
}

fn mutation() -> impl Strategy<Value = Vec<Mutation>> {
    let one = prop_oneof![
        3 => (any::<usize>(), replacement()).prop_map(|(i, v)| Mutation::Replace(i, v)),
        1 => any::<usize>().prop_map(Mutation::Remove),
        1 => (any::<usize>(), "[a-z_]{1,8}", replacement())
            .prop_map(|(i, k, v)| Mutation::AddKey(i, k, v)),
        1 => any::<usize>().prop_map(Mutation::Truncate),
        1 => any::<usize>().prop_map(Mutation::Duplicate),
    ];
    proptest::collection::vec(one, 1..4)
}

/// Applies the mutations to the valid scenario and returns the text.
fn mutate(ms: &[Mutation]) -> String {
    let mut v: serde_json::Value = serde_json::from_str(VALID).expect("VALID is JSON");
    let mut text = None;
    for m in ms {
        let mut all = Vec::new();
        paths(&v, &mut Vec::new(), &mut all);
        let pick = |i: usize| all[i % all.len()].clone();
        match m {
            Mutation::Replace(i, new) => *at(&mut v, &pick(*i)) = new.clone(),
            Mutation::Remove(i) => {
                let p = pick(*i);
                if let Some((last, parent)) = p.split_last() {
                    match (at(&mut v, parent), last) {
                        (serde_json::Value::Object(m), PathStep::Key(k)) => {
                            m.remove(k);
                        }
                        (serde_json::Value::Array(a), PathStep::Index(i)) => {
                            a.remove(*i);
                        }
                        _ => {}
                    }
                }
            }
            Mutation::AddKey(i, k, new) => {
                if let serde_json::Value::Object(m) = at(&mut v, &pick(*i)) {
                    m.insert(k.clone(), new.clone());
                }
            }
            Mutation::Duplicate(i) => {
                let p = pick(*i);
                let copy = at(&mut v, &p).clone();
                if let serde_json::Value::Array(a) = at(&mut v, &p) {
                    a.extend(copy.as_array().cloned().unwrap_or_default());
                }
            }
            Mutation::Truncate(i) => {
                let t = serde_json::to_string(&v).expect("serialisable");
                let mut cut = i % (t.len() + 1);
                while !t.is_char_boundary(cut) {
                    cut -= 1;
                }
                text = Some(t[..cut].to_owned());
            }
        }
    }
    text.unwrap_or_else(|| serde_json::to_string_pretty(&v).expect("serialisable"))
}

/// A parse result is acceptable when it is a valid scenario, or an error with a message.
fn check_parse(text: &str) -> Result<(), TestCaseError> {
    match Scenario::from_json(text) {
        Ok(s) => {
            prop_assert!(s.validate().is_ok(), "accepted but invalid: {text}");
            prop_assert!(!s.robots.is_empty());
        }
        Err(e) => {
            let msg = e.to_string();
            prop_assert!(!msg.trim().is_empty(), "empty message for {text:?}");
        }
    }
    Ok(())
}

/// Cases of each parser property below; docs/book/src/tests.md quotes it.
const PARSER_CASES: u32 = 4_096;

proptest! {
    #![proptest_config(config(PARSER_CASES))]

    #[test]
    fn from_json_never_panics_on_arbitrary_text(text in any::<String>()) {
        check_parse(&text)?;
    }

    #[test]
    fn from_json_never_panics_on_json_like_text(
        text in r#"[\[\]{}",:. 0-9eE+\-a-z_]{0,80}"#,
    ) {
        check_parse(&text)?;
    }

    /// Mutations of a valid scenario: replaced values of every type, removed and added keys,
    /// duplicated lists (many robots on the same start), truncated text.
    #[test]
    fn from_json_on_mutated_scenarios_is_ok_or_explains(ms in mutation()) {
        let text = mutate(&ms);
        check_parse(&text)?;
        // A scenario the parser accepts can be written back and read again (what
        // `dvf presets --preset NAME` and the page's export rely on), with the same robots.
        if let Ok(s) = Scenario::from_json(&text) {
            let again = Scenario::from_json(&s.to_json());
            prop_assert!(again.is_ok(), "{:?} for {}", again, s.to_json());
            prop_assert_eq!(again.unwrap().robots, s.robots);
        }
    }
}

/// The unmutated scenario parses: the mutation test starts from a valid point.
#[test]
fn the_valid_scenario_is_valid() {
    let s = Scenario::from_json(VALID).expect("valid");
    assert_eq!(s.robots.len(), 2);
    assert_eq!(
        mutate(&[]),
        serde_json::to_string_pretty(&serde_json::from_str::<serde_json::Value>(VALID).unwrap())
            .unwrap()
    );
}

/// `to_json` writes the resolved bounds, which extend 10 % past the farthest start, goal or
/// obstacle ring: for coordinates near the accepted limit (1e6) they exceed it, and the file
/// written back is rejected ("bounds[2]: must be at most 1e6 in magnitude").
#[test]
fn to_json_round_trips_at_the_magnitude_limit() {
    let s = Scenario::from_json(r#"{"robots": [{"start": [0, 0, 0], "goal": [1e6, 0, 0]}]}"#)
        .expect("coordinates of 1e6 are accepted");
    let again = Scenario::from_json(&s.to_json());
    assert!(again.is_ok(), "{again:?}");
}

/// `Scenario::steps` is documented as `ceil(duration / dt)`, but it rounds quotients within
/// 1e-9 of an integer, so a positive duration below ~1e-9·dt runs zero steps (and the report
/// says `time: 0`).
#[test]
fn a_positive_duration_runs_at_least_one_step() {
    let s = Scenario::from_json(
        r#"{"duration": 1e-11, "robots": [{"start": [0, 0, 0], "goal": [1, 0, 0]}]}"#,
    )
    .expect("a positive duration is accepted");
    assert!(s.steps() >= 1, "{} steps", s.steps());
}
