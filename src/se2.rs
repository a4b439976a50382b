//! The special Euclidean group SE(2): poses, their composition, and the logarithm map
//! (Section III of the paper, eqs. `eq_confi_matrix`, `eq_Upsi_log_h_def`, `eq_phi_def`).
//!
//! A pose `h = (p, θ)` is the homogeneous matrix `[[R(θ), p], [0, 1]]` of eq. `eq_confi_matrix`.
//! Its logarithm `Υ = log(h) = [[θ̂, φ], [0, 0]]` has the translation part
//! `φ = Ξ(θ) p` (eq. `eq_phi_def`, `eq_phi_def_simp`) with
//! `Ξ(θ) = [[α(θ), θ/2], [−θ/2, α(θ)]]` and `α(θ) = (θ/2)·(1 + cos θ)/sin θ = (θ/2)·cot(θ/2)`.

use glam::DVec2;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Below this |θ| (rad) `α(θ)` is evaluated by its Taylor series: the closed form is 0/0 at
/// θ = 0 and loses digits to cancellation next to it. At 1e-3 the first omitted series term,
/// θ⁶/30240 ≈ 3e-23, is far below one ulp of α ≈ 1.
const ALPHA_SERIES_BELOW: f64 = 1e-3;

/// Wraps an angle to `(−π, π]` (rad).
///
/// `±π` both map to `+π`: the heading range used throughout the crate.
#[inline]
#[must_use]
pub fn wrap_angle(a: f64) -> f64 {
    if a > -PI && a <= PI {
        return a;
    }
    let r = a.rem_euclid(2.0 * PI); // [0, 2π)
    if r > PI {
        r - 2.0 * PI
    } else {
        r
    }
}

/// Unit vector of the heading `θ` (rad), the body X axis expressed in the world frame.
#[inline]
#[must_use]
pub fn heading(theta: f64) -> DVec2 {
    let (s, c) = crate::maths::sin_cos(theta);
    DVec2::new(c, s)
}

/// Rotates `v` by `θ` (rad, counter-clockwise): `R(θ) v` with `R` of eq. `eq_rotation_matrix`.
#[inline]
#[must_use]
pub fn rotate(theta: f64, v: DVec2) -> DVec2 {
    heading(theta).rotate(v)
}

/// Rotates `v` by `−θ`: `R(θ)ᵀ v`, a world vector expressed in a frame of attitude `θ`.
#[inline]
#[must_use]
pub fn unrotate(theta: f64, v: DVec2) -> DVec2 {
    unrotate_by(heading(theta), v)
}

/// [`unrotate`] by the attitude whose [`heading`] is `h`: the same bits, for a caller that
/// rotates by one attitude several times and takes its sine and cosine once.
#[inline]
#[must_use]
pub fn unrotate_by(h: DVec2, v: DVec2) -> DVec2 {
    let (c, s) = (h.x, h.y);
    DVec2::new(c * v.x + s * v.y, -s * v.x + c * v.y)
}

/// `α(θ) = (θ/2)·cot(θ/2)`, the diagonal of `Ξ(θ)` in eq. `eq_Xi_for_phi`.
///
/// Regular on `(−2π, 2π)`, with `α(0) = 1` (the limit the paper takes by L'Hospital's rule in the
/// proof of Theorem 1) and `α(±π) = 0`.
#[inline]
#[must_use]
pub fn alpha(theta: f64) -> f64 {
    if theta.abs() < ALPHA_SERIES_BELOW {
        alpha_series(theta)
    } else {
        let h = 0.5 * theta;
        let (s, c) = crate::maths::sin_cos(h);
        h * c / s
    }
}

/// [`alpha`] from the cosine and sine `turn = (cos θ, sin θ)` of `θ`, which a step has at hand
/// (the robot's heading unrotated by its goal's, [`unrotate_by`]): `cot(θ/2)` is
/// `(1 + cos θ)/sin θ`, or `sin θ/(1 − cos θ)` where `cos θ < 0`, whichever has no
/// cancellation, so that no sine or cosine is taken. Below `ALPHA_SERIES_BELOW` the same series
/// as [`alpha`]. Both have period `2π` in `θ`, so any branch of `θ` gives the value of its own
/// branch. Within a few ulps of [`alpha`] when `turn` is exact; a `turn` off by `δ` moves it by
/// about `δ·|θ|/(2 sin²(θ/2))`, at most `δ/θ` near 0 (`alpha_of_the_turn_is_alpha`).
#[inline]
#[must_use]
pub fn alpha_turned(theta: f64, turn: DVec2) -> f64 {
    let h = 0.5 * theta;
    if theta.abs() < ALPHA_SERIES_BELOW {
        alpha_series(theta)
    } else if turn.x >= 0.0 {
        h * (1.0 + turn.x) / turn.y
    } else {
        h * turn.y / (1.0 - turn.x)
    }
}

