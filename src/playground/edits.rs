//! Edits of the live model, each validated for what it touches (see the module doc of
//! [`super`] for what an edit means at `t > 0`).
//!
//! [`Live::edit`] replaces the whole scenario (undo, import, links). The fine-grained edits
//! move, resize, set, add or remove one thing. Moving a robot, a goal or an obstacle and
//! resizing an obstacle check only what they touch (O(robots) at most, nothing serialised) and,
//! while the simulation has not stepped since the last edit, update it in place
//! ([`Simulation::place_robot`], [`Simulation::place_obstacle`]): a drag costs the robots near
//! the moved thing, not a step of the whole crowd. Every edit leaves the model with the same
//! bits as [`Live::edit`] of the edited scenario would (a test checks it).

use super::{Live, MAX_LIVE_STEPS};
use crate::error::Error;
use crate::obstacle::Obstacle;
use crate::params::{Avoidance, Slot};
use crate::scenario::{RobotSpec, Scenario, MAX_MAGNITUDE};
use crate::se2::Pose;
use crate::sim::Simulation;
use glam::DVec2;

impl Live {
    /// Replaces the scenario (see the module doc for what happens at `t > 0`) and predicts
    /// again.
    ///
    /// # Errors
    /// The first invalid field of `scenario`, or a robot that the edit would leave inside an
    /// obstacle; the live simulation is unchanged then.
    pub fn edit(&mut self, scenario: Scenario) -> Result<(), Error> {
        check(&scenario)?;
        if self.steps() == 0 {
            self.scenario = scenario;
            self.reset();
            return Ok(());
        }
        let now: Vec<Pose> = self.sim.robots().iter().map(|r| r.pose).collect();
        self.resume(scenario, &now)
    }

    /// Moves robot `index` to `pose`: its start at `t = 0`, its current pose later.
    ///
    /// # Errors
    /// An index out of range, a non-finite or too large value, a pose inside an obstacle or
    /// inside another robot's safe disc.
    pub fn move_robot(&mut self, index: usize, pose: Pose) -> Result<(), Error> {
        self.robot_index(index)?;
        if self.steps() == 0 {
            let mut spec = self.scenario.robots[index];
            spec.start = pose.to_array();
            return self.set_robot(index, spec);
        }
        // What the move touches, cheaply; the whole check of `resume` runs (and names the
        // field) only when something fails.
        let safe = 2.0 * self.scenario.params.safe_radius;
        let robots = self.sim.robots();
        let fine = pose
            .to_array()
            .iter()
            .all(|v| v.is_finite() && v.abs() <= MAX_MAGNITUDE)
            && self
                .scenario
                .obstacles
                .iter()
                .all(|o| o.clearance(pose.p) > 0.0)
            && (self.scenario.independent
                || robots
                    .iter()
                    .enumerate()
                    .all(|(k, r)| k == index || r.pose.p.distance(pose.p) >= safe));
        let goal = self.scenario.robots[index].goal_pose();
        let placed = fine && self.sim.place_robot(index, pose, goal);
        self.settle(placed, Some((index, pose)))
    }

    /// Moves robot `index`'s goal to `goal`.
    ///
    /// # Errors
    /// An index out of range, a non-finite or too large value, a goal inside an obstacle or
    /// its ring, or inside another goal's safe disc.
    pub fn move_goal(&mut self, index: usize, goal: Pose) -> Result<(), Error> {
        self.robot_index(index)?;
        let mut spec = self.scenario.robots[index];
        spec.goal = goal.to_array();
        self.set_robot(index, spec)
    }

