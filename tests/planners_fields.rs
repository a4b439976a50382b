//! The field planners `avf` and `cvf` (src/planner/avf.rs, src/planner/cvf.rs) against their
//! source, the DVF authors' comparison code
//! (github.com/Y1kee/CVF-for-Nonholonomic-Motion-Planning): the scenes of its Simulink models driven through the simulator, step by step and to the
//! source's own end condition; and a scene of the sweep families with each of them.
//!
//! The expected numbers come from the source's MATLAB functions (`Controller_AVF.m`,
//! `Controller_CVF.m`, `se2_controller_Unicycle.m` and the functions they call) ported line by
//! line to numpy and run in two ways: with the simulator's zero-order hold (the command held
//! over each step of 0.01 s, the unicycle moved along its exact arc), which must give the same
//! trajectory as the simulator up to rounding; and in continuous time (RK4, step 1e-3 s), the
//! model the source's Simulink runs integrate (variable step, at most 0.1 s, relative
//! tolerance 1e-3), which the held commands follow within half a step's lag.
//!
//! Native only: these run thousands of steps.
#![cfg(not(target_arch = "wasm32"))]

use dvf::scenario::Scenario;
use dvf::se2::wrap_angle;
use dvf::sweep::{scenario, Recipe};
use dvf::Simulation;

#[path = "../src/testing.rs"]
mod testing;
use testing::assert_close;

mod common;
use common::{dvf, stderr, stdout, TempFile};

/// The scene of `Unicycle_AVF.slx` and `Unicycle_CVF.slx` (their masks): start
/// (8.592…, 12.677) at 5.010 rad, goal (−8, 0) at 3π/2.
const SOURCE_SCENE: &str = r#""robots": [{
    "start": [8.59229469246884, 12.6765706716381, 5.00981357947841],
    "goal": [-8, 9.79717439317883e-16, 4.71238898038469]}]"#;

fn scene(planner: &str, robots: &str, duration: f64) -> Scenario {
    Scenario::from_json(&format!(
        r#"{{"name": "source", "duration": {duration}, "dt": 0.01, "planner": {planner},
             "params": {{"tol_position": 0.1}}, {robots}}}"#
    ))
    .unwrap()
}

/// A pose of the zero-order-hold reference at a step, with the command there.
struct Mark {
    step: usize,
    pose: [f64; 3],
    v: f64,
    omega: f64,
}

/// The source's run: the marks of its zero-order-hold run, its end condition (`v < v_max/10`
/// and `|p − p_d| < end_distance`, which stops its Simulink run) and the step at which the
/// held run meets it, and the continuous run's positions at whole seconds and the time it
/// meets it.
struct Source {
    marks: &'static [Mark],
    v_max: f64,
    end_distance: f64,
    end_step: usize,
    continuous: &'static [(f64, [f64; 2])],
    end_time: f64,
}

/// What the simulator's run of the source's scene gives: the step at which it meets the
/// source's end condition, the largest curvature `|ω|/v` it commanded before, the heading
/// error there, and how far the marks were from the held reference.
struct Outcome {
    end_step: usize,
    peak_curvature: f64,
    end_pose: [f64; 3],
    end_heading_error: f64,
    off_held: f64,
}