/// `α(θ)` by its series, for `|θ|` below `ALPHA_SERIES_BELOW` ([`alpha`], [`alpha_turned`]):
/// `θ/2·cot(θ/2) = 1 − θ²/12 − θ⁴/720 − θ⁶/30240 − …`, whose first omitted term is below
/// 3e-23 there.
#[inline]
fn alpha_series(theta: f64) -> f64 {
    let t2 = theta * theta;
    1.0 - t2 / 12.0 - t2 * t2 / 720.0
}

/// A planar pose: position `p` (world frame) and attitude `θ` (rad, counter-clockwise from
/// the world X axis).
#[derive(Clone, Copy, Debug, PartialEq, Default, Serialize, Deserialize)]
pub struct Pose {
    /// Position in the world frame.
    pub p: DVec2,
    /// Attitude (rad). Not necessarily wrapped; [`Pose::wrapped`] brings it to `(−π, π]`.
    pub theta: f64,
}

impl Pose {
    /// The identity pose (origin, heading along +X).
    pub const IDENTITY: Self = Self {
        p: DVec2::ZERO,
        theta: 0.0,
    };

    /// A pose from its coordinates `(x, y, θ)`.
    #[inline]
    #[must_use]
    pub const fn new(x: f64, y: f64, theta: f64) -> Self {
        Self {
            p: DVec2::new(x, y),
            theta,
        }
    }

    /// The same pose with the attitude wrapped to `(−π, π]`.
    #[inline]
    #[must_use]
    pub fn wrapped(self) -> Self {
        Self {
            p: self.p,
            theta: wrap_angle(self.theta),
        }
    }

    /// `[x, y, θ]`.
    #[inline]
    #[must_use]
    pub fn to_array(self) -> [f64; 3] {
        [self.p.x, self.p.y, self.theta]
    }

    /// Group product `self · other` (matrix product of eq. `eq_confi_matrix`).
    #[inline]
    #[must_use]
    pub fn compose(self, other: Self) -> Self {
        Self {
            p: self.p + rotate(self.theta, other.p),
            theta: wrap_angle(self.theta + other.theta),
        }
    }

    /// Group inverse `h⁻¹ = (−R(θ)ᵀ p, −θ)`.
    #[inline]
    #[must_use]
    pub fn inverse(self) -> Self {
        Self {
            p: -unrotate(self.theta, self.p),
            theta: wrap_angle(-self.theta),
        }
    }

    /// The error pose `h̃ = h_d⁻¹ h` of eq. `eq_tilde_h`, with `self = h` and `goal = h_d`:
    /// `x̃ = (x−x_d)cos θ_d + (y−y_d)sin θ_d`, `ỹ = −(x−x_d)sin θ_d + (y−y_d)cos θ_d`,
    /// `θ̃ = wrap(θ − θ_d)` on the principal branch `(−π, π]`.
    ///
    /// See also [`continue_branch`] for the branch used along a trajectory.
    #[inline]
    #[must_use]
    pub fn error_to(self, goal: Self) -> Self {
        Self {
            p: unrotate(goal.theta, self.p - goal.p),
            theta: wrap_angle(self.theta - goal.theta),
        }
    }
}

/// An element of the Lie algebra se(2): the exponential coordinates `Υ` of a pose
/// (eq. `eq_Upsi_log_h_def`): rotation `θ` and translation part `φ`.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Twist {
    /// `φ = Ξ(θ) p` (eq. `eq_phi_def`).
    pub phi: DVec2,
    /// The rotation angle (rad).
    pub theta: f64,
}

