//! Random scenarios and their statistics: the evidence that the planner keeps its promises on
//! scenes nobody tuned for.
//!
//! Three families ([`Family`]): `random` (the default), `dense` (the same draw with more robots
//! and obstacles) and `formation` ([`formation_scenario`]: robots from a column through a row
//! of obstacles into a grid, a line or a ring of goal slots).
//!
//! [`random_scenario`] draws `robots` robots and `obstacles` circular obstacles in a square
//! area; starts (and goals) are at least `separation` apart from each other and outside every
//! obstacle's influence ring, headings are uniform. Obstacles may overlap each other. Scenario
//! `k` of a sweep from seed `s` depends only on `s + k`, so a failure is reproduced from its
//! seed alone (`dvf sweep --seed S+k --count 1 --write DIR`).
//!
//! A sweep can be split across processes or machines: each shard writes one [`Outcome`] per
//! scenario (a JSON line), and [`Summary::of`] summarises any set of outcomes that covers the
//! seeds once, in the same arithmetic as an unsharded [`sweep`], so N shards merge to exactly
//! the summary of one run.

use crate::obstacle::Obstacle;
use crate::params::Avoidance;
use crate::params::Params;
use crate::scenario::{RobotSpec, Scenario};
use crate::sim::smoothness::{Smoothness, Sums};
use crate::sim::{self, Report};
use glam::DVec2;
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;
use std::ops::RangeInclusive;

/// The step of every random scenario (s).
pub const DT: f64 = 0.01;

/// Give up placing a pose after this many rejected draws (the area is too crowded).
const MAX_DRAWS: usize = 100_000;

/// The kind of scene a sweep draws.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Family {
    /// Robots and obstacles anywhere in the area ([`random_scenario`]).
    #[default]
    Random,
    /// Robots from a column on the left through a row of obstacles into a grid, a line or a
    /// ring of goal slots ([`formation_scenario`]).
    Formation,
    /// [`random_scenario`] with more robots and obstacles ([`Recipe::dense`]).
    Dense,
}

/// What [`random_scenario`] and [`formation_scenario`] draw from.
#[derive(Clone, Debug, PartialEq)]
pub struct Recipe {
    /// The kind of scene.
    pub family: Family,
    /// Number of robots, drawn uniformly from this range.
    pub robots: RangeInclusive<usize>,
    /// Number of obstacles, drawn uniformly from this range.
    pub obstacles: RangeInclusive<usize>,
    /// Side of the square area `[0, side]²` (m) that holds starts, goals and obstacle centres.
    pub side: f64,
    /// Obstacle disc radius `r_o` (m), uniform.
    pub obstacle_radius: RangeInclusive<f64>,
    /// Width of the influence ring `R_o − r_o` (m), uniform.
    pub ring_width: RangeInclusive<f64>,
    /// Least distance between two starts and between two goals, in units of `safe_radius`.
    pub separation: f64,
    /// [`Family::Formation`]: the distance between neighbouring goal slots, in units of
    /// `safe_radius`, uniform (at least 2, so that the goals can be held apart).
    pub spacing: RangeInclusive<f64>,
    /// Simulated seconds.
    pub duration: f64,
    /// The method's parameters.
    pub params: Params,
}

impl Default for Recipe {
    /// 4 to 16 robots and 0 to 5 obstacles (`r_o` 1 … 8, rings 1 … 5 wide) in a 100 × 100
    /// area, poses `3·safe_radius` apart, 120 s, default parameters.
    fn default() -> Self {
        Self {
            family: Family::Random,
            spacing: 3.0..=6.0,
            robots: 4..=16,
            obstacles: 0..=5,
            side: 100.0,
            obstacle_radius: 1.0..=8.0,
            ring_width: 1.0..=5.0,
            separation: 3.0,
            duration: 120.0,
            params: Params::default(),
        }
    }
}

impl Recipe {
    /// The dense family: 24 to 64 robots and 0 to 8 obstacles in the same area, poses
    /// `3·safe_radius` apart, 200 s.
    #[must_use]
    pub fn dense() -> Self {
        Self {
            family: Family::Dense,
            robots: 24..=64,
            obstacles: 0..=8,
            duration: 200.0,
            ..Self::default()
        }
    }

