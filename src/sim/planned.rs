//! The step of a planner other than DVF ([`crate::planner`]): the planner gives every robot's
//! command from the snapshot at once, and each command then meets the robot's limits and the
//! safety barrier exactly as DVF's does (`evaluation.rs`).

use super::Simulation;
use crate::controller::{saturate, Evaluation};
use crate::error::Error;
use crate::grid::Neighbours;
use crate::planner::{Planner, World};
use crate::safety;
use crate::scenario::Scenario;
use crate::Command;
use glam::DVec2;

/// A planner, the lists of the robots each robot senses, and its evaluations.
#[derive(Debug)]
pub(super) struct Planned {
    pub(super) planner: Box<dyn Planner>,
    near: Neighbours,
    evaluations: Vec<Evaluation>,
    positions: Vec<DVec2>,
}

impl Planned {
    pub(super) fn new(planner: Box<dyn Planner>) -> Self {
        Self {
            planner,
            near: Neighbours::new(),
            evaluations: Vec::new(),
            positions: Vec::new(),
        }
    }
}

impl Clone for Planned {
    fn clone(&self) -> Self {
        Self {
            planner: self.planner.clone_box(),
            near: self.near.clone(),
            evaluations: self.evaluations.clone(),
            positions: self.positions.clone(),
        }
    }
}

impl Simulation {
    /// A simulation at time 0 of scenario `s` whose robots `planner` drives, in place of the
    /// scenario's own `planner`: a planner of one's own, on the simulator's unicycle, sensing,
    /// limits, barrier, metrics and report. The report names it `custom`.
    ///
    /// # Errors
    /// As [`Simulation::new`].
    pub fn with_planner(s: &Scenario, planner: Box<dyn Planner>) -> Result<Self, Error> {
        s.validate()?;
        let mut sim = Self::of_valid(s, super::Neighbourhood::Grid);
        sim.planned = Some(Planned::new(planner));
        sim.planner = Some("custom".to_owned());
        sim.evaluate_all(None);
        sim.metrics.clear();
        sim.observe();
        Ok(sim)
    }

    /// Every robot's command from the planner, limited and made safe, into `last`, `commands`,
    /// `chords` and `headings_after`. A command that is not finite is a stop: nothing a
    /// planner computes reaches the unicycle as NaN.
    pub(super) fn plan_all(&mut self) {
        let Some(mut planned) = self.planned.take() else {
            return;
        };
        let rs = self.params.sense_radius;
        planned.positions.clear();
        planned
            .positions
            .extend(self.robots.iter().map(|r| r.pose.p));
        planned.near.build(&planned.positions, rs);
        planned.evaluations.clear();
        planned
            .evaluations
            .extend(self.robots.iter().map(|r| r.last));
        let world = World {
            time: self.time,
            dt: self.dt,
            params: &self.params,
            robots: &self.robots,
            obstacles: &self.obstacles,
            independent: self.independent,
            near: &planned.near,
        };
        planned.planner.plan(&world, &mut planned.evaluations);
        let mut constraints = std::mem::take(&mut self.scratch.constraints);
        for (i, e) in planned.evaluations.iter_mut().enumerate() {
            let c = e.command;
            e.command = if c.v.is_finite() && c.omega.is_finite() {
                saturate(&self.params, c)
            } else {
                Command::default()
            };
            let (p, h) = (self.robots[i].pose.p, self.headings[i]);
            // The direction the barrier turns from when it is blocked: the planner's, or the
            // way the command drives.
            if !(e.field.is_finite() && e.field != DVec2::ZERO) {
                e.field = h * e.command.v;
            }
            let binding = safety::neighbour_reach(&self.params, e.command.v);
            let binding2 = binding * binding;
            let neighbours = world
                .sensed(i)
                .map(|j| self.robots[j].pose.p)
                .filter(|q| q.distance_squared(p) <= binding2);
            let obstacles = self
                .sensed_obstacles(p)
                .map(|k| &self.obstacles[k as usize]);
            let (command, motion) = safety::filter_facing(
                &mut constraints,
                &self.params,
                self.dt,
                p,
                h,
                e.command,
                e.field,
                neighbours,
                obstacles,
            );
            e.command = command;
            self.commands[i] = command;
            self.chords[i] = motion.chord;
            self.headings_after[i] = motion.heading;
        }
        for (r, e) in self.robots.iter_mut().zip(&planned.evaluations) {
            r.last = *e;
        }
        self.scratch.constraints = constraints;
        self.planned = Some(planned);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::planner::{Built, Spec};
    use crate::testing::test;

    /// Every robot drives straight at 1 m/s: a planner with no avoidance of its own.
    #[derive(Clone, Debug)]
    struct Straight;

    impl Planner for Straight {
        fn plan(&mut self, world: &World<'_>, out: &mut [Evaluation]) {
            assert_eq!(out.len(), world.robots.len());
            for e in out {
                e.command = Command { v: 1.0, omega: 0.0 };
            }
        }
        fn clone_box(&self) -> Box<dyn Planner> {
            Box::new(self.clone())
        }
    }

    fn head_on(barrier: &str) -> Scenario {
        Scenario::from_json(&format!(
            r#"{{"duration": 6, "params": {{"barrier_rate": {barrier}}},
                "robots": [{{"start": [0, 0, 0], "goal": [6, 0, 0]}},
                           {{"start": [6, 0, 3.141592653589793], "goal": [0, 0, 3.141592653589793]}}]}}"#
        ))
        .unwrap()
    }

    fn straight(s: &Scenario) -> Simulation {
        Simulation::with_planner(s, Box::new(Straight)).unwrap()
    }

    /// The shared barrier stops two robots a planner drives into each other, as it does DVF's;
    /// without it (`barrier_rate: null`) they pass through each other. A violation is a pair
    /// closer than 2·r_ij = 0.5 m.
    #[test]
    fn the_barrier_keeps_a_planner_without_avoidance_safe() {
        let mut safe = straight(&head_on("2"));
        let mut bare = straight(&head_on("null"));
        for _ in 0..600 {
            safe.step();
            bare.step();
        }
        assert_eq!(safe.report().violations, 0);
        assert!(bare.report().violations >= 1);
        assert!(safe.report().min_pair_distance.unwrap() >= 0.5 - 1e-9);
    }

    /// The robot's limits bind every planner's command: at v_max = 0.5 the robots drive at
    /// half the planner's speed, exactly (the saturation scales, it does not add error).
    #[test]
    fn the_limits_bind_a_planners_command() {
        let mut s = head_on("null");
        s.params.v_max = Some(0.5);
        s.independent = true;
        let mut sim = straight(&s);
        sim.step();
        assert_eq!(sim.robots()[0].last.command.v, 0.5);
        assert!((sim.robots()[0].pose.p.x - 0.005).abs() < 1e-15);
    }

    /// `dvf-paper` is DVF with the paper's avoidance: the same bits as setting it in `params`.
    #[test]
    fn dvf_paper_is_dvf_with_the_papers_avoidance() {
        let mut s = crate::presets::preset("example4-obstacle-formation").unwrap();
        s.duration = 2.0;
        let mut paper = s.clone();
        paper.params.avoidance = crate::params::Avoidance::Paper;
        s.planner = Spec::named("dvf-paper");
        assert!(matches!(s.planner.build(), Ok(Built::Dvf(Some(_)))));
        let (a, b) = (crate::run(&s).unwrap(), crate::run(&paper).unwrap());
        assert_eq!(a.robots, b.robots);
        assert_eq!(a.planner.as_deref(), Some("dvf-paper"));
        assert_eq!(b.planner, None);
    }
}
