//! Formations: robots from a column through a row of obstacles into a grid, a line or a ring
//! of goal slots (`dvf sweep --family formation`) reach their slots with their headings,
//! without violation and without chattering once there. Native only: the smoothness
//! tallies are (the wasm module's size budget).
#![cfg(not(target_arch = "wasm32"))]

use dvf::sweep::{sweep, Recipe};

/// A modest formation sweep (slots 5 to 6 safe radii apart, obstacles on the way, random
/// headings, 9 to 12 robots, 16 scenes) meets the acceptance rate of the README's figures,
/// ≥ 99.5 % of the robots arriving (here: all of them, since one of some 170 would be
/// 0.6 %), with no violation and no robot chattering after it reached its slot. The bigger
/// counts are in the README (Notes on the paper, formations).
#[test]
fn a_formation_sweep_arrives_without_violation_or_chatter() {
    let recipe = Recipe {
        robots: 9..=12,
        spacing: 5.0..=6.0,
        duration: 150.0,
        ..Recipe::formation()
    };
    let s = sweep(&recipe, 0, 16, |_, _, _| {});
    assert_eq!(s.skipped, 0);
    assert_eq!(s.violations, 0, "{s:?}");
    assert!(s.success_rate >= 0.995, "{s:?}");
    assert_eq!(s.smoothness.chattering_robots, 0, "{s:?}");
}
