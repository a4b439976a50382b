//! `cvf`: the curvature-constrained vector field of "Curvature-Constrained Vector Field for
//! Motion Planning of Nonholonomic Robots", as its authors' code drives a unicycle with it:
//! `Algorithm_Comparison/Unicycle/Controller_CVF.m`, with `CVF.m`, `kw.m`, `omega_r.m` and
//! `mix.m`, of the repository github.com/Y1kee/CVF-for-Nonholonomic-Motion-Planning.
//!
//! The field circles the centre `p_Δ = p_d + r₂(−sin θ_d, cos θ_d)`, on whose circle of radius
//! `r₂` the goal lies with the field along the goal's heading. With `q = p − p_Δ`: a source
//! (`q/|q|`) inside `r₁`, a vortex (`q/|q|` turned left) at `r₂`, a sink outside `r₃`, the
//! normalised blends `λ·source + (1 − λ)·vortex` on `[r₁, r₂]` and `λ·vortex + (1 − λ)·sink` on
//! `[r₂, r₃]`, `λ = 2s³ − 3s² + 1` of the band's fraction `s`; `r_i = k_i·ρ`. The robot drives
//! forward at `v = v_max·tanh(|p − p_d|/c_p + |θ_e|/π)` (`θ_e` the heading's error to the field)
//! and turns with `ω₀ = −k_ω·θ_e + ω_r`: `ω_r` the rate of the field's direction along the
//! motion, exact (`omega_r.m`), and `k_ω = min(k_ω,max, (1/ρ − k(r)|sin β|)·v/|θ_e|)` the
//! dynamic gain of `kw.m`. `ω₀` is then clipped to `|ω| ≤ v/ρ`: the path's curvature stays at
//! most `1/ρ`.
//!
//! It has no avoidance of its own: other robots and obstacles meet only the simulator's
//! shared safety barrier.

use super::{gains, positive, Alone, Built, Entry};
use crate::sim::Robot;
use crate::controller::{Command, Evaluation};
use crate::error::Error;
use crate::maths::atan2;
use crate::se2::{heading, Pose};
use glam::DVec2;
use serde::Deserialize;
use std::f64::consts::PI;

/// The curvature-constrained field (`cvf`).
pub(super) const ENTRY: Entry = Entry {
    name: "cvf",
    title: "Curvature-constrained vector field",
    source: "Curvature-Constrained Vector Field for Motion Planning of Nonholonomic Robots; \
             Controller_CVF.m of github.com/Y1kee/CVF-for-Nonholonomic-Motion-Planning",
    avoids: "nothing",
    build: |map| {
        let g: Gains = gains(map)?;
        g.check()?;
        Ok(Built::Other(Box::new(Cvf(g))))
    },
};

/// The gains of `cvf`, with the values of `Controller_CVF.m` as defaults.
#[derive(Clone, Copy, Debug, PartialEq, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub(super) struct Gains {
    /// `ρ` (m): the least turning radius the path keeps (1).
    pub rho: f64,
    /// The planner's top speed (m/s, 3).
    pub v_max: f64,
    /// `r₁ = k1·ρ`: the source's radius (4).
    pub k1: f64,
    /// `r₂ = k2·ρ`: the vortex's radius, the goal's distance from the centre (8).
    pub k2: f64,
    /// `r₃ = k3·ρ`: the sink's radius (12).
    pub k3: f64,
    /// `c_p` (m): the distance to the goal at which the speed's argument reaches 1; `ρ` when
    /// absent (`Controller_CVF.m`; the repository's `se2_controller_Unicycle.m` takes 12ρ).
    pub c_p: Option<f64>,
    /// `k_ω,max` (1/s): the most the dynamic gain takes (`kw_max = 1` in `kw.m`).
    pub kw_max: f64,
    /// The source's end (m): the robot stops once it is within this distance of the goal
    /// and its speed is below `v_max/10` (`Controller_CVF.m` stops its run there, with
    /// `ρ/10`; `se2_controller_Unicycle.m` with `ρ/2`); 0 never stops.
    pub stop_within: f64,
}

