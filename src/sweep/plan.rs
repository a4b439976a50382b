//! A sweep as it is asked for ([`Request`]: the options of `dvf sweep` and of the Python
//! package's `dvf.sweep`), checked into a [`Plan`] of runs, and run whole ([`Plan::summaries`])
//! or one shard at a time ([`Plan::shard`]). Both faces go through here, so that they check the
//! same things with the same messages and write the same lines.

use super::outcome::{Outcome, Sweep};
use super::recipe::{Family, Recipe};
use super::settings::{label, points, value_of, with, Axis, Values};
use super::summary::{sweep_points, Summaries};
use crate::error::Error;
use crate::params::{Avoidance, DEFAULT_BARRIER_RATE};
use crate::planner::Spec;
use crate::scenario::{Scenario, MAX_OBSTACLES, MAX_ROBOTS};
use crate::sim::Report;

/// Largest number of scenarios in one sweep (its count times its grid's points).
pub const MAX_SWEEP: usize = 1_000_000;

/// What a sweep is asked for, before it is checked.
#[derive(Clone, Debug, PartialEq)]
pub struct Request {
    /// The kind of scene: `random`, `dense` or `formation`.
    pub family: String,
    /// Scenario `k` uses seed `seed + k`.
    pub seed: u64,
    /// Scenarios per grid point (1 … [`MAX_SWEEP`]).
    pub count: usize,
    /// Robots per scenario, drawn from `min..=max` (the family's range when `None`).
    pub robots: Option<(usize, usize)>,
    /// Obstacles per scenario, drawn from `min..=max` (the family's range when `None`).
    pub obstacles: Option<(usize, usize)>,
    /// The formation family's slot spacing in safe radii, `min..=max`.
    pub spacing: Option<(f64, f64)>,
    /// Robot avoidance: `exit` or `paper`.
    pub avoidance: String,
    /// The barrier's rate α (1/s), `None` for no barrier.
    pub barrier_rate: Option<f64>,
    /// `NAME=VALUE` texts, set in every scenario.
    pub set: Vec<String>,
    /// `NAME=a,b,c` or `NAME=start:stop:step` texts, the axes of the grid.
    pub grid: Vec<String>,
    /// The planner every scenario runs with ([`crate::planner`]; DVF by default).
    pub planner: Spec,
}

impl Default for Request {
    /// 100 random scenarios from seed 0, exit avoidance, the barrier at its default rate.
    fn default() -> Self {
        Self {
            family: "random".into(),
            seed: 0,
            count: 100,
            robots: None,
            obstacles: None,
            spacing: None,
            avoidance: "exit".into(),
            barrier_rate: Some(DEFAULT_BARRIER_RATE),
            set: Vec::new(),
            grid: Vec::new(),
            planner: Spec::default(),
        }
    }
}

/// A checked sweep: every grid point's recipe, the seeds and the identity its shard lines carry.
#[derive(Clone, Debug)]
pub struct Plan {
    seed: u64,
    count: usize,
    set: Values,
    runs: Vec<(Values, Recipe)>,
    id: String,
}

/// An [`Error::Invalid`] of `field`.
fn invalid(field: &str, message: String) -> Error {
    Error::Invalid {
        field: field.to_owned(),
        message,
    }
}

