//! The merge of a sweep's shards: their lines, checked to be one whole sweep, summarised as
//! the unsharded sweep summarises the same scenarios.
//!
//! Every line names its sweep ([`Sweep`]: an identity, the first seed, the count, the grid's
//! points and the shard), so that a set of lines that lost its first or last seeds, has a gap
//! or a seed twice, or mixes lines of another sweep is refused with a message that names the
//! seed and the shard to rerun.

use super::outcome::{Outcome, Sweep};
use super::settings::label;
use super::summary::{Group, Groups, Summaries, Summary};

/// At most this many scenarios in a sweep that is merged (the command line runs at most a
/// million).
pub const MAX_MERGE: usize = 10_000_000;

/// Why a set of lines is not one whole sweep.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum MergeError {
    /// A line that is not an outcome.
    #[error("{place}: not a line of dvf sweep --shard: {message}")]
    NotALine {
        /// `file:line`.
        place: String,
        /// What is wrong with it.
        message: String,
    },
    /// A line without the sweep it belongs to (written before lines recorded it).
    #[error("{place}: the line does not say which sweep it belongs to (its count, shard and identity), so the set cannot be checked to be whole; rerun every shard with this dvf (dvf sweep … --shard K/N) and merge the new lines")]
    Unmarked {
        /// `file:line`.
        place: String,
    },
    /// A line of another sweep than the first line's.
    #[error("{place}: seed {seed} was drawn from another recipe or belongs to another sweep (first seed, count, grid or number of shards) than seed {first_seed} of {first_place} (shards of different sweeps)")]
    OtherSweep {
        /// `file:line`.
        place: String,
        /// Its seed.
        seed: u64,
        /// Where the first line is.
        first_place: String,
        /// The first line's seed.
        first_seed: u64,
    },
    /// A seed outside the sweep's range, or a point outside its grid.
    #[error("{place}: seed {seed} at grid point {point} is outside the sweep (seeds {first} … {last}, {points} points)")]
    Outside {
        /// `file:line`.
        place: String,
        /// Its seed.
        seed: u64,
        /// Its point.
        point: usize,
        /// The sweep's first seed.
        first: u64,
        /// Its last seed.
        last: u64,
        /// Its points.
        points: usize,
    },
    /// A scenario given twice.
    #[error("seed {seed}{at} appears twice (a shard merged twice?)")]
    Twice {
        /// The seed.
        seed: u64,
        /// The grid point, as ` at name=value …` (empty without a grid).
        at: String,
    },
    /// Scenarios not given.
    #[error("seed {seed}{at} is missing (shard {shard} runs it; {missing} of the sweep's {total} scenarios missing: a shard not finished or not given?)")]
    Missing {
        /// The first missing seed.
        seed: u64,
        /// The grid point, as ` at name=value …` (empty without a grid).
        at: String,
        /// The shard that runs it, `K/N`.
        shard: String,
        /// How many are missing.
        missing: usize,
        /// How many the sweep has.
        total: usize,
    },
    /// No line at all.
    #[error("no outcomes to merge")]
    Empty,
}

/// The lines of a sweep's shards, as they are read.
#[derive(Default)]
pub struct Merge {
    first: Option<(String, Sweep, u64)>,
    outcomes: Vec<Outcome>,
}

impl Merge {
    /// An empty set.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// Reads one line (`place` names it in messages: `file:line`); a blank line is skipped.
    ///
    /// # Errors
    /// A line that is not an outcome, does not name its sweep (or names one that `dvf sweep`
    /// does not write), names another sweep than the first line, or lies outside its sweep.
    /// A refused line is not kept.
    pub fn add(&mut self, place: &str, line: &str) -> Result<(), MergeError> {
        if line.trim().is_empty() {
            return Ok(());
        }
        let not_a_line = |e: serde_json::Error| MergeError::NotALine {
            place: place.to_owned(),
            message: e.to_string(),
        };
        let value: serde_json::Value = serde_json::from_str(line).map_err(not_a_line)?;
        if value.get("sweep").is_none() {
            // Lines of shards from before they named their sweep list `converged_steps`.
            if value.get("converged_steps").is_some() {
                return Err(MergeError::Unmarked {
                    place: place.to_owned(),
                });
            }
            if value.get("scenarios").is_some() || value.get("groups").is_some() {
                return Err(MergeError::NotALine {
                    place: place.to_owned(),
                    message:
                        "it is a sweep's summary; merge the lines that dvf sweep --shard K/N prints"
                            .into(),
                });
            }
        }
        let o: Outcome = serde_json::from_value(value).map_err(not_a_line)?;
        let Some(sweep) = o.sweep.clone() else {
            return Err(MergeError::Unmarked {
                place: place.to_owned(),
            });
        };
        let [k, n] = sweep.shard;
        let total = sweep.count.checked_mul(sweep.points);
        if !(1..=n).contains(&k) || total.is_none_or(|t| t == 0 || t > MAX_MERGE) {
            return Err(MergeError::NotALine {
                place: place.to_owned(),
                message: format!(
                    "its sweep ({} scenarios at {} points, shard {k}/{n}) is not one dvf sweep writes",
                    sweep.count, sweep.points
                ),
            });
        }
        if let Some((first_place, first, first_seed)) = &self.first {
            let key = |s: &Sweep| (s.id.clone(), s.seed, s.count, s.points, s.shard[1]);
            if key(first) != key(&sweep) {
                return Err(MergeError::OtherSweep {
                    place: place.to_owned(),
                    seed: o.seed,
                    first_place: first_place.clone(),
                    first_seed: *first_seed,
                });
            }
        }
        let offset = o.seed.wrapping_sub(sweep.seed);
        if offset >= sweep.count as u64 || sweep.point >= sweep.points {
            return Err(MergeError::Outside {
                place: place.to_owned(),
                seed: o.seed,
                point: sweep.point,
                first: sweep.seed,
                last: sweep.seed.wrapping_add(sweep.count as u64).wrapping_sub(1),
                points: sweep.points,
            });
        }
        if self.first.is_none() {
            self.first = Some((place.to_owned(), sweep, o.seed));
        }
        self.outcomes.push(o);
        Ok(())
    }