impl Default for Gains {
    fn default() -> Self {
        Self {
            rho: 1.0,
            v_max: 3.0,
            k1: 4.0,
            k2: 8.0,
            k3: 12.0,
            c_p: None,
            kw_max: 1.0,
            stop_within: 0.1,
        }
    }
}

impl Gains {
    /// # Errors
    /// [`Error::Invalid`] naming the first gain out of its range.
    fn check(&self) -> Result<(), Error> {
        positive("rho", self.rho)?;
        positive("v_max", self.v_max)?;
        positive("k1", self.k1)?;
        for (name, v, below, below_name) in
            [("k2", self.k2, self.k1, "k1"), ("k3", self.k3, self.k2, "k2")]
        {
            if !(v.is_finite() && v > below) {
                return Err(Error::Invalid {
                    field: format!("planner.{name}"),
                    message: format!(
                        "must be a finite number greater than {below_name} ({below}), not {v}"
                    ),
                });
            }
        }
        if let Some(c) = self.c_p {
            positive("c_p", c)?;
        }
        positive("kw_max", self.kw_max)?;
        super::avf::not_negative("stop_within", self.stop_within)
    }
}

/// `cvf` for every robot, each on its own.
#[derive(Clone, Debug)]
struct Cvf(Gains);

impl Alone for Cvf {
    fn evaluate(&self, r: &Robot) -> Evaluation {
        let (command, field) = command(&self.0, r.pose, r.goal);
        Evaluation {
            command,
            field,
            goal_field: field,
            obstacle_keep: 1.0,
            robot_keep: 1.0,
            virtual_obstacle: None,
        }
    }
}

/// The radii `r₁ < r₂ < r₃` of the field's bands.
#[derive(Clone, Copy, Debug)]
struct Radii([f64; 3]);

impl Radii {
    fn of(g: &Gains) -> Self {
        Self([g.k1 * g.rho, g.k2 * g.rho, g.k3 * g.rho])
    }

    /// The band `r` lies in past `r₁`, as `(s, width, outer)`: `s ∈ [0, 1]` its fraction across
    /// the band of `width`, and whether it is the outer band; `None` inside `r₁` or outside `r₃`.
    fn band(self, r: f64) -> Option<(f64, f64, bool)> {
        let [r1, r2, r3] = self.0;
        if r <= r1 || r > r3 {
            None
        } else if r <= r2 {
            Some(((r - r1) / (r2 - r1), r2 - r1, false))
        } else {
            Some(((r - r2) / (r3 - r2), r3 - r2, true))
        }
    }
}

/// The blend `λ(s) = 2s³ − 3s² + 1`, 1 at the inner edge of a band and 0 at its outer.
fn mix(s: f64) -> f64 {
    (2.0 * s - 3.0) * s * s + 1.0
}

/// The field's unit direction at `q` (relative to the centre), `None` at the centre.
fn direction(radii: Radii, q: DVec2) -> Option<DVec2> {
    let u = q.try_normalize()?;
    let (source, vortex, sink) = (u, u.perp(), -u);
    let r = q.length();
    Some(match radii.band(r) {
        None if r <= radii.0[0] => source,
        None => sink,
        Some((s, _, outer)) => {
            let l = mix(s);
            let blend = if outer {
                l * vortex + (1.0 - l) * sink
            } else {
                l * source + (1.0 - l) * vortex
            };
            // λ and 1 − λ are never both 0: the blend has length ≥ 1/√2.
            blend.normalize()
        }
    })
}

/// `g(r) = −dψ/dr`, ψ the angle of the field from the radial direction: the part of the
/// direction's rate that motion across the bands adds (`omega_r.m`, `kw.m`).
fn band_rate(radii: Radii, r: f64) -> f64 {
    radii.band(r).map_or(0.0, |(s, width, _)| {
        let l = mix(s);
        (6.0 * s - 6.0 * s * s) / width / (2.0 * l * l - 2.0 * l + 1.0)
    })
}

