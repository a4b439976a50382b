//! Circular obstacles and their avoidance field (Section IV, eqs. `eq_Gamma_r_ob_avoid`,
//! `eq_Gamma_r_perp_ob_avoid`, `eq_ob_avoid_VF`, `eq_switch_func`, `eq_VF_all_V3`).
//!
//! Around an obstacle of radius `r_o` the ring `r_o < d ≤ R_o` carries a circular field
//! `Γ_r⊥` tangent to the circles about the obstacle; a transition `ς` of width `ε` blends it
//! with the goal field between `R_o` and `R_o + ε`.

use glam::DVec2;
use serde::{Deserialize, Serialize};

/// A circular obstacle.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Obstacle {
    /// Centre `p_o` (world frame).
    pub center: DVec2,
    /// Radius `r_o > 0` of the disc the robots must stay out of.
    pub radius: f64,
    /// Radius `R_o > r_o` of the influence ring inside which the circular field acts.
    pub influence: f64,
}

impl Obstacle {
    /// Distance from `p` to the obstacle's surface (negative inside).
    #[inline]
    #[must_use]
    pub fn clearance(&self, p: DVec2) -> f64 {
        p.distance(self.center) - self.radius
    }
}

/// The transition function `ς` of eq. `eq_switch_func`: 0 for `d < R`, 1 for `d > R + ε`,
/// and `½ sin(π(d − R)/ε − π/2) + ½` in between: the raised cosine of `(d − R)/ε`
/// (`maths::raised_cosine`). Continuous and non-decreasing in `d`, with a zero slope at
/// both ends of the band. `eps > 0`.
#[inline]
#[must_use]
pub fn transition(d: f64, big_r: f64, eps: f64) -> f64 {
    if d < big_r {
        0.0
    } else if d > big_r + eps {
        1.0
    } else {
        crate::maths::raised_cosine((d - big_r) / eps)
    }
}

/// The angle `θ_r ∈ [0, π]` between the direction of motion `motion` and the direction from
/// the robot to the obstacle `−Γ_r` (Section IV). `motion` is the heading times the sign of
/// the forward speed: the robot may drive backwards.
#[inline]
#[must_use]
pub fn approach_angle(motion: DVec2, gamma_r: DVec2) -> f64 {
    let c = motion.dot(-gamma_r) / (motion.length() * gamma_r.length());
    crate::maths::acos(c.clamp(-1.0, 1.0))
}

/// Which case of eq. `eq_ob_avoid_VF` applies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Approach {
    /// `θ_r ≥ π/2`: moving away from the obstacle, the goal field is kept.
    Clear,
    /// `0 < θ_r < π/2`: `Γ_r⊥` projected positively on the motion.
    Tangent,
    /// `θ_r = 0`: straight at the obstacle; `Γ_r` turned clockwise by π/2.
    HeadOn,
}

/// Classifies the approach by signs rather than by `acos`, so that the exact cases `θ_r = π/2`
/// and `θ_r = 0` are decided without round-off.
#[inline]
#[must_use]
pub fn classify(motion: DVec2, gamma_r: DVec2) -> Approach {
    if motion.dot(-gamma_r) <= 0.0 {
        Approach::Clear
    } else if gamma_r.perp().dot(motion) == 0.0 {
        Approach::HeadOn
    } else {
        Approach::Tangent
    }
}

/// The obstacle avoidance field `Γ_o` of eq. `eq_ob_avoid_VF` for a robot at relative position
/// `gamma_r = p − p_o` (eq. `eq_Gamma_r_ob_avoid`), moving along `motion`, whose goal field is
/// `goal_field` (world frame).
///
/// `Γ_r⊥ = ±R(π/2)Γ_r` (eq. `eq_Gamma_r_perp_ob_avoid`) has the length `d = |Γ_r|`.
#[inline]
#[must_use]
pub fn avoidance_field(gamma_r: DVec2, motion: DVec2, goal_field: DVec2) -> DVec2 {
    let ccw = gamma_r.perp(); // R(π/2)Γ_r
    match classify(motion, gamma_r) {
        Approach::Clear => goal_field,
        Approach::Tangent if ccw.dot(motion) > 0.0 => ccw,
        Approach::Tangent => -ccw,
        Approach::HeadOn => -ccw, // R(π/2)ᵀΓ_r: clockwise
    }
}

