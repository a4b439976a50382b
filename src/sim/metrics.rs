//! The metrics of the paper's figures, observed after every step: since when each robot has been
//! at its goal, the smallest distance between two robots and from a robot to an obstacle, and
//! the violation events (a pair closer than `2·r_ij`, a robot inside an obstacle disc; one
//! event for as long as it lasts), and how smooth each robot's commands are
//! (`smoothness.rs`). Planner-independent: they read poses and the neighbourhood
//! structures only.

use super::smoothness::Tally;
use super::{Neighbourhood, Robot};
use crate::grid::{Neighbours, ObstacleCells};
use crate::obstacle::Obstacle;
use crate::params::Params;

/// The running metrics of a [`super::Simulation`].
#[derive(Clone, Debug)]
pub(super) struct Metrics {
    pub(super) inside_since: Vec<Option<f64>>,
    pub(super) min_pair: Option<f64>,
    pub(super) min_clearance: Option<f64>,
    pub(super) violations: usize,
    /// Each robot's commands ([`Tally`]).
    pub(super) tallies: Vec<Tally>,
    // Whether each robot has reached its goal position (within `tol_position`) yet.
    reached: Vec<bool>,
    // The pairs `(i, j)`, `i < j`, closer than `2·r_ij`, ascending; `pair_scratch` receives the
    // current step's before the two are swapped.
    pair_violating: Vec<(u32, u32)>,
    pair_scratch: Vec<(u32, u32)>,
    // The pairs `(robot, obstacle)` with the robot inside the disc, ascending, and the
    // current step's.
    obstacle_violating: Vec<(u32, u32)>,
    obstacle_scratch: Vec<(u32, u32)>,
}

/// What the metrics observe: the state after a step, and the structures that find what is
/// near each robot.
pub(super) struct Observed<'a> {
    pub time: f64,
    pub params: &'a Params,
    pub independent: bool,
    pub robots: &'a [Robot],
    pub obstacles: &'a [Obstacle],
    pub obstacle_cells: &'a ObstacleCells,
    pub neighbourhood: Neighbourhood,
    /// The robots within `list_reach` of each robot (built for this state when the
    /// neighbourhood is [`Neighbourhood::Grid`]).
    pub near: &'a Neighbours,
    /// `max(R_s, 2·r_ij)`: the obstacles counted by the clearance metric.
    pub reach: f64,
    /// The reach of `near`'s lists (at least `2·r_ij`).
    pub list_reach: f64,
    // The closest listed pair's squared distance within `list_reach` (the pairs
    // `closest_listed2` visits), when the step's evaluations found it on their way.
    pub closest2: Option<f64>,
    /// Whether the passes over the robots run on rayon's threads (never in the wasm build,
    /// which does not read it).
    #[cfg_attr(target_arch = "wasm32", allow(dead_code))]
    pub threaded: bool,
}

impl Metrics {
    /// Nothing observed yet, for `n` robots.
    pub(super) fn new(n: usize) -> Self {
        Self {
            inside_since: vec![None; n],
            min_pair: None,
            min_clearance: None,
            violations: 0,
            tallies: vec![Tally::default(); n],
            reached: vec![false; n],
            // Room for a violating pair per robot: a violation allocates nothing.
            pair_violating: Vec::with_capacity(n),
            pair_scratch: Vec::with_capacity(n),
            obstacle_violating: Vec::with_capacity(n),
            obstacle_scratch: Vec::with_capacity(n),
        }
    }

    /// Back to nothing observed, keeping the buffers.
    pub(super) fn clear(&mut self) {
        self.inside_since.fill(None);
        self.min_pair = None;
        self.min_clearance = None;
        self.violations = 0;
        self.tallies.fill(Tally::default());
        self.reached.fill(false);
        self.pair_violating.clear();
        self.obstacle_violating.clear();
    }