    /// Robot `index` becomes `spec` (a new start only at `t = 0`: later the start is where
    /// [`Live::reset`] puts it, and the robot goes on from where it is).
    fn set_robot(&mut self, index: usize, spec: RobotSpec) -> Result<(), Error> {
        let old = self.scenario.robots[index];
        self.scenario.robots[index] = spec;
        if let Err(e) = self.scenario.validate_robot(index) {
            self.scenario.robots[index] = old;
            return Err(e);
        }
        let fresh = self.steps() == 0;
        let pose = if fresh {
            spec.start_pose()
        } else {
            self.sim.robots()[index].pose
        };
        let placed = self.sim.place_robot(index, pose, spec.goal_pose());
        if placed && fresh {
            // The one trail sample at t = 0 is the start.
            let min_pair = self.pairs.of(&self.sim);
            let now = self.sim.robots()[index].pose;
            self.trails.rewrite_newest(index, now, min_pair);
        }
        let settled = self.settle(placed, None);
        if settled.is_err() {
            self.scenario.robots[index] = old;
        }
        settled
    }

    /// Moves obstacle `index`'s centre to `center`.
    ///
    /// # Errors
    /// An index out of range, a non-finite value, or a robot's start, goal or (at `t > 0`)
    /// current pose that the obstacle would cover.
    pub fn move_obstacle(&mut self, index: usize, center: DVec2) -> Result<(), Error> {
        let o = self.obstacle(index)?;
        self.set_obstacle(index, Obstacle { center, ..o })
    }

    /// Gives obstacle `index` the disc radius `radius` and the influence radius `influence`.
    ///
    /// # Errors
    /// As [`Live::move_obstacle`], and a radius that is not positive or a ring not outside
    /// the disc.
    pub fn resize_obstacle(
        &mut self,
        index: usize,
        radius: f64,
        influence: f64,
    ) -> Result<(), Error> {
        let o = self.obstacle(index)?;
        self.set_obstacle(
            index,
            Obstacle {
                radius,
                influence,
                ..o
            },
        )
    }

    /// Obstacle `index` becomes `o`.
    fn set_obstacle(&mut self, index: usize, o: Obstacle) -> Result<(), Error> {
        let old = self.scenario.obstacles[index];
        self.scenario.obstacles[index] = o;
        if let Err(e) = self.scenario.validate_obstacle(index) {
            self.scenario.obstacles[index] = old;
            return Err(e);
        }
        // At t > 0 the robots must also be clear of it where they are now: when one is not,
        // the whole path of `settle` (`resume`) refuses the edit and names it.
        let clear = self.steps() == 0
            || self
                .sim
                .robots()
                .iter()
                .all(|r| o.clearance(r.pose.p) > 0.0);
        let placed = clear && self.sim.place_obstacle(index, o);
        let settled = self.settle(placed, None);
        if settled.is_err() {
            self.scenario.obstacles[index] = old;
        }
        settled
    }

    /// Ends an edit of `self.scenario`: when the simulation took it in place (`placed`), the
    /// buffers and the prediction follow; otherwise the simulation is rebuilt, at `t = 0` from
    /// the scenario, later from where the robots are now (robot `moved.0` at `moved.1`).
    fn settle(&mut self, placed: bool, moved: Option<(usize, Pose)>) -> Result<(), Error> {
        if placed {
            self.refresh();
            self.predict();
            return Ok(());
        }
        if self.steps() == 0 {
            self.reset();
            return Ok(());
        }
        let mut now: Vec<Pose> = self.sim.robots().iter().map(|r| r.pose).collect();
        if let Some((i, p)) = moved {
            now[i] = p;
        }
        self.resume(self.scenario.clone(), &now)
    }

