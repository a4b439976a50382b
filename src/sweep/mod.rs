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
//!
//! - `recipe.rs`: what a family draws from ([`Recipe`], [`Family`]);
//! - `generate.rs`: the scenarios themselves ([`scenario`], [`random_scenario`],
//!   [`formation_scenario`] and its goal [`slots`]);
//! - `outcome.rs`: one scenario run, as a shard's JSON line records it ([`Outcome`]);
//! - `summary.rs`: a sweep and its statistics ([`sweep`], [`Summary`], [`Quantiles`]).

mod generate;
mod outcome;
mod recipe;
mod summary;

pub use generate::{formation_scenario, random_scenario, scenario, slots, Layout};
pub use outcome::{Outcome, RecipeKey};
pub use recipe::{Family, Limits, Recipe, DT};
pub use summary::{sweep, Failure, Quantiles, Summary};