    /// Updates the metrics from the state `o`.
    pub(super) fn observe(&mut self, o: &Observed<'_>) {
        let p = o.params;
        let reach = o.reach;
        self.obstacle_scratch.clear();
        let quick = self.observe_on_threads(o);
        // On one thread, the closest listed pair as the step's evaluations found it, or else
        // found on the way, as on threads.
        let listed = !o.independent && o.neighbourhood == Neighbourhood::Grid;
        let search = listed && o.closest2.is_none();
        let mut closest2 = o.closest2.unwrap_or(f64::INFINITY);
        for (i, r) in o.robots.iter().enumerate().filter(|_| quick.is_none()) {
            if search {
                closest2 = closest2.min(closest_listed2(o, i));
            }
            let at_position = r.position_error() <= p.tol_position;
            self.reached[i] |= at_position;
            self.tallies[i].observe(r.last.command.omega, self.reached[i]);
            let inside = at_position && r.heading_error_abs() <= p.tol_heading;
            settle(&mut self.inside_since[i], inside, o.time);
            // The obstacles within the reach, as the robot senses them: the clearance metric
            // and the violations (a robot inside a disc is within every reach). None to look
            // up in a scene without obstacles.
            if o.obstacles.is_empty() {
                continue;
            }
            for k in o.obstacle_cells.near(r.pose.p) {
                let c = o.obstacles[k].clearance(r.pose.p);
                if c <= reach {
                    self.min_clearance = Some(self.min_clearance.map_or(c, |m: f64| m.min(c)));
                }
                if c < 0.0 {
                    self.obstacle_scratch.push((i as u32, k as u32));
                }
            }
        }
        self.violations += new_events(&self.obstacle_violating, &self.obstacle_scratch);
        std::mem::swap(&mut self.obstacle_violating, &mut self.obstacle_scratch);
        if o.independent {
            return;
        }
        let safe = 2.0 * p.safe_radius;
        let quick = quick.or_else(|| listed.then(|| closest_pair(closest2, safe)));
        let robots = o.robots;
        let n = robots.len();
        self.pair_scratch.clear();
        // The pairs in ascending (i, j), as a scan over all pairs visits them.
        let scratch = &mut self.pair_scratch;
        let mut pair = |i: usize, j: usize, min: &mut Option<f64>| {
            let d = robots[i].pose.p.distance(robots[j].pose.p);
            *min = Some(min.map_or(d, |m: f64| m.min(d)));
            if d < safe {
                scratch.push((i as u32, j as u32));
            }
        };
        let mut min = None;
        match o.neighbourhood {
            Neighbourhood::AllPairs => {
                for i in 0..n {
                    for j in i + 1..n {
                        pair(i, j, &mut min);
                    }
                }
            }
            Neighbourhood::Grid => {
                // Every pair closer than `2·r_ij` is in the lists (the reach is at least that),
                // and so is the closest pair whenever some pair is within the reach.
                // The lists may hold pairs a little beyond their reach (their skin): those are
                // left out, so that the pairs seen are those within the reach, whenever the
                // lists were built.
                match quick {
                    // No listed pair closer than `2·r_ij`: the closest is all there is to see.
                    Some((closest, false)) => min = closest,
                    _ => listed_pairs(robots, o.near, o.list_reach, |i, j| pair(i, j, &mut min)),
                }
                // No pair within the reach: the closest pair matters only while no closer one
                // has been seen, which a swarm at bounded density leaves behind at once.
                if min.is_none() && self.min_pair.is_none_or(|m| m > o.list_reach) {
                    for i in 0..n {
                        for j in i + 1..n {
                            let d = robots[i].pose.p.distance(robots[j].pose.p);
                            min = Some(min.map_or(d, |m: f64| m.min(d)));
                        }
                    }
                }
            }
        }
        if let Some(d) = min {
            self.min_pair = Some(self.min_pair.map_or(d, |m: f64| m.min(d)));
        }
        self.violations += new_events(&self.pair_violating, &self.pair_scratch);
        std::mem::swap(&mut self.pair_violating, &mut self.pair_scratch);
    }
}

impl Metrics {
    /// [`Self::observe_in_parallel`] when the step runs on threads (`o.threaded`); `None`
    /// otherwise, and always in the wasm build, which has one thread.
    #[cfg_attr(target_arch = "wasm32", allow(unused_variables, clippy::unused_self))]
    fn observe_on_threads(&mut self, o: &Observed<'_>) -> Option<(Option<f64>, bool)> {
        #[cfg(not(target_arch = "wasm32"))]
        if o.threaded {
            return Some(self.observe_in_parallel(o));
        }
        None
    }

