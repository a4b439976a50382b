//! One million steps of the ten-robot example (Example 4) with the page's buffers
//! ([`dvf::playground::Live`]), printing a JSON line every 100,000 steps: simulated time, resident
//! memory of the process (Linux `/proc/self/statm`), the minimum recorded pair distance and
//! the largest position error. Memory must stay flat and every number finite.
//!
//! Run: `cargo run --release --example long_run`

use dvf::playground::Live;
use dvf::presets::preset;

const STEPS: usize = 1_000_000;
const REPORT_EVERY: usize = 100_000;

/// Resident set size in KiB, when the platform tells it.
fn rss_kib() -> Option<u64> {
    let statm = std::fs::read_to_string("/proc/self/statm").ok()?;
    let pages: u64 = statm.split_whitespace().nth(1)?.parse().ok()?;
    Some(pages * 4)
}

fn main() {
    let mut s = preset("example4-obstacle-formation").expect("preset");
    // 1e6 steps within the 3,600 s limit: dt = 2 ms for 2,000 s.
    s.dt = 0.002;
    s.duration = STEPS as f64 * s.dt;
    let mut live = Live::new(s).expect("valid");
    let start = std::time::Instant::now();
    while !live.finished() {
        live.step(REPORT_EVERY);
        let report = live.simulation().report();
        // The trail rings hold NaN where nothing is recorded yet; poses are always set.
        let finite = live.poses().iter().all(|v| v.is_finite());
        let worst = report
            .robots
            .iter()
            .map(|r| r.position_error)
            .fold(0.0, f64::max);
        println!(
            "{}",
            serde_json::json!({
                "steps": live.steps(),
                "time": live.time(),
                "rss_kib": rss_kib(),
                "min_pair_distance": report.min_pair_distance,
                "max_position_error": worst,
                "violations": report.violations,
                "finite": finite,
                "wall_s": start.elapsed().as_secs_f64(),
            })
        );
    }
}