    /// The formation family: 9 to 25 robots, 0 to 3 obstacles on the way, goal slots 3 to 6
    /// safe radii apart, 300 s (see [`formation_scenario`]).
    #[must_use]
    pub fn formation() -> Self {
        Self {
            family: Family::Formation,
            robots: 9..=25,
            obstacles: 0..=3,
            obstacle_radius: 1.0..=4.0,
            ring_width: 1.0..=3.0,
            duration: 300.0,
            ..Self::default()
        }
    }

    /// The recipe of `family` with its default ranges.
    #[must_use]
    pub fn of(family: Family) -> Self {
        match family {
            Family::Random => Self::default(),
            Family::Formation => Self::formation(),
            Family::Dense => Self::dense(),
        }
    }
}

/// Scenario number `seed` of `recipe`'s family, or `None` if its poses could not be placed.
#[must_use]
pub fn scenario(recipe: &Recipe, seed: u64) -> Option<Scenario> {
    match recipe.family {
        Family::Random | Family::Dense => random_scenario(recipe, seed),
        Family::Formation => formation_scenario(recipe, seed),
    }
}

/// How the goal slots of a [`formation_scenario`] are laid out.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Layout {
    /// Rows and columns, as square as the count allows (the last row may be short).
    Grid,
    /// One straight line at a random angle.
    Line,
    /// A circle whose neighbouring slots are the spacing apart.
    Ring,
}

/// The goal slots of `n` robots `spacing` apart in `layout`, centred on the origin.
#[must_use]
pub fn slots(layout: Layout, n: usize, spacing: f64, angle: f64) -> Vec<DVec2> {
    let along = crate::maths::from_angle(angle);
    match layout {
        Layout::Grid => {
            let cols = (n as f64).sqrt().ceil() as usize;
            let rows = n.div_ceil(cols);
            let half = |k: usize| (k as f64 - 1.0) / 2.0;
            (0..n)
                .map(|k| {
                    let (r, c) = (k / cols, k % cols);
                    spacing * DVec2::new(c as f64 - half(cols), r as f64 - half(rows))
                })
                .collect()
        }
        Layout::Line => (0..n)
            .map(|k| spacing * (k as f64 - (n as f64 - 1.0) / 2.0) * along)
            .collect(),
        Layout::Ring => {
            let radius = if n < 2 {
                0.0
            } else {
                spacing / (2.0 * crate::maths::sin(PI / n as f64))
            };
            (0..n)
                .map(|k| radius * crate::maths::from_angle(angle + 2.0 * PI * k as f64 / n as f64))
                .collect()
        }
    }
}

