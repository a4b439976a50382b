//! Long runs with the page's buffers ([`dvf::playground::Live`]): the trails are rings, so memory
//! does not grow with the run; nothing turns non-finite; and the metrics do not drift (the
//! clock is `steps · dt`, not a running sum, and robots that arrived stay arrived).
//!
//! This test runs 100,000 steps of the ten-robot example; `cargo run --release --example
//! long_run` runs the full million and prints the process's memory as it goes.
#![cfg(not(target_arch = "wasm32"))]

use dvf::playground::{Live, MAX_TRAIL_SAMPLES};
use dvf::presets::preset;

const STEPS: usize = 100_000;
/// Steps per call, as the page advances per animation frame at high speed.
const STEPS_PER_FRAME: usize = 1_000;

#[test]
fn a_hundred_thousand_steps_keep_memory_flat_and_numbers_finite() {
    let mut s = preset("example4-obstacle-formation").unwrap();
    s.duration = STEPS as f64 * s.dt;
    let mut live = Live::new(s.clone()).unwrap();
    let sizes = |l: &Live| {
        (
            l.trails().poses().len(),
            l.trails().times().len(),
            l.trails().min_pair().len(),
            l.poses().len(),
            l.prediction().poses().len(),
        )
    };
    let at_start = sizes(&live);
    let safe = 2.0 * s.params.safe_radius;
    let mut frames = 0;
    while !live.finished() {
        assert_eq!(live.step(STEPS_PER_FRAME), STEPS_PER_FRAME);
        frames += 1;
        assert_eq!(sizes(&live), at_start, "a buffer grew at frame {frames}");
        assert!(live.poses().iter().all(|v| v.is_finite()));
        assert!(live.trails().history_len() <= MAX_TRAIL_SAMPLES);
    }
    assert_eq!(frames, STEPS / STEPS_PER_FRAME);
    assert_eq!(live.steps(), STEPS);
    // The clock is steps · dt: no accumulated round-off after 1e5 steps.
    assert_eq!(live.time(), STEPS as f64 * s.dt);
    // Every recorded trail sample is finite (the rest of the ring is NaN, not recorded) and
    // every recorded pair distance is at least the safe one.
    let per_robot = MAX_TRAIL_SAMPLES * 3;
    for (i, ring) in live.trails().poses().chunks(per_robot).enumerate() {
        let finite = ring.iter().filter(|v| v.is_finite()).count();
        assert_eq!(finite, live.trails().len_of(i) * 3, "robot {i}");
    }
    let recorded: Vec<f64> = live.trails().min_pair()[..live.trails().history_len()].to_vec();
    assert!(recorded.iter().all(|&d| d.is_finite() && d >= safe));
    // Arrived robots stayed arrived for the whole thousand seconds.
    let report = live.simulation().report();
    assert_eq!(report.violations, 0);
    for r in &report.robots {
        let t = r.converged_at.expect("converged");
        assert!(t < 30.0, "converged only at {t}");
        assert!(r.position_error <= s.params.tol_position);
    }
}
