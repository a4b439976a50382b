//! `clf-cbf`: the Robotarium's pose controller ([`super::clf`]) through its unicycle barrier
//! certificate, `create_uni_barrier_certificate` in `rps/utilities/barrier_certificates.py` of
//! robotarium_python_simulator (<https://github.com/robotarium/robotarium_python_simulator>),
//! after Wang, Ames & Egerstedt, "Safety barrier certificates for collisions-free multirobot
//! systems" (IEEE Transactions on Robotics, 2017).
//!
//! Each robot's look-ahead point `x_i = p_i + d (cos φ_i, sin φ_i)` moves as a single
//! integrator with velocity `ẋ_i = R(φ_i) (v_i, d ω_i)`. One quadratic program over every
//! robot's `ẋ` finds the velocities nearest the CLF's,
//!
//! ```text
//! min Σ ‖ẋ_i − ẋ̂_i‖²   subject to   −2 (x_i − x_j)ᵀ (ẋ_i − ẋ_j) ≤ γ h_ij³,
//!                                     h_ij = ‖x_i − x_j‖² − D_s²,
//! ```
//!
//! for every pair `i < j` of robots that sense each other (within `R_s`), with the safety
//! distance `D_s = 2 r + 2 d` (`r` the scene's `params.safe_radius`), and each `ẋ_i` inside
//! the source's octagon about the disc of radius `velocity_magnitude_limit`. The solution is
//! mapped back to `v = (cos φ, sin φ)·ẋ`, `ω = (−sin φ, cos φ)·ẋ / d`. When the program has no
//! solution every robot stops, as the source commands; a robot alone keeps the CLF's command,
//! as the source returns it. The program is solved by Clarabel, an interior-point solver.
//!
//! The defaults are the source's: `γ = 100` (`barrier_gain`), `d = 0.05` m
//! (`projection_distance`), a magnitude limit of 0.2 m/s (`null` leaves it out), and the CLF's
//! own. The certificate has no obstacles: obstacles are left to the shared safety barrier.

use super::clf::Gains as ClfGains;
use super::{gains, positive, Built, Entry, Planner, World};
use crate::controller::{Command, Evaluation};
use crate::error::Error;
use crate::maths::sin_cos;
use crate::se2::Pose;
use clarabel::algebra::CscMatrix;
use clarabel::solver::{
    DefaultSettings, DefaultSolver, IPSolver, SolverStatus, SupportedConeT,
};
use glam::DVec2;
use serde::Deserialize;
use serde_json::{Map, Value};
use std::f64::consts::FRAC_1_SQRT_2;

/// The planner's entry.
pub(super) const ENTRY: Entry = Entry {
    name: "clf-cbf",
    title: "CLF pose controller through unicycle barrier certificates (Robotarium)",
    source: "Robotarium, create_pose_controller_clf and create_uni_barrier_certificate \
             (robotarium_python_simulator, rps/utilities/controllers.py and \
             barrier_certificates.py), after Wang, Ames & Egerstedt, Safety barrier \
             certificates for collisions-free multirobot systems, 2017",
    avoids: "robots",
    build: |map| Ok(Built::Other(Box::new(ClfCbf(Gains::read(map)?)))),
};

/// `cos(π/8)`: the source's octagon about the disc of the magnitude limit.
const COS_PI_8: f64 = 0.923_879_532_511_286_7;

/// The CLF's gains and the certificate's, with the source's defaults.
#[derive(Clone, Copy, Debug, PartialEq, Deserialize)]
#[serde(default, deny_unknown_fields)]
struct Gains {
    /// The CLF's `γ` ([`ClfGains`]).
    approach_angle_gain: f64,
    /// The CLF's `k`.
    desired_angle_gain: f64,
    /// The CLF's `h`.
    rotation_error_gain: f64,
    /// The fastest a wheel turns in the CLF's command (rad/s); `None`: no wheel limit.
    wheel_velocity_limit: Option<f64>,
    /// The wheels' radius (m).
    wheel_radius: f64,
    /// The distance between the wheels (m).
    base_length: f64,
    /// `γ` of the barrier, `−ḣ ≤ γ h³`.
    barrier_gain: f64,
    /// `d`: how far ahead of the axle the look-ahead point is (m).
    projection_distance: f64,
    /// The look-ahead point's greatest speed (m/s), by the source's octagon; `None`: no limit.
    velocity_magnitude_limit: Option<f64>,
}

