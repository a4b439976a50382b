//! One scenario of a sweep as a shard records it: the sweep it belongs to, its seed, its
//! recipe's key and what happened, in numbers that read back from JSON to the same bits.

use super::generate::scenario;
use super::recipe::{Family, Recipe};
use super::settings::Values;
use crate::grid::Neighbours;
use crate::params::Avoidance;
use crate::planner::Spec;
use crate::scenario::Scenario;
use crate::sim::smoothness::Sums;
use crate::sim::{self, Report, Robot};
use glam::DVec2;
use serde::{Deserialize, Serialize};

/// What a shard records of a recipe, so that outcomes of different recipes are not merged:
/// the ranges and the settings the command line can change.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RecipeKey {
    /// The family (a line without one is of the random family).
    #[serde(default)]
    pub family: Family,
    /// The formation family's goal spacing `[min, max]`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spacing: Option<[f64; 2]>,
    /// Robots per scenario, `[min, max]`.
    pub robots: [usize; 2],
    /// Obstacles per scenario, `[min, max]`.
    pub obstacles: [usize; 2],
    /// Robot avoidance.
    pub avoidance: Avoidance,
    /// The barrier's rate (`None`: no barrier).
    pub barrier_rate: Option<f64>,
    /// The values set for every scenario (`dvf sweep --set`), by name.
    #[serde(default, skip_serializing_if = "Values::is_empty")]
    pub set: Values,
    /// The ranges the robots' limits are drawn from ([`Recipe::limits`]):
    /// `[[v_max min, max], [ω_max min, max]]`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub limits: Option<[[f64; 2]; 2]>,
    /// The planner (a line without one ran DVF).
    #[serde(default, skip_serializing_if = "Spec::is_default")]
    pub planner: Spec,
}

impl RecipeKey {
    /// The key of `recipe`.
    #[must_use]
    pub fn of(recipe: &Recipe) -> Self {
        Self {
            family: recipe.family,
            spacing: (recipe.family == Family::Formation)
                .then(|| [*recipe.spacing.start(), *recipe.spacing.end()]),
            robots: [*recipe.robots.start(), *recipe.robots.end()],
            obstacles: [*recipe.obstacles.start(), *recipe.obstacles.end()],
            avoidance: recipe.params.avoidance,
            barrier_rate: recipe.params.barrier_rate,
            set: Values::new(),
            limits: recipe.limits.as_ref().map(|l| {
                [
                    [*l.v_max.start(), *l.v_max.end()],
                    [*l.omega_max.start(), *l.omega_max.end()],
                ]
            }),
            planner: recipe.planner.clone(),
        }
    }
}

/// The sweep a shard's line belongs to: what `dvf sweep merge` needs to check that a set of
/// lines is one whole sweep.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Sweep {
    /// The sweep's identity ([`Sweep::id_of`]): lines of another recipe, grid, first seed or
    /// count have another.
    pub id: String,
    /// The first seed.
    pub seed: u64,
    /// Scenarios per grid point (seeds `seed … seed + count − 1`).
    pub count: usize,
    /// Points of the grid (1 without one).
    #[serde(default = "one", skip_serializing_if = "is_one")]
    pub points: usize,
    /// This line's point of the grid (0 … points − 1).
    #[serde(default, skip_serializing_if = "is_zero")]
    pub point: usize,
    /// The shard that ran it: `[K, N]`.
    pub shard: [usize; 2],
}

fn one() -> usize {
    1
}
fn is_one(n: &usize) -> bool {
    *n == 1
}
fn is_zero(n: &usize) -> bool {
    *n == 0
}

impl Sweep {
    /// The identity of the sweep of `count` scenarios from `seed` of `recipe` at each of the
    /// grid's `points`: 16 hex digits of the 64-bit FNV-1a hash of their JSON, the same on
    /// every platform and release.
    #[must_use]
    pub fn id_of(recipe: &Recipe, points: &[Values], seed: u64, count: usize) -> String {
        use std::hash::Hasher;
        let text = serde_json::to_string(&(recipe, points, seed, count)).unwrap_or_default();
        let mut h = fnv::FnvHasher::default();
        h.write(text.as_bytes());
        format!("{:016x}", h.finish())
    }
}

/// One robot of a scenario as a shard records it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Arrival {
    /// Its index in the scenario.
    pub robot: usize,
    /// Whether it was at its goal (within the tolerances) from some time to the end.
    pub arrived: bool,
    /// That time (s), rounded to 1e-9 s so that it reads as the multiple of the step it is
    /// (`0.35`, not `0.35000000000000003`); `None` if it did not arrive.
    pub time: Option<f64>,
}

/// The two robots that came closest to each other during a run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Closest {
    /// Their indices, the smaller first.
    pub pair: [usize; 2],
    /// Their least distance less the safe distance `2·r_ij` (negative: a violation).
    pub clearance: f64,
}

