//! How smooth the commands are: whether a real robot could follow them. A controller that
//! chatters (ω flipping sign from one step to the next) shows here even when every robot
//! arrives and nothing collides.
//!
//! Per robot, over the run and from the time it first reached its goal position
//! (`tol_position`): the *reversals*, sign changes of ω counted among the commands with
//! `|ω| > REVERSAL_OMEGA` (a turn one way, then the other), and the largest change of ω from
//! one step to the next. [`Smoothness`] sums them over robots (a run, a sweep).

use serde::{Deserialize, Serialize};

/// A command turns when `|ω|` exceeds this (rad/s); smaller turn rates are not counted as
/// reversals, so that a robot that holds its heading with tiny corrections does not count.
pub const REVERSAL_OMEGA: f64 = 1.0;

/// A robot chatters when it reverses its turn more often than this (per simulated second)
/// after it reached its goal position, averaged over that time (at least one second).
pub const CHATTER_RATE: f64 = 1.0;

/// One robot's commands, tallied step by step ([`Tally::observe`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Tally {
    /// Reversals over the run.
    pub reversals: u64,
    /// Reversals since the robot first reached its goal position.
    pub settled_reversals: u64,
    /// Commands observed since it first reached its goal position (each held for one step).
    pub settled_steps: u64,
    /// Largest `|ω_k − ω_{k−1}|` over the run (rad/s).
    pub max_omega_step: f64,
    /// Largest `|ω_k − ω_{k−1}|` since it first reached its goal position (rad/s).
    pub settled_max_omega_step: f64,
    #[serde(skip)]
    last_omega: Option<f64>,
    // The sign of the last command with |ω| > REVERSAL_OMEGA (0: none yet).
    #[serde(skip)]
    last_sign: f64,
}

impl Tally {
    /// Takes the next command's `omega`; `settled` says whether the robot has reached its goal
    /// position by now (once true, true for the rest of the run).
    pub fn observe(&mut self, omega: f64, settled: bool) {
        let step = self.last_omega.map_or(0.0, |w| (omega - w).abs());
        self.last_omega = Some(omega);
        self.max_omega_step = self.max_omega_step.max(step);
        let sign = if omega.abs() > REVERSAL_OMEGA {
            omega.signum()
        } else {
            0.0
        };
        let reversal = sign != 0.0 && self.last_sign == -sign;
        if sign != 0.0 {
            self.last_sign = sign;
        }
        self.reversals += u64::from(reversal);
        if settled {
            self.settled_steps += 1;
            self.settled_reversals += u64::from(reversal);
            self.settled_max_omega_step = self.settled_max_omega_step.max(step);
        }
    }

    /// Whether the robot chatters after it reached its goal position ([`CHATTER_RATE`]), with
    /// steps of `dt` seconds.
    #[must_use]
    pub fn chatters(&self, dt: f64) -> bool {
        let seconds = (self.settled_steps as f64 * dt).max(1.0);
        self.settled_reversals as f64 > CHATTER_RATE * seconds
    }
}

/// The smoothness of many robots' commands (a run's, a sweep's).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Smoothness {
    /// Reversals per simulated second over all robots and the whole run.
    pub reversals_per_s: f64,
    /// Reversals per simulated second after the robots reached their goal positions.
    pub settled_reversals_per_s: f64,
    /// Robots that chatter after reaching their goal position ([`Tally::chatters`]).
    pub chattering_robots: usize,
    /// Largest `|Δω|` of one step over all robots and the whole run (rad/s).
    pub max_omega_step: f64,
    /// Largest `|Δω|` of one step after a robot reached its goal position (rad/s).
    pub settled_max_omega_step: f64,
}

impl Smoothness {
    /// The figures of `tallies`, each over `steps` commands of `dt` seconds.
    #[must_use]
    pub fn of<'a>(tallies: impl IntoIterator<Item = &'a Tally>, steps: u64, dt: f64) -> Self {
        let mut sum = Sums::default();
        for t in tallies {
            sum.add(t, steps, dt);
        }
        sum.smoothness(dt)
    }
}

/// Integer sums of tallies and the largest steps: what [`Smoothness`] is computed from, in
/// the same arithmetic however the tallies were grouped (a line of `dvf sweep --shard`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Sums {
    /// Sum of [`Tally::reversals`].
    pub reversals: u64,
    /// Sum of the robots' steps.
    pub steps: u64,
    /// Sum of [`Tally::settled_reversals`].
    pub settled_reversals: u64,
    /// Sum of [`Tally::settled_steps`].
    pub settled_steps: u64,
    /// Robots that chatter.
    pub chattering: usize,
    /// Largest [`Tally::max_omega_step`].
    pub max_omega_step: f64,
    /// Largest [`Tally::settled_max_omega_step`].
    pub settled_max_omega_step: f64,
}