/// Runs `s` until the source's end condition, noting how far the marks are from the held
/// reference (pose and command, the largest difference) and checking the continuous run's
/// positions (within 0.05 m: the held command lags the continuous one by half a step,
/// 0.015 m at 3 m/s, and the two drift apart by a few hundredths over the run).
fn follow(s: &Scenario, source: &Source) -> Outcome {
    let mut sim = Simulation::new(s).unwrap();
    let goal = sim.robots()[0].goal;
    let mut peak_curvature: f64 = 0.0;
    let mut off_held: f64 = 0.0;
    let (mut marks, mut continuous) = (source.marks.iter(), source.continuous.iter());
    let (mut mark, mut at) = (marks.next(), continuous.next());
    for step in 0..s.steps() {
        let r = sim.robots()[0];
        let c = r.last.command;
        if let Some(m) = mark.filter(|m| m.step == step) {
            for d in [
                r.pose.p.x - m.pose[0],
                r.pose.p.y - m.pose[1],
                wrap_angle(r.pose.theta - m.pose[2]),
                c.v - m.v,
                c.omega - m.omega,
            ] {
                off_held = off_held.max(d.abs());
            }
            mark = marks.next();
        }
        if let Some((_, p)) = at.filter(|(t, _)| (sim.time() - t).abs() < 1e-9) {
            assert_close!(r.pose.p.x, p[0], 0.05);
            assert_close!(r.pose.p.y, p[1], 0.05);
            at = continuous.next();
        }
        if c.v < source.v_max / 10.0 && r.pose.p.distance(goal.p) < source.end_distance {
            assert!(mark.is_none() && at.is_none(), "ended before every mark");
            assert_eq!(c.v, 0.0, "the robot stops where the source ends its run");
            return Outcome {
                end_step: step,
                peak_curvature,
                end_pose: r.pose.to_array(),
                end_heading_error: wrap_angle(r.pose.theta - goal.theta).abs(),
                off_held,
            };
        }
        peak_curvature = peak_curvature.max(c.omega.abs() / c.v);
        sim.step();
    }
    panic!("{}: the source's end condition was never met", s.name);
}

/// After the source's end the robot stays where it stopped, to the end of the run.
fn stays(s: &Scenario, out: &Outcome) -> ::dvf::Report {
    let report = ::dvf::run(s).unwrap();
    assert_eq!(report.robots[0].final_pose, out.end_pose);
    report
}