/// The blend of eq. `eq_VF_all_V3` over the sensed obstacles:
/// `Γ_P = (Π ς_i) Γ̃_d + Σ (1 − ς_i) Γ_oi`. Returns `(Γ_P, Π ς_i, on_surface)`; the product
/// also scales the attitude feedback of eq. `eq_nonholo_controller_ob_avoid`, and
/// `on_surface` says (with the exits only) whether the robot is within [`SURFACE`]`·ε` of a
/// disc, where the safety barrier may hold it still.
///
/// `exit = Some(distance to the goal position)` adds two exits the paper lacks (`None` is the
/// paper's blend):
/// - an obstacle whose surface is farther than the goal is let go ([`goal_first`]): without
///   that, a goal in the transition band `R_o < |p_d − p_o| < R_o + ε` would hold the robot
///   in a spurious equilibrium next to it (the circular field does not vanish at the goal, the
///   goal field does);
/// - an obstacle the robot moves away from drops out of the blend rather than adding the goal
///   field with the weight `1 − ς` (which, with several obstacles, can outweigh the ring the
///   robot is in and push it into a disc);
/// - every obstacle circled turns the same way as the nearest one (by clearance), so that
///   overlapping rings are rounded as one: in the notch between two discs their circular
///   fields, each turned by its own `θ_r` rule, point into the notch from both sides and sum
///   to a field that holds the robot there; turned alike they sum to a field along it.
/// - on the surface (clearance below [`SURFACE`]`·ε`), where the safety barrier allows no
///   approach, an obstacle the goal field points into is classified by the goal field instead
///   of the motion (the `θ_r` rule of eq. `eq_ob_avoid_VF` with `Γ̃_d` for the motion): the
///   robot circles it towards its goal. Classified by the motion, a robot whose goal lies behind
///   the disc flips from step to step between `Γ_r⊥` (heading a little into the disc) and `Γ̃_d`
///   (heading a little out of it, the obstacle let go), and the barrier holds it still either
///   way.
#[must_use]
pub fn blend<'a, I>(
    p: DVec2,
    motion: DVec2,
    goal_field: DVec2,
    obstacles: I,
    eps: f64,
    exit: Option<f64>,
) -> (DVec2, f64, bool)
where
    I: IntoIterator<Item = &'a Obstacle>,
    I::IntoIter: Clone,
{
    let obstacles = obstacles.into_iter();
    let moving = |o: &Obstacle| measured(o, p, motion, goal_field, eps, exit.is_some());
    // The turning sense (+1 counter-clockwise) of the nearest obstacle that is circled.
    let sense = exit.and_then(|_| {
        obstacles
            .clone()
            .filter(|o| transition(p.distance(o.center), o.influence, eps) < 1.0)
            .filter(|o| classify(moving(o), p - o.center) != Approach::Clear)
            .min_by(|a, b| a.clearance(p).total_cmp(&b.clearance(p)))
            .map(|o| {
                let gamma_r = p - o.center;
                avoidance_field(gamma_r, moving(o), goal_field)
                    .dot(gamma_r.perp())
                    .signum()
            })
    });
    let mut keep = 1.0;
    let mut sum = DVec2::ZERO;
    let mut on_surface = false;
    for o in obstacles {
        let gamma_r = p - o.center;
        let mut s = transition(gamma_r.length(), o.influence, eps);
        if let Some(g) = exit {
            let clearance = o.clearance(p);
            on_surface |= clearance < SURFACE * eps;
            s = 1.0 - (1.0 - s) * (1.0 - goal_first(clearance, g, eps));
        }
        // Exit: an obstacle the robot moves away from has no say (ς = 1), which for one
        // obstacle is the paper's `Γ_o = Γ̃_d` and for several keeps such an obstacle's
        // `(1 − ς)·Γ̃_d` from outweighing the ring of another that the robot is entering.
        let motion = moving(o);
        let approach = classify(motion, gamma_r);
        if exit.is_some() && approach == Approach::Clear {
            continue;
        }
        if s < 1.0 {
            keep *= s;
            let field = match (sense, approach) {
                (Some(sigma), Approach::Tangent | Approach::HeadOn) => sigma * gamma_r.perp(),
                _ => avoidance_field(gamma_r, motion, goal_field),
            };
            sum += (1.0 - s) * field;
        }
    }
    (keep * goal_field + sum, keep, on_surface)
}

/// The direction an obstacle's `θ_r` is measured against in [`blend`]: the motion, or with
/// the exits (`exit`) the goal field on the surface while it points into the disc.
#[inline(never)]
fn measured(
    o: &Obstacle,
    p: DVec2,
    motion: DVec2,
    goal_field: DVec2,
    eps: f64,
    exit: bool,
) -> DVec2 {
    if exit && goal_field.dot(p - o.center) < 0.0 && o.clearance(p) < SURFACE * eps {
        goal_field
    } else {
        motion
    }
}

/// The band `r_o < d < r_o + SURFACE·ε` in which [`blend`] classifies an obstacle by the goal
/// field: a robot there is held by the barrier rather than by the field.
pub const SURFACE: f64 = 0.003;