    /// The pass over the robots of [`Self::observe`] (arrival, smoothness, clearance and the
    /// robots inside a disc) on rayon's threads, with the smallest distance of the pairs
    /// [`listed_pairs`] visits (`None` for none) and whether one of them is closer than
    /// `2·r_ij`. The same bits as the serial pass: each robot's metrics land in its own slots,
    /// a minimum is exact whatever the order of its terms, and `√` is monotone and correctly
    /// rounded (the square root of the smallest squared distance is the smallest distance).
    /// The rare step with a robot inside a disc lists those in a second, serial pass.
    #[cfg(not(target_arch = "wasm32"))]
    fn observe_in_parallel(&mut self, o: &Observed<'_>) -> (Option<f64>, bool) {
        use rayon::prelude::*;
        let (p, reach, time) = (o.params, o.reach, o.time);
        let (closest, inside, closest2) = (
            o.robots,
            &mut self.reached[..],
            &mut self.tallies[..],
            &mut self.inside_since[..],
        )
            .into_par_iter()
            .enumerate()
            .with_min_len(super::parallel::CHEAP_CHUNK)
            .map(|(i, (r, reached, tally, since))| {
                let at_position = r.position_error() <= p.tol_position;
                *reached |= at_position;
                tally.observe(r.last.command.omega, *reached);
                let inside = at_position && r.heading_error_abs() <= p.tol_heading;
                settle(since, inside, time);
                let mut closest = f64::INFINITY;
                let mut inside_a_disc = false;
                // None to look up in a scene without obstacles.
                if !o.obstacles.is_empty() {
                    for k in o.obstacle_cells.near(r.pose.p) {
                        let c = o.obstacles[k].clearance(r.pose.p);
                        if c <= reach {
                            closest = closest.min(c);
                        }
                        inside_a_disc |= c < 0.0;
                    }
                }
                let closest2 = match o.closest2 {
                    Some(_) => f64::INFINITY,
                    None => closest_listed2(o, i),
                };
                (closest, inside_a_disc, closest2)
            })
            .reduce(
                || (f64::INFINITY, false, f64::INFINITY),
                |a, b| (a.0.min(b.0), a.1 | b.1, a.2.min(b.2)),
            );
        // A clearance within the reach is finite (positions are).
        if closest.is_finite() {
            self.min_clearance = Some(self.min_clearance.map_or(closest, |m| m.min(closest)));
        }
        if inside {
            for (i, r) in o.robots.iter().enumerate() {
                for k in o.obstacle_cells.near(r.pose.p) {
                    if o.obstacles[k].clearance(r.pose.p) < 0.0 {
                        self.obstacle_scratch.push((i as u32, k as u32));
                    }
                }
            }
        }
        let closest2 = o.closest2.map_or(closest2, |known| known.min(closest2));
        closest_pair(closest2, 2.0 * p.safe_radius)
    }
}

/// The smallest squared distance from robot `i` to the robots of higher index its list holds
/// within the lists' reach (`+∞` for none): the pairs [`listed_pairs`] visits for `i`.
fn closest_listed2(o: &Observed<'_>, i: usize) -> f64 {
    let (robots, reach2) = (o.robots, o.list_reach * o.list_reach);
    let p = robots[i].pose.p;
    // Without a branch to mispredict, and a select rather than `f64::min` (a call in wasm):
    // the same minimum, squared distances being neither NaN nor −0.
    o.near.of(i).iter().fold(f64::INFINITY, |m, &j| {
        let d2 = robots[j as usize].pose.p.distance_squared(p);
        let counted = (j as usize > i) & (d2 <= reach2);
        if counted & (d2 < m) {
            d2
        } else {
            m
        }
    })
}

/// From the smallest squared distance of the listed pairs, their smallest distance (`None`
/// for none: `+∞`) and whether it is below `safe`. The same bits as the smallest of their
/// distances: `√` is monotone and correctly rounded.
fn closest_pair(closest2: f64, safe: f64) -> (Option<f64>, bool) {
    let closest = closest2.is_finite().then(|| closest2.sqrt());
    (closest, closest.is_some_and(|d| d < safe))
}

/// The pairs `(i, j)`, `i < j`, in ascending order, of the robots `near` lists within `reach`
/// of each other: the lists may hold pairs a little beyond their reach (their skin, see
/// `Simulation::find_neighbours`), which are left out, so that these are exactly the pairs
/// within the reach whenever the lists were built.
pub(super) fn listed_pairs(
    robots: &[Robot],
    near: &Neighbours,
    reach: f64,
    mut each: impl FnMut(usize, usize),
) {
    for (i, r) in robots.iter().enumerate() {
        for &j in near.of(i) {
            let j = j as usize;
            if j > i && robots[j].pose.p.distance_squared(r.pose.p) <= reach * reach {
                each(i, j);
            }
        }
    }
}

/// Since when a robot has been at its goal (`since`), now that it is `inside` or not at `time`.
fn settle(since: &mut Option<f64>, inside: bool, time: f64) {
    match (inside, *since) {
        (true, None) => *since = Some(time),
        (false, Some(_)) => *since = None,
        _ => {}
    }
}

/// Violation events: the pairs violating `now` that were not at the last observation (`was`;
/// both lists ascending: a merge).
fn new_events(was: &[(u32, u32)], now: &[(u32, u32)]) -> usize {
    let mut was = was.iter().peekable();
    let mut events = 0;
    for pair in now {
        while was.next_if(|w| *w < pair).is_some() {}
        if was.next_if(|w| *w == pair).is_none() {
            events += 1;
        }
    }
    events
}
