//! The `orca` and `move-to-pose` planners (src/planner/orca.rs, src/planner/move_to_pose.rs)
//! against their sources: each source's own example run through the simulator, its numbers
//! checked within a tolerance that says where the two may differ; then a scene of the sweep
//! families run with each, and bad gains refused naming the field. They run natively, in Node
//! (`wasm-pack test --node`) and in Chromium (`make test-browser`).

#[path = "../src/testing.rs"]
mod testing;
use testing::test;

use dvf::scenario::Scenario;
use dvf::Simulation;

/// The poses after every step of `s` (a lone robot), and the first step after which its
/// command was a stop (`None`: it never stopped).
fn track(s: &Scenario, steps: usize) -> (Vec<[f64; 3]>, Option<usize>) {
    let mut sim = Simulation::new(s).expect("a valid scenario");
    let mut poses = Vec::with_capacity(steps);
    let mut stopped = None;
    for k in 1..=steps {
        sim.step();
        let r = &sim.robots()[0];
        if stopped.is_none() && r.last.command.v == 0.0 && r.last.command.omega == 0.0 {
            stopped = Some(k);
        }
        poses.push(r.pose.to_array());
    }
    (poses, stopped)
}

fn lone(planner: &str, start: [f64; 3], goal: [f64; 3], duration: f64) -> Scenario {
    Scenario::from_json(&format!(
        r#"{{"dt": 0.01, "duration": {duration}, "planner": {planner},
            "robots": [{{"start": {start:?}, "goal": {goal:?}}}]}}"#
    ))
    .unwrap()
}

/// One of PythonRobotics' move_to_pose cases (tests/data/sources/move_to_pose.py prints the
/// numbers): its start and goal, the file's own loop (`euler`: the pose after steps 1 to 5,
/// and the file's speed and turn rate of each) and the same law moved by the exact
/// integration (`exact`: after steps 1 to 5, after the last step, and that step).
struct Case {
    start: [f64; 3],
    goal: [f64; 3],
    euler: [[f64; 5]; 5],
    exact: [[f64; 3]; 5],
    exact_end: [f64; 3],
    exact_steps: usize,
}

/// PythonRobotics' tests/test_move_to_pose.py::test_stability (5, 5, 0) → (1, 4, 0), the goal
/// behind the robot (it reverses), and test_reach_goal's (5, 5, π/2) → (10, 10, 0), where the
/// turn rate starts at its limit of 7 rad/s.
const CASES: [Case; 2] = [
    Case {
        start: [5.0, 5.0, 0.0],
        goal: [1.0, 4.0, 0.0],
        euler: [
            [
                4.85014581171577,
                4.993387719480052,
                0.04409615936283551,
                -15.0,
                4.409615936283556,
            ],
            [
                4.700661354991044,
                4.980962052587946,
                0.08293281318900636,
                -15.0,
                3.883665382617063,
            ],
            [
                4.551689209769199,
                4.963432079741371,
                0.1171341567390547,
                -15.0,
                3.4201343550048353,
            ],
            [
                4.403312323288352,
                4.941425272652427,
                0.14724352683812825,
                -15.0,
                3.010937009907373,
            ],
            [
                4.255570396440223,
                4.915496079622135,
                0.17373395153711568,
                -15.0,
                2.649042469898742,
            ],
        ],
        exact: [
            [4.850048607055772, 4.9966933239112725, 0.04409615936283551],
            [4.700361235775275, 4.987162233240158, 0.08307878169413296],
            [4.551122664175161, 4.972141525030624, 0.11754352558936665],
            [4.40244869490591, 4.952284270321376, 0.14800969027622557],
            [4.25440436014941, 4.928169624363785, 0.1749301129587968],
        ],
        exact_end: [1.0009325865242826, 3.9999727719944964, -0.04135151234557144],
        exact_steps: 96,
    },
    Case {
        start: [5.0, 5.0, std::f64::consts::FRAC_PI_2],
        goal: [10.0, 10.0, 0.0],
        euler: [
            [
                5.01049142710063,
                5.149632650037992,
                1.5007963267948963,
                15.0,
                -7.0,
            ],
            [
                5.031422894297265,
                5.298165049469888,
                1.430796326794896,
                15.0,
                -7.0,
            ],
            [
                5.06269187927418,
                5.44486968667851,
                1.3607963267948966,
                15.0,
                -7.0,
            ],
            [
                5.104143914672212,
                5.589028379657325,
                1.2908054271014695,
                15.0,
                -6.999089969342704,
            ],
            [
                5.154394525019697,
                5.730360881792203,
                1.2291867781746504,
                15.0,
                -6.16186489268185,
            ],
        ],
        exact: [
            [5.005247856600115, 5.1498775300089985, 1.5007963267948963],
            [5.020965722401492, 5.299020959951935, 1.430796326794896],
            [5.047076611305397, 5.446699785384499, 1.3607963267948966],
            [5.0834526321912055, 5.59219067549453, 1.2907963267948963],
            [5.129351092307658, 5.734970614880898, 1.2287374526672998],
        ],
        exact_end: [9.999074766905691, 10.000026965112266, -0.05258428506904966],
        exact_steps: 118,
    },
];

