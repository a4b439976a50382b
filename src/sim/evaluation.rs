//! Each robot's command from what it senses ([`Simulation::evaluation`], the one place where
//! the method enters the loop), and where the evaluations are stored: in runs of
//! [`STORED_BY`] robots, all the robots in one run on the calling thread
//! ([`Simulation::evaluate_here`]), or a run per chunk on rayon's threads (`parallel.rs`).

use super::{Robot, Simulation};
use crate::controller::{evaluate_facing, Evaluation, Facing};
use crate::safety;
use crate::se2::{unrotate_by, Pose};
use crate::swarm::Neighbour;
use crate::unicycle::Motion;
use crate::Command;
use glam::DVec2;

impl Simulation {
    /// Evaluates every robot on the calling thread, in one run (`evaluate_run`), and returns
    /// the smallest squared distance its evaluations found to a listed robot (`Scratch`).
    pub(super) fn evaluate_here(&mut self) -> f64 {
        // The buffers taken out of `self` once for all robots, not once per robot.
        let mut scratch = std::mem::take(&mut self.scratch);
        scratch.closest2 = f64::INFINITY;
        let mut slots = self.take_slots();
        self.evaluate_run(0, slots.run(), &mut scratch);
        self.put_slots(slots);
        let closest2 = scratch.closest2;
        self.scratch = scratch;
        closest2
    }

    /// Robot `i`'s command from what it senses now, into `last`/`commands` (see
    /// [`Self::evaluation`]): for the in-place edits, which evaluate a few robots.
    pub(super) fn evaluate_robot(&mut self, i: usize) {
        let mut scratch = std::mem::take(&mut self.scratch);
        let mut evaluated = (Evaluation::default(), Motion::default());
        self.evaluation(i, &self.robots[i], &mut scratch, &mut evaluated);
        put(
            (
                &mut self.robots[i],
                &mut self.commands[i],
                &mut self.chords[i],
                &mut self.headings_after[i],
            ),
            &evaluated,
        );
        self.scratch = scratch;
    }

    /// Robot `i`'s command from what it senses now (the robots within `R_s` at the snapshot's
    /// speeds, the obstacles within `R_s`): the DVF controller made safe by the barrier, with
    /// the chord of its step. The one place where the method enters the loop (see the module
    /// doc of `sim`). It reads the snapshot only, so robots can be evaluated in any order or
    /// at once.
    // Out of line: `evaluate_run`'s loop stays small, and the evaluation's registers are its
    // own (`benches/peer.rs` guards the step's time).
    #[inline(never)]
    fn evaluation(
        &self,
        i: usize,
        me: &Robot,
        scratch: &mut Scratch,
        out: &mut (Evaluation, Motion),
    ) {
        let rs = self.params.sense_radius;
        let listed = self.listed();
        // The grid's lists hold the robots within their reach: when that is at most the sensing
        // radius, they are the sensed robots that can change the command (see `list_reach`).
        let r = if listed { self.reach.min(rs) } else { rs };
        let r2 = r * r;
        let neighbours = &mut scratch.neighbours;
        let p = me.pose.p;
        // The error pose, and the heading and the heading error's cosine and sine (the heading
        // rotated back by the goal's) for the controller and the barrier: taken before the
        // sensing loop, whose end the processor mispredicts when the number of listed robots
        // varies, so that the controller finds them ready when it starts again there.
        let err = Pose {
            p: self.error_position(i, me),
            theta: me.heading_error,
        };
        let h = self.headings[i];
        let facing = Facing {
            heading: h,
            error: unrotate_by(self.goal_headings[i], h),
        };
        // The sensed robots within the controller's reach, as a count of the buffer's first
        // slots, and the others sensed, as a range of its slots. Either way those within reach
        // come in ascending index: the grid's lists are sorted.
        let split = self.controller_reach.min(r);
        let (count, others) = if listed {
            // Each listed robot's record (`sense_all`) written in the next free slot of one of
            // two runs, and kept by moving that run's end when it is sensed: no branch to
            // mispredict (in a jam about a third of the listed robots lie in the lists' skin).
            // The lists never hold the robot itself.
            // The first run, from the buffer's start in ascending index, holds the sensed
            // robots within the controller's reach (`controller_reach`); the second, from the
            // end down, the others sensed, which only the barrier reads. The controller is then
            // given the first alone: the virtual obstacle's choice (`swarm::cluster`) tests
            // every robot it is given for the avoidance range, which in a jam is a branch the
            // processor cannot predict. The same bits: the controller sees the robots it can
            // use in the same order, and the barrier's limits are minima and maxima, whatever
            // the order.
            // On the way, the closest listed robot, for the metrics' closest pair (the least
            // squared distance over the robots' lists is that of the closest pair, each pair
            // being seen from both ends, with the same bits: (a − b)² = (b − a)²). The nearest
            // listed robot is sensed exactly when any is, and is then the nearest sensed: the
            // loop keeps it by a select alone (`minsd`) and compares it with the radius once.
            // The buffer only grows, so that it is not filled anew for every robot: its slots
            // outside the runs hold robots of earlier evaluations, never read.
            let list = self.near.of(i);
            let len = list.len();
            if neighbours.len() < 2 * len {
                neighbours.resize(2 * len, Neighbour::default());
            }
            let split2 = split * split;
            // The first run's end, and the second's start: it grows down from the buffer's
            // end, and its next slot `far − 1` stays above the first run's slots (at least
            // `len` while a listed robot is left to place).
            let (mut near, mut far) = (0, 2 * len);
            let mut nearest2 = f64::INFINITY;
            for &j in list {
                let neighbour = self.sensed[j as usize];
                let d2 = neighbour.position.distance_squared(p);
                let within = d2 <= split2;
                neighbours[std::hint::select_unpredictable(within, near, far - 1)] = neighbour;
                near += usize::from(within);
                // Those within the controller's reach are sensed (`split ≤ r`): the second run
                // takes the others sensed.
                far -= usize::from(d2 <= r2) - usize::from(within);
                nearest2 = if d2 < nearest2 { d2 } else { nearest2 };
            }
            if nearest2 <= r2 && nearest2 < scratch.closest2 {
                scratch.closest2 = nearest2;
            }
            (near, far..2 * len)
        } else if !self.independent {
            neighbours.clear();
            neighbours.extend(
                self.sensed
                    .iter()
                    .enumerate()
                    .filter(|&(j, n)| j != i && n.position.distance_squared(p) <= r2)
                    .map(|(_, &n)| n),
            );
            (neighbours.len(), 0..0)
        } else {
            (0, 0..0)
        };
        let (near, far) = (&neighbours[..count], &neighbours[others]);
        // The sensed obstacles, found once for the controller's passes and the barrier's (none
        // to look up in a scene without obstacles, a crowd's).
        let sensed = &mut scratch.obstacles;
        sensed.clear();
        if !self.obstacles.is_empty() {
            sensed.extend(self.sensed_obstacles(me.pose.p));
        }
        // Written in its slot and changed there, not returned: a copy would read the command
        // in one piece right after the barrier wrote it in two, and wait for both writes
        // to reach the cache.
        let e = &mut out.0;
        self.evaluate_facing(me.pose, facing, err, self.speeds[i], near, sensed, e);
        let sensed = sensed.iter().map(|&k| &self.obstacles[k as usize]);
        // The neighbours the barrier can bind on at this speed (the others change nothing).
        // The second run lies beyond the controller's reach: only a robot whose barrier reaches
        // farther reads it (a slow robot's reaches 2.8 m in a crowd, the controller's 8).
        let binding = safety::neighbour_reach(&self.params, e.command.v);
        let binding2 = binding * binding;
        (e.command, out.1) = safety::filter_facing(
            &mut scratch.constraints,
            &self.params,
            self.dt,
            me.pose.p,
            h,
            e.command,
            e.field,
            near.iter()
                .chain(if binding > split { far } else { &[] })
                .map(|n| n.position)
                .filter(|q| q.distance_squared(me.pose.p) <= binding2),
            sensed,
        );
    }

