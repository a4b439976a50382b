//! The scenarios of a sweep: scenario `seed` of a recipe depends on the seed alone.

use super::recipe::{Family, Limits, Recipe};
use crate::obstacle::Obstacle;
use crate::params::Params;
use crate::scenario::{RobotSpec, Scenario};
use glam::DVec2;
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;
use std::f64::consts::PI;

/// Give up placing a pose after this many rejected draws (the area is too crowded).
const MAX_DRAWS: usize = 100_000;

/// Scenario number `seed` of `recipe`'s family, or `None` if its poses could not be placed.
#[must_use]
pub fn scenario(recipe: &Recipe, seed: u64) -> Option<Scenario> {
    match recipe.family {
        Family::Random | Family::Dense => random_scenario(recipe, seed),
        Family::Formation => formation_scenario(recipe, seed),
    }
}

/// The scenario's parameters: the recipe's, with the limits drawn for `seed` when the recipe
/// draws them ([`Limits`]), from a generator of their own so that the scene is drawn alike.
fn params_of(recipe: &Recipe, seed: u64) -> Params {
    let mut params = recipe.params;
    if let Some(Limits { v_max, omega_max }) = &recipe.limits {
        let mut rng = Pcg64::seed_from_u64(seed ^ LIMITS_STREAM);
        params.v_max = Some(rng.random_range(v_max.clone()));
        params.omega_max = Some(rng.random_range(omega_max.clone()));
    }
    params
}

/// Mixed into a scenario's seed for the generator of its limits ([`params_of`]), so that the
/// limits are not drawn from the scene's stream.
const LIMITS_STREAM: u64 = 0x11A1_75ED_0F11_4175;

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
        seed,
        format!("formation scenario ({name}), seed {seed}"),
        robots,
        obstacles,
    ))
}

/// Scenario `seed` of `recipe` (its duration, step and parameters, with the limits it draws).
fn scene(
    recipe: &Recipe,
    seed: u64,
    name: String,
    robots: Vec<RobotSpec>,
    obstacles: Vec<Obstacle>,
) -> Scenario {
    Scenario {
        planner: recipe.planner.clone(),
        name,
        bounds: None,
        duration: recipe.duration,
        dt: recipe.dt,
        params: params_of(recipe, seed),
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
        seed,
        format!("random scenario, seed {seed}"),
        robots,
        obstacles,
    ))
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

    /// A recipe that draws the limits draws them within its ranges, for each scenario anew,
    /// and leaves the scene as the recipe without limits draws it; fixed limits are the
    /// values asked for.
    #[test]
    fn limits_are_drawn_apart_from_the_scene() {
        for family in [Family::Random, Family::Dense, Family::Formation] {
            let plain = Recipe::of(family);
            let drawn = Recipe {
                limits: Some(Limits {
                    v_max: 1.0..=5.0,
                    omega_max: 0.5..=3.0,
                }),
                ..plain.clone()
            };
            let mut seen = std::collections::BTreeSet::new();
            for seed in 0..20 {
                let a = scenario(&plain, seed).expect("a scene");
                let b = scenario(&drawn, seed).expect("a scene");
                let (v, w) = (b.params.v_max.unwrap(), b.params.omega_max.unwrap());
                assert!(
                    (1.0..=5.0).contains(&v) && (0.5..=3.0).contains(&w),
                    "{v} {w}"
                );
                seen.insert(v.to_bits());
                assert_eq!((a.params.v_max, a.params.omega_max), (None, None));
                let unlimited = Scenario {
                    params: a.params,
                    ..b.clone()
                };
                assert_eq!(unlimited, a, "seed {seed}: the scene is the same");
                b.validate().expect("a limited scenario is valid");
            }
            assert_eq!(seen.len(), 20, "a limit for each scenario");
            let fixed = scenario(&plain.clone().limited(2.0, 1.0), 3).expect("a scene");
            assert_eq!(
                (fixed.params.v_max, fixed.params.omega_max),
                (Some(2.0), Some(1.0))
            );
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
}