impl Twist {
    /// The Lyapunov function `Φ = ½⟨Υ, Υ⟩` of the proof of Theorem 1 (eq. `eq_dot_Phi_1`), with
    /// the Frobenius inner product of the 3×3 matrices: `⟨Υ, Υ⟩ = |φ|² + 2θ²` (the skew block
    /// holds θ twice).
    #[inline]
    #[must_use]
    pub fn lyapunov(self) -> f64 {
        0.5 * (self.phi.length_squared() + 2.0 * self.theta * self.theta)
    }
}

/// `φ(p, θ) = Ξ(θ) p` (eq. `eq_phi_def`): the translation part of `log(h)` for
/// `h = (p, θ)`. The angle is used as given, so that a caller may evaluate the logarithm on
/// the branch of its choice (any `θ ∈ (−2π, 2π)`); [`log`] uses the principal branch.
/// `α(θ)` comes from the sine and cosine of `θ` ([`alpha_turned`]), as a step takes it.
#[inline]
#[must_use]
pub fn phi(p: DVec2, theta: f64) -> DVec2 {
    phi_turned(p, theta, heading(theta))
}

/// [`phi`] with `α(θ)` taken from the cosine and sine of `θ` ([`alpha_turned`]).
#[inline]
#[must_use]
pub fn phi_turned(p: DVec2, theta: f64, turn: DVec2) -> DVec2 {
    xi(p, theta, alpha_turned(theta, turn))
}

/// `Ξ(θ)·p` with the diagonal `a = α(θ)`.
#[inline]
fn xi(p: DVec2, theta: f64, a: f64) -> DVec2 {
    let h = 0.5 * theta;
    DVec2::new(a * p.x + h * p.y, -h * p.x + a * p.y)
}

/// The logarithm map of SE(2) on the principal branch `θ ∈ (−π, π]` (eq. `eq_Upsi_log_h_def`).
///
/// At `θ = π` the rotation has two logarithms (`±π`); this returns the `+π` one.
#[inline]
#[must_use]
pub fn log(h: Pose) -> Twist {
    let theta = wrap_angle(h.theta);
    Twist {
        phi: phi(h.p, theta),
        theta,
    }
}

/// The exponential map of SE(2), inverse of [`log`]: `p = V(θ) φ` with
/// `V(θ) = (1/θ)[[sin θ, −(1 − cos θ)], [1 − cos θ, sin θ]]`.
#[must_use]
pub fn exp(u: Twist) -> Pose {
    let t = u.theta;
    let (s_over_t, c_over_t) = if t.abs() < ALPHA_SERIES_BELOW {
        // sin t / t and (1 − cos t)/t by their series.
        (1.0 - t * t / 6.0, t / 2.0 - t * t * t / 24.0)
    } else {
        let (s, c) = crate::maths::sin_cos(t);
        (s / t, (1.0 - c) / t)
    };
    let p = DVec2::new(
        s_over_t * u.phi.x - c_over_t * u.phi.y,
        c_over_t * u.phi.x + s_over_t * u.phi.y,
    );
    Pose { p, theta: t }
}

/// How far past `±π` (rad) the heading error may run on its current branch before it is
/// re-wrapped (see [`continue_branch`]).
pub const BRANCH_HYSTERESIS: f64 = PI / 2.0;