    /// Robot `i`'s `pose.error_to(goal).p`, with its goal's sine and cosine taken once
    /// (`goal_headings`): the same bits.
    #[inline]
    fn error_position(&self, i: usize, me: &Robot) -> DVec2 {
        unrotate_by(self.goal_headings[i], me.pose.p - me.goal.p)
    }

    /// Evaluates the robots `base..` whose slots `run` holds (taken out of the simulation,
    /// which the evaluations read meanwhile), with the buffers of `scratch`. Each evaluation is
    /// written in a buffer of [`STORED_BY`] that stays in the first-level cache, and the
    /// buffer is stored once full: copied to its robot right after it was written, an
    /// evaluation would be read in other pieces than it was written in, and each read across
    /// two writes would wait for both to reach the cache.
    // Not inlined: one copy for one thread and for each chunk on threads, with the evaluation
    // kept out of line.
    #[inline(never)]
    pub(super) fn evaluate_run(&self, base: usize, run: Run<'_>, scratch: &mut Scratch) {
        let (robots, commands, chords, after) = run;
        let mut block = std::mem::take(&mut scratch.evaluated);
        block.resize(STORED_BY, (Evaluation::default(), Motion::default()));
        for start in (0..robots.len()).step_by(STORED_BY) {
            let end = (start + STORED_BY).min(robots.len());
            for ((j, me), slot) in (start..end).zip(&robots[start..end]).zip(&mut block) {
                self.evaluation(base + j, me, scratch, slot);
            }
            for ((((r, command), chord), after), evaluated) in robots[start..end]
                .iter_mut()
                .zip(&mut commands[start..end])
                .zip(&mut chords[start..end])
                .zip(&mut after[start..end])
                .zip(&block)
            {
                put((r, command, chord, after), evaluated);
            }
        }
        scratch.evaluated = block;
    }

    /// The robots' slots that an evaluation writes, taken out of the simulation while the
    /// evaluations read it ([`Self::evaluate_run`]); [`Self::put_slots`] puts them back.
    pub(super) fn take_slots(&mut self) -> Slots {
        Slots {
            robots: std::mem::take(&mut self.robots),
            commands: std::mem::take(&mut self.commands),
            chords: std::mem::take(&mut self.chords),
            after: std::mem::take(&mut self.headings_after),
        }
    }

