//! The dynamic vector field `Γ̃_d` towards a goal pose (Section III, eqs. `eq_DVF`,
//! `eq_DVF_arbitr`, `eq_DVF_in_Fb`).
//!
//! For a goal `h_d` and the error pose `h̃ = h_d⁻¹ h`, the fully actuated closed loop of the
//! proof of Theorem 1 is the body twist `η = −Υ̃`: body velocity `−φ̃`, angular velocity `−θ̃`.
//! This module therefore defines the field in the *body* frame as `Γ̃_dᴮ = −φ̃` and in the
//! world frame as `Γ̃_d = R(θ)(−φ̃)`, with `θ` the robot's attitude.
//!
//! Eq. `eq_DVF_arbitr` literally reads `−R(θ̃)φ̃`: that is the same velocity expressed in the
//! *goal* frame, equal to the world-frame field only when `θ_d = 0` (see
//! docs/notes-on-the-paper.md). [`goal_frame_field`] evaluates it as written, for comparison.
//!
//! The field is "dynamic" because it depends on the attitude: the same point has different
//! arrows for different `θ`.

use crate::se2::{phi, rotate, Pose};
use glam::DVec2;

/// `Γ̃_dᴮ = −φ(x̃, ỹ, θ̃)`: the field in the robot's body frame for the error pose `err`
/// (`err.theta` on the branch chosen by the caller, see [`crate::se2::continue_branch`]).
///
/// Components: `x` along the heading, `y` to the robot's left. Units: length per unit time
/// at unit gain.
#[inline]
#[must_use]
pub fn goal_field_body(err: Pose) -> DVec2 {
    -phi(err.p, err.theta)
}

/// [`goal_field_body`] with the cosine and sine of the heading error, `turn`
/// = `(cos θ̃, sin θ̃)`, at hand ([`crate::se2::phi_turned`]): a step's, without a sine or cosine.
#[inline]
#[must_use]
pub fn goal_field_body_turned(err: Pose, turn: DVec2) -> DVec2 {
    -crate::se2::phi_turned(err.p, err.theta, turn)
}

/// `Γ̃_d = R(θ)Γ̃_dᴮ`: the field in the world frame for a robot of attitude `theta` (rad) with
/// error pose `err` (eq. `eq_DVF_in_Fb` read backwards).
#[inline]
#[must_use]
pub fn goal_field_world(theta: f64, err: Pose) -> DVec2 {
    rotate(theta, goal_field_body(err))
}

/// The field of a robot at `pose` towards `goal`, in the world frame, with the heading error on
/// the principal branch. This is what `dvf field` samples.
#[inline]
#[must_use]
pub fn goal_field_at(pose: Pose, goal: Pose) -> DVec2 {
    goal_field_world(pose.theta, pose.error_to(goal))
}

/// Eq. `eq_DVF_arbitr` as printed: `−R(θ̃)φ̃`, the field expressed in the goal frame.
/// It coincides with [`goal_field_at`] only for goals with `θ_d = 0`; it is kept to show, and
/// test, why the crate does not use it as a world-frame field.
#[inline]
#[must_use]
pub fn goal_frame_field(pose: Pose, goal: Pose) -> DVec2 {
    let err = pose.error_to(goal);
    rotate(err.theta, goal_field_body(err))
}

/// Samples the world-frame field of `goal` at attitude `theta` (rad) on an `n × n` grid
/// spanning `bounds = [xmin, ymin, xmax, ymax]`, corners included, row by row from `ymin`.
/// Each sample is `[x, y, Γx, Γy]`. `n ≥ 2`.
#[must_use]
pub fn sample_grid(goal: Pose, theta: f64, bounds: [f64; 4], n: usize) -> Vec<[f64; 4]> {
    let [x0, y0, x1, y1] = bounds;
    let last = (n.max(2) - 1) as f64;
    let mut out = Vec::with_capacity(n * n);
    for j in 0..n {
        let y = y0 + (y1 - y0) * j as f64 / last;
        for i in 0..n {
            let x = x0 + (x1 - x0) * i as f64 / last;
            let g = goal_field_at(Pose::new(x, y, theta), goal);
            out.push([x, y, g.x, g.y]);
        }
    }
    out
}