/// One scenario of a sweep: its seed, its recipe and what happened (one JSON line of a shard).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Outcome {
    /// The sweep it belongs to (set by a shard; a line without it is refused by the merge).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sweep: Option<Sweep>,
    /// The scenario's seed.
    pub seed: u64,
    /// The grid point's values, by name (empty without a grid).
    #[serde(default, skip_serializing_if = "Values::is_empty")]
    pub values: Values,
    /// The recipe it was drawn from.
    pub recipe: RecipeKey,
    /// Its poses could not be placed: not run.
    pub skipped: bool,
    /// The step (s).
    pub dt: f64,
    /// Obstacles in the scenario.
    pub obstacles: usize,
    /// Every robot, in scenario order.
    pub robots: Vec<Arrival>,
    /// Violation events.
    pub violations: usize,
    /// The closest pair of robots over the run (`None` with fewer than two robots).
    pub closest: Option<Closest>,
    /// The robots' smoothness tallies, summed, the largest steps of ω rounded to 1e-3 rad/s
    /// (a short decimal reads back to the same bits, so that a merge gives exactly the
    /// unsharded summary).
    pub smoothness: Sums,
}

impl Outcome {
    /// Scenario `seed` of `recipe` skipped: its robots or obstacles could not be placed, so
    /// nothing ran.
    #[must_use]
    pub fn skipped(recipe: &Recipe, seed: u64) -> Self {
        Self {
            sweep: None,
            seed,
            values: Values::new(),
            recipe: RecipeKey::of(recipe),
            skipped: true,
            dt: recipe.dt,
            obstacles: 0,
            robots: Vec::new(),
            violations: 0,
            closest: None,
            smoothness: Sums::default(),
        }
    }

    /// Runs scenario `seed` of `recipe`; `on_report` sees the run.
    pub fn run(recipe: &Recipe, seed: u64, on_report: impl FnOnce(&Scenario, &Report)) -> Self {
        let mut outcome = Self::skipped(recipe, seed);
        if let Some(scenario) = scenario(recipe, seed) {
            let mut closest = ClosestPair::default();
            // A generated scenario passes its checks (`generate.rs`); one that did not would
            // count as skipped.
            let Ok(report) = sim::run_with(&scenario, |s| {
                closest.observe(s.robots());
                Ok::<(), crate::Error>(())
            }) else {
                return outcome;
            };
            outcome.skipped = false;
            outcome.obstacles = scenario.obstacles.len();
            outcome.robots = report
                .robots
                .iter()
                .enumerate()
                .map(|(robot, r)| Arrival {
                    robot,
                    arrived: r.converged_at.is_some(),
                    time: r.converged_at.map(|t| (t * 1e9).round() / 1e9),
                })
                .collect();
            outcome.violations = report.violations;
            outcome.closest = closest.best.map(|(i, j, d)| Closest {
                pair: [i, j],
                clearance: d - 2.0 * scenario.params.safe_radius,
            });
            let sums = &mut outcome.smoothness;
            for r in &report.robots {
                sums.add(&r.smoothness, report.steps as u64, scenario.dt);
            }
            let round = |x: f64| (x * 1e3).round() / 1e3;
            sums.max_omega_step = round(sums.max_omega_step);
            sums.settled_max_omega_step = round(sums.settled_max_omega_step);
            on_report(&scenario, &report);
        }
        outcome
    }

    /// The step after which each arrived robot stayed at its goal, in robot order: the times
    /// as multiples of the step, the same from a line read back as from the run.
    pub fn arrival_steps(&self) -> impl Iterator<Item = u64> + '_ {
        self.robots
            .iter()
            .filter_map(|a| a.time)
            .map(|t| (t / self.dt).round() as u64)
    }
}

/// The closest pair of robots over the states of a run, as [`sim::run_with`] shows them.
#[derive(Default)]
struct ClosestPair {
    points: Vec<DVec2>,
    /// The positions at the previous observation.
    last: Vec<DVec2>,
    search: Neighbours,
    /// `(i, j, distance)` with `i < j`, the first pair found at the least distance.
    best: Option<(usize, usize, f64)>,
    /// A lower bound of the least pair distance now less the best: while it is positive no
    /// pair can be closer than the best, and the pairs are not searched.
    slack: f64,
    /// The last closest pair's distance: the reach of the next search.
    reach: f64,
}