    /// Sets one number of the scenario: `duration`, `dt`, or a parameter by its JSON key
    /// (`k_v`, `barrier_rate`, …; [`ParamValue::None`] for "none" where a parameter is
    /// optional, text for `avoidance`). A parameter touches every robot: the whole scenario is
    /// checked and the simulation rebuilt.
    ///
    /// # Errors
    /// An unknown name, a value of the wrong kind, or the first invalid field of the edited
    /// scenario.
    pub fn set_param(&mut self, name: &str, value: ParamValue) -> Result<(), Error> {
        let mut s = self.scenario.clone();
        let field = || match name {
            "duration" | "dt" => name.to_owned(),
            _ => format!("params.{name}"),
        };
        let set = match (slot(&mut s, name), value) {
            (None, _) => {
                return Err(Error::Parse {
                    field: field(),
                    message: "no such parameter".into(),
                })
            }
            (Some(Slot::Number(x)), ParamValue::Number(v)) => {
                *x = v;
                true
            }
            (Some(Slot::Optional(x)), ParamValue::Number(v)) => {
                *x = Some(v);
                true
            }
            (Some(Slot::Optional(x)), ParamValue::None) => {
                *x = None;
                true
            }
            (Some(Slot::Mode(x)), ParamValue::Text(t)) => {
                Avoidance::from_name(&t).map(|m| *x = m).is_some()
            }
            _ => false,
        };
        if !set {
            return Err(Error::Parse {
                field: field(),
                message: "a value of the wrong kind: a number (null where optional; \"exit\" or \"paper\" for avoidance)".into(),
            });
        }
        self.edit(s)
    }

    /// Adds a robot (at its start, also at `t > 0`).
    ///
    /// # Errors
    /// The robot's first invalid field, or too many robots.
    pub fn add_robot(&mut self, spec: RobotSpec) -> Result<(), Error> {
        let mut s = self.scenario.clone();
        s.robots.push(spec);
        self.edit(s)
    }

    /// Removes robot `index`; the robots after it move down one index.
    ///
    /// # Errors
    /// An index out of range, or the last robot.
    pub fn remove_robot(&mut self, index: usize) -> Result<(), Error> {
        self.robot_index(index)?;
        let mut s = self.scenario.clone();
        s.robots.remove(index);
        self.edit(s)
    }

    /// Adds an obstacle.
    ///
    /// # Errors
    /// Its first invalid field, a robot it would cover, or too many obstacles.
    pub fn add_obstacle(&mut self, o: Obstacle) -> Result<(), Error> {
        let mut s = self.scenario.clone();
        s.obstacles.push(o);
        self.edit(s)
    }

    /// Removes obstacle `index`; the obstacles after it move down one index.
    ///
    /// # Errors
    /// An index out of range.
    pub fn remove_obstacle(&mut self, index: usize) -> Result<(), Error> {
        self.obstacle(index)?;
        let mut s = self.scenario.clone();
        s.obstacles.remove(index);
        self.edit(s)
    }

    fn robot_index(&self, index: usize) -> Result<(), Error> {
        let count = self.scenario.robots.len();
        if index < count {
            Ok(())
        } else {
            Err(Error::RobotIndex { index, count })
        }
    }

    fn obstacle(&self, index: usize) -> Result<Obstacle, Error> {
        self.scenario
            .obstacles
            .get(index)
            .copied()
            .ok_or_else(|| Error::Invalid {
                field: "obstacle".into(),
                message: format!(
                    "no obstacle {index}: the scenario has {} (numbered from 0)",
                    self.scenario.obstacles.len()
                ),
            })
    }

    /// Restarts the simulation from `now` (poses of the first robots) under `scenario`,
    /// keeping the clock and the trails of the robots that remain.
    pub(super) fn resume(&mut self, scenario: Scenario, now: &[Pose]) -> Result<(), Error> {
        let mut from = scenario.clone();
        let time = self.time();
        for (i, (r, p)) in from.robots.iter_mut().zip(now).enumerate() {
            check_pose_now(i, *p, &scenario.obstacles, time)?;
            *r = RobotSpec {
                start: p.to_array(),
                goal: r.goal,
            };
        }
        // The safe distance is a promise: an edit may not put two robots inside each
        // other's safe disc where they are now, added robots at their starts included (at
        // t = 0 the scenario's validation says so).
        let safe = 2.0 * from.params.safe_radius;
        if !from.independent {
            let at: Vec<DVec2> = from.robots.iter().map(|r| r.start_pose().p).collect();
            if let Some((i, j, d)) = crate::grid::closest_pair_below(&at, safe) {
                return Err(too_close_now(i, j, d, safe, time));
            }
        }
        let steps = self.steps();
        let n = scenario.robots.len();
        self.sim = Simulation::of_valid(&from, crate::sim::Neighbourhood::Grid);
        self.base_time = time;
        self.base_steps = steps;
        self.scenario = scenario;
        if n != self.trails.lens().len() {
            self.trails.resize(n);
        }
        self.record_every = super::record_every(&self.scenario, self.trails.capacity());
        self.refresh();
        self.predict();
        Ok(())
    }
}