    /// Puts back the slots [`Self::take_slots`] took.
    pub(super) fn put_slots(&mut self, slots: Slots) {
        self.robots = slots.robots;
        self.commands = slots.commands;
        self.chords = slots.chords;
        self.headings_after = slots.after;
    }

    /// The controller ([`crate::controller::evaluate`]) of a robot at `pose` with error `err`
    /// (to its goal) and speed `speed`, among the obstacles within `R_s` of it and the sensed
    /// `neighbours`: what a step computes for each robot, and what the playground samples as
    /// the field around one. One function for both (through `evaluate_facing`).
    #[inline]
    #[must_use]
    pub fn evaluate_at(
        &self,
        pose: Pose,
        err: Pose,
        speed: f64,
        neighbours: &[Neighbour],
    ) -> Evaluation {
        self.evaluate_at_with(pose, err, speed, neighbours, &mut Vec::new())
    }

    /// [`Self::evaluate_at`] with a buffer for the indices of the obstacles it senses, reused
    /// from call to call by a caller that samples many points (the playground's field view),
    /// so that a call allocates nothing once the buffer has grown.
    #[inline]
    #[must_use]
    pub fn evaluate_at_with(
        &self,
        pose: Pose,
        err: Pose,
        speed: f64,
        neighbours: &[Neighbour],
        obstacles: &mut Vec<u32>,
    ) -> Evaluation {
        obstacles.clear();
        obstacles.extend(self.sensed_obstacles(pose.p));
        let mut e = Evaluation::default();
        self.evaluate_facing(
            pose,
            Facing::of(pose.theta, err.theta),
            err,
            speed,
            neighbours,
            obstacles,
            &mut e,
        );
        e
    }

    /// [`Self::evaluate_at`] with the heading and heading error of `pose` taken by the caller
    /// ([`evaluate_facing`]) and the obstacles it senses found already
    /// ([`Self::sensed_obstacles`]).
    // Not inlined: the step's evaluation keeps its own registers around the controller's
    // (`benches/peer.rs` guards the step's time). The evaluation is written through `out`
    // rather than returned, so that it is read back in the pieces it was written in; that
    // takes an eighth argument.
    #[inline(never)]
    #[allow(clippy::too_many_arguments)]
    fn evaluate_facing(
        &self,
        pose: Pose,
        facing: Facing,
        err: Pose,
        speed: f64,
        neighbours: &[Neighbour],
        sensed: &[u32],
        out: &mut Evaluation,
    ) {
        *out = evaluate_facing(
            &self.params,
            pose,
            facing,
            err,
            speed,
            sensed.iter().map(|&k| &self.obstacles[k as usize]),
            neighbours.iter().copied(),
        );
    }
}

/// A step stores its evaluations this many at a time (`Simulation::evaluate_run`): written in
/// a buffer that stays in the first-level cache, and stored once a few dozen other robots
/// have been evaluated since.
const STORED_BY: usize = 64;

/// The robots' slots that their evaluations write (`Simulation::take_slots`): their states
/// (`last`), commands, chords and headings after the step.
pub(super) struct Slots {
    pub(super) robots: Vec<Robot>,
    pub(super) commands: Vec<Command>,
    pub(super) chords: Vec<DVec2>,
    pub(super) after: Vec<DVec2>,
}

impl Slots {
    /// The slots of all the robots, as one run.
    fn run(&mut self) -> Run<'_> {
        (
            &mut self.robots,
            &mut self.commands,
            &mut self.chords,
            &mut self.after,
        )
    }
}

/// The slots of a run of robots ([`Slots::run`]).
pub(super) type Run<'a> = (
    &'a mut [Robot],
    &'a mut [Command],
    &'a mut [DVec2],
    &'a mut [DVec2],
);

/// Stores a robot's evaluation and the motion of its step in its slots: its state's `last`, its
/// command, its chord and its heading after the step.
#[inline]
fn put(
    (r, command, chord, after): (&mut Robot, &mut Command, &mut DVec2, &mut DVec2),
    &(e, m): &(Evaluation, Motion),
) {
    r.last = e;
    *command = e.command;
    *chord = m.chord;
    *after = m.heading;
}

/// A robot evaluation's buffers, reused from robot to robot: its sensed neighbours and
/// obstacles, the barrier's constraints and a run's evaluations before they are stored; and
/// the smallest squared distance from a robot evaluated with them to a listed robot within
/// the lists' reach (`+∞` for none), for the metrics' closest pair.
#[derive(Clone, Debug, Default)]
pub(super) struct Scratch {
    pub(super) neighbours: Vec<Neighbour>,
    // The robot's sensed obstacles (`Simulation::sensed_obstacles`): found once, read by the
    // controller's passes over them and by the barrier.
    pub(super) obstacles: Vec<u32>,
    pub(super) constraints: safety::Constraints,
    pub(super) closest2: f64,
    // The evaluations of a run before they are stored (`Simulation::evaluate_run`).
    evaluated: Vec<(Evaluation, Motion)>,
}