/// Scenario number `seed` of the formation family: robots in a column on the left
/// (`separation` apart, at `x = 0`), a row of obstacles on the way (at `x` between 20 and 30,
/// their rings at least `4·safe_radius` apart, so that there are gaps), and goal slots in a
/// grid, a line or a ring (drawn) `spacing` apart (drawn), whose nearest slot is at least
/// `10·safe_radius` past the obstacles. Every robot's goal is a slot in the order of the
/// slots; start and goal headings are uniform. `None` if the obstacles could not be placed.
#[must_use]
pub fn formation_scenario(recipe: &Recipe, seed: u64) -> Option<Scenario> {
    let mut rng = Pcg64::seed_from_u64(seed);
    let r = recipe.params.safe_radius;
    let n = rng.random_range(recipe.robots.clone());
    let layout = [Layout::Grid, Layout::Line, Layout::Ring][rng.random_range(0..3)];
    let spacing = rng.random_range(recipe.spacing.clone()) * r;
    let angle = rng.random_range(-PI..PI);
    let gap = recipe.separation * r;
    let column = gap * (n as f64 - 1.0);
    let starts: Vec<DVec2> = (0..n)
        .map(|k| DVec2::new(0.0, k as f64 * gap - column / 2.0))
        .collect();
    // The row of obstacles across the column's height (at least 40 safe radii).
    let height = column.max(40.0 * r);
    let n_obstacles = rng.random_range(recipe.obstacles.clone());
    let mut obstacles: Vec<Obstacle> = Vec::with_capacity(n_obstacles);
    for _ in 0..n_obstacles {
        let placed = (0..MAX_DRAWS).find_map(|_| {
            let radius = rng.random_range(recipe.obstacle_radius.clone()) * r;
            let influence = radius + rng.random_range(recipe.ring_width.clone()) * r;
            let center = DVec2::new(
                rng.random_range(20.0..=30.0) * r,
                rng.random_range(-height / 2.0..=height / 2.0),
            );
            let apart = obstacles
                .iter()
                .all(|o| center.distance(o.center) >= o.influence + influence + 4.0 * r);
            apart.then_some(Obstacle {
                center,
                radius,
                influence,
            })
        })?;
        obstacles.push(placed);
    }
    let reach = obstacles
        .iter()
        .map(|o| o.center.x + o.influence)
        .fold(30.0 * r, f64::max);
    let mut goals = slots(layout, n, spacing, angle);
    let nearest = goals.iter().map(|g| g.x).fold(f64::INFINITY, f64::min);
    let shift = DVec2::new(reach + 10.0 * r - nearest, 0.0);
    for g in &mut goals {
        *g += shift;
    }
    let robots = with_headings(&starts, &goals, &mut rng);
    let name = match layout {
        Layout::Grid => "grid",
        Layout::Line => "line",
        Layout::Ring => "ring",
    };
    Some(scene(
        recipe,
        format!("formation scenario ({name}), seed {seed}"),
        robots,
        obstacles,
    ))
}

/// A scenario of `recipe` (its duration and parameters, the sweep's step).
fn scene(
    recipe: &Recipe,
    name: String,
    robots: Vec<RobotSpec>,
    obstacles: Vec<Obstacle>,
) -> Scenario {
    Scenario {
        name,
        bounds: None,
        duration: recipe.duration,
        dt: DT,
        params: recipe.params,
        independent: false,
        robots,
        obstacles,
    }
}

/// Robots from `starts` to `goals` (in order) with uniform start and goal headings.
fn with_headings(starts: &[DVec2], goals: &[DVec2], rng: &mut Pcg64) -> Vec<RobotSpec> {
    starts
        .iter()
        .zip(goals)
        .map(|(s, g)| RobotSpec {
            start: [s.x, s.y, rng.random_range(-PI..PI)],
            goal: [g.x, g.y, rng.random_range(-PI..PI)],
        })
        .collect()
}

/// Scenario number `seed` of `recipe`, or `None` if its poses could not be placed (the recipe
/// asks for more room than the area has).
#[must_use]
pub fn random_scenario(recipe: &Recipe, seed: u64) -> Option<Scenario> {
    let mut rng = Pcg64::seed_from_u64(seed);
    let side = recipe.side;
    let n_obstacles = rng.random_range(recipe.obstacles.clone());
    let obstacles: Vec<Obstacle> = (0..n_obstacles)
        .map(|_| {
            let center = DVec2::new(rng.random_range(0.0..side), rng.random_range(0.0..side));
            let radius = rng.random_range(recipe.obstacle_radius.clone());
            let influence = radius + rng.random_range(recipe.ring_width.clone());
            Obstacle {
                center,
                radius,
                influence,
            }
        })
        .collect();
    let n_robots = rng.random_range(recipe.robots.clone());
    let gap = recipe.separation * recipe.params.safe_radius;
    let mut place = |taken: &[DVec2]| -> Option<DVec2> {
        (0..MAX_DRAWS).find_map(|_| {
            let p = DVec2::new(rng.random_range(0.0..side), rng.random_range(0.0..side));
            let free = obstacles.iter().all(|o| p.distance(o.center) > o.influence)
                && taken.iter().all(|q| p.distance(*q) >= gap);
            free.then_some(p)
        })
    };
    let mut starts = Vec::with_capacity(n_robots);
    let mut goals = Vec::with_capacity(n_robots);
    for _ in 0..n_robots {
        starts.push(place(&starts)?);
        goals.push(place(&goals)?);
    }
    let robots = with_headings(&starts, &goals, &mut rng);
    Some(scene(
        recipe,
        format!("random scenario, seed {seed}"),
        robots,
        obstacles,
    ))
}