/// A value for [`Live::set_param`].
#[derive(Clone, Debug, PartialEq)]
pub enum ParamValue {
    /// A number.
    Number(f64),
    /// "None" for an optional parameter (`null` in JSON).
    None,
    /// Text (the avoidance mode).
    Text(String),
}

/// The number, optional number or mode of `s` that `name` (a JSON key) names: `duration`,
/// `dt`, or a parameter of the table ([`crate::params::PARAMETERS`]).
fn slot<'a>(s: &'a mut Scenario, name: &str) -> Option<Slot<'a>> {
    match name {
        "duration" => Some(Slot::Number(&mut s.duration)),
        "dt" => Some(Slot::Number(&mut s.dt)),
        _ => s.params.slot(name),
    }
}

/// The scenario checks plus the playground's step limit.
pub(super) fn check(s: &Scenario) -> Result<(), Error> {
    // The robot count is the scenario's own limit (MAX_LIVE_ROBOTS): validated there.
    s.validate()?;
    let steps = s.steps();
    if steps > MAX_LIVE_STEPS {
        return Err(Error::Invalid {
            field: "duration".into(),
            message: format!(
                "the playground runs at most {MAX_LIVE_STEPS} steps live, not {steps} (duration / dt): shorten the duration or raise dt (the `dvf` command line runs longer scenarios)"
            ),
        });
    }
    Ok(())
}

/// Robot `i` at `p` now (at `time`): finite, of bounded magnitude, outside every one of
/// `obstacles`.
fn check_pose_now(i: usize, p: Pose, obstacles: &[Obstacle], time: f64) -> Result<(), Error> {
    let field = format!("robots[{i}]");
    for (k, v) in p.to_array().into_iter().enumerate() {
        if !v.is_finite() || v.abs() > MAX_MAGNITUDE {
            return Err(Error::Invalid {
                field: format!("{field}.pose[{k}]"),
                message: format!(
                    "must be a finite number of magnitude at most {MAX_MAGNITUDE:e}, not {v}"
                ),
            });
        }
    }
    for (j, o) in obstacles.iter().enumerate() {
        if o.clearance(p.p) <= 0.0 {
            return Err(Error::Invalid {
                field,
                message: format!(
                    "would be inside obstacles[{j}] (radius {}) where it is now, at t = {time:.2} s",
                    o.radius
                ),
            });
        }
    }
    Ok(())
}