impl Default for Gains {
    /// The defaults of `create_pose_controller_clf` and `create_uni_barrier_certificate`.
    fn default() -> Self {
        let clf = ClfGains::default();
        Self {
            approach_angle_gain: clf.approach_angle_gain,
            desired_angle_gain: clf.desired_angle_gain,
            rotation_error_gain: clf.rotation_error_gain,
            wheel_velocity_limit: clf.wheel_velocity_limit,
            wheel_radius: clf.wheel_radius,
            base_length: clf.base_length,
            barrier_gain: 100.0,
            projection_distance: 0.05,
            velocity_magnitude_limit: Some(0.2),
        }
    }
}

impl Gains {
    fn read(map: &Map<String, Value>) -> Result<Self, Error> {
        let g: Self = gains(map)?;
        g.clf().check()?;
        positive("barrier_gain", g.barrier_gain)?;
        positive("projection_distance", g.projection_distance)?;
        if let Some(m) = g.velocity_magnitude_limit {
            positive("velocity_magnitude_limit", m)?;
        }
        Ok(g)
    }

    fn clf(&self) -> ClfGains {
        ClfGains {
            approach_angle_gain: self.approach_angle_gain,
            desired_angle_gain: self.desired_angle_gain,
            rotation_error_gain: self.rotation_error_gain,
            wheel_velocity_limit: self.wheel_velocity_limit,
            wheel_radius: self.wheel_radius,
            base_length: self.base_length,
        }
    }

    /// The look-ahead point of a robot at `pose`.
    fn ahead(&self, pose: Pose) -> DVec2 {
        let (s, c) = sin_cos(pose.theta);
        pose.p + self.projection_distance * DVec2::new(c, s)
    }

    /// The certificate: `commands` (one per robot at `poses`) made safe for the `pairs`
    /// `(i, j)`, `i < j`, at the safety distance `ds` between look-ahead points. Every robot
    /// stops when the program has no solution.
    fn certify(
        &self,
        ds: f64,
        poses: &[Pose],
        pairs: &[(usize, usize)],
        commands: &mut [Command],
    ) {
        if poses.len() < 2 {
            return;
        }
        let (rows, nominal) = self.program(ds, poses, pairs, commands);
        let octagon = self
            .velocity_magnitude_limit
            .map_or(f64::INFINITY, |m| m / COS_PI_8);
        let safe = solve(&nominal, &rows, octagon);
        self.apply(poses, safe.as_deref(), commands);
    }