/// The command of a robot at `pose` bound for `goal`, and the velocity it wants in the world
/// frame (along the field, at the commanded speed).
///
/// Within `stop_within` of the goal and slower than `v_max/10` the robot stops, where the
/// source ends its run: the field's circle through the goal attracts slowly, and a robot that
/// went on would pass the goal a few centimetres aside and go round the circle again.
///
/// At the centre `p_Δ` the field has no direction: there the robot takes its own heading for
/// the field's (`θ_e = 0`, no feed-forward), where the source's normalisation of a zero vector
/// would give NaN. Where `ω₀ = 0` the command turns by 0 (the source's `sat = 0/0`).
pub(super) fn command(g: &Gains, pose: Pose, goal: Pose) -> (Command, DVec2) {
    let radii = Radii::of(g);
    let h = heading(pose.theta);
    let centre = goal.p + radii.0[1] * heading(goal.theta).perp();
    let q = pose.p - centre;
    let r = q.length();
    let t = direction(radii, q).unwrap_or(h);
    // logm(R_rᵀR): the angle from the field's direction to the heading.
    let error = atan2(t.perp_dot(h), t.dot(h));
    let c_p = g.c_p.unwrap_or(g.rho);
    let d = pose.p.distance(goal.p);
    let v = g.v_max * libm::tanh(d / c_p + error.abs() / PI);
    if d < g.stop_within && v < g.v_max / 10.0 {
        return (Command::default(), DVec2::ZERO);
    }
    let omega = if r > 0.0 {
        let gr = band_rate(radii, r);
        let u = q / r;
        // omega_r.m: the rate of the field's direction along ṗ = v·h.
        let feed = v * (u.perp().dot(h) / r + gr * u.dot(h));
        // kw.m: the dynamic gain; a NaN (0/0 at θ_e = 0) or ∞ takes k_ω,max, as MATLAB's min.
        // On the field (θ_e = 0) the feedback is 0 whatever the gain, even the −∞ that radii
        // whose band rate g exceeds 1/ρ would give there.
        let k = if r >= g.rho { 1.0 / r + gr } else { r / (g.rho * g.rho) };
        let beta = pose.theta - atan2(q.y, q.x) + atan2(gr, 1.0 / r);
        let k0 = (1.0 / g.rho - k * crate::maths::sin(beta).abs()) / error.abs() * v;
        let kw = g.kw_max.min(k0);
        let omega0 = if error == 0.0 { feed } else { -kw * error + feed };
        // `max` and `min` rather than `clamp`, which would panic on a NaN bound.
        let most = v / g.rho;
        omega0.max(-most).min(most)
    } else {
        0.0
    };
    (Command { v, omega }, t * v)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{assert_close, test};
    use serde_json::json;


    /// The command and the field's direction at poses in every band and with other gains,
    /// against `Controller_CVF.m` (with `CVF.m`, `kw.m`, `omega_r.m`) run line by line in a
    /// numpy port (its `logm` of a rotation taken as the angle, θ given in [0, 2π) as its
    /// kinematics block gives it). The goal is the source's scene's, (−8, 0) at 3π/2, whose
    /// centre `p_Δ` is the origin. The formulas are the same, rounded differently (an atan2 of
    /// two vectors for `logm`): within 1e-12.
    #[test]
    fn the_command_is_the_sources_at_given_poses() {
        let goal = Pose::new(-8.0, 9.797_174_393_178_83e-16, 4.712_388_980_384_69);
        let base = Gains::default();
        let wide = Gains {
            rho: 2.0,
            v_max: 1.0,
            ..base
        };
        let small = Gains {
            rho: 0.5,
            k1: 3.0,
            k2: 6.0,
            k3: 10.0,
            v_max: 2.0,
            c_p: Some(6.0),
            ..base
        };
        // (gains, pose, v, ω, ∠ of the field); the first is clipped to |ω| = v/ρ, the
        // second is inside ρ, the sixth has a dynamic gain below 1.
        let cases = [
            (
                base,
                Pose::new(0.5, 0.1, 1.7),
                2.999_999_904_677_949_3,
                2.999_999_904_677_949_3,
                0.197_395_559_849_881_7,
            ),
            (
                base,
                Pose::new(-0.3, 0.2, 0.0),
                2.999_999_759_152_147,
                -2.215_384_437_527_746_3,
                2.553_590_050_042_224_4,
            ),
            (
                base,
                Pose::new(2.0, 1.0, 0.3),
                2.999_999_989_914_560_4,
                -0.054_930_035_746_132_866,
                0.463_647_609_000_806_26,
            ),
            (
                base,
                Pose::new(5.0, -2.0, 2.0),
                2.999_999_999_993_741,
                -2.778_564_321_542_261_5,
                -0.015_131_148_975_717_915,
            ),
            (
                base,
                Pose::new(-7.0, 6.0, -1.0),
                2.999_983_483_312_005,
                -2.303_696_631_863_903,
                -2.001_179_947_657_839,
            ),
            (
                base,
                Pose::new(-6.0, -3.0, 1.2),
                2.999_165_391_787_767_6,
                -2.654_339_539_741_602,
                -1.421_762_675_044_500_7,
            ),
            (
                base,
                Pose::new(8.592_294_692_468_84, 12.676_570_671_638_1, 5.009_813_579_478_41),
                3.0,
                -1.045_709_548_487_403,
                -2.166_473_290_145_374_3,
            ),
            (
                wide,
                Pose::new(-8.3, 0.4, 2.0),
                0.802_973_868_854_288_9,
                0.321_327_693_301_227_4,
                -1.591_066_025_012_951_6,
            ),
            (
                small,
                Pose::new(3.0, 4.0, -2.5),
                1.929_096_847_403_443,
                -0.216_121_936_080_509_84,
                -2.677_945_044_588_987,
            ),
            (
                small,
                Pose::new(-9.0, 1.0, 0.1),
                0.982_453_096_355_203_4,
                -1.750_107_001_754_041_7,
                -0.848_677_561_998_836_5,
            ),
        ];
        for (g, at, v, omega, angle) in cases {
            let (c, f) = command(&g, at, goal);
            assert_close!(c.v, v, 1e-12);
            assert_close!(c.omega, omega, 1e-12);
            assert_close!(f.y.atan2(f.x), angle, 1e-12);
            assert_close!(f.length(), v, 1e-12);
        }
    }

    /// On the circle of radius r₂ the field is the vortex: at the goal it points along the
    /// goal's heading, whatever that is.
    #[test]
    fn at_the_goal_the_field_is_the_goals_heading() {
        for theta in [0.0, 1.0, -2.5, 3.0] {
            let goal = Pose::new(2.0, -1.0, theta);
            let g = Gains::default();
            let centre = goal.p + 8.0 * heading(theta).perp();
            let t = direction(Radii::of(&g), goal.p - centre).unwrap();
            assert_close!(t.angle_to(heading(theta)), 0.0, 1e-12);
            // There, on its heading, the robot is at rest.
            let (c, _) = command(&g, goal, goal);
            assert_eq!(c.v, 0.0);
            assert_eq!(c.omega, 0.0);
        }
    }

    /// The turn rate never asks for a curvature above 1/ρ, anywhere: a grid of poses.
    #[test]
    fn the_curvature_stays_within_one_over_rho() {
        let g = Gains {
            rho: 1.5,
            ..Gains::default()
        };
        let goal = Pose::new(1.0, 2.0, 0.7);
        for i in 0..40 {
            for j in 0..40 {
                for k in 0..8 {
                    let at = Pose::new(
                        -30.0 + 1.53 * f64::from(i),
                        -30.0 + 1.51 * f64::from(j),
                        -3.0 + 0.77 * f64::from(k),
                    );
                    let (c, _) = command(&g, at, goal);
                    assert!(c.v >= 0.0 && c.omega.is_finite(), "{at:?}: {c:?}");
                    assert!(c.omega.abs() <= c.v / g.rho * (1.0 + 1e-15), "{at:?}: {c:?}");
                }
            }
        }
    }

    /// Radii whose band is narrow make `kw.m`'s gain −∞ on the field (`θ_e = 0` with a
    /// negative numerator): the feedback is 0 there, not NaN. The poses are those of the band
    /// whose heading the field's direction gives exactly.
    #[test]
    fn on_the_field_a_narrow_band_gives_no_nan() {
        let g = Gains {
            k1: 4.0,
            k2: 4.1,
            ..Gains::default()
        };
        let goal = Pose::default();
        let centre = DVec2::new(0.0, 4.1);
        let mut found = 0;
        for i in 1..200 {
            let r = 4.0 + 0.1 * f64::from(i) / 200.0;
            for j in 0..64 {
                let q = r * heading(f64::from(j) * 0.098);
                let t = direction(Radii::of(&g), q).unwrap();
                let at = Pose::new(centre.x + q.x, centre.y + q.y, atan2(t.y, t.x));
                let h = heading(at.theta);
                if atan2(t.perp_dot(h), t.dot(h)) != 0.0 {
                    continue;
                }
                found += 1;
                let (c, _) = command(&g, at, goal);
                assert!(c.omega.is_finite(), "{at:?}: {c:?}");
            }
        }
        assert!(found > 0);
    }

    /// At the centre the field has no direction: no NaN.
    #[test]
    fn at_the_centre_it_keeps_its_heading() {
        let goal = Pose::default();
        let centre = Pose::new(0.0, 8.0, 0.4);
        let (c, f) = command(&Gains::default(), centre, goal);
        assert!(c.v.is_finite() && c.v > 0.0, "{c:?}");
        assert_eq!(c.omega, 0.0);
        assert_close!(f.angle_to(heading(0.4)), 0.0, 1e-12);
    }

    /// Random poses, goals and gains, at every scale a scenario allows (coordinates up to
    /// 1e6), robots on their goal's position or on the field's singular points among them:
    /// every command and field is finite.
    #[test]
    fn every_command_is_finite() {
        let mut rng = crate::testing::XorShift(0x005E_EDF1_E1D5);
        for i in 0..20_000 {
            let g = Gains {
                rho: 10f64.powf(rng.range(-3.0, 3.0)),
                v_max: 10f64.powf(rng.range(-3.0, 3.0)),
                k1: rng.range(0.1, 5.0),
                k2: rng.range(5.0, 10.0),
                k3: rng.range(10.0, 20.0),
                c_p: Some(10f64.powf(rng.range(-3.0, 3.0))),
                kw_max: 10f64.powf(rng.range(-3.0, 3.0)),
                stop_within: rng.range(0.0, 1.0),
            };
            g.check().unwrap();
            let scale = 10f64.powf(rng.range(-6.0, 6.0));
            let offset = |rng: &mut crate::testing::XorShift| {
                scale * DVec2::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0))
            };
            let goal = Pose {
                p: offset(&mut rng),
                theta: rng.heading(),
            };
            let at = match i % 4 {
                0 => Pose::new(goal.p.x, goal.p.y, rng.heading()),
                1 => {
                    let centre = goal.p + g.k2 * g.rho * heading(goal.theta).perp();
                    Pose::new(centre.x, centre.y, rng.heading())
                }
                _ => {
                    let p = goal.p + offset(&mut rng);
                    Pose::new(p.x, p.y, rng.heading())
                }
            };
            let (c, f) = command(&g, at, goal);
            let finite = c.v.is_finite() && c.omega.is_finite() && f.is_finite();
            assert!(finite, "{g:?} {at:?} {goal:?}: {c:?}");
        }
    }

    fn refused(gains: serde_json::Value) -> String {
        crate::planner::refused(&ENTRY, gains)
    }

    #[test]
    fn bad_gains_are_refused_naming_the_field() {
        assert!(refused(json!({"rho": 0})).starts_with("planner.rho: "));
        assert!(refused(json!({"v_max": -3})).starts_with("planner.v_max: "));
        assert!(refused(json!({"k1": 0})).starts_with("planner.k1: "));
        assert!(refused(json!({"k2": 4})).starts_with("planner.k2: "));
        assert!(refused(json!({"k1": 2, "k2": 3, "k3": 3})).starts_with("planner.k3: "));
        assert!(refused(json!({"c_p": 0})).starts_with("planner.c_p: "));
        assert!(refused(json!({"kw_max": 0})).starts_with("planner.kw_max: "));
        assert!(refused(json!({"stop_within": -1})).starts_with("planner.stop_within: "));
        assert!(refused(json!({"rho": "1"})).starts_with("planner.rho: "));
        let e = refused(json!({"r2": 8}));
        assert!(e.starts_with("planner") && e.contains("r2"), "{e}");
        let serde_json::Value::Object(map) = json!({"rho": 0.5, "c_p": 6, "k3": 20}) else {
            unreachable!()
        };
        assert!((ENTRY.build)(&map).is_ok());
    }
}
