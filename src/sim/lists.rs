//! The Verlet lists of a [`Simulation`]: the robots near each robot, from the grid
//! ([`crate::grid::Neighbours`]), built for a reach widened by a skin and kept over the steps
//! while they still hold every pair within the reach.

use super::{metrics, parallel, Neighbourhood, Simulation};
use crate::params::Params;
use crate::safety;
use crate::swarm::{cluster_reach, pair_range};
use glam::DVec2;

impl Simulation {
    /// Makes room for `factor` times as many sensed pairs as the current step has, so that
    /// steps allocate nothing while the swarm senses fewer (the lists grow by doubling
    /// otherwise, a few times over a run whose robots close in).
    pub fn reserve_neighbours(&mut self, factor: f64) {
        self.near.reserve(factor);
        // The barrier's constraints: a robot's listed neighbours (without lists, every robot)
        // and the obstacles at most.
        let longest = if self.listed() {
            (0..self.robots.len())
                .map(|i| self.near.of(i).len())
                .max()
                .unwrap_or(0)
        } else {
            self.robots.len()
        };
        let obstacles = self.obstacles.len();
        let most = (longest as f64 * factor) as usize + obstacles;
        let reserve = |scratch: &mut super::Scratch| {
            scratch.constraints.reserve(most);
            // The sensing loop's two runs take up to twice a list (`evaluation`).
            let have = scratch.neighbours.len();
            scratch.neighbours.reserve((2 * most).saturating_sub(have));
            // The sensed obstacles: all of them at most.
            scratch.obstacles.reserve(obstacles);
        };
        reserve(&mut self.scratch);
        self.scratches.iter_mut().for_each(reserve);
    }

    /// Whether the robots' neighbours come from the grid's lists.
    pub(super) fn listed(&self) -> bool {
        !self.independent && self.neighbourhood == Neighbourhood::Grid
    }

    /// Keeps the grid's lists holding every pair within `list_reach` where the robots are
    /// now. They are built for a reach widened by a skin of [`SKIN`]`·reach` (Verlet lists):
    /// while no robot has moved more than half the skin since, a pair within the reach now was
    /// within the widened reach then. Once some robot has, they are kept while a search around
    /// the robots that have finds them still whole ([`Self::lists_still_hold`]), and rebuilt
    /// otherwise. Readers test the distance (the evaluation, the metrics,
    /// `min_listed_pair_distance`), so they see exactly the pairs within the reach, in
    /// ascending index, whenever the lists were built.
    ///
    /// `none_moved` is whether no robot has moved more than half the skin since, when the
    /// caller has found it already (the step's integration); `None` tests it here.
    pub(super) fn find_neighbours(&mut self, none_moved: Option<bool>) {
        if !self.listed() {
            return;
        }
        // Never built (`positions` is empty until then), or some robot moved too far since and
        // the lists miss a pair.
        let fresh = self.positions.len() == self.robots.len()
            && (none_moved.unwrap_or_else(|| self.none_moved_beyond(self.half_skin()))
                || self.lists_still_hold());
        if !fresh {
            // The positions packed together: the search reads them many times over, and a
            // robot's whole state is some 200 bytes.
            self.positions.clear();
            self.positions.extend(self.robots.iter().map(|r| r.pose.p));
            let (built, threaded) = (self.built_reach(), self.threaded());
            parallel::build_lists(threaded, &mut self.near, &self.positions, built);
        }
    }

    /// Whether the lists still hold every pair within their reach, once some robot has moved
    /// more than half the skin since they were built: a pair of robots that have each moved
    /// less is within the widened reach still (see [`Self::find_neighbours`]), and the pairs of
    /// the robots that have moved more are looked for in the cells of the lists' last build
    /// ([`crate::grid::Neighbours::list_all_near`]), which hold every robot that has moved
    /// less than the whole skin. The lists are rebuilt instead once a robot has moved farther,
    /// or once more than one robot in [`MOVED_SHARE`] has moved more than half the skin.
    ///
    /// In a jam a few robots move at the speed limit and the rest crawl: the lists are then
    /// rebuilt about when the fastest robot nears the whole skin rather than half of it
    /// (`lists_kept_past_half_the_skin_hold_every_pair` checks what they hold meanwhile). In
    /// open space every robot moves about as fast as the fastest, and the lists are rebuilt
    /// once the first crosses half the skin.
    fn lists_still_hold(&self) -> bool {
        let half = self.half_skin();
        let whole = 2.0 * half;
        let most = self.robots.len() / MOVED_SHARE;
        let mut moved = 0;
        for (&was, r) in self.positions.iter().zip(&self.robots) {
            if !moved_within(was, r.pose.p, whole) {
                return false;
            }
            moved += usize::from(!moved_within(was, r.pose.p, half));
            if moved > most {
                return false;
            }
        }
        let (reach, built) = (self.reach, self.built_reach());
        let now = |i: usize| self.robots[i].pose.p;
        (self.positions.iter().zip(&self.robots).enumerate()).all(|(j, (&was, r))| {
            moved_within(was, r.pose.p, half)
                || self
                    .near
                    .list_all_near(&self.positions, now, j, reach, built)
        })
    }

    /// The reach the lists are built for: their reach widened by the skin. The search of
    /// [`Self::lists_still_hold`] takes the build's test again with it, so both take it here.
    fn built_reach(&self) -> f64 {
        self.reach + SKIN * self.reach
    }