/// The planner follows PythonRobotics' move_to_pose step by step.
///
/// - Against the law moved by the exact integration (the script's `exact` run): within 1e-12
///   at every checked step and at the end. Both compute the same operations but for the
///   arctangent and hypot (musl's here, the platform's in numpy, each within an ulp) and the
///   sinc (a series here, a sine in numpy); over a hundred steps of a contracting loop these
///   ulps stay below 1e-14 on x86-64, and 1e-12 leaves room for another platform's library.
/// - Against the file's own loop (`euler`): its heading update is the same (`θ += ω·dt`), but
///   it moves the robot by `v·dt` along the heading after the turn, where the exact arc moves
///   it by `v·dt·sinc(ω·dt/2)` along the mean heading `θ + ω·dt/2`. From the same pose with
///   the same command the two land within `|v·ω|·dt²/2` of each other (the chord's angle
///   differs by `ω·dt/2`, its length by less than `(ω·dt)²/24` of it); after `k` steps the
///   poses differ by at most the sum of these over the file's commands (the law contracts, so
///   earlier differences do not grow over five steps), which the test allows: 3.3e-3 m after
///   the first step of the first case. The headings agree to 1e-12 after the first step (one
///   product and one sum from the same command).
/// - The robot stops within 1 mm of its goal after the moves of the script's `exact` run; the
///   file's loop runs one step more (it tests the distance from before its last move), a
///   step shorter than `K_ρ·0.001·dt = 9e-5 m`.
#[test]
fn move_to_pose_follows_python_robotics() {
    let dt = 0.01;
    for case in &CASES {
        let s = lone(r#""move-to-pose""#, case.start, case.goal, 2.0);
        let (poses, stopped) = track(&s, s.steps());
        let at = |k: usize| poses[k - 1];
        for (k, want) in (1..=5).zip(&case.exact) {
            for (a, b) in at(k).iter().zip(want) {
                assert!((a - b).abs() <= 1e-12, "step {k}: {:?} vs {want:?}", at(k));
            }
        }
        let mut bound = 0.0;
        for (k, want) in (1..=5).zip(&case.euler) {
            bound += (want[3] * want[4]).abs() * dt * dt / 2.0;
            let p = at(k);
            let off = (p[0] - want[0]).hypot(p[1] - want[1]);
            assert!(
                off <= bound,
                "step {k}: {p:?} is {off:e} from {want:?}, over {bound:e}"
            );
        }
        assert!((at(1)[2] - case.euler[0][2]).abs() <= 1e-12);
        assert_eq!(stopped, Some(case.exact_steps), "{:?}", case.start);
        let end = *poses.last().unwrap();
        for (a, b) in end.iter().zip(&case.exact_end) {
            assert!(
                (a - b).abs() <= 1e-12,
                "end: {end:?} vs {:?}",
                case.exact_end
            );
        }
        let g = case.goal;
        assert!((end[0] - g[0]).hypot(end[1] - g[1]) <= 1e-3);
    }
}

/// Two robots head-on, `barrier_rate` as given, each bound for the other's start with its
/// own heading: robot 0 from (0, 0) heading 0, robot 1 from (`gap`, 0) heading π.
fn head_on(gap: f64, barrier: &str, planner: &str) -> Scenario {
    Scenario::from_json(&format!(
        r#"{{"dt": 0.01, "duration": 40, "planner": {planner},
            "params": {{"barrier_rate": {barrier}}},
            "robots": [{{"start": [0, 0, 0], "goal": [{gap}, 0, 0]}},
                       {{"start": [{gap}, 0, 3.141592653589793], "goal": [0, 0, 3.141592653589793]}}]}}"#
    ))
    .unwrap()
}