    /// The summary of the lines read, checked to hold every scenario of the sweep once.
    ///
    /// # Errors
    /// No lines, a scenario twice, or scenarios missing (the first one named, with its shard).
    pub fn finish(self) -> Result<Summaries, MergeError> {
        let Some((_, sweep, _)) = self.first else {
            return Err(MergeError::Empty);
        };
        let (count, points) = (sweep.count, sweep.points);
        // The outcomes in sweep order: point by point, seed by seed.
        let index = |o: &Outcome| {
            let point = o.sweep.as_ref().map_or(0, |s| s.point);
            point * count + o.seed.wrapping_sub(sweep.seed) as usize
        };
        let mut outcomes = self.outcomes;
        outcomes.sort_by_key(index);
        let total = count * points;
        let mut seen = vec![false; total];
        for o in &outcomes {
            let k = index(o);
            if std::mem::replace(&mut seen[k], true) {
                return Err(MergeError::Twice {
                    seed: o.seed,
                    at: at(o),
                });
            }
        }
        if let Some(k) = seen.iter().position(|s| !s) {
            let point = k / count;
            let values = outcomes
                .iter()
                .find(|o| o.sweep.as_ref().is_some_and(|s| s.point == point));
            return Err(MergeError::Missing {
                seed: sweep.seed.wrapping_add((k % count) as u64),
                at: values
                    .map(at)
                    .unwrap_or_else(|| format!(" at grid point {point}")),
                shard: format!("{}/{}", k % sweep.shard[1] + 1, sweep.shard[1]),
                missing: seen.iter().filter(|s| !**s).count(),
                total,
            });
        }
        if points == 1 && outcomes.first().is_none_or(|o| o.values.is_empty()) {
            return Ok(Summaries::One(Summary::of(sweep.seed, &outcomes)));
        }
        Ok(Summaries::Grid(Groups {
            groups: outcomes
                .chunks(count)
                .map(|chunk| Group {
                    values: chunk[0].values.clone(),
                    summary: Summary::of(sweep.seed, chunk),
                })
                .collect(),
        }))
    }
}

/// ` at name=value …` for an outcome of a grid point, empty without a grid.
fn at(o: &Outcome) -> String {
    if o.values.is_empty() {
        return String::new();
    }
    format!(" at {}", label(&o.values, " "))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sweep::Recipe;
    use crate::testing::test;

    /// A skipped scenario's line of the sweep of `count` seeds from 10, shard `[k, n]`.
    fn line(seed: u64, count: usize, shard: [usize; 2]) -> String {
        let recipe = Recipe::default();
        let o = Outcome {
            sweep: Some(Sweep {
                id: Sweep::id_of(&recipe, &[], 10, count),
                seed: 10,
                count,
                points: 1,
                point: 0,
                shard,
            }),
            ..Outcome::skipped(&recipe, seed)
        };
        serde_json::to_string(&o).unwrap()
    }

    /// Lines that no sweep writes are refused, not trusted: a shard K of N outside 1 … N, a
    /// sweep too large to check; a refused line is not kept, and the rest still merges.
    #[test]
    fn lines_no_sweep_writes_are_refused_without_a_panic() {
        let mut m = Merge::new();
        let zero = line(10, 2, [1, 1]).replace("\"shard\":[1,1]", "\"shard\":[1,0]");
        assert!(matches!(
            m.add("a:1", &zero),
            Err(MergeError::NotALine { .. })
        ));
        let huge = line(10, 2, [1, 1]).replace("\"count\":2", "\"count\":18446744073709551615");
        assert!(matches!(
            m.add("a:2", &huge),
            Err(MergeError::NotALine { .. })
        ));
        let outside = line(9, 2, [1, 1]);
        assert!(matches!(
            m.add("a:3", &outside),
            Err(MergeError::Outside { .. })
        ));
        m.add("a:4", &line(10, 2, [1, 1])).unwrap();
        m.add("a:5", &line(11, 2, [1, 1])).unwrap();
        let Summaries::One(s) = m.finish().unwrap() else {
            panic!("one summary without a grid")
        };
        assert_eq!((s.seed, s.skipped, s.success_rate), (10, 2, None));
        assert_eq!(Merge::new().finish(), Err(MergeError::Empty));
    }
}
