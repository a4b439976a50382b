//! The method's parameters, with the defaults in one place, and their table ([`PARAMETERS`]):
//! each parameter's JSON key, symbol, unit, range and meaning, declared once here and read by
//! the scenario's checks ([`crate::scenario`]), the playground's edits
//! ([`crate::playground::Live::set_param`]) and, through the wasm facade, the page's panel and
//! messages.
//!
//! The paper leaves every number open (docs/notes-on-the-paper.md §6). The defaults below make all four of its
//! examples work (the presets in [`crate::presets`] use them unless they say otherwise), and
//! satisfy the two conditions the controller needs to converge from any pose:
//! `k_a > 2·k_ω` (no spurious equilibrium where the field is perpendicular to the heading) and
//! `k_ω ≥ k_v` (the attitude loop no slower than the position loop).

use serde::{Deserialize, Serialize};

/// The avoidance modes as `params.avoidance` spells them, the default first.
pub const AVOIDANCE_MODES: [&str; 2] = ["exit", "paper"];

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

impl Avoidance {
    /// The mode `name` spells (one of [`AVOIDANCE_MODES`]), or `None`.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "exit" => Some(Self::Exit),
            "paper" => Some(Self::Paper),
            _ => None,
        }
    }
}

/// What values a parameter takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Kind {
    /// A finite number greater than 0.
    Number,
    /// A finite number greater than 0, or `null` for "none" (no saturation, no barrier).
    Optional,
    /// One of [`AVOIDANCE_MODES`].
    Mode,
}

/// One row of the parameter table: how the scenario file, the page and the messages name a
/// parameter, and what it takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Parameter {
    /// The key in the scenario's `params` object (`avoid_radius`).
    pub name: &'static str,
    /// The page's name for it, the paper's symbol where it has one (`R_c`).
    pub symbol: &'static str,
    /// Its unit (`m`, `1/s`), empty for a mode.
    pub unit: &'static str,
    /// What values it takes.
    pub kind: Kind,
    /// Its range as a person reads it (`> 0`, `> 0 or none`, `exit or paper`).
    pub range: &'static str,
    /// What it means, in one line.
    pub meaning: &'static str,
    /// Whether the page's parameter panel shows it (`align_fade` is a numerical guard only).
    pub panel: bool,
}

