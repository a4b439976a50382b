//! The method's parameters, with the defaults in one place.
//!
//! The paper leaves every number open (docs/notes-on-the-paper.md §6). The defaults below make all four of its
//! examples work (the presets in [`crate::presets`] use them unless they say otherwise), and
//! satisfy the two conditions the controller needs to converge from any pose:
//! `k_a > 2·k_ω` (no spurious equilibrium where the field is perpendicular to the heading) and
//! `k_ω ≥ k_v` (the attitude loop no slower than the position loop).

use serde::{Deserialize, Serialize};

/// The default barrier rate `α` (1/s): over a gap of 1 m a robot approaches at most 5 m/s
/// towards an obstacle and 2.5 m/s towards a neighbour (which does the same); the field is
/// rarely braked outside the last metre.
pub const DEFAULT_BARRIER_RATE: f64 = 5.0;

/// How robots avoid each other (Section V).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Avoidance {
    /// As the paper writes it: inside the avoidance range a robot always blends in the
    /// circular field of the virtual obstacle. Robots that enter each other's ring can circle
    /// forever (docs/notes-on-the-paper.md §5).
    Paper,
    /// The paper's field with the exit the obstacle field already has (eq. `eq_ob_avoid_VF`,
    /// case `θ_r ≥ π/2`): a robot whose motion under its goal field leads away from the virtual
    /// obstacle follows its goal field; only a robot that would approach the cluster circles it.
    #[default]
    Exit,
}

/// Parameters of the field and the controller (the scenario file's `params` object).
/// Lengths in scenario units, angles in radians, times in seconds.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Params {
    /// `k_v > 0`: gain of the forward speed on the field (eq. `eq_nonholo_controller`). 1/s.
    pub k_v: f64,
    /// `k_ω > 0`: gain of the attitude feedback `−k_ω θ̃`. 1/s.
    pub k_omega: f64,
    /// `k_a > 0`: gain of the alignment term `k_a·atan(Γᴮʸ/Γᴮˣ)`. 1/s.
    pub k_a: f64,
    /// `ε > 0`: width of the transition band of `ς` (eq. `eq_switch_func`).
    pub transition_width: f64,
    /// `v_c > 0`: the common speed of robots circling a virtual obstacle
    /// (eq. `eq_nonholo_controller_co_avoid`).
    pub avoid_speed: f64,
    /// `R_c`: radius of the avoidance ring about a virtual obstacle; robots closer than
    /// `2(R_c + ε)` start avoiding each other.
    pub avoid_radius: f64,
    /// `r_ij`: a robot's safe radius; two robots closer than `2·r_ij` count as a collision.
    pub safe_radius: f64,
    /// `R_s`: sensing radius. A robot knows the robots within `R_s` and the obstacles whose
    /// surface is within `R_s`.
    pub sense_radius: f64,
    /// `|v| ≤ v_max` when set (off by default, as in the paper).
    pub v_max: Option<f64>,
    /// `|ω| ≤ ω_max` when set (off by default).
    pub omega_max: Option<f64>,
    /// A robot has converged when its position error is at most this.
    pub tol_position: f64,
    /// … and its heading error at most this (rad).
    pub tol_heading: f64,
    /// `g`: field magnitude below which the alignment term fades out, as
    /// `k_a·|Γ|²/(|Γ|² + g²)·atan(Γᴮʸ/Γᴮˣ)` (docs/notes-on-the-paper.md §3: at the goal the direction of a
    /// vanishing field is round-off). Length/s, far below `tol_position`. Not in the paper.
    pub align_fade: f64,
    /// `"exit"` (default) or `"paper"`: see [`Avoidance`].
    pub avoidance: Avoidance,
    /// `α`: rate of the safety barrier ([`crate::safety`]), 1/s. A robot may close its gap
    /// to a neighbour's safe distance or to an obstacle's surface by at most the fraction
    /// `α·dt` of it per step, so no two robots come closer than `2·r_ij` and no robot enters an
    /// obstacle. `null` turns the barrier off (the paper's controller alone). Not in the
    /// paper. Needs `α·dt ≤ 1/2`.
    pub barrier_rate: Option<f64>,
}

impl Default for Params {
    fn default() -> Self {
        Self {
            k_v: 1.0,
            k_omega: 1.0,
            k_a: 10.0,
            transition_width: 1.0,
            avoid_speed: 2.0,
            avoid_radius: 3.0,
            safe_radius: 1.0,
            sense_radius: 20.0,
            v_max: None,
            omega_max: None,
            tol_position: 0.05,
            tol_heading: 0.02,
            align_fade: 1e-6,
            avoidance: Avoidance::Exit,
            barrier_rate: Some(DEFAULT_BARRIER_RATE),
        }
    }
}