    /// The program's rows (the pairs', then each robot's octagon) and the look-ahead points'
    /// velocities under `commands`, `(v, d·ω)` turned into the world frame.
    fn program(
        &self,
        ds: f64,
        poses: &[Pose],
        pairs: &[(usize, usize)],
        commands: &[Command],
    ) -> (Vec<Row>, Vec<f64>) {
        let d = self.projection_distance;
        let mut nominal = Vec::with_capacity(2 * poses.len());
        for (p, u) in poses.iter().zip(commands) {
            let (s, c) = sin_cos(p.theta);
            nominal.push(c * u.v - s * d * u.omega);
            nominal.push(s * u.v + c * d * u.omega);
        }
        let ahead: Vec<DVec2> = poses.iter().map(|&p| self.ahead(p)).collect();
        let mut rows = Vec::with_capacity(pairs.len() + 8 * poses.len());
        for &(i, j) in pairs {
            let diff = ahead[i] - ahead[j];
            let h = diff.length_squared() - ds * ds;
            rows.push(Row {
                cols: [2 * i, 2 * i + 1, 2 * j, 2 * j + 1],
                vals: [-2.0 * diff.x, -2.0 * diff.y, 2.0 * diff.x, 2.0 * diff.y],
                b: self.barrier_gain * h * h * h,
            });
        }
        if let Some(m) = self.velocity_magnitude_limit {
            // The source's octagon, row by row: its first side at m, the others at m·cos(π/8).
            let s = FRAC_1_SQRT_2;
            let sides = [
                ([1.0, 0.0], m),
                ([s, s], m * COS_PI_8),
                ([0.0, 1.0], m * COS_PI_8),
                ([-s, s], m * COS_PI_8),
                ([-1.0, 0.0], m * COS_PI_8),
                ([-s, -s], m * COS_PI_8),
                ([0.0, -1.0], m * COS_PI_8),
                ([s, -s], m * COS_PI_8),
            ];
            for i in 0..poses.len() {
                for (a, bound) in sides {
                    rows.push(Row {
                        cols: [2 * i, 2 * i + 1, 0, 0],
                        vals: [a[0], a[1], 0.0, 0.0],
                        b: bound,
                    });
                }
            }
        }
        (rows, nominal)
    }

    /// The commands whose look-ahead points move at `x` (every robot stopped for `None`).
    fn apply(&self, poses: &[Pose], x: Option<&[f64]>, commands: &mut [Command]) {
        for ((p, u), i) in poses.iter().zip(commands.iter_mut()).zip(0..) {
            *u = x.map_or(Command::default(), |x| {
                let (s, c) = sin_cos(p.theta);
                let (dx, dy) = (x[2 * i], x[2 * i + 1]);
                Command {
                    v: c * dx + s * dy,
                    omega: (-s * dx + c * dy) / self.projection_distance,
                }
            });
        }
    }
}

/// One constraint `aᵀx ≤ b` of the program, `a` nonzero in at most four columns (zeros in
/// `vals` stand for none).
#[derive(Clone, Copy, Debug)]
struct Row {
    cols: [usize; 4],
    vals: [f64; 4],
    b: f64,
}

impl Row {
    fn at(&self, x: &[f64]) -> f64 {
        self.cols.iter().zip(self.vals).map(|(&c, v)| v * x[c]).sum()
    }

    /// `|aᵀx|` at most, for every `x` with each robot's velocity `(x_2i, x_2i+1)` at most
    /// `reach` long.
    fn most(&self, reach: f64) -> f64 {
        (DVec2::new(self.vals[0], self.vals[1]).length()
            + DVec2::new(self.vals[2], self.vals[3]).length())
            * reach
    }
}

/// `min ‖x − x̂‖²` subject to every row, as the source poses it (`½ xᵀ(2I)x − 2x̂ᵀx`), or
/// `None` when it has no solution or a number in it is not finite (but for bounds of +∞).
///
/// A pair far apart has a bound `γ h³` many orders above its other numbers (1e14 for robots
/// 100 m apart), which leaves the interior-point iteration without a solution
/// (`runs_a_sweep_scene_to_every_goal`). So the rows that no velocity within reach can meet
/// are left out at first: the reach is `2‖x̂‖` (when `x = 0` is feasible the solution is no
/// farther from `x̂` than 0 is), or `octagon`, the most a velocity within the octagon can be
/// (`m / cos(π/8)` bounds it). The program is then solved with the rows kept, and a row left
/// out that its solution breaks is put back and the program solved again: the solution that
/// meets every row is the program's own, whether or not the reach held.
fn solve(nominal: &[f64], rows: &[Row], octagon: f64) -> Option<Vec<f64>> {
    let reach = (2.0 * nominal.iter().map(|x| x * x).sum::<f64>().sqrt()).min(octagon);
    // A bound of +∞ (a pair so far apart that γ h³ overflows) is a row every x meets.
    let finite = |x: &f64| x.is_finite();
    let row_ok = |r: &Row| r.vals.iter().all(finite) && (r.b.is_finite() || r.b == f64::INFINITY);
    if !(nominal.iter().all(finite) && rows.iter().all(row_ok)) {
        return None;
    }
    let mut kept: Vec<bool> = rows.iter().map(|r| r.b <= r.most(reach)).collect();
    loop {
        let x = if kept.iter().any(|&k| k) {
            solve_kept(nominal, rows, &kept, settings())?
        } else {
            nominal.to_vec()
        };
        let mut broken = false;
        for (r, k) in rows.iter().zip(kept.iter_mut()) {
            if !*k && r.at(&x) > r.b {
                *k = true;
                broken = true;
            }
        }
        if !broken {
            return Some(x);
        }
    }
}