/// One scenario of a sweep that did not keep every promise.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Failure {
    /// Its seed: `random_scenario(recipe, seed)` rebuilds it.
    pub seed: u64,
    /// Robots that had not converged at the end.
    pub unconverged: usize,
    /// Violation events (see [`Report::violations`]).
    pub violations: usize,
}

/// What a sweep found.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Summary {
    /// First seed.
    pub seed: u64,
    /// Scenarios run.
    pub scenarios: usize,
    /// Robots over all scenarios.
    pub robots: usize,
    /// Robots that converged (within tolerance from some time to the end).
    pub converged: usize,
    /// `converged / robots`.
    pub success_rate: f64,
    /// Violation events over all scenarios.
    pub violations: usize,
    /// Scenarios whose poses could not be placed (not run).
    pub skipped: usize,
    /// Quantiles of the convergence time of converged robots (s): min, 10 %, median, 90 %, max.
    pub convergence_time: Quantiles,
    /// How smooth the turn rates were, over all robots of all scenarios.
    pub smoothness: Smoothness,
    /// Every scenario with an unconverged robot or a violation.
    pub failures: Vec<Failure>,
}

/// Order statistics of a sample.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Quantiles {
    /// Smallest value.
    pub min: f64,
    /// 10th percentile.
    pub p10: f64,
    /// Median.
    pub p50: f64,
    /// 90th percentile.
    pub p90: f64,
    /// Largest value.
    pub max: f64,
}

impl Quantiles {
    /// Nearest-rank quantiles of `values` (all zero when empty).
    #[must_use]
    pub fn of(mut values: Vec<f64>) -> Self {
        if values.is_empty() {
            return Self::default();
        }
        values.sort_by(f64::total_cmp);
        let at = |q: f64| values[((values.len() - 1) as f64 * q).round() as usize];
        Self {
            min: at(0.0),
            p10: at(0.1),
            p50: at(0.5),
            p90: at(0.9),
            max: at(1.0),
        }
    }
}

/// What a shard records of a recipe, so that outcomes of different recipes are not merged:
/// the ranges and the settings the command line can change.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RecipeKey {
    /// The family (lines written before families existed are of the random one).
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
        }
    }
}

/// One scenario of a sweep: its seed, its recipe and what happened (one JSON line of a shard).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Outcome {
    /// The scenario's seed.
    pub seed: u64,
    /// The recipe it was drawn from.
    pub recipe: RecipeKey,
    /// Its poses could not be placed: not run.
    pub skipped: bool,
    /// Robots.
    pub robots: usize,
    /// The step after which each converged robot stayed converged (its time is `k · DT`), in
    /// robot order: steps rather than seconds, so that the line reads back to the same bits.
    pub converged_steps: Vec<u64>,
    /// Violation events.
    pub violations: usize,
    /// The robots' smoothness tallies, summed, the largest steps of ω rounded to 1e-3 rad/s
    /// (a short decimal reads back to the same bits, so that a merge gives exactly the
    /// unsharded summary).
    pub smoothness: Sums,
}

