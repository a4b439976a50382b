//! `avf`: the dipole-like vector field of D. Panagou, "A Distributed Feedback Motion Planning
//! Protocol for Multiple Unicycle Agents of Different Classes", IEEE TAC 62(3), 2017
//! (doi:10.1109/TAC.2016.2576020), as the DVF authors' comparison drives a unicycle with it:
//! `Algorithm_Comparison/Unicycle/Controller_AVF.m`, `AVF.m` and `dAVFdt.m` of the repository
//! github.com/Y1kee/CVF-for-Nonholonomic-Motion-Planning.
//!
//! In the goal frame (`q = R(θ_d)ᵀ(p − p_d)`, `p̂` the goal's heading, the frame's X axis) the
//! field is `F = λ(p̂ᵀq)q − (qᵀq)p̂ = ((λ − 1)x² − y², λxy)`. Its integral curves are
//! `|q| = c·|sin ∠q|^(λ−1)`: for `λ > 1` every one of them ends at the goal tangent to `p̂`
//! (for `λ = 2`, the source's, they are the circles through the goal tangent to `p̂`), but for
//! the half line ahead of the goal, the field's separatrix, where it points away from the
//! goal. The robot drives forward at `v = v_max·tanh|p − p_d|` and turns with
//! `ω = −k_ω·wrap(θ − θ_d − ∠F) + dφ/dt`, `dφ/dt` the rate of the field's direction along the
//! robot's motion. The source takes that rate by central differences of the normalised field
//! (step 1e-6); here it is the exact derivative, `F × (J_F q̇)/|F|²`, with `F` and `J_F` taken
//! at `q/|q|` (both are homogeneous in `q`, so the rate is the same and no power of a small
//! `|q|` underflows next to the goal).
//!
//! It has no avoidance of its own: other robots and obstacles meet only the simulator's
//! shared safety barrier.

use super::{gains, positive, Alone, Built, Entry};
use crate::sim::Robot;
use crate::controller::{Command, Evaluation};
use crate::error::Error;
use crate::se2::{heading, rotate, unrotate, wrap_angle, Pose};
use glam::DVec2;
use serde::Deserialize;

/// The dipole-like field (`avf`).
pub(super) const ENTRY: Entry = Entry {
    name: "avf",
    title: "Dipole-like vector field",
    source: "Panagou, A Distributed Feedback Motion Planning Protocol for Multiple Unicycle \
             Agents of Different Classes, IEEE TAC 2017 (doi:10.1109/TAC.2016.2576020); \
             Controller_AVF.m of github.com/Y1kee/CVF-for-Nonholonomic-Motion-Planning",
    avoids: "nothing",
    build: |map| {
        let g: Gains = gains(map)?;
        g.check()?;
        Ok(Built::Other(Box::new(Avf(g))))
    },
};

/// The gains of `avf`, with the source's values as defaults.
#[derive(Clone, Copy, Debug, PartialEq, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub(super) struct Gains {
    /// `λ > 1`: the field's shape (2: circles through the goal, `AVF.m`).
    pub lambda: f64,
    /// The planner's top speed (m/s): `v = v_max·tanh|p − p_d|`. 3, the value
    /// `Controller_CVF.m` sets in the globals `Controller_AVF.m` reads.
    pub v_max: f64,
    /// `k_ω` (1/s): the gain of the heading error to the field (`kw = 1` in
    /// `Controller_AVF.m`).
    pub k_omega: f64,
    /// The source's end (m): the robot stops once it is within this distance of the goal
    /// and its speed is below `v_max/10` (`Controller_AVF.m` stops its run there, with
    /// `ρ/10` and `ρ = 1`); 0 never stops.
    pub stop_within: f64,
}

impl Default for Gains {
    fn default() -> Self {
        Self {
            lambda: 2.0,
            v_max: 3.0,
            k_omega: 1.0,
            stop_within: 0.1,
        }
    }
}