impl ClosestPair {
    /// Takes in the robots' positions: a pair closer than the closest so far replaces it.
    /// A pair's distance shrinks in a step by at most twice the largest move of a robot, so
    /// the pairs are searched (at O(N) cost for a bounded density) only once the moves since
    /// the last search add up to the gap between the closest pair then and the best.
    fn observe(&mut self, robots: &[Robot]) {
        self.points.clear();
        self.points.extend(robots.iter().map(|r| r.pose.p));
        if let Some((_, _, best)) = self.best {
            if self.last.len() == self.points.len() {
                let moved = self
                    .last
                    .iter()
                    .zip(&self.points)
                    .map(|(a, b)| a.distance(*b))
                    .fold(0.0, f64::max);
                self.slack -= 2.0 * moved;
                // A margin far above the round-off of distances among coordinates of at most
                // 10⁷ (crate::scenario::MAX_BOUNDS).
                if moved.is_finite() && self.slack > 1e-6 * (1.0 + best) {
                    std::mem::swap(&mut self.last, &mut self.points);
                    return;
                }
            }
        }
        if let Some((i, j, d)) = self.closest_now() {
            if self.best.is_none_or(|(_, _, b)| d < b) {
                self.best = Some((i, j, d));
            }
            self.slack = d - self.best.map_or(d, |(_, _, b)| b);
        }
        std::mem::swap(&mut self.last, &mut self.points);
    }

    /// The closest pair of `points` now (the first found at the least distance): the lists
    /// within the last closest distance, then four times that, until some pair is listed.
    fn closest_now(&mut self) -> Option<(usize, usize, f64)> {
        if self.points.iter().filter(|p| p.is_finite()).count() < 2 {
            return None;
        }
        let mut reach = if self.reach.is_finite() && self.reach > 0.0 {
            self.reach
        } else {
            1.0
        };
        // Two finite points within 10⁷ of the origin are listed after at most 20 tries.
        for _ in 0..64 {
            // A little past the reach: a pair at the reach itself is listed whatever the
            // rounding of its squared distance against the squared reach.
            self.search.build(&self.points, reach * (1.0 + 1e-9));
            let mut closest: Option<(usize, usize, f64)> = None;
            for i in 0..self.points.len() {
                for &j in self.search.of(i) {
                    let j = j as usize;
                    let d = self.points[i].distance(self.points[j]);
                    if j > i && closest.is_none_or(|(_, _, c)| d < c) {
                        closest = Some((i, j, d));
                    }
                }
            }
            if let Some(c) = closest {
                self.reach = c.2;
                return Some(c);
            }
            reach *= 4.0;
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::test;

    /// The closest pair is the pair at the report's least distance, and a line reads back to
    /// the same outcome, arrival times as multiples of the step.
    #[test]
    fn an_outcome_names_the_closest_pair_and_reads_back() {
        let recipe = Recipe {
            robots: 8..=8,
            ..Recipe::default()
        };
        for seed in 0..4 {
            let s = scenario(&recipe, seed).expect("room for eight robots");
            let mut closest = ClosestPair::default();
            let report = sim::run_with(&s, |sim| {
                closest.observe(sim.robots());
                Ok::<(), crate::Error>(())
            })
            .unwrap();
            let (i, j, d) = closest.best.expect("eight robots have a closest pair");
            // The same positions and the same distance as the report's metric: exact.
            assert_eq!(Some(d), report.min_pair_distance);
            assert!(i < j && j < 8, "{i} {j}");
            let o = Outcome::run(&recipe, seed, |_, _| {});
            assert!(!o.skipped);
            let c = o.closest.clone().expect("a closest pair");
            assert_eq!(
                (c.pair, c.clearance),
                ([i, j], d - 2.0 * s.params.safe_radius)
            );
            assert_eq!(o.robots.len(), 8);
            for (k, a) in o.robots.iter().enumerate() {
                assert_eq!((a.robot, a.arrived), (k, a.time.is_some()));
            }
            let line = serde_json::to_string(&o).unwrap();
            let back: Outcome = serde_json::from_str(&line).unwrap();
            assert_eq!(back, o);
            for (t, r) in o.robots.iter().zip(&report.robots) {
                // The step a time stands for is the report's; the time prints as that multiple
                // of the step (at most 6 digits for a time under 1000 s at 0.01 s).
                let Some(t) = t.time else { continue };
                let k = (r.converged_at.unwrap() / s.dt).round();
                assert_eq!((t / s.dt).round(), k);
                assert!(t.to_string().len() <= 7, "{t}");
            }
        }
    }

    /// In crowds of more than 32 robots (searched through cells rather than all pairs) the
    /// closest pair is still at the report's least distance, exactly.
    #[test]
    fn the_closest_pair_of_a_dense_scene_is_the_reports() {
        let recipe = Recipe {
            robots: 40..=40,
            ..Recipe::dense()
        };
        for seed in 0..2 {
            let s = scenario(&recipe, seed).expect("room for forty robots");
            let mut closest = ClosestPair::default();
            let report = sim::run_with(&s, |sim| {
                closest.observe(sim.robots());
                Ok::<(), crate::Error>(())
            })
            .unwrap();
            assert_eq!(closest.best.map(|c| c.2), report.min_pair_distance);
        }
    }
}
