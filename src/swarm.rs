//! Collision avoidance among robots through a virtual obstacle (Section V, eqs.
//! `eq_tilde_p_o`, `eq_Gamma_r_co_avoid`, `eq_Gamma_r_perp_co_avoid`, `DVF_Gamma_Qi`).
//!
//! A robot that has neighbours closer than the avoidance range places a virtual obstacle at
//! the centroid of itself and those neighbours (the midpoint for two robots) and circles it
//! along `Γ_ri⊥`, the tangent whose projection on its own body Y axis is positive: every robot
//! turns left, so that the two robots of a pair circle their midpoint the same way.

use crate::se2::heading;
use glam::DVec2;

/// The virtual obstacle `p̃_o` of robot `i` at `p_i`: the centroid of `p_i` and of the
/// neighbours' positions `others` (eq. `eq_tilde_p_o` for two robots, its convex-combination
/// generalisation for more). `None` without neighbours.
#[must_use]
pub fn virtual_obstacle(p_i: DVec2, others: impl IntoIterator<Item = DVec2>) -> Option<DVec2> {
    let mut sum = p_i;
    let mut n = 1usize;
    for q in others {
        sum += q;
        n += 1;
    }
    (n > 1).then(|| sum / n as f64)
}

/// The avoidance range on the distance between two robots: the transition of the virtual
/// obstacle field starts at `|p_i − p̃_o| = R_c + ε`, which for a pair is
/// `d_ij = 2(R_c + ε)`. Neighbours farther than this never influence a robot.
#[inline]
#[must_use]
pub fn pair_range(avoid_radius: f64, eps: f64) -> f64 {
    2.0 * (avoid_radius + eps)
}

/// `Γ_ri⊥` of eq. `eq_Gamma_r_perp_co_avoid` for a robot at `p_i` with attitude `theta`
/// circling the virtual obstacle `p_o`: perpendicular to `Γ_ri = p_i − p̃_o`
/// (eq. `eq_Gamma_r_co_avoid`), of the same length, with a positive projection on the body Y
/// axis `R(π/2)(cos θ, sin θ)`.
///
/// The paper leaves the case of a zero projection open (the robot's heading already tangent);
/// here the robot then keeps the tangent along its heading.
#[inline]
#[must_use]
pub fn tangent_field(p_i: DVec2, theta: f64, p_o: DVec2) -> DVec2 {
    let gamma_r = p_i - p_o;
    let e = heading(theta);
    let ccw = gamma_r.perp(); // R(π/2)Γ_ri
                              // ⟨σ R(π/2)Γ, R(π/2)e⟩ = σ⟨Γ, e⟩.
    let s = gamma_r.dot(e);
    if s > 0.0 || (s == 0.0 && ccw.dot(e) >= 0.0) {
        ccw
    } else {
        -ccw
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::approx::assert_close;
    use std::f64::consts::{FRAC_PI_2, PI};

    #[test]
    fn virtual_obstacle_is_the_midpoint_and_the_centroid() {
        let a = DVec2::new(0.0, 0.0);
        let b = DVec2::new(4.0, 2.0);
        assert_eq!(virtual_obstacle(a, [b]), Some(DVec2::new(2.0, 1.0)));
        let c = DVec2::new(-1.0, 7.0);
        assert_eq!(virtual_obstacle(a, [b, c]), Some(DVec2::new(1.0, 3.0)));
        assert_eq!(virtual_obstacle(a, []), None);
    }

    /// Two robots heading at each other both turn left and circle their midpoint the same
    /// way, so their distance is constant along the field (eq. `eq_dot_f_ij`).
    #[test]
    fn head_on_pair_circles_the_same_way() {
        let pi = DVec2::new(-2.0, 0.0);
        let pj = DVec2::new(2.0, 0.0);
        let o = virtual_obstacle(pi, [pj]).unwrap();
        let gi = tangent_field(pi, 0.0, o);
        let gj = tangent_field(pj, PI, o);
        // Positive projection on each body Y axis.
        assert!(gi.dot(heading(FRAC_PI_2)) > 0.0);
        assert!(gj.dot(heading(PI + FRAC_PI_2)) > 0.0);
        // d/dt |p_i − p_j|² = 2(p_i − p_j)ᵀ(Γ_i − Γ_j) = 0.
        assert_close!((pi - pj).dot(gi - gj), 0.0, 1e-12);
        assert_close!(gi.length(), 2.0, 1e-15);
    }

    #[test]
    fn tangent_is_perpendicular_to_the_radius() {
        for k in 0..24 {
            let t = k as f64 * 0.27;
            let p = DVec2::new(1.0, 2.0);
            let g = tangent_field(p, t, DVec2::new(-0.5, 0.3));
            assert_close!(g.dot(p - DVec2::new(-0.5, 0.3)), 0.0, 1e-12);
            assert!(g.dot(heading(t + FRAC_PI_2)) >= 0.0);
        }
    }
}