impl Gains {
    /// # Errors
    /// [`Error::Invalid`] naming the first gain out of its range.
    fn check(&self) -> Result<(), Error> {
        if !(self.lambda.is_finite() && self.lambda > 1.0) {
            return Err(Error::Invalid {
                field: "planner.lambda".to_owned(),
                message: format!(
                    "must be a finite number > 1 (at λ ≤ 1 the field's curves do not end at \
                     the goal), not {}",
                    self.lambda
                ),
            });
        }
        positive("v_max", self.v_max)?;
        positive("k_omega", self.k_omega)?;
        not_negative("stop_within", self.stop_within)
    }
}

/// A gain that must be a finite number ≥ 0.
///
/// # Errors
/// [`Error::Invalid`] naming `planner.{name}`.
pub(super) fn not_negative(name: &str, v: f64) -> Result<(), Error> {
    if v.is_finite() && v >= 0.0 {
        Ok(())
    } else {
        Err(Error::Invalid {
            field: format!("planner.{name}"),
            message: format!("must be a finite number ≥ 0, not {v}"),
        })
    }
}

/// `avf` for every robot, each on its own.
#[derive(Clone, Debug)]
struct Avf(Gains);

impl Alone for Avf {
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

/// `F(q)` in the goal frame.
fn field(lambda: f64, q: DVec2) -> DVec2 {
    DVec2::new((lambda - 1.0) * q.x * q.x - q.y * q.y, lambda * q.x * q.y)
}

/// `J_F(q) u`: the derivative of `F` at `q` along `u`.
fn field_along(lambda: f64, q: DVec2, u: DVec2) -> DVec2 {
    DVec2::new(
        2.0 * (lambda - 1.0) * q.x * u.x - 2.0 * q.y * u.y,
        lambda * (q.y * u.x + q.x * u.y),
    )
}

/// The unit direction of the field at `q` in the goal frame, `None` at the goal (where the
/// field vanishes).
#[cfg(test)]
fn direction(lambda: f64, q: DVec2) -> Option<DVec2> {
    field(lambda, q.try_normalize()?).try_normalize()
}

/// The command of a robot at `pose` bound for `goal`, and the velocity it wants in the world
/// frame (along the field, at the commanded speed).
///
/// Within `stop_within` of the goal and slower than `v_max/10` the robot stops, where the
/// source ends its run. At the goal position the field has no direction: there a robot that
/// does not stop turns to the goal's heading (`∠F` taken as 0 and its rate as 0), where the
/// source's normalisation of a zero vector would give NaN.
pub(super) fn command(g: &Gains, pose: Pose, goal: Pose) -> (Command, DVec2) {
    let r = pose.p - goal.p;
    let d = r.length();
    let v = g.v_max * libm::tanh(d);
    if d < g.stop_within && v < g.v_max / 10.0 {
        return (Command::default(), DVec2::ZERO);
    }
    // The robot's heading in the goal frame.
    let h = heading(wrap_angle(pose.theta - goal.theta));
    let q = unrotate(goal.theta, r);
    let (along, rate) = match q.try_normalize() {
        Some(u) => {
            let f = field(g.lambda, u);
            let n2 = f.length_squared();
            // q̇ = v·h; at q/|q| the derivative scales by 1/|q|, so the rate is
            // F × (J_F h)/|F|² · v/|q|, with v/|q| = v_max·tanh(d)/d.
            let rate = f.perp_dot(field_along(g.lambda, u, h)) / n2 * (v / d);
            match f.try_normalize() {
                Some(t) if rate.is_finite() => (t, rate),
                _ => (DVec2::X, 0.0),
            }
        }
        None => (DVec2::X, 0.0),
    };
    // wrap(θ − θ_d − ∠F): the angle from the field's direction to the heading.
    let error = crate::maths::atan2(along.perp_dot(h), along.dot(h));
    let omega = -g.k_omega * error + rate;
    (Command { v, omega }, rotate(goal.theta, along) * v)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{assert_close, test};
    use serde_json::json;


    /// The source's scene (the masks of `Unicycle_AVF.slx`): start (8.592…, 12.677) at
    /// 5.010 rad, goal (−8, 0) at 3π/2.
    fn source_scene() -> (Pose, Pose) {
        (
            Pose::new(8.592_294_692_468_84, 12.676_570_671_638_1, 5.009_813_579_478_41),
            Pose::new(-8.0, 9.797_174_393_178_83e-16, 4.712_388_980_384_69),
        )
    }

    /// The command and the field's direction at four poses, against `Controller_AVF.m` run
    /// line by line in a numpy port (its `logm` of a rotation taken as the angle, its
    /// `dAVFdt.m` by central differences with its step 1e-6, θ given in [0, 2π) as its
    /// kinematics block gives it). The central differences of a field whose direction turns
    /// at ~1 rad/m differ from the exact rate by ~1e-9 rad/s (their rounding, ε/1e-6 ≈ 2e-10,
    /// and their truncation, ~1e-12): ω within 1e-8; v and the direction are the same
    /// formulas, within 1e-12.
    #[test]
    fn the_command_is_the_sources_at_given_poses() {
        let g = Gains::default();
        let (start, goal) = source_scene();
        let cases = [
            // (pose, goal, v, ω, ∠F in the world frame)
            (start, goal, 3.0, -2.403_643_709_628_822, 2.875_602_834_273_417_7),
            (
                Pose::new(2.0, 1.0, 0.3),
                Pose::default(),
                2.932_236_706_751_336,
                0.200_014_287_681_819_6,
                0.927_295_218_001_612_3,
            ),
            (
                Pose::new(1.0, 2.0, -2.0),
                Pose::new(0.5, -1.0, 1.0),
                2.986_339_984_986_982_3,
                -1.959_342_509_667_381_3,
                1.811_295_298_760_539_5,
            ),
            (
                Pose::new(-3.0, -1.0, 2.9),
                Pose::default(),
                2.989_268_651_028_787_4,
                -3.266_098_163_896_105,
                0.643_501_108_793_284_4,
            ),
        ];
        for (at, to, v, omega, angle) in cases {
            let (c, f) = command(&g, at, to);
            assert_close!(c.v, v, 1e-12);
            assert_close!(c.omega, omega, 1e-8);
            assert_close!(f.y.atan2(f.x), angle, 1e-12);
            assert_close!(f.length(), v, 1e-12);
        }
    }

    /// A point that follows the field (λ = 2) exactly stays on the circle through the goal
    /// tangent to p̂ that it starts on, and ends at the goal: RK4 on the unit field in the
    /// goal frame from (−3, 2), whose circle has its centre at (0, 13/4) and radius 13/4.
    /// 2·10⁴ steps of 5e-4 m (10 m of arc, more than the 7.9 m to the goal, which the unit
    /// field then circles on at the goal's neighbourhood): RK4's error per step is ~h⁵·κ⁴ ≈
    /// 1e-18 m away from the goal, so the distance to the circle stays within 1e-9 m until
    /// the point is within 1e-3 of the goal.
    #[test]
    fn integral_curves_are_circles_through_the_goal_tangent_to_its_heading() {
        let f = |q: DVec2| direction(2.0, q).unwrap_or(DVec2::ZERO);
        let (centre, radius) = (DVec2::new(0.0, 3.25), 3.25);
        let mut q = DVec2::new(-3.0, 2.0);
        assert_close!(q.distance(centre), radius, 1e-15);
        let h = 5e-4;
        let mut closest = f64::INFINITY;
        for _ in 0..20_000 {
            let k1 = f(q);
            let k2 = f(q + 0.5 * h * k1);
            let k3 = f(q + 0.5 * h * k2);
            let k4 = f(q + h * k3);
            q += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
            closest = closest.min(q.length());
            if q.length() < 1e-3 {
                break;
            }
            assert_close!(q.distance(centre), radius, 1e-9);
        }
        assert!(closest < 1e-3, "{closest}");
        // On the circle at the goal the field points along p̂.
        let t = direction(2.0, DVec2::new(-1e-4, 1e-4 * 1e-4 / 6.5)).unwrap();
        assert_close!(t.x, 1.0, 1e-8);
    }

    /// For λ = 3 the curves are |q| = c·sin²∠q: the invariant holds along the field too.
    #[test]
    fn integral_curves_keep_their_invariant_for_other_lambdas() {
        let lambda = 3.0;
        let invariant = |q: DVec2| q.length() / (q.y / q.length()).powi(2);
        let f = |q: DVec2| direction(lambda, q).unwrap();
        let mut q = DVec2::new(-2.0, 1.5);
        let c = invariant(q);
        let h = 1e-3;
        for _ in 0..2_000 {
            let k1 = f(q);
            let k2 = f(q + 0.5 * h * k1);
            let k3 = f(q + 0.5 * h * k2);
            let k4 = f(q + h * k3);
            q += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
            assert_close!(invariant(q), c, 1e-9 * c);
        }
    }

    /// Near the goal and slow, the robot stops where the source ends its run; with no end
    /// (`stop_within = 0`) it stops at the goal position and turns to the goal heading: no NaN.
    #[test]
    fn near_the_goal_it_stops_or_turns_to_the_goal_heading() {
        let stop = command(&Gains::default(), Pose::new(1.09, 2.0, 0.5), Pose::new(1.0, 2.0, 0.0));
        assert_eq!(stop, (Command::default(), DVec2::ZERO));
        let (c, _) = command(&Gains::default(), Pose::new(1.11, 2.0, 0.5), Pose::new(1.0, 2.0, 0.0));
        assert!(c.v > 0.3, "{c:?}");
        let g = Gains {
            stop_within: 0.0,
            ..Gains::default()
        };
        let (c, f) = command(&g, Pose::new(1.0, 2.0, 0.5), Pose::new(1.0, 2.0, 0.0));
        assert_eq!(c.v, 0.0);
        assert_close!(c.omega, -0.5, 1e-15);
        assert_eq!(f, DVec2::ZERO);
        let (c, _) = command(&g, Pose::new(1e-200, 0.0, 0.5), Pose::default());
        assert!(c.v.is_finite() && c.omega.is_finite(), "{c:?}");
    }

    /// Random poses, goals and gains, at every scale a scenario allows (coordinates up to
    /// 1e6), robots on their goal's position or on the field's singular points among them:
    /// every command and field is finite.
    #[test]
    fn every_command_is_finite() {
        let mut rng = crate::testing::XorShift(0x005E_EDF1_E1D5);
        for i in 0..20_000 {
            let g = Gains {
                lambda: 1.0 + 10f64.powf(rng.range(-6.0, 6.0)),
                v_max: 10f64.powf(rng.range(-3.0, 3.0)),
                k_omega: 10f64.powf(rng.range(-3.0, 3.0)),
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
        assert!(refused(json!({"lambda": 1})).starts_with("planner.lambda: "));
        assert!(refused(json!({"lambda": "2"})).starts_with("planner.lambda: "));
        assert!(refused(json!({"v_max": 0})).starts_with("planner.v_max: "));
        assert!(refused(json!({"k_omega": -1})).starts_with("planner.k_omega: "));
        assert!(refused(json!({"stop_within": -0.1})).starts_with("planner.stop_within: "));
        let e = refused(json!({"k_w": 1}));
        assert!(e.starts_with("planner") && e.contains("k_w"), "{e}");
        let serde_json::Value::Object(map) = json!({"lambda": 3, "v_max": 1}) else {
            unreachable!()
        };
        assert!((ENTRY.build)(&map).is_ok());
    }
}