/// Clarabel's settings for the program: its defaults (gaps and feasibility to 1e-8), quiet.
fn settings() -> DefaultSettings<f64> {
    DefaultSettings {
        verbose: false,
        ..DefaultSettings::default()
    }
}

/// [`solve`]'s program with the rows `kept` only, by Clarabel.
fn solve_kept(
    nominal: &[f64],
    rows: &[Row],
    kept: &[bool],
    settings: DefaultSettings<f64>,
) -> Option<Vec<f64>> {
    let n = nominal.len();
    let (mut is, mut js, mut vs, mut b) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for r in rows.iter().zip(kept).filter(|(_, &k)| k).map(|(r, _)| r) {
        for (&c, v) in r.cols.iter().zip(r.vals) {
            if v != 0.0 {
                is.push(b.len());
                js.push(c);
                vs.push(v);
            }
        }
        b.push(r.b);
    }
    let a = CscMatrix::new_from_triplets(b.len(), n, is, js, vs);
    let mut p = CscMatrix::identity(n);
    p.nzval.iter_mut().for_each(|x| *x = 2.0);
    let q: Vec<f64> = nominal.iter().map(|x| -2.0 * x).collect();
    let cones = [SupportedConeT::NonnegativeConeT(b.len())];
    let mut solver = DefaultSolver::new(&p, &q, &a, &b, &cones, settings).ok()?;
    solver.solve();
    matches!(
        solver.solution.status,
        SolverStatus::Solved | SolverStatus::AlmostSolved
    )
    .then(|| solver.solution.x.clone())
}

/// The CLF on every robot, then the certificate over all of them.
#[derive(Clone, Debug)]
struct ClfCbf(Gains);

impl Planner for ClfCbf {
    fn plan(&mut self, world: &World<'_>, out: &mut [Evaluation]) {
        let clf = self.0.clf();
        let mut commands: Vec<Command> = world
            .robots
            .iter()
            .map(|r| clf.command(r.pose, r.goal))
            .collect();
        let pairs: Vec<(usize, usize)> = (0..world.robots.len())
            .flat_map(|i| world.sensed(i).filter(move |&j| j > i).map(move |j| (i, j)))
            .collect();
        let poses: Vec<Pose> = world.robots.iter().map(|r| r.pose).collect();
        let ds = 2.0 * world.params.safe_radius + 2.0 * self.0.projection_distance;
        self.0.certify(ds, &poses, &pairs, &mut commands);
        for (e, command) in out.iter_mut().zip(commands) {
            *e = Evaluation {
                command,
                ..Evaluation::default()
            };
        }
    }