impl Outcome {
    /// Runs scenario `seed` of `recipe`; `on_report` sees the run.
    pub fn run(recipe: &Recipe, seed: u64, on_report: impl FnOnce(&Scenario, &Report)) -> Self {
        let mut outcome = Self {
            seed,
            recipe: RecipeKey::of(recipe),
            skipped: true,
            robots: 0,
            converged_steps: Vec::new(),
            violations: 0,
            smoothness: Sums::default(),
        };
        if let Some(scenario) = scenario(recipe, seed) {
            let report = sim::run(&scenario);
            outcome.skipped = false;
            outcome.robots = report.robots.len();
            outcome.converged_steps = report
                .robots
                .iter()
                .filter_map(|r| r.converged_at)
                .map(|t| (t / DT).round() as u64)
                .collect();
            outcome.violations = report.violations;
            // The tallies are native only (the wasm module's size budget).
            #[cfg(not(target_arch = "wasm32"))]
            {
                let sums = &mut outcome.smoothness;
                for r in &report.robots {
                    sums.add(&r.smoothness, report.steps as u64, DT);
                }
                let round = |x: f64| (x * 1e3).round() / 1e3;
                sums.max_omega_step = round(sums.max_omega_step);
                sums.settled_max_omega_step = round(sums.settled_max_omega_step);
            }
            on_report(&scenario, &report);
        }
        outcome
    }
}

/// Runs scenarios `seed, seed + 1, …` (`count` of them) and summarises them. `on_report`
/// sees each run (for writing failures out). Natively the scenarios run on every core
/// (rayon); the summary is the same bits with any number of threads, since [`Summary::of`]
/// takes the outcomes in seed order.
pub fn sweep(
    recipe: &Recipe,
    seed: u64,
    count: usize,
    on_report: impl Fn(u64, &Scenario, &Report) + Sync,
) -> Summary {
    let run = |k: u64| {
        let s = seed.wrapping_add(k);
        Outcome::run(recipe, s, |scenario, report| on_report(s, scenario, report))
    };
    #[cfg(not(target_arch = "wasm32"))]
    let outcomes: Vec<Outcome> = {
        use rayon::prelude::*;
        (0..count as u64).into_par_iter().map(run).collect()
    };
    #[cfg(target_arch = "wasm32")]
    let outcomes: Vec<Outcome> = (0..count as u64).map(run).collect();
    Summary::of(seed, &outcomes)
}

