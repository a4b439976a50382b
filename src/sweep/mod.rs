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
//! Any parameter, the step, the duration and the area can be set for every scenario
//! ([`set`]), or varied over a grid of points ([`Axis`], [`points`]), each point a group of
//! the summary ([`sweep_points`], [`Summaries`]).
//!
//! A sweep can be split across processes or machines: each shard writes one [`Outcome`] per
//! scenario (a JSON line that names its [`Sweep`]), and [`Merge`] checks that a set of lines
//! is one whole sweep and summarises it with [`Summary::of`], in the same arithmetic as an
//! unsharded [`sweep`], so N shards merge to exactly the summary of one run.
//!
//! - `recipe.rs`: what a family draws from ([`Recipe`], [`Family`]);
//! - `settings.rs`: what the command line sets and varies ([`set`], [`Axis`], [`points`]);
//! - `generate.rs`: the scenarios themselves ([`scenario`], [`random_scenario`],
//!   [`formation_scenario`] and its goal [`slots`]);
//! - `outcome.rs`: one scenario run, as a shard's JSON line records it ([`Outcome`]);
//! - `summary.rs`: a sweep and its statistics ([`sweep`], [`Summary`], [`Quantiles`]);
//! - `merge.rs`: shards' lines checked and summarised ([`Merge`]);
//! - `plan.rs`: a sweep as the command line and the Python package ask for it ([`Request`]),
//!   checked ([`Plan`]) and run whole or shard by shard.

mod generate;
mod merge;
mod outcome;
mod plan;
mod recipe;
mod settings;
mod summary;

pub use generate::{formation_scenario, random_scenario, scenario, slots, Layout};
pub use merge::{Merge, MergeError};
pub use outcome::{Arrival, Closest, Outcome, RecipeKey, Sweep};
pub use plan::{nothing_ran, Plan, Request, MAX_SWEEP};
pub use recipe::{Family, Limits, Recipe, DT};
pub use settings::{
    label, points, set, value_of, with, Axis, Values, MAX_AXIS, MAX_POINTS, RECIPE_NAMES,
};
pub use summary::{sweep, sweep_points, Failure, Group, Groups, Quantiles, Summaries, Summary};