/// `avf` on the source's scene: the trajectory of `Controller_AVF.m` (v_max = 3 and ρ = 1 from
/// the globals `Controller_CVF.m` sets, k_ω = 1), which ends at 8.37 s within ρ/10 of the goal
/// with its heading within 0.02 rad of the goal's: the field's curves end tangent to it.
/// Tolerance 1e-9 on the held run: the source takes the field's rate by central differences
/// (step 1e-6), whose rounding (ε/1e-6 ≈ 2e-10 rad/s) its 800 steps carry along, where the
/// planner takes it exactly. Past its end the robot stays put, arrived by the source's
/// tolerance.
#[test]
fn avf_drives_the_sources_scene_as_its_code_does() {
    let source = Source {
        marks: &[
            Mark {
                step: 100,
                pose: [
                    7.097_501_716_970_15,
                    10.373_842_927_227_21,
                    3.555_017_297_263_943_6,
                ],
                v: 2.999_999_999_999_999,
                omega: -0.718_746_448_919_453_7,
            },
            Mark {
                step: 200,
                pose: [
                    4.165_078_737_786_536,
                    9.813_406_717_733_669,
                    3.213_511_319_361_339_6,
                ],
                v: 2.999_999_999_999_841,
                omega: -0.066_173_109_722_116_96,
            },
            Mark {
                step: 500,
                pose: [
                    -4.330_261_227_332_984,
                    7.346_673_776_214_817,
                    3.799_768_655_547_618,
                ],
                v: 2.999_999_558_322_379_3,
                omega: 0.303_484_526_603_714_56,
            },
        ],
        v_max: 3.0,
        end_distance: 0.1,
        end_step: 836,
        continuous: &[
            (1.0, [7.104_096_79, 10.367_959_16]),
            (2.0, [4.173_524_84, 9.798_995_24]),
            (5.0, [-4.324_924_53, 7.338_184_96]),
        ],
        end_time: 8.370,
    };
    let s = scene(r#""avf""#, SOURCE_SCENE, 12.0);
    let out = follow(&s, &source);
    assert!(out.off_held <= 1e-9, "{:e}", out.off_held);
    assert_eq!(out.end_step, source.end_step);
    assert_close!(out.end_step as f64 * s.dt, source.end_time, 0.05);
    assert!(out.end_heading_error < 0.02, "{}", out.end_heading_error);
    // Judged by the source's tolerance (ρ/10), the robot has arrived with its heading.
    let report = stays(&s, &out);
    assert_eq!(report.planner.as_deref(), Some("avf"));
    assert_eq!(
        report.robots[0].converged_at,
        Some(source.end_step as f64 * s.dt)
    );
}

/// `cvf` on the source's scene: the trajectory of `Controller_CVF.m` (ρ = 1, r = 4, 8, 12,
/// v_max = 3, c_p = ρ), which ends at 27.19 s within ρ/10 of the goal, its curvature below
/// 1/ρ throughout. The same formulas rounded differently: 1e-11 on the held run, rounding
/// that its 2700 steps carry along.
#[test]
fn cvf_drives_the_sources_scene_as_its_code_does() {
    let source = Source {
        marks: &[
            Mark {
                step: 100,
                pose: [
                    8.313_996_393_089_933,
                    9.745_877_964_302_633,
                    4.332_779_859_332_119,
                ],
                v: 3.0,
                omega: -0.401_817_286_665_976_6,
            },
            Mark {
                step: 200,
                pose: [
                    6.428_523_870_507_724,
                    7.587_334_375_316_384,
                    3.306_389_470_878_779,
                ],
                v: 2.999_999_999_999_962,
                omega: -1.640_943_657_849_616_8,
            },
            Mark {
                step: 500,
                pose: [
                    -2.420_783_646_640_244_6,
                    8.029_407_334_312_944,
                    3.466_581_725_379_013_4,
                ],
                v: 2.999_999_980_765_345_2,
                omega: 0.338_951_559_938_655_06,
            },
            Mark {
                step: 1000,
                pose: [
                    -8.098_176_443_437_522,
                    -1.314_169_400_227_879_6,
                    4.880_899_468_587_605_5,
                ],
                v: 2.598_738_052_989_063_4,
                omega: 0.315_258_324_610_124_9,
            },
        ],
        v_max: 3.0,
        end_distance: 0.1,
        end_step: 2717,
        continuous: &[
            (1.0, [8.317_635_13, 9.745_271_59]),
            (2.0, [6.431_326_22, 7.589_252_45]),
            (5.0, [-2.419_910_03, 8.021_950_66]),
            (10.0, [-8.098_617_35, -1.291_115_74]),
        ],
        end_time: 27.186,
    };
    let s = scene(r#""cvf""#, SOURCE_SCENE, 40.0);
    let out = follow(&s, &source);
    assert!(out.off_held <= 1e-11, "{:e}", out.off_held);
    assert_eq!(out.end_step, source.end_step);
    assert_close!(out.end_step as f64 * s.dt, source.end_time, 0.05);
    assert!(out.peak_curvature <= 1.0, "{}", out.peak_curvature);
    assert!(out.end_heading_error < 0.02, "{}", out.end_heading_error);
    let report = stays(&s, &out);
    assert_eq!(
        report.robots[0].converged_at,
        Some(source.end_step as f64 * s.dt)
    );
}

/// `cvf` on the paper's first example (`Simulation_Verification/RUN_Example.m`: start (0, 0.5)
/// at 5π/4, goal (4, 4√3) at 5π/6, ρ = 1, v_max = ρ, k = 4, 8, 12; its controller
/// `se2_controller_Unicycle.m` takes c_p = 12ρ and ends within ρ/2). There the clip of the turn
/// rate binds: the path's curvature reaches 1/ρ and never passes it. 1e-11 on the held run.
#[test]
fn cvf_drives_the_papers_first_example_with_its_gains() {
    let source = Source {
        marks: &[
            Mark {
                step: 100,
                pose: [
                    -0.299_529_946_653_199_6,
                    -0.249_664_869_595_571_3,
                    4.747_364_026_633_629,
                ],
                v: 0.756_170_417_198_345,
                omega: 0.756_170_417_198_345,
            },
            Mark {
                step: 500,
                pose: [
                    0.292_720_847_848_471_8,
                    -2.989_008_726_198_531_6,
                    4.832_558_958_901_55,
                ],
                v: 0.711_131_174_496_945_5,
                omega: -0.017_210_129_786_032_334,
            },
            Mark {
                step: 1000,
                pose: [
                    1.855_532_310_645_100_7,
                    -6.128_884_676_796_215,
                    6.082_418_985_749_205,
                ],
                v: 0.801_510_189_051_648_7,
                omega: 0.361_060_091_198_856_7,
            },
            Mark {
                step: 2000,
                pose: [
                    7.262_507_899_325_141,
                    -1.850_075_051_686_153_7,
                    7.558_687_866_781_789,
                ],
                v: 0.652_944_735_210_390_6,
                omega: 0.092_433_881_892_358_6,
            },
        ],
        v_max: 1.0,
        end_distance: 0.5,
        end_step: 5811,
        continuous: &[
            (1.0, [-0.298_863_64, -0.249_370_91]),
            (5.0, [0.279_388_11, -2.990_722_72]),
            (10.0, [1.832_029_61, -6.136_975_48]),
            (20.0, [7.257_126_41, -1.873_619_42]),
        ],
        end_time: 58.152,
    };
    let robots = r#""robots": [{"start": [0, 0.5, 3.9269908169872414],
        "goal": [4, 6.928203230275509, 2.6179938779914944]}]"#;
    let s = scene(
        r#"{"name": "cvf", "v_max": 1, "c_p": 12, "stop_within": 0.5}"#,
        robots,
        70.0,
    );
    let out = follow(&s, &source);
    assert!(out.off_held <= 1e-11, "{:e}", out.off_held);
    assert_eq!(out.end_step, source.end_step);
    assert_close!(out.end_step as f64 * s.dt, source.end_time, 0.05);
    assert!(out.peak_curvature <= 1.0, "{}", out.peak_curvature);
    assert_close!(out.peak_curvature, 1.0, 1e-12);
    stays(&s, &out);
}

