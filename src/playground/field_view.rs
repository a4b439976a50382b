//! What the page draws of the field: `Γ` sampled on a grid around a robot (the arrows), and the
//! integral curves of a goal field (the paper's Fig. 1).
//!
//! Layouts (flat `f64`): field samples `[nx · ny · 4]`, `x, y, Γx, Γy`, row by row from `ymin`;
//! integral curves `[curves · points · 2]`, `x, y`.

use super::Live;
use crate::error::Error;
use crate::field::integral_curve;
use crate::se2::Pose;
use crate::swarm::Neighbour;

/// Values per field sample: `x, y, Γx, Γy`.
pub const FIELD_STRIDE: usize = 4;
/// Values per point of an integral curve: `x, y`.
pub const CURVE_STRIDE: usize = 2;
/// The largest field grid side.
pub const MAX_GRID_SIDE: usize = 200;
/// The largest number of integral curves per side (each is an RK4 run of its own).
pub const MAX_CURVE_SIDE: usize = 40;
/// Points kept per integral curve.
pub const CURVE_POINTS: usize = 81;
/// Integration step of the integral curves (field time units).
const CURVE_DT: f64 = 0.05;
/// `θ̃` decays like `e^{−t}` along a curve: 8 time units leave `e^{−8} ≈ 3e-4` of it.
const CURVE_TIME: f64 = 8.0;

impl Live {
    /// Samples, on an `nx × ny` grid over `bounds = [xmin, ymin, xmax, ymax]`, the field `Γ`
    /// that robot `index` would follow at each point with its current attitude and goal,
    /// among the obstacles and the other robots where they are now (what it senses from
    /// there). The arrows turn as the robot turns: the field is dynamic.
    ///
    /// The robots sensed from a sample come from a [`crate::grid::Cells`] table of the robots
    /// (cells `R_s` wide): O(robots + samples), the same sets in the same order as a scan.
    ///
    /// # Errors
    /// An index out of range, a grid side outside `2..=MAX_GRID_SIDE`, or bad bounds.
    pub fn sample_field(
        &mut self,
        index: usize,
        bounds: [f64; 4],
        nx: usize,
        ny: usize,
    ) -> Result<&[f64], Error> {
        let robot = *self.robot(index)?;
        grid_side("nx", nx)?;
        grid_side("ny", ny)?;
        check_bounds(bounds)?;
        let rs = self.sim.params().sense_radius;
        let independent = self.scenario.independent;
        let robots = self.sim.robots();
        if !independent {
            self.field_points.clear();
            self.field_points.extend(robots.iter().map(|r| r.pose.p));
            self.field_cells.build(&self.field_points, rs);
        }
        let [x0, y0, x1, y1] = bounds;
        self.field.clear();
        for j in 0..ny {
            let y = y0 + (y1 - y0) * j as f64 / (ny - 1) as f64;
            for i in 0..nx {
                let x = x0 + (x1 - x0) * i as f64 / (nx - 1) as f64;
                let pose = Pose::new(x, y, robot.pose.theta);
                self.neighbours.clear();
                if !independent {
                    self.near.clear();
                    let points = &self.field_points;
                    self.field_cells
                        .within(points, pose.p, rs, index, &mut self.near);
                    self.neighbours.extend(self.near.iter().map(|&k| {
                        let o = &robots[k as usize];
                        Neighbour {
                            position: o.pose.p,
                            speed: o.last.command.v.abs(),
                            slowest_near: crate::swarm::SLOWEST_UNKNOWN,
                        }
                    }));
                }
                let e = self.sim.evaluate_at_with(
                    pose,
                    pose.error_to(robot.goal),
                    robot.last.command.v.abs(),
                    &self.neighbours,
                    &mut self.sensed_obstacles,
                );
                self.field.extend_from_slice(&[x, y, e.field.x, e.field.y]);
            }
        }
        Ok(&self.field)
    }

    /// Integral curves of the goal field of robot `index`'s goal (the paper's Fig. 1): from
    /// each point of an `n × n` grid over `bounds`, with attitude `theta0` (rad) at the start,
    /// [`CURVE_POINTS`] points each.
    ///
    /// # Errors
    /// An index out of range, `n` outside `2..=MAX_CURVE_SIDE`, bad bounds or a non-finite
    /// `theta0`.
    pub fn integral_curves(
        &mut self,
        index: usize,
        theta0: f64,
        bounds: [f64; 4],
        n: usize,
    ) -> Result<&[f64], Error> {
        let goal = self.robot(index)?.goal;
        if !(2..=MAX_CURVE_SIDE).contains(&n) {
            return Err(Error::Invalid {
                field: "n".into(),
                message: format!("must be between 2 and {MAX_CURVE_SIDE}, not {n}"),
            });
        }
        check_bounds(bounds)?;
        if !theta0.is_finite() {
            return Err(Error::Invalid {
                field: "theta0".into(),
                message: format!("must be a finite angle in radians, not {theta0}"),
            });
        }
        let steps = (CURVE_TIME / CURVE_DT).round() as usize;
        let every = steps / (CURVE_POINTS - 1);
        let [x0, y0, x1, y1] = bounds;
        self.curves.clear();
        for j in 0..n {
            // Cell centres, so that no curve starts on the border.
            let y = y0 + (y1 - y0) * (j as f64 + 0.5) / n as f64;
            for i in 0..n {
                let x = x0 + (x1 - x0) * (i as f64 + 0.5) / n as f64;
                let curve = integral_curve(Pose::new(x, y, theta0), goal, CURVE_DT, steps);
                for p in curve.iter().step_by(every).take(CURVE_POINTS) {
                    self.curves.extend_from_slice(&[p.x, p.y]);
                }
            }
        }
        Ok(&self.curves)
    }

    /// The last field samples ([`Live::sample_field`]).
    #[must_use]
    pub fn field(&self) -> &[f64] {
        &self.field
    }
    /// The last integral curves ([`Live::integral_curves`]).
    #[must_use]
    pub fn curves(&self) -> &[f64] {
        &self.curves
    }
}

fn grid_side(field: &str, n: usize) -> Result<(), Error> {
    if (2..=MAX_GRID_SIDE).contains(&n) {
        Ok(())
    } else {
        Err(Error::Invalid {
            field: field.into(),
            message: format!("must be between 2 and {MAX_GRID_SIDE}, not {n}"),
        })
    }
}

fn check_bounds(b: [f64; 4]) -> Result<(), Error> {
    let ok = b
        .iter()
        .all(|v| v.is_finite() && v.abs() <= crate::scenario::MAX_BOUNDS)
        && b[0] < b[2]
        && b[1] < b[3];
    if ok {
        Ok(())
    } else {
        Err(Error::Invalid {
            field: "bounds".into(),
            message: format!(
                "must be four finite numbers [xmin, ymin, xmax, ymax] with xmin < xmax and ymin < ymax, not {b:?}"
            ),
        })
    }
}
