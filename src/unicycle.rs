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

/// Below this half turn `|ω·dt/2|` (rad) its sine and cosine come from their Taylor series
/// ([`half_turn`]): a step's turn is small, and the series costs a few multiplications where
/// the library's sine and cosine cost a call each and an argument reduction.
const SERIES_BELOW: f64 = 0.125;

/// `(sin x / x, cos x)` of the half turn `x` of a step. Below [`SERIES_BELOW`] from the Taylor
/// series, whose first omitted terms, `x¹⁰/39916800` and `x¹²/479001600`, are below 2.4e-17
/// and 3e-20 there: a fifth of an ulp of 1 and less, so both are within the round-off of the
/// library's (an ulp or two, `half_turn_is_the_sine_and_cosine`).
#[inline]
#[must_use]
fn half_turn(x: f64) -> (f64, f64) {
    if x.abs() < SERIES_BELOW {
        let x2 = x * x;
        // sinc x = 1 − x²/3! + x⁴/5! − x⁶/7! + x⁸/9!, and
        // cos x = 1 − x²/2! + x⁴/4! − x⁶/6! + x⁸/8! − x¹⁰/10!, in Horner's form with the
        // coefficients as constants (a product, where `x²/9!` would be a division).
        let sinc = 1.0
            + x2 * (-1.0 / 6.0
                + x2 * (1.0 / 120.0 + x2 * (-1.0 / 5040.0 + x2 * (1.0 / 362_880.0))));
        let cos = 1.0
            + x2 * (-0.5
                + x2 * (1.0 / 24.0
                    + x2 * (-1.0 / 720.0 + x2 * (1.0 / 40_320.0 + x2 * (-1.0 / 3_628_800.0)))));
        (sinc, cos)
    } else {
        let (s, c) = crate::maths::sin_cos(x);
        (s / x, c)
    }
}

/// The chord of one step: holding `(v, ω)` for `dt` from heading `theta` moves a unicycle by
/// `v·dt·chord(theta, ω, dt)`, that is `v·dt·sinc(ω·dt/2)` along the mean heading
/// `θ + ω·dt/2` (eq. `eq_kine_nonho` integrated in closed form over an arc).
#[inline]
#[must_use]
pub fn chord(theta: f64, omega: f64, dt: f64) -> DVec2 {
    chord_from(heading(theta), omega, dt)
}

/// [`chord`] from the heading `h = (cos θ, sin θ)` ([`heading`]) a caller has taken already:
/// the mean heading is `h` turned by the half turn `ω·dt/2`, whose sine and cosine come from
/// their Taylor series while it is small (below 0.125 rad, within 2 ulps of the library's),
/// so that a step takes no sine or cosine of its own.
#[inline]
#[must_use]
pub fn chord_from(h: DVec2, omega: f64, dt: f64) -> DVec2 {
    motion(h, omega, dt).chord
}

/// What holding a turn rate `ω` for `dt` does to a unicycle with heading `h`
/// ([`motion`]): the chord of its arc ([`chord_from`]) and its heading at the end
/// ([`turned`]).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Motion {
    /// The chord per unit of `v·dt`.
    pub chord: DVec2,
    /// The heading after the step, `(cos, sin)(θ + ω·dt)`.
    pub heading: DVec2,
}

/// [`chord_from`] and [`turned`] with one half turn: the mean heading `m` is `h` turned by the
/// half turn, the chord is `sinc(ω·dt/2)·m` and the heading after the step is `m` turned by
/// the half turn again. The same bits as the two functions (each is this one's field): the
/// barrier takes the chord, and a step keeps the heading with it, so that the step's
/// integration need not take the half turn's series again.
#[inline]
#[must_use]
pub fn motion(h: DVec2, omega: f64, dt: f64) -> Motion {
    let half = 0.5 * omega * dt;
    let (sinc, cos) = half_turn(half);
    let r = DVec2::new(cos, sinc * half);
    let mean = r.rotate(h);
    Motion {
        chord: sinc * mean,
        heading: r.rotate(mean),
    }
}

/// The heading `h = (cos θ, sin θ)` ([`heading`]) after a step's turn `ω·dt`: `h` rotated
/// twice by the half turn, whose sine and cosine [`chord_from`] takes too (from their series
/// while it is small), so that a simulation keeps each robot's heading from step to step
/// without a sine or cosine. Each step rounds it by an ulp or two, in length and in angle:
/// after 10⁶ steps of the same turn, within 1e-9 of `heading(θ)` of the integrated `θ`
/// (`turned_heading_stays_the_heading`), far below anything the controller or the barrier
/// resolves.
#[inline]
#[must_use]
pub fn turned(h: DVec2, omega: f64, dt: f64) -> DVec2 {
    motion(h, omega, dt).heading
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

    /// The series against the library's sine and cosine, on both sides of the switch and at
    /// random half turns below it: within 2 ulps (the library is correctly rounded to within
    /// an ulp, and the series' Horner sums round a few times, each below an ulp of 1).
    #[test]
    fn half_turn_is_the_sine_and_cosine() {
        let mut rng = crate::testing::XorShift(0x5DEE_CE66_D1CE_4E5B);
        let below = SERIES_BELOW * (1.0 - 1e-15);
        let mut xs = vec![0.0, 1e-9, -1e-5, below, -below, SERIES_BELOW, 0.3, -2.0];
        xs.extend((0..10_000).map(|_| (rng.unit() * 2.0 - 1.0) * SERIES_BELOW));
        for x in xs {
            let (sinc, cos) = half_turn(x);
            let sinc_lib = if x == 0.0 { 1.0 } else { x.sin() / x };
            assert_close!(sinc, sinc_lib, 2.0 * f64::EPSILON);
            assert_close!(cos, x.cos(), 2.0 * f64::EPSILON);
        }
    }

    /// A heading kept by [`turned`] against the heading of the integrated attitude, over 10⁶
    /// steps of a steady turn (whose rounding, the same at every step, adds up) and of turns
    /// drawn at random, on both sides of the series' bound: within 1e-9, as its doc says.
    #[test]
    fn turned_heading_stays_the_heading() {
        let dt = 0.01;
        let mut rng = crate::testing::XorShift(0x7E57_0F7E_AD1E_0001);
        for omega in [3.0, -30.0, 0.0, f64::NAN] {
            let (mut theta, mut h) = (0.4, heading(0.4));
            for _ in 0..1_000_000 {
                // NaN: a turn drawn at random, up to 60 rad/s (a half turn of 0.3 rad).
                let w = if omega.is_nan() {
                    (2.0 * rng.unit() - 1.0) * 60.0
                } else {
                    omega
                };
                h = turned(h, w, dt);
                theta = wrap_angle(theta + w * dt);
            }
            assert_close!(h.distance(heading(theta)), 0.0, 1e-9);
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
