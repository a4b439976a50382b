//! The comparison's tables in Markdown, as the book shows them (`make compare-table`,
//! examples/compare.rs): the paper's examples, one row per example and planner
//! ([`examples_table`]), and the sweep families with and without the robots' limits, one row
//! per family and planner ([`families_table`]).

use super::{compare_with, Comparison};
use crate::error::Error;
use crate::planner::Spec;
use crate::presets::preset;
use crate::sweep::{Plan, Request};

/// The paper's four examples, by preset.
pub const EXAMPLES: [&str; 4] = [
    "table1-free-space",
    "table2-obstacles",
    "example3-circle-swap",
    "example4-obstacle-formation",
];

/// A number as the tables print it: `digits` decimals, `—` for none.
fn cell(v: Option<f64>, digits: usize) -> String {
    v.map_or_else(|| "—".to_owned(), |v| format!("{v:.digits$}"))
}

/// The header (when `header`) and the rows of one comparison's run metrics: one row per
/// planner, with a first column `label` (the scene's name, say) when there is one.
#[must_use]
pub fn run_rows(label: Option<&str>, c: &Comparison, header: bool) -> String {
    let mut out = String::new();
    let (scene, rule) = if label.is_some() {
        ("| scene ", "|---")
    } else {
        ("", "")
    };
    if header {
        out.push_str(&format!(
            "{scene}| planner | arrived | last arrival (s) | path (m) | effort ∫(v²+ω²)dt | peak curvature (1/m) | reversals | chattering | closest pair (m) | closest clearance (m) | violations | µs/step |\n\
             {rule}|---|---|---|---|---|---|---|---|---|---|---|---|\n",
        ));
    }
    let first = label.map_or_else(String::new, |l| format!("| {l} "));
    for p in &c.planners {
        let m = &p.metrics;
        out.push_str(&format!(
            "{first}| {} | {}/{} | {} | {:.1} | {:.1} | {:.2} | {} | {} | {} | {} | {} | {:.2} |\n",
            p.planner.name,
            m.arrived,
            p.robots.len(),
            cell(m.time_to_last_arrival, 2),
            m.path_length,
            m.control_effort,
            m.peak_curvature,
            m.reversals,
            m.chattering_robots,
            cell(m.min_pair_distance, 3),
            cell(m.min_obstacle_clearance, 3),
            m.violations,
            1e3 * m.ms_per_step,
        ));
    }
    out
}

/// The simulated time of each example in [`examples_table`] (s): at least this long, so that a
/// planner slower than DVF has the time to arrive, and its last arrival says how long it took.
pub const EXAMPLE_DURATION: f64 = 120.0;

/// The planners of the book's table, with the gains that fit the scenes' robot where a
/// source's defaults describe its own robot: `clf` and `clf-cbf` without the GRITSbot's wheel
/// and speed limits (0.16 and 0.2 m/s: the scene's `v_max`, when set, limits them instead),
/// `avf` and `cvf` stopping within 3 cm of the goal rather than the source's ρ/10 = 10 cm (the
/// scenes count a robot arrived within `tol_position` = 5 cm), `move-to-pose` stopping within
/// 1e-6 m rather than 1 mm (at 1 mm its heading is still some 0.1 rad off, beyond
/// `tol_heading`). Every other gain is its source's.
#[must_use]
pub fn book_planners() -> Vec<Spec> {
    let gains = |name: &str, json: &str| Spec {
        name: name.to_owned(),
        gains: serde_json::from_str(json).unwrap_or_default(),
    };
    crate::planner::PLANNERS
        .iter()
        .map(|e| match e.name {
            "clf" => gains(e.name, r#"{"wheel_velocity_limit": null}"#),
            "clf-cbf" => gains(
                e.name,
                r#"{"wheel_velocity_limit": null, "velocity_magnitude_limit": null}"#,
            ),
            "avf" | "cvf" => gains(e.name, r#"{"stop_within": 0.03}"#),
            "move-to-pose" => gains(e.name, r#"{"stop_distance": 1e-6}"#),
            _ => Spec::named(e.name),
        })
        .collect()
}

/// The paper's examples ([`EXAMPLES`]), each run for at least [`EXAMPLE_DURATION`], with each
/// of `planners`: one Markdown table, a row per example and planner, with the compute time
/// read from `clock` (ms).
///
/// # Errors
/// As [`compare_with`].
pub fn examples_table(planners: &[Spec], mut clock: impl FnMut() -> f64) -> Result<String, Error> {
    let mut out = String::new();
    for (k, name) in EXAMPLES.iter().enumerate() {
        let mut s = preset(name)?;
        s.duration = s.duration.max(EXAMPLE_DURATION);
        let c = compare_with(&s, planners, &mut clock)?;
        out.push_str(&run_rows(Some(name), &c, k == 0));
    }
    Ok(out)
}

/// One family's sweep as [`families_table`] runs it: a label and its request (whose `planner`
/// is set for each planner in turn).
#[derive(Clone, Debug)]
pub struct FamilySweep {
    /// The family as the table names it (`random`, `dense, v_max = ω_max = 2`).
    pub label: String,
    /// The sweep.
    pub request: Request,
}

/// The sweeps of the book's table: the three families, `count` scenes each from seed 0, without
/// limits and with `v_max = ω_max = 2`.
#[must_use]
pub fn book_sweeps(count: usize) -> Vec<FamilySweep> {
    let mut out = Vec::new();
    for family in ["random", "dense", "formation"] {
        for limited in [false, true] {
            out.push(FamilySweep {
                label: if limited {
                    format!("{family}, v_max = ω_max = 2")
                } else {
                    family.to_owned()
                },
                request: Request {
                    family: family.into(),
                    count,
                    set: if limited {
                        vec!["v_max=2".into(), "omega_max=2".into()]
                    } else {
                        Vec::new()
                    },
                    ..Request::default()
                },
            });
        }
    }
    out
}

/// Each of `sweeps` run with each of `planners` (`dvf sweep --planner`): one Markdown table, a
/// row per sweep and planner: the scenes that ran, the robots that arrived with their heading
/// (count and rate), the violation events, the median and the largest arrival time, the
/// robots that chatter, the scenes with a failure.
///
/// # Errors
/// A sweep's request or a planner refused ([`Plan::new`]), naming the field.
pub fn families_table(planners: &[Spec], sweeps: &[FamilySweep]) -> Result<String, Error> {
    let mut out = String::from(
        "| family | planner | scenes | arrived | rate | violations | median arrival (s) | last arrival (s) | chattering | failed scenes |\n\
         |---|---|---|---|---|---|---|---|---|---|\n",
    );
    for sweep in sweeps {
        for spec in planners {
            let plan = Plan::new(&Request {
                planner: spec.clone(),
                ..sweep.request.clone()
            })?;
            let summaries = plan.summaries(|_, _, _, _| {});
            for (_, s) in summaries.all() {
                let any = s.robots > 0;
                out.push_str(&format!(
                    "| {} | {} | {} | {}/{} | {} | {} | {} | {} | {} | {} |\n",
                    sweep.label,
                    spec.name,
                    s.scenarios,
                    s.converged,
                    s.robots,
                    cell(s.success_rate.map(|r| 100.0 * r), 2) + " %",
                    s.violations,
                    cell((s.converged > 0).then_some(s.convergence_time.p50), 2),
                    cell((s.converged > 0).then_some(s.convergence_time.max), 2),
                    s.smoothness.chattering_robots,
                    if any {
                        s.failures.len().to_string()
                    } else {
                        "—".into()
                    },
                ));
            }
        }
    }
    Ok(out)
}
