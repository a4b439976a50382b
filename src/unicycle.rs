//! The unicycle (eq. `eq_kine_nonho`): `ṗ = v·(cos θ, sin θ)`, `θ̇ = ω`, integrated in closed
//! form over one step of a held command. Every planner that drives unicycles shares it: the
//! simulation moves robots with [`integrate`], and the safety barrier bounds the chord of the
//! next step ([`chord`]).
//!
//! Integration is exact for the zero-order hold a digital controller implies: `(v, ω)` is held
//! over the step, and the unicycle follows an arc of a circle (a segment when `ω = 0`), so
//! there is no integration error to tune away.

use crate::controller::Command;
use crate::se2::{heading, wrap_angle, Pose};
use glam::DVec2;

/// Below this `|ω·dt|` the arc's `sin(x)/x` is taken from its series.
const SINC_SERIES_BELOW: f64 = 1e-4;

/// The chord of one step: holding `(v, ω)` for `dt` from heading `theta` moves a unicycle by
/// `v·dt·chord(theta, ω, dt)`, that is `v·dt·sinc(ω·dt/2)` along the mean heading
/// `θ + ω·dt/2` (eq. `eq_kine_nonho` integrated in closed form over an arc).
#[inline]
#[must_use]
pub fn chord(theta: f64, omega: f64, dt: f64) -> DVec2 {
    let half = 0.5 * omega * dt;
    let sinc = if half.abs() < SINC_SERIES_BELOW {
        1.0 - half * half / 6.0
    } else {
        half.sin() / half
    };
    sinc * heading(theta + half)
}

/// Exact pose after holding `c` for `dt` from `pose` (see [`chord`]).
#[inline]
#[must_use]
pub fn integrate(pose: Pose, c: Command, dt: f64) -> Pose {
    integrate_along(pose, c, dt, chord(pose.theta, c.omega, dt))
}

/// [`integrate`] with its chord `chord(pose.theta, c.omega, dt)` computed already (the safety
/// barrier computes it to clamp the speed): the same bits.
#[inline]
#[must_use]
pub fn integrate_along(pose: Pose, c: Command, dt: f64, chord: DVec2) -> Pose {
    Pose {
        p: pose.p + c.v * dt * chord,
        theta: wrap_angle(pose.theta + c.omega * dt),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{assert_close, test};

    /// Closed-form integration against a fine Euler integration of the same held command.
    #[test]
    fn integration_is_exact_for_a_held_command() {
        let start = Pose::new(1.0, 2.0, 0.4);
        for c in [
            Command { v: 3.0, omega: 2.0 },
            Command {
                v: -1.0,
                omega: -0.5,
            },
            Command { v: 2.0, omega: 0.0 },
            Command {
                v: 2.0,
                omega: 1e-9,
            },
        ] {
            let exact = integrate(start, c, 0.5);
            let mut h = start;
            let n = 200_000;
            for _ in 0..n {
                let dt = 0.5 / n as f64;
                h.p += c.v * dt * heading(h.theta + 0.5 * c.omega * dt);
                h.theta += c.omega * dt;
            }
            // The reference sums 2e5 increments: its round-off alone reaches ~1e-11, so the
            // closed form is checked to 1e-9 in position and 1e-10 rad in heading.
            assert_close!(exact.p.distance(h.p), 0.0, 1e-9);
            assert_close!(wrap_angle(exact.theta - h.theta), 0.0, 1e-10);
        }
    }

    #[test]
    fn chord_is_the_step_of_the_arc() {
        for (theta, omega) in [(0.3, 0.0), (-2.0, 7.0), (3.0, -40.0)] {
            let pose = Pose::new(1.0, -2.0, theta);
            let next = integrate(pose, Command { v: 3.0, omega }, 0.05);
            let step = 3.0 * 0.05 * chord(theta, omega, 0.05);
            // Both are closed forms of the same arc: round-off only.
            assert_close!((next.p - pose.p - step).length(), 0.0, 1e-14);
        }
    }
}
