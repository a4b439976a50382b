//! What the robots of a [`Simulation`] sense: each robot as the others sense it this step (one
//! packed record per robot), the obstacles near a point, and the reaches beyond which a sensed
//! robot changes no command.

use super::{parallel, Robot, Simulation};
use crate::grid::ObstacleCells;
use crate::params::{Avoidance, Params};
use crate::safety;
use crate::swarm::{at_rest_beside, cluster_reach, pair_range, Neighbour, SLOWEST_UNKNOWN};
use glam::DVec2;

impl Simulation {
    /// The reach of what a robot senses: the sensing radius, and the collision distance
    /// `2·r_ij` of the violation count should it be larger (the obstacles' cells and the
    /// clearance metric).
    pub(super) fn sense_reach(&self) -> f64 {
        self.params.sense_radius.max(2.0 * self.params.safe_radius)
    }

    /// The obstacles' cells for the current obstacles ([`ObstacleCells`]).
    pub(super) fn build_obstacle_cells(&mut self) {
        self.obstacle_cells = match self.neighbourhood {
            super::Neighbourhood::Grid => ObstacleCells::build(&self.obstacles, self.sense_reach()),
            super::Neighbourhood::AllPairs => ObstacleCells::all(self.obstacles.len()),
        };
    }

    /// Each robot as the others sense it this step, into `sensed`: its position, its speed
    /// and, when the step knows it ([`slowest_known`]), its slowest robot within the
    /// avoidance range of it (at another position), from the lists and the snapshot's speeds.
    /// A robot deciding whether a neighbour stands in a parked formation reads that
    /// ([`Neighbour::slowest_near`]) instead of searching its own neighbours around that one.
    /// The same answer, since it would find the same robots: with `R_s` at least twice the
    /// range, every robot within the range of a neighbour within the range is sensed. The
    /// deciding robot itself may be the slowest, which changes nothing: it is never at rest
    /// next to itself (`swarm::AT_REST_RATIO` < 1), nor is any robot at least as fast.
    ///
    /// A robot's slowest neighbour is read only when that robot is at rest beside the robot
    /// deciding (`swarm::in_a_parked_formation`), and a robot deciding moves at most as fast
    /// as the fastest robot, or at the circling speed `v_c` on an obstacle's surface
    /// (`Approach::speed`): the robots not at rest beside the faster of those two are given
    /// `+∞` without a search, which nothing reads. In open space that is every robot.
    ///
    /// One record per robot and step, read by every robot that lists it: the sensing loop of
    /// an evaluation copies it whole rather than gathering position, speed and slowest robot
    /// from three arrays (one of them the robots' whole states).
    pub(super) fn sense_all(&mut self) {
        if self.independent {
            return;
        }
        let known = self.slowest_known;
        let range = pair_range(self.params.avoid_radius, self.params.transition_width);
        let range2 = range * range;
        let fastest = self
            .speeds
            .iter()
            .fold(self.params.avoid_speed, |m, &s| if s > m { s } else { m });
        let mut out = std::mem::take(&mut self.sensed);
        // The robots and their speeds walked together, the search out of line: a robot that
        // is not at rest (every one in open space) costs a comparison and a copy.
        let record = |(n, (r, &speed)): (usize, (&Robot, &f64))| Neighbour {
            position: r.pose.p,
            speed,
            slowest_near: if !known {
                SLOWEST_UNKNOWN
            } else if at_rest_beside(speed, fastest) {
                self.slowest_near(n, range2)
            } else {
                f64::INFINITY
            },
        };
        parallel::sense(
            self.threaded(),
            &self.robots,
            &self.speeds,
            record,
            &mut out,
        );
        self.sensed = out;
    }

    /// The smallest snapshot speed of the robots within `√range2` of robot `n` (at another
    /// position), from its list: [`Self::sense_all`]'s search, for a robot at rest.
    #[inline(never)]
    fn slowest_near(&self, n: usize, range2: f64) -> f64 {
        let p = self.robots[n].pose.p;
        let mut slowest = f64::INFINITY;
        for &m in self.near.of(n) {
            let q = self.robots[m as usize].pose.p;
            // Without a branch to mispredict (in a jam about half the listed robots are in the
            // range): a select, which is also one instruction in wasm, where `f64::min` is a
            // call (to `fmin`, for its rule on NaN). The same minimum: speeds are `|v|`, never
            // NaN nor −0.
            let near = (q != p) & (q.distance_squared(p) <= range2);
            let speed = self.speeds[m as usize];
            slowest = if near & (speed < slowest) {
                speed
            } else {
                slowest
            };
        }
        slowest
    }

    /// The obstacles a robot at `p` senses: those whose surface is within `R_s`, as indices in
    /// ascending order (the cells' candidates, tested).
    pub(super) fn sensed_obstacles(&self, p: DVec2) -> impl Iterator<Item = u32> + '_ {
        let rs = self.params.sense_radius;
        self.obstacle_cells
            .near(p)
            .filter(move |&k| self.obstacles[k].clearance(p) <= rs)
            .map(|k| k as u32)
    }

    /// A distance beyond which nothing is sensed: `R_s` and a relative margin, so that
    /// round-off in a distance cannot leave out a robot whose evaluation changes (evaluating
    /// one too many gives the same bits).
    pub(super) fn sense_margin(&self) -> f64 {
        self.params.sense_radius * (1.0 + 1e-9) + 1e-9
    }
}

/// Whether a step can find each robot's slowest robots within the avoidance range
/// ([`Simulation::sense_all`]) and give its neighbours' to the robot that senses them: with
/// the default avoidance (the paper's looks for no parked formation) and a sensing radius at
/// least twice the range (so that a robot senses every robot its search would have found).
pub(super) fn slowest_known(p: &Params) -> bool {
    let range = pair_range(p.avoid_radius, p.transition_width);
    p.avoidance == Avoidance::Exit
        && p.sense_radius >= safety::widened(cluster_reach(range, p.avoidance, false))
}

/// The reach of the sensed robots the controller can use ([`crate::controller::evaluate_facing`]):
/// the avoidance range `2(R_c + ε)` within which the virtual obstacle's choice takes them
/// ([`crate::swarm::cluster`]), and the reach of `make_room` (`PRESSED·r_ij`), each widened
/// ([`safety::widened`]). A robot farther than both changes neither: the choice leaves
/// it out, and `make_room` adds an exact zero for it (its transition is 1 beyond its reach).
/// Everything sensed with the default avoidance when the step does not know its neighbours'
/// slowest robots ([`slowest_known`]): the choice then looks among them for parked ones
/// around each neighbour within the range.
pub(super) fn controller_reach(p: &Params, slowest_known: bool) -> f64 {
    if p.avoidance == Avoidance::Exit && !slowest_known {
        return f64::INFINITY;
    }
    let range = pair_range(p.avoid_radius, p.transition_width);
    let room = crate::swarm::PRESSED * p.safe_radius;
    safety::widened(range.max(room))
}