impl Summary {
    /// The summary of `outcomes`, in seed order from `seed` (the first): what [`sweep`] prints
    /// for the same scenarios, however they were split and in whatever order they arrive.
    #[must_use]
    pub fn of(seed: u64, outcomes: &[Outcome]) -> Self {
        let mut outcomes: Vec<&Outcome> = outcomes.iter().collect();
        outcomes.sort_by_key(|o| o.seed.wrapping_sub(seed));
        let mut robots = 0;
        let mut converged = 0;
        let mut violations = 0;
        let mut skipped = 0;
        let mut times = Vec::new();
        let mut failures = Vec::new();
        let mut smooth = Sums::default();
        for o in &outcomes {
            if o.skipped {
                skipped += 1;
                continue;
            }
            let unconverged = o.robots - o.converged_steps.len();
            robots += o.robots;
            converged += o.converged_steps.len();
            violations += o.violations;
            smooth.merge(&o.smoothness);
            times.extend(o.converged_steps.iter().map(|&k| k as f64 * DT));
            if unconverged > 0 || o.violations > 0 {
                failures.push(Failure {
                    seed: o.seed,
                    unconverged,
                    violations: o.violations,
                });
            }
        }
        let count = outcomes.len();
        Summary {
            seed,
            scenarios: count - skipped,
            robots,
            converged,
            success_rate: if robots == 0 {
                1.0
            } else {
                converged as f64 / robots as f64
            },
            violations,
            skipped,
            convergence_time: Quantiles::of(times),
            smoothness: smooth.smoothness(DT),
            failures,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::test;

    #[test]
    fn random_scenarios_keep_the_recipe() {
        let recipe = Recipe::default();
        for seed in 0..200 {
            let s = random_scenario(&recipe, seed).expect("room for 16 robots");
            assert!(recipe.robots.contains(&s.robots.len()));
            assert!(recipe.obstacles.contains(&s.obstacles.len()));
            s.validate().expect("a random scenario is valid");
            let gap = recipe.separation * recipe.params.safe_radius;
            for (i, a) in s.robots.iter().enumerate() {
                for p in [a.start_pose().p, a.goal_pose().p] {
                    assert!(s
                        .obstacles
                        .iter()
                        .all(|o| p.distance(o.center) > o.influence));
                }
                for b in &s.robots[..i] {
                    assert!(a.start_pose().p.distance(b.start_pose().p) >= gap);
                    assert!(a.goal_pose().p.distance(b.goal_pose().p) >= gap);
                }
            }
        }
        // The same seed gives the same scenario; another seed another one.
        assert_eq!(random_scenario(&recipe, 7), random_scenario(&recipe, 7));
        assert_ne!(random_scenario(&recipe, 7), random_scenario(&recipe, 8));
    }

    /// Every family gives the same scenario for the same seed and another for another seed;
    /// the formation family's scenarios are valid, keep their ranges, put their goal slots
    /// the drawn spacing apart and their obstacles between the start column and the slots.
    #[test]
    fn families_are_deterministic_per_seed_and_keep_their_recipe() {
        for family in [Family::Random, Family::Dense, Family::Formation] {
            let recipe = Recipe::of(family);
            assert_eq!(scenario(&recipe, 11), scenario(&recipe, 11));
            assert_ne!(scenario(&recipe, 11), scenario(&recipe, 12));
        }
        let recipe = Recipe::formation();
        let r = recipe.params.safe_radius;
        let mut layouts = std::collections::BTreeSet::new();
        for seed in 0..60 {
            let s = formation_scenario(&recipe, seed).expect("room for the obstacles");
            s.validate().expect("a formation scenario is valid");
            assert!(recipe.robots.contains(&s.robots.len()));
            assert!(recipe.obstacles.contains(&s.obstacles.len()));
            layouts.insert(s.name.split(['(', ')']).nth(1).unwrap().to_owned());
            let goals: Vec<DVec2> = s.robots.iter().map(|g| g.goal_pose().p).collect();
            // The nearest other slot of every slot is within the spacing range (a relative
            // 1e-9 for the round-off of placing and measuring).
            for (i, g) in goals.iter().enumerate() {
                let nearest = goals
                    .iter()
                    .enumerate()
                    .filter(|&(j, _)| j != i)
                    .map(|(_, q)| g.distance(*q))
                    .fold(f64::INFINITY, f64::min);
                let (lo, hi) = (*recipe.spacing.start() * r, *recipe.spacing.end() * r);
                assert!(
                    nearest >= lo * (1.0 - 1e-9) && nearest <= hi * (1.0 + 1e-9),
                    "seed {seed}: slot {i} is {nearest} from the nearest"
                );
            }
            for o in &s.obstacles {
                assert!(s.robots.iter().all(|a| {
                    a.start_pose().p.x < o.center.x - o.influence
                        && a.goal_pose().p.x > o.center.x + o.influence
                }));
            }
        }
        // All three layouts occur.
        assert_eq!(layouts.len(), 3, "{layouts:?}");
    }

    #[test]
    fn slots_are_spaced_as_asked() {
        for layout in [Layout::Grid, Layout::Line, Layout::Ring] {
            for n in [1, 2, 5, 9, 10, 25] {
                let s = slots(layout, n, 3.0, 0.7);
                assert_eq!(s.len(), n);
                for (i, a) in s.iter().enumerate() {
                    for b in &s[..i] {
                        // Neighbouring slots are the spacing apart, none closer (round-off of
                        // sines and products: 1e-12 relative).
                        assert!(a.distance(*b) >= 3.0 * (1.0 - 1e-12), "{layout:?} {n}");
                    }
                }
            }
        }
    }

    #[test]
    fn an_impossible_recipe_is_refused_not_looped() {
        let recipe = Recipe {
            robots: 50..=50,
            side: 5.0,
            ..Recipe::default()
        };
        assert_eq!(random_scenario(&recipe, 1), None);
    }

    #[test]
    fn quantiles_by_nearest_rank() {
        let q = Quantiles::of((0..=10).rev().map(f64::from).collect());
        assert_eq!(
            q,
            Quantiles {
                min: 0.0,
                p10: 1.0,
                p50: 5.0,
                p90: 9.0,
                max: 10.0
            }
        );
        assert_eq!(Quantiles::of(vec![]), Quantiles::default());
    }
}