/// Scenes of the sweep's random family (4 robots, 2 obstacles) and of its formation family (9
/// robots, 1 obstacle) run with the planner `name` without a NaN in any pose or command, a
/// panic or a collision (the shared barrier is the field planners' only avoidance).
fn sweep_scenes_run_with(name: &str) {
    let random = Recipe {
        robots: 4..=4,
        obstacles: 2..=2,
        duration: 60.0,
        ..Recipe::default()
    };
    let formation = Recipe {
        robots: 9..=9,
        obstacles: 1..=1,
        duration: 60.0,
        ..Recipe::formation()
    };
    for recipe in [random, formation] {
        for seed in 0..3 {
            let mut s = scenario(&recipe, seed).unwrap();
            s.planner = ::dvf::planner::Spec::named(name);
            let mut sim = Simulation::new(&s).unwrap();
            for _ in 0..s.steps() {
                sim.step();
                for r in sim.robots() {
                    let c = r.last.command;
                    let finite = r.pose.p.is_finite() && r.pose.theta.is_finite();
                    assert!(
                        finite && c.v.is_finite() && c.omega.is_finite(),
                        "{name} {seed}"
                    );
                }
            }
            let report = sim.report();
            assert_eq!(report.planner.as_deref(), Some(name));
            assert_eq!(report.violations, 0, "{name} {seed}");
        }
    }
}

#[test]
fn sweep_scenes_run_with_avf() {
    sweep_scenes_run_with("avf");
}

#[test]
fn sweep_scenes_run_with_cvf() {
    sweep_scenes_run_with("cvf");
}

/// `dvf simulate FILE` runs the source's scene with `avf` and its gains, to the source's end
/// (step 836, where the robot stops), and refuses bad gains with a message that names the
/// field, without a panic.
#[test]
fn dvf_simulate_runs_a_field_planner_and_refuses_bad_gains() {
    let file = TempFile::with_text(
        "avf",
        &format!(
            r#"{{"duration": 12, "dt": 0.01, "params": {{"tol_position": 0.1}},
                "planner": {{"name": "avf", "lambda": 2, "k_omega": 1}}, {SOURCE_SCENE}}}"#
        ),
    );
    let o = dvf(&["simulate", file.arg()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let r: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(r["planner"], "avf", "{r}");
    let converged = r["robots"][0]["converged_at"].as_f64().unwrap();
    assert_close!(converged, 8.36, 1e-9);
    for (planner, field) in [
        (r#"{"name": "cvf", "k2": 3}"#, "planner.k2: "),
        (r#"{"name": "avf", "lambda": 1}"#, "planner.lambda: "),
        (r#"{"name": "cvf", "rho": -1}"#, "planner.rho: "),
    ] {
        let file = TempFile::with_text(
            "bad",
            &format!(r#"{{"planner": {planner}, {SOURCE_SCENE}}}"#),
        );
        let o = dvf(&["simulate", file.arg()]);
        assert!(!o.status.success());
        let e = stderr(&o);
        assert!(e.contains(field) && !e.contains("panicked"), "{e}");
    }
}
