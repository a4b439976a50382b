//! The acceptance table of the robots' limits: each family of `dvf sweep` with `v_max` and
//! `ω_max` fixed ([`Recipe::limited`]), one row per family and pair of limits: robots that
//! arrive with their heading, violations and chattering robots, and the seeds of the
//! scenarios where a robot did not arrive. docs/book/src/performance.md holds its table.
//!
//! Run: `cargo run --release --example limits -- [COUNT [SEED [DURATION [FAMILIES [LIMITS]]]]]`,
//! for instance `cargo run --release --example limits -- 300 1000 900 random,dense,formation 2:2,1:1,5:5`
//! (the defaults).

use dvf::sweep::{sweep, Family, Recipe};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let arg = |k: usize, default: &str| args.get(k).cloned().unwrap_or_else(|| default.into());
    let count: usize = arg(0, "300").parse().expect("COUNT is a number");
    let seed: u64 = arg(1, "1000").parse().expect("SEED is a number");
    let duration: f64 = arg(2, "900")
        .parse()
        .expect("DURATION is a number of seconds");
    let families: Vec<Family> = arg(3, "random,dense,formation")
        .split(',')
        .map(|f| serde_json::from_value(serde_json::json!(f)).expect("a family"))
        .collect();
    let limits: Vec<(f64, f64)> = arg(4, "2:2,1:1,5:5")
        .split(',')
        .map(|l| {
            let (v, w) = l.split_once(':').expect("LIMITS are v_max:omega_max pairs");
            (v.parse().expect("v_max"), w.parse().expect("omega_max"))
        })
        .collect();
    println!("| family | v_max, ω_max | scenarios | robots | arrived | violations | chattering | failed seeds |");
    println!("|---|---|---|---|---|---|---|---|");
    for &family in &families {
        for &(v, w) in &limits {
            // 0:0 runs without limits, for comparison.
            let limited = Recipe::of(family);
            let limited = if v > 0.0 || w > 0.0 {
                limited.limited(v, w)
            } else {
                limited
            };
            let recipe = Recipe {
                duration,
                ..limited
            };
            let start = std::time::Instant::now();
            let s = sweep(&recipe, seed, count, |_, _, _| {});
            let failed: Vec<String> = s
                .failures
                .iter()
                .map(|f| format!("{}({}/{})", f.seed, f.unconverged, f.violations))
                .collect();
            println!(
                "| {family:?} | {v}, {w} | {} | {} | {:.2} % | {} | {} | {} |",
                s.scenarios,
                s.robots,
                s.success_rate.map_or(f64::NAN, |r| 100.0 * r),
                s.violations,
                s.smoothness.chattering_robots,
                failed.join(" ")
            );
            eprintln!("{family:?} {v},{w}: {:.0} s", start.elapsed().as_secs_f64());
        }
    }
}