impl Sums {
    /// Adds a robot's tally of a run of `steps` steps of `dt`.
    pub fn add(&mut self, t: &Tally, steps: u64, dt: f64) {
        self.reversals += t.reversals;
        self.steps += steps;
        self.settled_reversals += t.settled_reversals;
        self.settled_steps += t.settled_steps;
        self.chattering += usize::from(t.chatters(dt));
        self.max_omega_step = self.max_omega_step.max(t.max_omega_step);
        self.settled_max_omega_step = self.settled_max_omega_step.max(t.settled_max_omega_step);
    }

    /// Adds other sums.
    pub fn merge(&mut self, o: &Self) {
        self.reversals += o.reversals;
        self.steps += o.steps;
        self.settled_reversals += o.settled_reversals;
        self.settled_steps += o.settled_steps;
        self.chattering += o.chattering;
        self.max_omega_step = self.max_omega_step.max(o.max_omega_step);
        self.settled_max_omega_step = self.settled_max_omega_step.max(o.settled_max_omega_step);
    }

    /// The figures, with steps of `dt` seconds.
    #[must_use]
    pub fn smoothness(&self, dt: f64) -> Smoothness {
        let rate = |n: u64, steps: u64| {
            if steps == 0 {
                0.0
            } else {
                n as f64 / (steps as f64 * dt)
            }
        };
        Smoothness {
            reversals_per_s: rate(self.reversals, self.steps),
            settled_reversals_per_s: rate(self.settled_reversals, self.settled_steps),
            chattering_robots: self.chattering,
            max_omega_step: self.max_omega_step,
            settled_max_omega_step: self.settled_max_omega_step,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::test;

    /// A constructed sequence: a turn left, small corrections of both signs (not counted),
    /// a turn right (one reversal), arrival, then chattering +8/−22 rad/s (every step a
    /// reversal). Counts are exact integers; the steps are differences of numbers exactly
    /// representable in binary, so they are compared exactly too.
    #[test]
    fn reversals_and_steps_of_a_constructed_sequence() {
        let mut t = Tally::default();
        for w in [0.0, 3.0, 0.5, -0.5, 0.25, -2.0] {
            t.observe(w, false);
        }
        assert_eq!(t.reversals, 1);
        assert_eq!(t.settled_reversals, 0);
        assert_eq!(t.max_omega_step, 3.0);
        assert_eq!(t.settled_steps, 0);
        // Arrived: the first settled command is −2 again (no reversal, no step).
        t.observe(-2.0, true);
        for k in 0..100 {
            t.observe(if k % 2 == 0 { 8.0 } else { -22.0 }, true);
        }
        // 100 sign changes after arrival, all counted: −2 → 8 is the first.
        assert_eq!(t.settled_reversals, 100);
        assert_eq!(t.reversals, 101);
        assert_eq!(t.settled_steps, 101);
        assert_eq!(t.settled_max_omega_step, 30.0);
        assert_eq!(t.max_omega_step, 30.0);
        // 100 reversals in 1.01 s at dt = 0.01: chattering.
        assert!(t.chatters(0.01));
        let s = Smoothness::of([&t], 107, 0.01);
        // Rates: 101 / 1.07 s and 100 / 1.01 s, to the round-off of one division.
        assert!((s.reversals_per_s - 101.0 / 1.07).abs() < 1e-9);
        assert!((s.settled_reversals_per_s - 100.0 / 1.01).abs() < 1e-9);
        assert_eq!(s.chattering_robots, 1);
    }

    /// A robot that turns once after arriving (its small loop) does not chatter; sums
    /// grouped differently give the same figures.
    #[test]
    fn one_loop_is_no_chatter_and_sums_merge() {
        let mut calm = Tally::default();
        for k in 0..500 {
            calm.observe(if k < 250 { 2.0 } else { -1.5 }, k >= 100);
        }
        assert_eq!(calm.settled_reversals, 1);
        assert!(!calm.chatters(0.01));
        let mut other = Tally::default();
        other.observe(5.0, true);
        let mut a = Sums::default();
        a.add(&calm, 500, 0.01);
        let mut b = Sums::default();
        b.add(&other, 500, 0.01);
        let mut merged = a;
        merged.merge(&b);
        assert_eq!(
            merged.smoothness(0.01),
            Smoothness::of([&calm, &other], 500, 0.01)
        );
    }
}