/// How far an obstacle is let go because the goal is nearer than its surface: 0 while
/// `to_goal ≥ clearance`, 1 once `to_goal ≤ clearance − ε`, the transition `ς` in between.
///
/// Every point of the segment from the robot to its goal is then farther than
/// `clearance − to_goal` from the disc (triangle inequality), so heading for the goal cannot
/// need the circular field; the safety barrier ([`crate::safety`]) covers the curvature of the
/// real path.
#[inline]
#[must_use]
pub fn goal_first(clearance: f64, to_goal: f64, eps: f64) -> f64 {
    transition(clearance - to_goal, 0.0, eps)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::assert_close;
    use crate::testing::test;
    use std::f64::consts::PI;

    #[test]
    fn transition_limits_and_continuity() {
        let (r, e) = (3.0, 0.5);
        assert_eq!(transition(2.9, r, e), 0.0);
        assert_eq!(transition(3.0, r, e), 0.0);
        assert_close!(transition(3.25, r, e), 0.5, 1e-15);
        assert_close!(transition(3.5, r, e), 1.0, 1e-15);
        assert_eq!(transition(3.6, r, e), 1.0);
        // Continuity: a fine sweep never jumps by more than the steepest slope allows
        // (π/(2ε) per unit distance) and never decreases.
        let mut prev = transition(2.8, r, e);
        for k in 1..=1000 {
            let d = 2.8 + k as f64 * 1e-3;
            let s = transition(d, r, e);
            assert!(s >= prev);
            assert!(s - prev <= PI / (2.0 * e) * 1e-3 + 1e-12, "jump at {d}");
            prev = s;
        }
    }

    #[test]
    fn three_cases_of_theta_r() {
        // Robot at (0, 2) relative to the obstacle.
        let gamma_r = DVec2::new(0.0, 2.0);
        let goal = DVec2::new(7.0, 7.0);
        // Case 1: moving away (θ_r = π) and tangentially (θ_r = π/2) keeps the goal field.
        assert_eq!(classify(DVec2::Y, gamma_r), Approach::Clear);
        assert_eq!(classify(DVec2::X, gamma_r), Approach::Clear);
        assert_eq!(avoidance_field(gamma_r, DVec2::X, goal), goal);
        assert_close!(approach_angle(DVec2::X, gamma_r), PI / 2.0, 1e-15);
        // Case 2: approaching obliquely: tangent with positive projection on the motion.
        let m = DVec2::new(1.0, -1.0);
        assert_eq!(classify(m, gamma_r), Approach::Tangent);
        let f = avoidance_field(gamma_r, m, goal);
        assert_eq!(f.dot(gamma_r), 0.0);
        assert!(f.dot(m) > 0.0);
        assert_close!(f.length(), 2.0, 1e-15);
        let f = avoidance_field(gamma_r, DVec2::new(-1.0, -1.0), goal);
        assert!(f.dot(DVec2::new(-1.0, -1.0)) > 0.0);
        // Case 3: straight at it: Γ_r turned clockwise by π/2 = (2, 0).
        assert_eq!(classify(-DVec2::Y, gamma_r), Approach::HeadOn);
        assert_eq!(
            avoidance_field(gamma_r, -DVec2::Y, goal),
            DVec2::new(2.0, 0.0)
        );
        assert_eq!(approach_angle(-DVec2::Y, gamma_r), 0.0);
    }

    /// Along the circular field the distance to the obstacle is constant (proof of Theorem 3):
    /// d/dt |p − p_o|² = 2Γ_rᵀΓ_o = 0.
    #[test]
    fn circular_field_is_tangent() {
        for k in 0..36 {
            let a = k as f64 * 10f64.to_radians();
            let gamma_r = 2.5 * DVec2::from_angle(a);
            let m = DVec2::from_angle(a + 2.0); // approaching
            let f = avoidance_field(gamma_r, m, DVec2::ZERO);
            assert_close!(f.dot(gamma_r), 0.0, 1e-12);
        }
    }

    /// On the surface, moving out of the disc with a goal field into it: the obstacle is
    /// circled towards the goal (clockwise here) rather than let go.
    #[test]
    fn on_the_surface_the_goal_field_decides() {
        let o = Obstacle {
            center: DVec2::ZERO,
            radius: 1.0,
            influence: 2.0,
        };
        let (p, motion, g) = (
            DVec2::new(1.0 + 1e-6, 0.0),
            DVec2::new(0.1, 1.0),
            DVec2::new(-1.0, -0.5),
        );
        let (f, keep, on_surface) = blend(p, motion, g, [&o], 1.0, Some(10.0));
        assert_eq!(keep, 0.0);
        assert!(on_surface);
        assert!(f.x.abs() < 1e-15 && f.y < 0.0, "{f:?}");
        // Away from the surface, or in the paper's blend, the obstacle is let go.
        let far = DVec2::new(1.1, 0.0);
        assert_eq!(
            blend(far, motion, g, [&o], 1.0, Some(10.0)),
            (g, 1.0, false)
        );
        assert_eq!(blend(p, motion, g, [&o], 1.0, None).0, g);
    }

    #[test]
    fn blend_far_away_is_the_goal_field() {
        let o = Obstacle {
            center: DVec2::ZERO,
            radius: 1.0,
            influence: 2.0,
        };
        let g = DVec2::new(-3.0, 1.0);
        let (f, keep, _) = blend(DVec2::new(10.0, 0.0), -DVec2::X, g, [&o], 0.5, None);
        assert_eq!((f, keep), (g, 1.0));
        // Inside the ring, approaching: purely tangential, attitude feedback off.
        let (f, keep, _) = blend(
            DVec2::new(1.5, 0.0),
            DVec2::new(-1.0, 0.2),
            g,
            [&o],
            0.5,
            None,
        );
        assert_eq!(keep, 0.0);
        assert_close!(f.x, 0.0, 1e-15);
    }
}