/// A robot alone tracks ORCA's velocity by collvoid's law, by hand: its goal lies π/3 to the
/// left of its heading and far away, so ORCA's velocity is the preferred one, 1 m/s toward
/// the goal, and the first command is `v = 1·(π/3)(√3/2)/(2(1 − ½)) = π√3/6 = 0.90690`,
/// `ω = (π/3)/0.4 = 2.61799` rad/s; with `ω_max = 2` the turn is 2 and the speed the same.
/// Within 1e-6: ORCA computes in `f32`, whose rounding of the velocity (a relative 6e-8 per
/// component) moves both the speed and the angle by less than 1e-7.
#[test]
fn orca_tracks_its_velocity_by_collvoids_law() {
    let goal = [
        100.0 * (std::f64::consts::FRAC_PI_3).cos(),
        100.0 * (std::f64::consts::FRAC_PI_3).sin(),
        0.0,
    ];
    for (omega_max, omega) in [("null", std::f64::consts::FRAC_PI_3 / 0.4), ("2", 2.0)] {
        let mut s = lone(r#""orca""#, [0.0, 0.0, 0.0], goal, 1.0);
        s.params.omega_max = serde_json::from_str(omega_max).unwrap();
        let sim = Simulation::new(&s).unwrap();
        let c = sim.robots()[0].last.command;
        let v = std::f64::consts::PI * 3f64.sqrt() / 6.0;
        assert!((c.v - v).abs() <= 1e-6, "{c:?}");
        assert!((c.omega - omega).abs() <= 1e-6, "{c:?}");
    }
}

/// ORCA's velocity by hand, through the planner: two robots at rest head-on, their look-ahead
/// points (0.15 m ahead of each) `D = 12` m apart, each a disc of radius `r_ij + d = 1.15`, so
/// `S = 2.3`. With both velocities 0 the relative velocity lies outside the velocity obstacle
/// and projects onto its cut-off circle (centre `D/τ = 1.2` m/s ahead, radius `S/τ = 0.23`,
/// `τ = 10` s): the half-plane `v_x ≤ (D − S)/τ = 0.97` (`dodgy_2d` takes the whole of `u`
/// outside the obstacle, where RVO2 takes half). The preferred velocity, 1 m/s straight ahead,
/// is cut to 0.97 m/s, and the tracking drives it straight: `v = 0.97`, `ω = 0`, both robots.
/// Within 1e-6 for `f32`'s rounding.
#[test]
fn orca_slows_two_robots_head_on_as_its_half_planes_say() {
    let s = head_on(12.3, "null", r#""orca""#);
    let sim = Simulation::new(&s).unwrap();
    for r in sim.robots() {
        let c = r.last.command;
        assert!((c.v - 0.97).abs() <= 1e-6, "{c:?}");
        assert!(c.omega.abs() <= 1e-6, "{c:?}");
    }
}

/// Two robots head-on pass each other by ORCA alone (`barrier_rate: null`), as RVO2's and
/// `dodgy_2d`'s agents do: never closer than `2·r_ij = 2` m (their look-ahead discs keep
/// `2(r_ij + d) = 2.3` m between the points 0.15 m ahead of each), and both arrive with their
/// heading.
#[test]
fn orca_passes_two_robots_head_on_without_the_barrier() {
    let r = dvf::run(&head_on(20.0, "null", r#""orca""#)).unwrap();
    assert_eq!(r.violations, 0);
    assert!(r.min_pair_distance.unwrap() >= 2.0, "{r:?}");
    for robot in &r.robots {
        assert!(robot.converged_at.is_some(), "{robot:?}");
    }
}

/// `n` robots evenly on a circle of radius 10 m, each bound for the antipode with its start
/// heading (toward the centre): RVO2's `Circle` example (250 agents on 200 m) scaled down.
fn circle(n: usize, barrier: &str, planner: &str) -> Scenario {
    let robots: Vec<String> = (0..n)
        .map(|k| {
            let a = 2.0 * std::f64::consts::PI * k as f64 / n as f64;
            let (x, y, h) = (10.0 * a.cos(), 10.0 * a.sin(), a + std::f64::consts::PI);
            format!(
                r#"{{"start": [{x}, {y}, {h}], "goal": [{}, {}, {h}]}}"#,
                -x, -y
            )
        })
        .collect();
    Scenario::from_json(&format!(
        r#"{{"dt": 0.01, "duration": 80, "planner": {planner},
            "params": {{"barrier_rate": {barrier}}}, "robots": [{}]}}"#,
        robots.join(",")
    ))
    .unwrap()
}

/// RVO2's `Circle` swap, 16 robots (3.9 m apart on the circle, 2 m wide), by ORCA alone:
/// nobody closer than `2·r_ij`, every robot at its antipode with its heading within the 80 s.
#[test]
fn orca_swaps_a_circle_without_the_barrier() {
    let r = dvf::run(&circle(16, "null", r#""orca""#)).unwrap();
    assert_eq!(r.violations, 0);
    assert!(
        r.min_pair_distance.unwrap() >= 2.0,
        "{:?}",
        r.min_pair_distance
    );
    for robot in &r.robots {
        assert!(robot.converged_at.is_some(), "{robot:?}");
    }
}

/// Scenes of the sweep families run with each planner, with the shared barrier (the default):
/// finite poses and no violation; ORCA also brings every robot of the small random scene (4
/// robots, 2 obstacles) and of a dense one (26 robots, 7 obstacles) to its pose.
#[test]
fn the_planners_run_the_sweep_families() {
    use dvf::planner::Spec;
    use dvf::sweep::{scenario, Family, Recipe};
    let small = Recipe {
        robots: 4..=4,
        obstacles: 2..=2,
        ..Recipe::of(Family::Random)
    };
    let scenes = [
        (scenario(&small, 0).unwrap(), true),
        (scenario(&Recipe::of(Family::Dense), 0).unwrap(), true),
        (scenario(&Recipe::of(Family::Formation), 0).unwrap(), false),
    ];
    assert_eq!(
        (scenes[0].0.robots.len(), scenes[0].0.obstacles.len()),
        (4, 2)
    );
    for (scene, orca_arrives) in scenes {
        for planner in ["orca", "move-to-pose"] {
            let mut s = scene.clone();
            s.planner = Spec::named(planner);
            let r = dvf::run(&s).unwrap();
            assert_eq!(r.planner.as_deref(), Some(planner));
            assert_eq!(r.violations, 0, "{planner} on {}", s.name);
            for robot in &r.robots {
                assert!(robot.final_pose.iter().all(|x| x.is_finite()), "{robot:?}");
                if planner == "orca" && orca_arrives {
                    assert!(robot.converged_at.is_some(), "{} {robot:?}", s.name);
                }
            }
        }
    }
}

/// Bad gains are refused naming the field, and so are unknown ones.
#[test]
fn bad_gains_are_refused_naming_the_field() {
    for (planner, field) in [
        (
            r#"{"name": "orca", "time_horizon": 0}"#,
            "planner.time_horizon",
        ),
        (
            r#"{"name": "orca", "lookahead": -0.1}"#,
            "planner.lookahead",
        ),
        (
            r#"{"name": "orca", "max_speed": "fast"}"#,
            "planner.max_speed",
        ),
        (r#"{"name": "orca", "tau": 1}"#, "planner.tau"),
        (
            r#"{"name": "move-to-pose", "kp_rho": -9}"#,
            "planner.kp_rho",
        ),
        (
            r#"{"name": "move-to-pose", "stop_distance": 0}"#,
            "planner.stop_distance",
        ),
        (r#"{"name": "move-to-pose", "k_rho": 9}"#, "planner.k_rho"),
    ] {
        let e = Scenario::from_json(&format!(
            r#"{{"planner": {planner}, "robots": [{{"start": [0, 0, 0], "goal": [1, 0, 0]}}]}}"#
        ))
        .unwrap_err()
        .to_string();
        assert!(e.starts_with(&format!("{field}: ")), "{planner}: {e}");
    }
}

/// A step too small for `f32` (which `dodgy_2d` computes in, and whose step must be positive)
/// panics nothing: the robots' first commands are finite.
#[test]
fn orca_takes_a_step_below_f32s_range() {
    let mut s = head_on(12.3, "2", r#""orca""#);
    s.dt = 1e-50;
    s.duration = 1e-45;
    let sim = Simulation::new(&s).unwrap();
    for r in sim.robots() {
        assert!(r.last.command.v.is_finite() && r.last.command.omega.is_finite());
    }
}

/// ORCA's run is the same bits in every build: `dodgy_2d`'s `f32` arithmetic is IEEE's, lane
/// for lane, natively and in wasm, and the tracking takes its sines and arctangents from
/// `src/maths.rs`. The bits are those of the native build.
#[test]
fn orca_gives_the_same_bits_in_every_build() {
    let r = dvf::run(&circle(8, "2", r#""orca""#)).unwrap();
    let bits: Vec<[u64; 3]> = r
        .robots
        .iter()
        .map(|x| x.final_pose.map(f64::to_bits))
        .collect();
    let native: [[u64; 3]; 8] = [
        [
            13845165043210823999,
            13804164843229805120,
            4614256656552045828,
        ],
        [
            13842969320401197542,
            13842994760573616376,
            13835860133968814566,
        ],
        [
            4583010704117815734,
            13845167116565047646,
            13833125093779451180,
        ],
        [
            4619642530336471389,
            13842963689916694510,
            13828621494152080684,
        ],
        [
            4621794123742222798,
            4582106844292853641,
            13160153362312160354,
        ],
        [
            4619613021837197469,
            4619603334287647728,
            4605249457297304876,
        ],
        [
            13804967950235590351,
            4621793722354056120,
            4609753056924675332,
        ],
        [
            13842992578283991921,
            4619598415165224406,
            4612488097114038716,
        ],
    ];
    assert_eq!(bits, native);
    assert!(r.robots.iter().all(|x| x.converged_at.is_some()));
}