    fn clone_box(&self) -> Box<dyn Planner> {
        Box::new(self.clone())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::planner::Spec;
    use crate::scenario::Scenario;
    use crate::testing::{assert_close, test};
    use std::f64::consts::PI;


    fn command(v: f64, omega: f64) -> Command {
        Command { v, omega }
    }

    /// `D_s` of the source's default `safety_radius = 0.15` (= 2r, r = 0.075) and `d`.
    const DS: f64 = 0.15 + 2.0 * 0.05;

    /// Two robots head-on, their look-ahead points 0.3 m apart on the x axis, each driving at
    /// 0.15 m/s: one constraint binds, `0.6 (ẋ₁ − ẋ₂) ≤ γ h³` with `h = 0.3² − 0.25²`, and the
    /// program's solution is the projection of the nominal velocities on it: by symmetry each
    /// look-ahead point slows to `γ h³ / 1.2` and neither turns. The Robotarium's
    /// `create_uni_barrier_certificate(safety_radius=0.15)` (robotarium_python_simulator at
    /// commit b23069e, with cvxopt 1.3.3) gives 0.001733112 at the source's solver tolerances
    /// (1e-2) and 0.0017330729166671 at 1e-12. Tolerance 1e-8: the interior-point solver's
    /// accuracy (Clarabel's 1e-8 gaps) on speeds of 0.15.
    #[test]
    fn head_on_the_binding_constraint_is_projected_on() {
        let g = Gains::default();
        let poses = [Pose::new(-0.2, 0.0, 0.0), Pose::new(0.2, 0.0, PI)];
        let mut commands = [command(0.15, 0.0), command(0.15, 0.0)];
        g.certify(DS, &poses, &[(0, 1)], &mut commands);
        let h: f64 = 0.3 * 0.3 - DS * DS;
        let expected = 100.0 * h * h * h / 1.2;
        assert_close!(expected, 0.001_733_072_916_667_078, 1e-15);
        for c in commands {
            assert_close!(c.v, expected, 1e-8);
            assert_close!(c.omega, 0.0, 1e-8);
        }
    }

    /// Four robots crossing, with the CLF's commands toward goals across the middle: several
    /// constraints and the octagon bind at once. The expected commands are the Robotarium's
    /// (`create_pose_controller_clf()` then `create_uni_barrier_certificate(safety_radius=0.15)`
    /// on these poses, as above, cvxopt at 1e-12 tolerances). Tolerance 1e-6 on speeds of
    /// 0.2 m/s and turn rates of 4 rad/s (= 0.2 / d): Clarabel stops at relative gaps of 1e-8
    /// and the turn rate divides the look-ahead point's velocity by d = 0.05.
    #[test]
    fn four_robots_get_the_robotariums_commands() {
        let g = Gains::default();
        let poses = [
            Pose::new(-0.3, 0.0, 0.1),
            Pose::new(0.3, 0.02, 3.0),
            Pose::new(0.0, 0.25, -1.2),
            Pose::new(0.05, -0.3, 1.7),
        ];
        let goals = [
            Pose::new(0.6, 0.0, 0.0),
            Pose::new(-0.6, 0.0, PI),
            Pose::new(0.0, -0.6, -PI / 2.0),
            Pose::new(0.0, 0.6, PI / 2.0),
        ];
        let mut commands: Vec<Command> = poses
            .iter()
            .zip(&goals)
            .map(|(&p, &q)| g.clf().command(p, q))
            .collect();
        let nominal = [
            (0.156_608_993_168_405_93, -0.064_590_606_316_077_63),
            (0.154_299_483_876_883_05, 0.108_581_259_487_941_6),
            (0.146_960_827_306_245_27, -0.248_365_194_166_757_37),
            (0.157_996_336_983_952_9, -0.038_165_009_829_468_21),
        ];
        for (c, (v, omega)) in commands.iter().zip(nominal) {
            assert_close!(c.v, v, 1e-12);
            assert_close!(c.omega, omega, 1e-12);
        }
        let pairs = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)];
        g.certify(DS, &poses, &pairs, &mut commands);
        let expected = [
            (0.036_311_580_156_580_744, -0.259_599_634_719_006_16),
            (-0.005_732_827_221_960_628, 0.020_361_002_737_897_704),
            (0.003_668_243_477_377_284_7, 0.166_494_592_384_538_62),
            (0.058_694_341_526_177_56, 0.375_984_535_529_009_8),
        ];
        for (c, (v, omega)) in commands.iter().zip(expected) {
            assert_close!(c.v, v, 1e-6);
            assert_close!(c.omega, omega, 1e-6);
        }
    }

    /// Leaving out the rows out of reach and putting back those the solution breaks gives the
    /// program's own solution. On 200 random scenes of 5 robots in a 1.5 m square (every pair
    /// a row, the octagon on or off, random commands up to 0.5 m/s and 3 rad/s), `solve`
    /// agrees with the program of every row at once solved to 1e-10 gaps (where that solver
    /// finishes: on at least 190 scenes); so does `solve` told a reach of 1 mm/s, too small,
    /// which leaves out rows the solution needs and puts them back. Tolerance 1e-4 m/s on the
    /// look-ahead points' velocities: an interior-point solution to Clarabel's default gaps
    /// ε = 1e-8 is within about √ε of the optimum.
    #[test]
    fn leaving_out_rows_out_of_reach_keeps_the_solution() {
        let mut rng = crate::testing::XorShift(0x05ee_dc1f);
        let tight = DefaultSettings {
            verbose: false,
            tol_gap_abs: 1e-10,
            tol_gap_rel: 1e-10,
            tol_feas: 1e-10,
            ..DefaultSettings::default()
        };
        let (mut left_out, mut put_back, mut compared) = (0, 0, 0);
        for k in 0..200 {
            let g = Gains {
                velocity_magnitude_limit: (k % 2 == 0).then_some(0.2),
                ..Gains::default()
            };
            let poses: Vec<Pose> = (0..5)
                .map(|_| Pose::new(rng.range(0.0, 1.5), rng.range(0.0, 1.5), rng.range(-PI, PI)))
                .collect();
            let pairs: Vec<(usize, usize)> =
                (0..5).flat_map(|i| (i + 1..5).map(move |j| (i, j))).collect();
            let commands: Vec<Command> = (0..5)
                .map(|_| command(rng.range(-0.5, 0.5), rng.range(-3.0, 3.0)))
                .collect();
            let (rows, nominal) = g.program(DS, &poses, &pairs, &commands);
            let octagon = g.velocity_magnitude_limit.map_or(f64::INFINITY, |m| m / COS_PI_8);
            let reach = (2.0 * nominal.iter().map(|x| x * x).sum::<f64>().sqrt()).min(octagon);
            left_out += rows.iter().filter(|r| r.b > r.most(reach)).count();
            let every = solve_kept(&nominal, &rows, &vec![true; rows.len()], tight.clone());
            if let Some(x) = &every {
                put_back += rows
                    .iter()
                    .filter(|r| r.b > r.most(1e-3) && r.at(x) > r.b - 1e-6)
                    .count();
            }
            let Some(every) = every else { continue };
            compared += 1;
            for short in [octagon, 1e-3] {
                let x = solve(&nominal, &rows, short).unwrap();
                for (a, b) in x.iter().zip(&every) {
                    assert_close!(*a, *b, 1e-4);
                }
            }
        }
        assert!(left_out >= 100, "{left_out}");
        assert!(put_back >= 10, "{put_back}");
        assert!(compared >= 190, "{compared}");
    }

    /// Two look-ahead points on top of each other: `h < 0` and the constraint `0 ≤ γ h³` has no
    /// solution, so every robot stops, as the source commands.
    #[test]
    fn an_infeasible_program_stops_every_robot() {
        let g = Gains::default();
        let poses = [Pose::new(0.0, 0.0, 0.0), Pose::new(0.1, 0.0, PI), Pose::new(3.0, 3.0, 0.0)];
        let mut commands = [command(0.1, 0.0), command(0.1, 0.0), command(0.1, 1.0)];
        g.certify(DS, &poses, &[(0, 1)], &mut commands);
        assert_eq!(commands, [Command::default(); 3]);
    }

    /// A robot alone keeps its command, beyond the octagon too, as the source returns it.
    #[test]
    fn a_robot_alone_keeps_its_command() {
        let mut commands = [command(3.0, 1.0)];
        Gains::default().certify(DS, &[Pose::new(0.0, 0.0, 0.0)], &[], &mut commands);
        assert_eq!(commands, [command(3.0, 1.0)]);
    }

    /// Two robots swapping places on a Robotarium-sized scene (r = 0.075 m, the source's step
    /// of 0.033 s), with the shared barrier off so that the certificate alone keeps them
    /// apart: their look-ahead points never come closer than `D_s = 0.25` m (less 1e-9 m for
    /// round-off), and the 2 cm offset lets them pass each other to their goals.
    #[test]
    fn two_robots_swapping_keep_their_look_ahead_points_apart() {
        let s = Scenario::from_json(
            r#"{"duration": 40, "dt": 0.033, "planner": "clf-cbf",
                "params": {"safe_radius": 0.075, "barrier_rate": null},
                "robots": [{"start": [-0.6, 0, 0], "goal": [0.6, 0, 0]},
                           {"start": [0.6, 0.02, 3.141592653589793],
                            "goal": [-0.6, 0.02, 3.141592653589793]}]}"#,
        )
        .unwrap();
        let g = Gains::default();
        let mut sim = crate::Simulation::new(&s).unwrap();
        let mut closest = f64::INFINITY;
        while sim.time() < s.duration {
            let r = sim.robots();
            closest = closest.min(g.ahead(r[0].pose).distance(g.ahead(r[1].pose)));
            sim.step();
        }
        assert!(closest >= DS - 1e-9, "{closest}");
        let report = sim.report();
        for r in &report.robots {
            assert!(r.position_error < 0.05, "{r:?}");
        }
    }

    /// A scene of the random sweep family (16 robots, 2 obstacles, 100 m across; the wheel
    /// and magnitude limits off so that the robots cross it) runs with the certificate and
    /// the shared barrier without NaN, and every robot reaches its pose: the bounds `γ h³` of
    /// far pairs (1e9 and more) leave the program solvable (`solve` keeps only the rows within
    /// reach).
    #[test]
    fn runs_a_sweep_scene_to_every_goal() {
        let recipe = crate::sweep::Recipe {
            robots: 16..=16,
            obstacles: 2..=2,
            ..crate::sweep::Recipe::default()
        };
        let mut s = crate::sweep::scenario(&recipe, 7).unwrap();
        s.planner = serde_json::from_str(
            r#"{"name": "clf-cbf", "wheel_velocity_limit": null,
                "velocity_magnitude_limit": null}"#,
        )
        .unwrap();
        let report = crate::run(&s).unwrap();
        assert_eq!(report.robots.len(), 16);
        for r in &report.robots {
            assert!(r.final_pose.iter().all(|x| x.is_finite()), "{r:?}");
            assert!(r.converged_at.is_some(), "{r:?}");
        }
        assert_eq!(report.violations, 0);
        assert_eq!(report.planner.as_deref(), Some("clf-cbf"));
    }

    /// A gain that is not a positive number, or one the planner does not have, is refused
    /// naming the field.
    #[test]
    fn refuses_bad_gains_naming_the_field() {
        for (json, field) in [
            (r#"{"name": "clf-cbf", "barrier_gain": 0}"#, "planner.barrier_gain"),
            (r#"{"name": "clf-cbf", "projection_distance": -0.1}"#, "planner.projection_distance"),
            (r#"{"name": "clf-cbf", "velocity_magnitude_limit": "fast"}"#, "planner.velocity_magnitude_limit"),
            (r#"{"name": "clf-cbf", "base_length": 0}"#, "planner.base_length"),
            (r#"{"name": "clf-cbf", "safety_radius": 0.2}"#, "planner.safety_radius"),
        ] {
            let spec: Spec = serde_json::from_str(json).unwrap();
            let e = spec.build().unwrap_err().to_string();
            assert!(e.starts_with(&format!("{field}:")), "{json}: {e}");
        }
    }
}