    /// How far a robot may move before the lists are rebuilt: half their skin, less the
    /// round-off of a few ulps in the distances, which must not spend the whole skin.
    pub(super) fn half_skin(&self) -> f64 {
        let skin = SKIN * self.reach;
        0.5 * skin * (1.0 - 1e-6)
    }

    /// Whether no robot has moved more than `half` since the lists were built at `positions`
    /// (a pass of its own; a step finds it while it integrates).
    fn none_moved_beyond(&self, half: f64) -> bool {
        self.positions
            .iter()
            .zip(&self.robots)
            .all(|(&was, r)| moved_within(was, r.pose.p, half))
    }

    /// The smallest distance between two robots now, when the neighbour lists hold it: the
    /// lists (always built for the current positions) hold every pair within their reach (at
    /// least `2·r_ij`, at most `max(R_s, 2·r_ij)`), so when some pair is listed their minimum
    /// is the minimum over all pairs (the same value as a scan). `None` when there are no
    /// lists (independent robots, [`Neighbourhood::AllPairs`]) or no pair within their reach.
    #[must_use]
    pub fn min_listed_pair_distance(&self) -> Option<f64> {
        if !self.listed() {
            return None;
        }
        let r = &self.robots;
        let mut m = f64::INFINITY;
        metrics::listed_pairs(r, &self.near, self.reach, |i, j| {
            m = m.min(r[i].pose.p.distance(r[j].pose.p));
        });
        m.is_finite().then_some(m)
    }
}

/// The reach of the neighbour lists: the sensed robots that can change a command, and the
/// collision distance `2·r_ij`. A sensed robot changes a command only within the reach of
/// the virtual obstacle's choice ([`crate::swarm::cluster_reach`]: the avoidance range
/// `2(R_c + ε)`, twice that where a parked formation is looked for among the robot's own
/// neighbours, not when `slowest_known`) or within the barrier's
/// [`safety::neighbour_reach`] at the fastest speed `v_max` allows; beyond both, it is
/// sensed and ignored, so the lists leave it out with the same bits. In a crowd with the
/// default avoidance that is the barrier's 10 m instead of `R_s` = 20. Without `v_max` and
/// with a barrier, the sensing radius.
pub(super) fn list_reach(p: &Params, slowest_known: bool) -> f64 {
    let range = pair_range(p.avoid_radius, p.transition_width);
    let avoidance = safety::widened(cluster_reach(range, p.avoidance, slowest_known));
    let barrier = match (p.barrier_rate, p.v_max) {
        (None, _) => 0.0,
        (Some(_), Some(v)) => safety::neighbour_reach(p, v),
        (Some(_), None) => f64::INFINITY,
    };
    p.sense_radius
        .min(avoidance.max(barrier))
        .max(2.0 * p.safe_radius)
}

/// Whether a robot at `now` has moved at most `half` from `was` (see
/// `Simulation::find_neighbours`).
#[inline]
pub(super) fn moved_within(was: DVec2, now: DVec2, half: f64) -> bool {
    was.distance_squared(now) <= half * half
}

/// Once more than one robot in this many has moved more than half the lists' skin, the lists
/// are rebuilt rather than searched around those robots (`Simulation::lists_still_hold`). A
/// search around a robot costs about as much as that robot's share of a rebuild, and the
/// lists kept past half their skin postpone a rebuild by some twelve steps in a jam: searching
/// around more than a twelfth of the robots in a step costs more than the step's share of the
/// rebuild it saves. The crowd of 10,000, whose jam has one robot in ten running, then
/// rebuilds at once. Its cost is guarded by `benches/peer.rs` (the jam over open space).
const MOVED_SHARE: usize = 12;

/// The skin of the Verlet lists, relative to their reach (see `Simulation::find_neighbours`):
/// wider lists to read against fewer rebuilds. A quarter is a usual choice for Verlet lists,
/// and its cost in open space and in the jam is guarded by `benches/peer.rs`.
const SKIN: f64 = 0.25;

#[cfg(test)]
mod tests {
    use super::Simulation;
    use crate::testing::test;

    /// Through the jam of a crowd, the lists are kept at some steps after a robot has moved
    /// more than half their skin (`lists_still_hold`), and at every such step they list every
    /// pair within their reach (a scan over all pairs): what the step's evaluations and
    /// metrics read from them is then what a rebuild would have given.
    #[test]
    fn lists_kept_past_half_the_skin_hold_every_pair() {
        let s = crate::presets::crowd(200);
        let mut sim = Simulation::new(&s).unwrap();
        let (reach, n) = (sim.reach, sim.robots.len());
        let mut kept = 0;
        // Past the jam at the centre (about 16 s).
        while sim.time() < 25.0 {
            sim.step();
            if sim.none_moved_beyond(sim.half_skin()) {
                continue;
            }
            kept += 1;
            let p = |i: usize| sim.robots[i].pose.p;
            for i in 0..n {
                for j in 0..n {
                    assert!(
                        i == j
                            || p(i).distance_squared(p(j)) > reach * reach
                            || sim.near.of(i).contains(&(j as u32)),
                        "step {}: robots {i} and {j} are within the reach and not listed",
                        sim.steps
                    );
                }
            }
        }
        assert!(
            kept >= 50,
            "the lists were kept past half their skin at {kept} steps"
        );
    }
}