/// A parameter's value in place, to read or write ([`Params::slot`]).
#[derive(Debug, PartialEq)]
pub enum Slot<'a> {
    /// A [`Kind::Number`].
    Number(&'a mut f64),
    /// A [`Kind::Optional`].
    Optional(&'a mut Option<f64>),
    /// The [`Kind::Mode`].
    Mode(&'a mut Avoidance),
}

/// Declares [`PARAMETERS`] and [`Params::slot`] from one list, so that a parameter's key is
/// written once.
macro_rules! parameter_table {
    ($($name:ident: $kind:ident, $symbol:literal, $unit:literal, $range:literal, $panel:literal, $meaning:literal;)*) => {
        /// Every parameter of [`Params`], in the order the page's panel lists them; the
        /// scenario's checks test the numbers in this order, then the optional ones.
        pub const PARAMETERS: &[Parameter] = &[$(Parameter {
            name: stringify!($name),
            symbol: $symbol,
            unit: $unit,
            kind: Kind::$kind,
            range: $range,
            meaning: $meaning,
            panel: $panel,
        },)*];

        impl Params {
            /// The parameter whose JSON key is `name`, in place; `None` for a name that is
            /// not one.
            #[must_use]
            pub fn slot(&mut self, name: &str) -> Option<Slot<'_>> {
                match name {
                    $(stringify!($name) => Some(Slot::$kind(&mut self.$name)),)*
                    _ => None,
                }
            }
        }
    };
}

parameter_table! {
    k_v: Number, "k_v", "1/s", "> 0", true, "gain of the forward speed on the field";
    k_omega: Number, "k_ω", "1/s", "> 0", true, "gain of the attitude feedback −k_ω θ̃";
    k_a: Number, "k_a", "1/s", "> 0", true, "gain of the alignment term";
    transition_width: Number, "ε", "m", "> 0", true, "width of the transition band ς";
    avoid_speed: Number, "v_c", "m/s", "> 0", true, "speed while circling a virtual obstacle";
    avoid_radius: Number, "R_c", "m", "> r_ij", true, "radius of the ring about a virtual obstacle";
    safe_radius: Number, "r_ij", "m", "> 0", true, "safe radius: closer than 2·r_ij is a collision";
    sense_radius: Number, "R_s", "m", "> 0", true, "sensing radius";
    v_max: Optional, "v_max", "m/s", "> 0 or none", true, "speed saturation (empty: none)";
    omega_max: Optional, "ω_max", "rad/s", "> 0 or none", true, "turn-rate saturation (empty: none)";
    barrier_rate: Optional, "α", "1/s", "> 0 or none, α·dt ≤ 1/2", true,
        "safety barrier: a gap to a safe disc or an obstacle shrinks by at most α·dt per step (empty: off, the paper alone)";
    tol_position: Number, "tol_p", "m", "> 0", true, "a robot has converged within this distance of its goal";
    tol_heading: Number, "tol_θ", "rad", "> 0", true, "a robot has converged within this heading error";
    align_fade: Number, "align_fade", "m/s", "> 0", false, "field magnitude below which the alignment term fades out";
    avoidance: Mode, "avoidance", "", "exit or paper", true,
        "how robots avoid each other: the paper's ring, or the ring with an exit (default)";
}

/// The parameter whose JSON key is `name`.
#[must_use]
pub fn parameter(name: &str) -> Option<&'static Parameter> {
    PARAMETERS.iter().find(|p| p.name == name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_names_every_field_of_params_once() {
        let json = serde_json::to_value(Params::default()).expect("params serialise");
        let keys: Vec<&str> = json
            .as_object()
            .expect("an object")
            .keys()
            .map(String::as_str)
            .collect();
        assert_eq!(keys.len(), PARAMETERS.len());
        let mut p = Params::default();
        for row in PARAMETERS {
            assert!(
                keys.contains(&row.name),
                "{} is a field of Params",
                row.name
            );
            assert_eq!(
                PARAMETERS.iter().filter(|q| q.name == row.name).count(),
                1,
                "{} is in the table once",
                row.name
            );
            let kind = match p.slot(row.name).expect("a slot for every row") {
                Slot::Number(_) => Kind::Number,
                Slot::Optional(_) => Kind::Optional,
                Slot::Mode(_) => Kind::Mode,
            };
            assert_eq!(kind, row.kind, "{}'s kind", row.name);
            assert_eq!(
                row.unit.is_empty(),
                row.kind == Kind::Mode,
                "{}'s unit",
                row.name
            );
        }
        assert!(p.slot("kv").is_none());
        assert_eq!(parameter("avoid_radius").map(|p| p.symbol), Some("R_c"));
    }

    #[test]
    fn a_slot_writes_its_field() {
        let mut p = Params::default();
        if let Some(Slot::Number(x)) = p.slot("sense_radius") {
            *x = 7.0;
        }
        if let Some(Slot::Optional(x)) = p.slot("barrier_rate") {
            *x = None;
        }
        if let Some(Slot::Mode(m)) = p.slot("avoidance") {
            *m = Avoidance::Paper;
        }
        assert_eq!(
            (p.sense_radius, p.barrier_rate, p.avoidance),
            (7.0, None, Avoidance::Paper)
        );
        for (i, name) in AVOIDANCE_MODES.iter().enumerate() {
            let mode = Avoidance::from_name(name).expect("a mode");
            assert_eq!(serde_json::to_value(mode).expect("serialises"), *name);
            assert_eq!(i == 0, mode == Avoidance::default());
        }
        assert_eq!(Avoidance::from_name("Exit"), None);
    }
}