impl Plan {
    /// Checks `request`: its family, ranges and count, every `set` and grid value (with the
    /// scenario file's own checks, [`with`]), before anything runs.
    ///
    /// # Errors
    /// The first option that is out of range, named by its field (`robots`, `set`, `k_v`, …).
    pub fn new(request: &Request) -> Result<Self, Error> {
        let family = match request.family.as_str() {
            "random" => Family::Random,
            "dense" => Family::Dense,
            "formation" => Family::Formation,
            other => {
                return Err(invalid(
                    "family",
                    format!("must be random, dense or formation, not {other:?}"),
                ))
            }
        };
        let mut recipe = Recipe::of(family);
        if !(1..=MAX_SWEEP).contains(&request.count) {
            return Err(invalid(
                "count",
                format!("must be between 1 and {MAX_SWEEP}, not {}", request.count),
            ));
        }
        let robots = request
            .robots
            .unwrap_or((*recipe.robots.start(), *recipe.robots.end()));
        if robots.0 == 0 || robots.1 > MAX_ROBOTS || robots.0 > robots.1 {
            return Err(invalid(
                "robots",
                format!(
                    "must be a range within 1..={MAX_ROBOTS}, not {}..={}",
                    robots.0, robots.1
                ),
            ));
        }
        let obstacles = request
            .obstacles
            .unwrap_or((*recipe.obstacles.start(), *recipe.obstacles.end()));
        if obstacles.1 > MAX_OBSTACLES || obstacles.0 > obstacles.1 {
            return Err(invalid(
                "obstacles",
                format!(
                    "must be a range within 0..={MAX_OBSTACLES}, not {}..={}",
                    obstacles.0, obstacles.1
                ),
            ));
        }
        if let Some((a, b)) = request.spacing {
            if family != Family::Formation {
                return Err(invalid(
                    "spacing",
                    "only the formation family has goal slots".into(),
                ));
            }
            if !(a.is_finite() && b.is_finite() && 2.0 <= a && a <= b && b <= 100.0) {
                return Err(invalid(
                    "spacing",
                    format!("must be a range within 2..=100 safe radii, not {a}..={b}"),
                ));
            }
            recipe.spacing = a..=b;
        }
        recipe.robots = robots.0..=robots.1;
        recipe.obstacles = obstacles.0..=obstacles.1;
        recipe.params.avoidance = Avoidance::from_name(&request.avoidance).ok_or_else(|| {
            invalid(
                "avoidance",
                format!("must be exit or paper, not {:?}", request.avoidance),
            )
        })?;
        if let Some(r) = request.barrier_rate {
            if !(r.is_finite() && r > 0.0) {
                return Err(invalid(
                    "barrier_rate",
                    format!("must be a positive rate or none, not {r}"),
                ));
            }
        }
        recipe.params.barrier_rate = request.barrier_rate;
        // The planner's name and gains are checked before anything runs; a planner other
        // than DVF is part of the recipe, and so of the sweep's identity: shards run with
        // different planners do not merge.
        request.planner.build()?;
        recipe.planner = request.planner.clone();
        let mut set = Values::new();
        for text in &request.set {
            let Some((name, value)) = text.split_once('=') else {
                return Err(invalid("set", format!("expected NAME=VALUE, not {text:?}")));
            };
            let name = name.trim();
            if set.insert(name.to_owned(), value_of(value)).is_some() {
                return Err(invalid("set", format!("{name} is given twice")));
            }
        }
        let recipe = with(&recipe, &set)?;
        let axes = request
            .grid
            .iter()
            .map(|t| Axis::parse(t))
            .collect::<Result<Vec<_>, _>>()?;
        if let Some(a) = axes.iter().find(|a| set.contains_key(&a.name)) {
            return Err(invalid(&a.name, "given by both set and grid".into()));
        }
        let grid = points(&axes)?;
        // Every point's values are read and checked before anything runs.
        let runs: Vec<(Values, Recipe)> = grid
            .iter()
            .map(|v| Ok((v.clone(), with(&recipe, v)?)))
            .collect::<Result<_, Error>>()?;
        if request.count * runs.len() > MAX_SWEEP {
            return Err(invalid(
                "count",
                format!(
                    "count × grid points must be at most {MAX_SWEEP}, not {} × {}",
                    request.count,
                    runs.len()
                ),
            ));
        }
        let id = Sweep::id_of(&recipe, &grid, request.seed, request.count);
        Ok(Self {
            seed: request.seed,
            count: request.count,
            set,
            runs,
            id,
        })
    }

    /// How many scenarios the sweep runs: its count times its grid's points.
    #[must_use]
    pub fn total(&self) -> usize {
        self.count * self.runs.len()
    }

    /// Runs every scenario on every core and summarises them, one group per grid point;
    /// `on_report` sees each run (its point's values, its seed, the scenario and its report).
    pub fn summaries(
        &self,
        on_report: impl Fn(&Values, u64, &Scenario, &Report) + Sync,
    ) -> Summaries {
        sweep_points(&self.runs, self.seed, self.count, on_report)
    }

