//! The in-place edits of a [`Simulation`] that has taken no step yet (the playground's drags):
//! a robot or an obstacle moved, with the same bits as a new simulation of the edited
//! scenario, at the cost of the robots that sense the change.

use super::{Robot, Simulation};
use crate::obstacle::Obstacle;
use crate::scenario::MAX_MAGNITUDE;
use crate::se2::{heading, Pose};
use glam::DVec2;

impl Simulation {
    /// Puts robot `i` at `pose`, bound for `goal`, in a simulation that has taken no step yet:
    /// afterwards it holds the same bits as [`Simulation::new`] of the scenario with that robot
    /// there, at the cost of the robots that sense it (where it was and where it is now) and an
    /// O(N) rebuild of the neighbour lists, rather than a whole step's evaluation. The
    /// playground's drags go through here.
    ///
    /// Returns `false`, changing nothing, once a step has been taken (the snapshot speeds are
    /// then no longer those of a new simulation), for an index out of range, or for a pose or
    /// goal with a coordinate the validation refuses (not finite, or beyond
    /// [`MAX_MAGNITUDE`]): build a new simulation then, which names the field.
    pub fn place_robot(&mut self, i: usize, pose: Pose, goal: Pose) -> bool {
        let numbers = pose.to_array().into_iter().chain(goal.to_array());
        let valid = numbers.clone().all(in_range);
        if self.steps != 0 || i >= self.robots.len() || !valid {
            return false;
        }
        let was = self.robots[i].pose.p;
        self.robots[i] = Robot::at(pose, goal);
        self.goal_headings[i] = heading(self.robots[i].goal.theta);
        self.headings[i] = heading(self.robots[i].pose.theta);
        let now = self.robots[i].pose.p;
        if self.planned.is_some() {
            // A planner other than DVF may plan jointly: every robot is planned again.
            self.find_neighbours(None);
            self.plan_all();
        } else if now == was {
            // Only robot `i` depends on its own goal and heading.
            self.evaluate_robot(i);
        } else {
            self.find_neighbours(None);
            self.sense_all();
            let near = self.sense_margin();
            let affected = |q: DVec2| q.distance(was) <= near || q.distance(now) <= near;
            for j in 0..self.robots.len() {
                if j == i || (!self.independent && affected(self.robots[j].pose.p)) {
                    self.evaluate_robot(j);
                }
            }
        }
        self.observe_again();
        true
    }

    /// Replaces obstacle `k` in a simulation that has taken no step yet, with the same bits as
    /// [`Simulation::new`] of the scenario with that obstacle: the robots within `R_s` of its
    /// old or new disc are evaluated again. Returns `false`, changing nothing, once a step has
    /// been taken, for an index out of range, or for an obstacle the validation refuses for
    /// its numbers (not finite or beyond [`MAX_MAGNITUDE`], `radius ≤ 0`, `influence ≤ radius`).
    pub fn place_obstacle(&mut self, k: usize, obstacle: Obstacle) -> bool {
        let Obstacle {
            center,
            radius,
            influence,
        } = obstacle;
        let valid = [center.x, center.y, radius, influence]
            .into_iter()
            .all(in_range)
            && radius > 0.0
            && influence > radius;
        if self.steps != 0 || k >= self.obstacles.len() || !valid {
            return false;
        }
        let was = self.obstacles[k];
        self.obstacles[k] = obstacle;
        self.build_obstacle_cells();
        if self.planned.is_some() {
            self.plan_all();
            self.observe_again();
            return true;
        }
        let near = self.sense_margin();
        for j in 0..self.robots.len() {
            let p = self.robots[j].pose.p;
            if was.clearance(p) <= near || obstacle.clearance(p) <= near {
                self.evaluate_robot(j);
            }
        }
        self.observe_again();
        true
    }

    /// The metrics of a simulation that has taken no step, observed again from scratch.
    fn observe_again(&mut self) {
        // Only some robots were evaluated again: the metrics search the lists themselves.
        self.closest2 = None;
        self.metrics.clear();
        self.observe();
    }
}

/// A coordinate or radius the validation accepts: finite, at most [`MAX_MAGNITUDE`] in size.
fn in_range(v: f64) -> bool {
    v.is_finite() && v.abs() <= MAX_MAGNITUDE
}