/// Robots `i < j` `d < safe` apart where they are now.
fn too_close_now(i: usize, j: usize, d: f64, safe: f64, time: f64) -> Error {
    Error::Invalid {
        field: format!("robots[{j}]"),
        message: format!(
            "would be {d:.3} from robots[{i}] where they are now, at t = {time:.2} s: closer than the safe distance 2 · safe_radius = {safe}"
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::presets::{crowd_with_obstacles, preset, DEFAULT_PRESET};
    use crate::testing::{test, XorShift};

    /// Everything the page reads of a model, and its report: equal text means equal bits
    /// (`Debug` prints every float exactly, NaN and −0 included).
    fn state(l: &Live) -> Vec<(&'static str, String)> {
        vec![
            ("robots", format!("{:?}", l.simulation().robots())),
            ("report", format!("{:?}", l.simulation().report())),
            ("poses", format!("{:?}", l.poses())),
            ("status", format!("{:?}", l.status())),
            ("trails", format!("{:?}", l.trails())),
            ("prediction", format!("{:?}", l.prediction())),
            ("clock", format!("{:?}", (l.time(), l.steps()))),
            ("scenario", format!("{:?}", l.scenario())),
        ]
    }

    /// The parts of two states that differ, by name.
    fn differ(a: &Live, b: &Live) -> Vec<&'static str> {
        state(a)
            .into_iter()
            .zip(state(b))
            .filter(|(x, y)| x != y)
            .map(|(x, _)| x.0)
            .collect()
    }

    /// Each fine-grained edit leaves the same bits as the whole-scenario path it replaces
    /// (`edit` at t = 0, `resume` later), in a crowd (cells) and in Example 4 (the scan), at
    /// t = 0 and paused at t > 0, and a refused edit changes nothing.
    #[test]
    fn fine_grained_edits_equal_the_whole_scenario_path() {
        let mut rng = XorShift(0x5DEE_CE66_D1CE_4E5B);
        for mut scene in [
            crowd_with_obstacles(60, 12),
            preset(DEFAULT_PRESET).unwrap(),
        ] {
            // Two seconds: the prediction (compared too) runs to the end, and an edit means
            // the same however long the run; a short one keeps the test quick under wasm,
            // where a long test blocks the browser's page.
            scene.duration = 2.0;
            for steps in [0, 7] {
                let mut live = Live::new(scene.clone()).unwrap();
                live.step(steps);
                let n = scene.robots.len();
                let mut accepted = 0;
                for round in 0..20 {
                    let before = live.clone();
                    let mut reference = live.clone();
                    let i = (rng.next_u64() % n as u64) as usize;
                    let (x0, y0, x1, y1) = {
                        let b = scene.resolved_bounds();
                        (b[0], b[1], b[2], b[3])
                    };
                    let p = Pose::new(rng.range(x0, x1), rng.range(y0, y1), rng.heading());
                    let (got, want) = match round % 4 {
                        0 => {
                            let got = live.move_robot(i, p);
                            let want = if reference.steps() == 0 {
                                let mut s = reference.scenario().clone();
                                s.robots[i].start = p.to_array();
                                reference.edit(s)
                            } else {
                                let mut now: Vec<Pose> =
                                    reference.sim.robots().iter().map(|r| r.pose).collect();
                                now[i] = p;
                                let s = reference.scenario().clone();
                                reference.resume(s, &now)
                            };
                            (got, want)
                        }
                        1 => {
                            let got = live.move_goal(i, p);
                            let mut s = reference.scenario().clone();
                            s.robots[i].goal = p.to_array();
                            (got, reference.edit(s))
                        }
                        kind => {
                            let m = scene.obstacles.len();
                            let k = (rng.next_u64() % m as u64) as usize;
                            let mut o = before.scenario().obstacles[k];
                            let got = if kind == 2 {
                                o.center = p.p;
                                live.move_obstacle(k, o.center)
                            } else {
                                o.radius = rng.range(0.2, 2.0);
                                o.influence = o.radius * rng.range(0.8, 3.0);
                                live.resize_obstacle(k, o.radius, o.influence)
                            };
                            let mut s = reference.scenario().clone();
                            s.obstacles[k] = o;
                            (got, reference.edit(s))
                        }
                    };
                    match (&got, &want) {
                        (Ok(()), Ok(())) => accepted += 1,
                        (Err(a), Err(b)) => {
                            assert_eq!(a.to_string(), b.to_string(), "round {round}");
                            assert_eq!(differ(&live, &before), [""; 0], "a refused edit changed");
                        }
                        _ => panic!("round {round}: {got:?} where the whole path gives {want:?}"),
                    }
                    assert_eq!(
                        differ(&live, &reference),
                        [""; 0],
                        "round {round}, steps {steps}"
                    );
                }
                assert!(accepted >= 3, "only {accepted} edits were valid");
            }
        }
    }
}