/// One integral curve of the dynamic field from `start`, the way the paper draws Fig. 1:
/// the point follows `ṗ = Γ̃_d(p, θ)` while the attitude parameter follows `θ̇ = −θ̃`
/// (eq. `eq_dot_theta_minus_theta`, relative to the goal). RK4 with step `dt` for `steps`
/// steps; returns the visited points including `start`.
#[must_use]
pub fn integral_curve(start: Pose, goal: Pose, dt: f64, steps: usize) -> Vec<DVec2> {
    // State (p, θ̃) with θ̃ integrated unwrapped: θ̃(t) = θ̃(0)e^{−t} never crosses ±π.
    let f = |p: DVec2, e: f64| -> (DVec2, f64) {
        let theta = goal.theta + e;
        let err = Pose {
            p: crate::se2::unrotate(goal.theta, p - goal.p),
            theta: e,
        };
        (goal_field_world(theta, err), -e)
    };
    let mut p = start.p;
    let mut e = crate::se2::wrap_angle(start.theta - goal.theta);
    let mut out = Vec::with_capacity(steps + 1);
    out.push(p);
    for _ in 0..steps {
        let (k1p, k1e) = f(p, e);
        let (k2p, k2e) = f(p + 0.5 * dt * k1p, e + 0.5 * dt * k1e);
        let (k3p, k3e) = f(p + 0.5 * dt * k2p, e + 0.5 * dt * k2e);
        let (k4p, k4e) = f(p + dt * k3p, e + dt * k3e);
        p += dt / 6.0 * (k1p + 2.0 * k2p + 2.0 * k3p + k4p);
        e += dt / 6.0 * (k1e + 2.0 * k2e + 2.0 * k3e + k4e);
        out.push(p);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::assert_close;
    use crate::testing::test;
    use std::f64::consts::{FRAC_PI_2, PI};

    #[test]
    fn field_vanishes_exactly_at_the_goal_position() {
        let goal = Pose::new(3.0, -4.0, 1.0);
        for t in [-3.0, -1.0, 0.0, 0.5, PI] {
            assert_eq!(goal_field_at(Pose::new(3.0, -4.0, t), goal).length(), 0.0);
        }
        assert!(goal_field_at(Pose::new(3.1, -4.0, 1.0), goal).length() > 0.0);
    }

    /// With the attitude at the goal's (θ̃ = 0), φ̃ = p̃ and the field points straight at the goal.
    #[test]
    fn aligned_attitude_points_at_the_goal() {
        let goal = Pose::new(10.0, 5.0, 0.7);
        let pose = Pose::new(-2.0, 1.0, 0.7);
        let g = goal_field_at(pose, goal);
        let to_goal = goal.p - pose.p;
        assert_close!(g.perp_dot(to_goal), 0.0, 1e-9);
        assert!(g.dot(to_goal) > 0.0);
        assert_close!(g.length(), to_goal.length(), 1e-9);
    }

    /// The literal eq. (DVF_arbitr) equals the world field for θ_d = 0 and differs for
    /// θ_d = π/2 by exactly the goal rotation (docs/notes-on-the-paper.md §1).
    #[test]
    fn literal_goal_frame_field_is_rotated_by_the_goal_attitude() {
        let pose = Pose::new(1.0, 2.0, 0.3);
        let g0 = Pose::new(40.0, 0.0, 0.0);
        assert_close!(
            goal_frame_field(pose, g0).distance(goal_field_at(pose, g0)),
            0.0,
            1e-12
        );
        let g1 = Pose::new(40.0, 40.0, FRAC_PI_2);
        let world = goal_field_at(pose, g1);
        let literal = goal_frame_field(pose, g1);
        assert!(world.distance(literal) > 1.0);
        assert_close!(rotate(g1.theta, literal).distance(world), 0.0, 1e-9);
    }

    /// The field's integral curves converge to the goal position (Theorem 2): the fully
    /// actuated point with θ̇ = −θ̃ decays like e^{−t}, so after 20 time units the distance has
    /// shrunk by e^{−20} ≈ 2e-9 (tolerance 1e-6 of a 50-unit start).
    #[test]
    fn integral_curves_converge() {
        let goal = Pose::new(5.0, -3.0, -2.0);
        for start in [
            Pose::new(-40.0, 20.0, FRAC_PI_2),
            Pose::new(30.0, 30.0, -FRAC_PI_2),
            Pose::new(0.0, 0.0, PI),
        ] {
            let curve = integral_curve(start, goal, 0.01, 2000);
            let end = *curve.last().unwrap();
            assert_close!(end.distance(goal.p), 0.0, 1e-6);
        }
    }

    #[test]
    fn grid_spans_the_bounds_corners_included() {
        let s = sample_grid(Pose::IDENTITY, 0.0, [-1.0, -2.0, 3.0, 4.0], 5);
        assert_eq!(s.len(), 25);
        assert_eq!([s[0][0], s[0][1]], [-1.0, -2.0]);
        assert_eq!([s[24][0], s[24][1]], [3.0, 4.0]);
        assert_eq!([s[4][0], s[4][1]], [3.0, -2.0]);
    }
}