    /// Runs shard `k` of `n` (from 1): scenarios `k − 1, k − 1 + n, …` of [`Plan::total`],
    /// point by point and seed by seed, handing each [`Outcome`] (a line of `dvf sweep
    /// --shard`, naming its sweep) to `each` as it finishes, so that a shard cut short leaves
    /// whole lines. `on_report` sees each run as in [`Plan::summaries`].
    ///
    /// # Errors
    /// `k` or `n` out of range (as [`Error::Invalid`] of `shard`), or the first error of `each`.
    pub fn shard<E: From<Error>>(
        &self,
        (k, n): (usize, usize),
        on_report: impl Fn(&Values, u64, &Scenario, &Report),
        mut each: impl FnMut(Outcome) -> Result<(), E>,
    ) -> Result<(), E> {
        if n == 0 || !(1..=n).contains(&k) {
            return Err(
                invalid("shard", format!("must be K/N with 1 ≤ K ≤ N, not {k}/{n}")).into(),
            );
        }
        for index in (k - 1..self.total()).step_by(n) {
            let point = index / self.count;
            let (values, recipe) = &self.runs[point];
            let s = self.seed.wrapping_add((index % self.count) as u64);
            let mut outcome = Outcome::run(recipe, s, |scenario, report| {
                on_report(values, s, scenario, report);
            });
            outcome.sweep = Some(Sweep {
                id: self.id.clone(),
                seed: self.seed,
                count: self.count,
                points: self.runs.len(),
                point,
                shard: [k, n],
            });
            outcome.values.clone_from(values);
            outcome.recipe.set.clone_from(&self.set);
            each(outcome)?;
        }
        Ok(())
    }
}

/// Why a summary reports nothing: `None` when some scenario ran at every grid point, else the
/// message that says which point ran none and what to ask for instead.
#[must_use]
pub fn nothing_ran(summaries: &Summaries) -> Option<String> {
    summaries.all().into_iter().find_map(|(values, s)| {
        (s.scenarios == 0).then(|| {
            let at = values.map_or(String::new(), |v| format!(" at {}", label(v, " ")));
            format!(
                "no scenario ran{at}: all {} were skipped because their robots or obstacles could not be placed; ask for fewer robots (--robots) or obstacles (--obstacles), or a larger area (--set side=…)",
                s.skipped
            )
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every option out of range is refused before anything runs, named by its field.
    #[test]
    fn a_request_out_of_range_is_refused_by_its_field() {
        let bad = |f: fn(&mut Request), field: &str| {
            let mut r = Request {
                count: 2,
                ..Request::default()
            };
            f(&mut r);
            let e = Plan::new(&r).expect_err(field).to_string();
            assert!(e.starts_with(&format!("{field}: ")), "{field}: {e}");
        };
        bad(|r| r.family = "swirl".into(), "family");
        bad(|r| r.count = 0, "count");
        bad(|r| r.robots = Some((0, 4)), "robots");
        bad(|r| r.obstacles = Some((3, 2)), "obstacles");
        bad(|r| r.spacing = Some((3.0, 4.0)), "spacing");
        bad(|r| r.avoidance = "around".into(), "avoidance");
        bad(|r| r.barrier_rate = Some(-1.0), "barrier_rate");
        bad(|r| r.planner = Spec::named("rrt"), "planner");
        bad(|r| r.set = vec!["k_v".into()], "set");
        bad(|r| r.set = vec!["k_v=1".into(), "k_v=2".into()], "set");
        bad(|r| r.set = vec!["k_v=-1".into()], "params.k_v");
        bad(
            |r| {
                r.set = vec!["k_v=1".into()];
                r.grid = vec!["k_v=1,2".into()];
            },
            "k_v",
        );
        let r = Request {
            count: 2,
            ..Request::default()
        };
        let plan = Plan::new(&r).expect("the default request is valid");
        let e = plan
            .shard((3, 2), |_, _, _, _| {}, |_| Ok::<(), Error>(()))
            .expect_err("shard 3/2");
        assert!(e.to_string().starts_with("shard: "), "{e}");
    }

    /// The shards of a plan together hold each scenario once, with the whole sweep's identity.
    #[test]
    fn shards_cover_the_sweep_once() {
        let plan = Plan::new(&Request {
            count: 3,
            robots: Some((2, 3)),
            grid: vec!["k_v=1,2".into()],
            ..Request::default()
        })
        .expect("valid");
        let mut seen = Vec::new();
        for k in 1..=2 {
            plan.shard(
                (k, 2),
                |_, _, _, _| {},
                |o| {
                    let sweep = o.sweep.expect("a shard line names its sweep");
                    seen.push((sweep.point, o.seed, sweep.id));
                    Ok::<(), Error>(())
                },
            )
            .expect("runs");
        }
        seen.sort();
        assert_eq!(seen.len(), plan.total());
        assert!(seen
            .windows(2)
            .all(|w| w[0].2 == w[1].2 && (w[0].0, w[0].1) != (w[1].0, w[1].1)));
    }
}