/// Continues the heading error `θ̃` along a trajectory.
///
/// The logarithm of a rotation by `±π` is two-valued, and the principal branch jumps from
/// `+π` to `−π` when `θ̃` crosses it: `φ` and with it the field would flip. Instead the error is
/// unwrapped from its previous value `prev` (the change over one step is wrapped, never the
/// error itself) and re-wrapped into `(−π, π]` only once `|θ̃|` exceeds
/// `π + BRANCH_HYSTERESIS`. Every value stays inside `(−2π, 2π)`, where `Ξ(θ̃)` is regular and
/// `log` is a valid (non-principal) logarithm of the same pose, so the proof of Theorem 1 holds
/// on it unchanged.
///
/// `theta` is the robot's attitude and `goal_theta` the goal attitude (rad).
#[inline]
#[must_use]
pub fn continue_branch(prev: f64, theta: f64, goal_theta: f64) -> f64 {
    let principal = wrap_angle(theta - goal_theta);
    let next = prev + wrap_angle(principal - prev);
    if next.abs() > PI + BRANCH_HYSTERESIS {
        principal
    } else {
        next
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::assert_close;
    use crate::testing::test;
    use std::f64::consts::FRAC_PI_2;

    /// 3×3 homogeneous matrix of a pose (eq. `eq_confi_matrix`).
    fn matrix(h: Pose) -> [[f64; 3]; 3] {
        let (s, c) = crate::maths::sin_cos(h.theta);
        [[c, -s, h.p.x], [s, c, h.p.y], [0.0, 0.0, 1.0]]
    }

    fn mul(a: [[f64; 3]; 3], b: [[f64; 3]; 3]) -> [[f64; 3]; 3] {
        let mut m = [[0.0; 3]; 3];
        for (i, row) in m.iter_mut().enumerate() {
            for (j, cell) in row.iter_mut().enumerate() {
                *cell = (0..3).map(|k| a[i][k] * b[k][j]).sum();
            }
        }
        m
    }

    /// Matrix exponential by scaling and squaring with a Taylor series: an evaluation of
    /// `exp` that shares no code with the closed forms above.
    fn expm(u: Twist) -> [[f64; 3]; 3] {
        let a = [
            [0.0, -u.theta, u.phi.x],
            [u.theta, 0.0, u.phi.y],
            [0.0, 0.0, 0.0],
        ];
        let scale = 2f64.powi(10);
        let a: Vec<Vec<f64>> = a
            .iter()
            .map(|r| r.iter().map(|x| x / scale).collect())
            .collect();
        let a = [
            [a[0][0], a[0][1], a[0][2]],
            [a[1][0], a[1][1], a[1][2]],
            [a[2][0], a[2][1], a[2][2]],
        ];
        let mut term = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        let mut sum = term;
        for k in 1..20 {
            term = mul(term, a);
            for row in term.iter_mut() {
                for x in row.iter_mut() {
                    *x /= k as f64;
                }
            }
            for i in 0..3 {
                for j in 0..3 {
                    sum[i][j] += term[i][j];
                }
            }
        }
        for _ in 0..10 {
            sum = mul(sum, sum);
        }
        sum
    }

    #[test]
    fn wrap_angle_range() {
        for k in -50..=50 {
            let a = k as f64 * 0.37;
            let w = wrap_angle(a);
            assert!(w > -PI && w <= PI, "{a} -> {w}");
            let turns = (a - w) / (2.0 * PI);
            assert_close!(turns, turns.round(), 1e-12);
        }
        assert_eq!(wrap_angle(-PI), PI);
        assert_eq!(wrap_angle(PI), PI);
    }

    #[test]
    fn alpha_is_continuous_at_the_series_switch() {
        // Both sides of the switch agree to a few ulps: the series is exact there.
        let below = alpha(ALPHA_SERIES_BELOW * (1.0 - 1e-12));
        let above = alpha(ALPHA_SERIES_BELOW * (1.0 + 1e-12));
        assert_close!(below, above, 1e-14);
        assert_eq!(alpha(0.0), 1.0);
        assert_close!(alpha(PI), 0.0, 1e-15);
        // Against the paper's form (θ/2)(1+cos θ)/sin θ away from the singular points.
        for t in [0.01, 0.3, 1.0, 2.0, 3.0, -2.5] {
            let paper = t / 2.0 * (1.0 + f64::cos(t)) / f64::sin(t);
            assert_close!(alpha(t), paper, 1e-12);
        }
    }

    /// `α` from the cosine and sine of `θ` against `α(θ)` over the branches a continued heading
    /// error takes (`|θ| ≤ π + BRANCH_HYSTERESIS`), with the turn as a step has it (the
    /// library's cosine and sine, rounded) and at the points where one form of the cotangent
    /// would be 0/0 (`±π`) or switches (`±π/2`, the series' bound). Within 1e-14 of `max(1, |α|)`:
    /// a few ulps of the quotient, and of the rounded cosine and sine over `sin θ` ≥ 1e-3 where
    /// the series stops.
    #[test]
    fn alpha_of_the_turn_is_alpha() {
        let mut rng = crate::testing::XorShift(0x0A1F_A0F7_0123_4567);
        let bound = PI + BRANCH_HYSTERESIS;
        let mut thetas = vec![0.0, PI, -PI, FRAC_PI_2, -FRAC_PI_2, bound, -bound];
        for t in [ALPHA_SERIES_BELOW, -ALPHA_SERIES_BELOW] {
            thetas.extend([t * (1.0 - 1e-12), t, t * (1.0 + 1e-12)]);
        }
        thetas.extend((0..20_000).map(|_| (2.0 * rng.unit() - 1.0) * bound));
        for t in thetas {
            let (a, b) = (alpha_turned(t, heading(t)), alpha(t));
            assert_close!(a, b, 1e-14 * b.abs().max(1.0));
        }
    }

    #[test]
    fn compose_inverse_is_identity() {
        let h = Pose::new(3.0, -2.0, 2.5);
        let e = h.compose(h.inverse());
        assert_close!(e.p.length(), 0.0, 1e-12);
        assert_close!(e.theta, 0.0, 1e-12);
        // The error pose is h_d⁻¹ h.
        let g = Pose::new(-1.0, 4.0, -1.2);
        let a = h.error_to(g);
        let b = g.inverse().compose(h);
        assert_close!(a.p.distance(b.p), 0.0, 1e-12);
        assert_close!(a.theta, b.theta, 1e-12);
    }

    /// The log map against the matrix logarithm: `expm(log(h)) = h` with an independent
    /// matrix exponential. Tolerance 1e-9: the series sums 20 terms of a matrix scaled by
    /// 2⁻¹⁰ and squares 10 times, each losing a few ulps relative to |p| ≤ 50.
    #[test]
    fn log_inverts_matrix_exponential() {
        for &(x, y, t) in &[
            (1.0, 2.0, 0.5),
            (-30.0, 40.0, -2.9),
            (10.0, 0.0, 1e-7),
            (0.0, -5.0, 0.0),
            (7.0, 3.0, PI),
            (7.0, 3.0, -PI + 1e-9),
        ] {
            let h = Pose::new(x, y, t);
            let m = expm(log(h));
            let want = matrix(h);
            for i in 0..2 {
                for j in 0..3 {
                    assert_close!(m[i][j], want[i][j], 1e-9);
                }
            }
            // And the closed-form exp round-trips.
            let back = exp(log(h));
            assert_close!(back.p.distance(h.p), 0.0, 1e-9);
        }
    }

    /// φ → 0 iff p → 0 (proof of Theorem 1): det Ξ = α² + θ²/4 > 0 on (−2π, 2π), so
    /// |φ| is bounded below by a positive multiple of |p|.
    #[test]
    fn phi_vanishes_only_at_the_origin() {
        for k in -40..=40 {
            let t = k as f64 * 0.15; // covers (−2π, 2π) minus the endpoints
            let det = alpha(t).powi(2) + t * t / 4.0;
            assert!(det > 0.3, "det Ξ({t}) = {det}");
            for &(x, y) in &[(1.0, 0.0), (0.0, 1.0), (-0.6, 0.8)] {
                let p = DVec2::new(x, y);
                let f = phi(p, t);
                // |Ξ p|² = det Ξ · |p|² because Ξ is a scaled rotation.
                assert_close!(f.length_squared(), det, 1e-12);
            }
        }
        assert_eq!(phi(DVec2::ZERO, 2.0), DVec2::ZERO);
    }

    #[test]
    fn branch_continues_through_pi() {
        // θ̃ sweeping from 3 to 3.5 rad crosses +π: the continued error does not jump.
        let goal = 0.0;
        let mut e = wrap_angle(3.0 - goal);
        let mut prev_phi = phi(DVec2::new(1.0, 1.0), e);
        for k in 1..=50 {
            let theta = wrap_angle(3.0 + 0.01 * k as f64);
            e = continue_branch(e, theta, goal);
            assert_close!(e, 3.0 + 0.01 * k as f64, 1e-12);
            let f = phi(DVec2::new(1.0, 1.0), e);
            assert!(f.distance(prev_phi) < 0.02, "φ jumped at step {k}");
            prev_phi = f;
        }
        // Past π + hysteresis it falls back to the principal branch.
        let far = continue_branch(PI + BRANCH_HYSTERESIS - 0.01, -PI / 2.0 + 0.1, 0.0);
        assert_close!(far, -PI / 2.0 + 0.1, 1e-12);
    }

    #[test]
    fn lyapunov_of_identity_is_zero() {
        assert_eq!(log(Pose::IDENTITY).lyapunov(), 0.0);
    }
}
