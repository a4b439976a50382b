//! The paper's four examples (Section VI) as scenarios, shared by the command line and the
//! browser. Where the paper gives numbers they are used as printed; where it does not
//! (obstacle positions in Example 2, the formations of Examples 3 and 4) the choice is stated
//! on the preset.

use crate::error::Error;
use crate::obstacle::Obstacle;
use crate::params::Params;
use crate::scenario::{RobotSpec, Scenario};
use glam::DVec2;
use std::f64::consts::{FRAC_PI_2, PI};

mod teaching;
use teaching::{teach_obstacle, teach_one_robot, teach_two_robots};
pub use teaching::{TEACH_OMEGA_MAX, TEACH_V_MAX};

/// A named preset.
#[derive(Clone, Copy, Debug)]
pub struct Preset {
    /// The name used on the command line and in the page (`--preset NAME`).
    pub name: &'static str,
    /// One line on what it shows.
    pub summary: &'static str,
    build: fn() -> Scenario,
}

impl Preset {
    /// The scenario.
    #[must_use]
    pub fn scenario(&self) -> Scenario {
        (self.build)()
    }
}

/// Every preset, the default first.
pub const PRESETS: &[Preset] = &[
    Preset {
        name: "example4-obstacle-formation",
        summary: "Example 4: ten robots pass an obstacle (r_o = 5, R_o = 10) into a line formation, r_ij = 5, T = 25 s",
        build: example4,
    },
    Preset {
        name: "table1-free-space",
        summary: "Example 1 / Table I: six goals from (0, 0, 0) in free space, each an independent run, 60 s",
        build: table1,
    },
    Preset {
        name: "table2-obstacles",
        summary: "Example 2 / Table II: three starts to (0, 0, 0) around obstacles r_o = 1.5, R_o = 3, T = 20 s",
        build: table2,
    },
    Preset {
        name: "example3-line-swap",
        summary: "Example 3, scenario 1: five robots from one line formation to another, orientations kept, T = 15 s",
        build: example3_line,
    },
    Preset {
        name: "example3-circle-swap",
        summary: "Example 3, scenario 2: six robots swap antipodally on a circle, orientations kept, T = 15 s",
        build: example3_circle,
    },
    Preset {
        name: "formation-gap-grid",
        summary: "Not in the paper: twelve robots through a gap into a 4 × 3 grid of slots 5 r_ij apart, T = 90 s",
        build: formation_gap_grid,
    },
    // Teaching presets: small scenes at speeds a class can follow (TEACH_V_MAX, TEACH_OMEGA_MAX).
    Preset {
        name: "teach-one-robot",
        summary: "Teaching: one robot from (−30, 25, π/2) to (0, 0, 0), the scene of the paper's Fig. 1, at up to 2 m/s and 1 rad/s, T = 60 s",
        build: teach_one_robot,
    },
    Preset {
        name: "teach-obstacle",
        summary: "Teaching: one robot drives round an obstacle (r_o = 4, R_o = 8) to the far side, at up to 2 m/s and 1 rad/s, T = 60 s",
        build: teach_obstacle,
    },
    Preset {
        name: "teach-two-robots",
        summary: "Teaching: two robots meet head on and pass each other (r_ij = 1), at up to 2 m/s and 1 rad/s, T = 60 s",
        build: teach_two_robots,
    },
    // The "real robot" presets: the examples above with the limits of a small
    // differential-drive robot ([`real_robot`]).
    Preset {
        name: "real-example4-obstacle-formation",
        summary: "Real robot, Example 4: ten robots pass an obstacle into a line, with a small robot's limits (v_max = 2.1·r_ij per s, ω_max = 2.84 rad/s), T = 60 s",
        build: || real_robot(example4(), 60.0),
    },
    Preset {
        name: "real-table1-free-space",
        summary: "Real robot, Example 1 / Table I: six goals in free space, with a small robot's limits (v_max = 2.1·r_ij per s, ω_max = 2.84 rad/s), 90 s",
        build: || real_robot(table1(), 90.0),
    },
    Preset {
        name: "real-table2-obstacles",
        summary: "Real robot, Example 2 / Table II: three starts around obstacles, with a small robot's limits (v_max = 2.1·r_ij per s, ω_max = 2.84 rad/s), T = 60 s",
        build: || real_robot(table2(), 60.0),
    },
    Preset {
        name: "real-example3-line-swap",
        summary: "Real robot, Example 3, scenario 1: line to line, with a small robot's limits (v_max = 2.1·r_ij per s, ω_max = 2.84 rad/s), T = 90 s",
        build: || real_robot(example3_line(), 90.0),
    },
    Preset {
        name: "real-example3-circle-swap",
        summary: "Real robot, Example 3, scenario 2: antipodal swap on a circle, with a small robot's limits (v_max = 2.1·r_ij per s, ω_max = 2.84 rad/s), T = 60 s",
        build: || real_robot(example3_circle(), 60.0),
    },
    Preset {
        name: "real-formation-gap-grid",
        summary: "Real robot, not in the paper: twelve robots through a gap into a grid, with a small robot's limits (v_max = 2.1·r_ij per s, ω_max = 2.84 rad/s), T = 180 s",
        build: || real_robot(formation_gap_grid(), 180.0),
    },
];

/// The preset shown when nothing else is asked for.
pub const DEFAULT_PRESET: &str = "example4-obstacle-formation";

/// The name of a [`crowd`] of N robots is this followed by N (`crowd-1000`).
pub const CROWD_PREFIX: &str = "crowd-";

/// Looks a preset up by name: one of [`PRESETS`], or `crowd-N` for a [`crowd`] of N robots
/// (N = 1 … [`CROWD_MAX`], digits only).
///
/// # Errors
/// [`Error::UnknownPreset`] listing the names that exist.
pub fn preset(name: &str) -> Result<Scenario, Error> {
    if let Some(n) = crowd_size(name) {
        return Ok(crowd(n));
    }
    PRESETS
        .iter()
        .find(|p| p.name == name)
        .map(Preset::scenario)
        .ok_or_else(|| Error::UnknownPreset {
            name: name.to_owned(),
            available: PRESETS
                .iter()
                .map(|p| p.name)
                .chain([&*format!("{CROWD_PREFIX}N (N = 1 … {CROWD_MAX})")])
                .collect::<Vec<_>>()
                .join(", "),
        })
}

/// N of a name `crowd-N` within the crowd's range.
fn crowd_size(name: &str) -> Option<usize> {
    let digits = name.strip_prefix(CROWD_PREFIX)?;
    if digits.is_empty() || digits.len() > 5 || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    let n: usize = digits.parse().ok()?;
    (1..=CROWD_MAX).contains(&n).then_some(n)
}

fn robot(start: [f64; 3], goal: [f64; 3]) -> RobotSpec {
    RobotSpec { start, goal }
}

/// Table I: from `(0, 0, 0)` to six goals. The robots are independent runs (the paper's
/// Example 1 is one robot under six goals), drawn together.
fn table1() -> Scenario {
    let goals = [
        [0.0, 40.0, 0.0],
        [40.0, 40.0, FRAC_PI_2],
        [40.0, 0.0, -FRAC_PI_2],
        [40.0, -40.0, 0.0],
        [-20.0, -40.0, -FRAC_PI_2],
        [-40.0, 0.0, PI],
    ];
    Scenario {
        planner: crate::planner::Spec::default(),
        name: "Table I: motion planning in free space".into(),
        bounds: Some([-55.0, -55.0, 55.0, 55.0]),
        duration: 60.0,
        dt: 0.01,
        params: Params::default(),
        independent: true,
        robots: goals.iter().map(|g| robot([0.0, 0.0, 0.0], *g)).collect(),
        obstacles: vec![],
    }
}

/// Table II: three starts to `(0, 0, 0)`, `r_o = 1.5`, `R_o = 3`, `T = 20 s`. The paper does
/// not give the obstacle positions; each obstacle here sits on the obstacle-free path of one
/// robot (found by simulating without obstacles), so that every robot has to go around one.
fn table2() -> Scenario {
    let starts = [[0.0, 30.0, 0.0], [-30.0, 30.0, FRAC_PI_2], [-35.0, 0.0, PI]];
    let obstacle = |x: f64, y: f64| Obstacle {
        center: DVec2::new(x, y),
        radius: 1.5,
        influence: 3.0,
    };
    Scenario {
        planner: crate::planner::Spec::default(),
        name: "Table II: motion planning with obstacle avoidance".into(),
        bounds: Some([-45.0, -15.0, 15.0, 40.0]),
        duration: 20.0,
        dt: 0.01,
        params: Params::default(),
        independent: true,
        robots: starts.iter().map(|s| robot(*s, [0.0, 0.0, 0.0])).collect(),
        obstacles: TABLE2_OBSTACLES
            .iter()
            .map(|&[x, y]| obstacle(x, y))
            .collect(),
    }
}

/// Obstacle centres of the Table II preset: points on each robot's obstacle-free path
/// (see the test `table2_obstacles_block_the_free_paths`).
pub const TABLE2_OBSTACLES: [[f64; 2]; 3] = [[-9.2, 14.0], [-18.0, 13.0], [-19.6, 4.1]];

/// Twelve robots in a column at `x = −30` (`3·r_ij` apart, headings fanned out) drive through
/// the gap between two obstacles (`r_o = 5`, `R_o = 7`, centres 18 apart at `x = 0`) into a
/// grid of four columns and three rows of slots `5·r_ij` apart, parked facing east and west
/// by turns (Example 4's task with a grid of parking slots). The farthest slots lie behind
/// the nearest ones.
fn formation_gap_grid() -> Scenario {
    let robots = (0..12)
        .map(|k| {
            let (row, col) = ((k % 3) as f64, (3 - k / 3) as f64);
            let y = 3.0 * k as f64 - 16.5;
            let facing = if k % 2 == 0 { 0.0 } else { PI };
            robot(
                [-30.0, y, 0.25 * y / 16.5 * PI],
                [20.0 + 5.0 * col, 5.0 * (row - 1.0), facing],
            )
        })
        .collect();
    let obstacle = |y: f64| Obstacle {
        center: DVec2::new(0.0, y),
        radius: 5.0,
        influence: 7.0,
    };
    Scenario {
        planner: crate::planner::Spec::default(),
        name: "Formation: through a gap into a grid".into(),
        bounds: None,
        duration: 90.0,
        dt: 0.01,
        params: Params::default(),
        independent: false,
        robots,
        obstacles: vec![obstacle(-9.0), obstacle(9.0)],
    }
}

/// Example 3, scenario 1: five robots in a column at `x = −20` heading east swap to a column
/// at `x = 20` in reverse order, keeping their heading: every path crosses the others near
/// the middle.
fn example3_line() -> Scenario {
    Scenario {
        name: "Example 3: line to line with collision avoidance".into(),
        bounds: Some([-30.0, -30.0, 30.0, 30.0]),
        duration: 15.0,
        ..line_swap(5, 10.0)
    }
}

/// Example 3, scenario 2: six robots on a circle of radius 20, each facing the centre, swap
/// with the antipodal robot and end with their initial orientation.
fn example3_circle() -> Scenario {
    Scenario {
        name: "Example 3: antipodal swap on a circle".into(),
        bounds: Some([-30.0, -30.0, 30.0, 30.0]),
        duration: 15.0,
        ..circle_swap(6, 20.0)
    }
}

/// `n` robots evenly spaced on a circle of `radius` about the origin, each facing the centre,
/// swap with the antipodal robot and end with their initial heading (Example 3, scenario 2,
/// for any `n`). 120 s, default parameters.
#[must_use]
pub fn circle_swap(n: usize, radius: f64) -> Scenario {
    let robots = (0..n)
        .map(|k| {
            let a = 2.0 * PI * k as f64 / n as f64;
            let p = radius * crate::maths::from_angle(a);
            let facing = crate::se2::wrap_angle(a + PI);
            robot([p.x, p.y, facing], [-p.x, -p.y, facing])
        })
        .collect();
    swap(
        format!("{n} robots swap across a circle of radius {radius}"),
        robots,
    )
}

/// Neighbouring starts of a [`crowd`] are this many safe radii `r_ij` apart.
pub const CROWD_SPACING: f64 = 4.0;

/// A [`crowd`]'s speed limit `v_max` (m/s). Without one the field's speed grows with the
/// distance to the goal (`k_v·|Γ|`), thousands of m/s across a large circle: a robot would
/// cross the sensing radius `R_s` in one step and meet a neighbour the barrier never saw.
/// At this speed a step moves a robot `0.2` of the default `R_s = 20`.
pub const CROWD_MAX_SPEED: f64 = 20.0;

/// The most robots a [`crowd`] is meant for (the page's limit; the builder takes any `n`).
pub const CROWD_MAX: usize = 10_000;

/// A crowd of `n` robots swapping antipodally on a circle, headings kept ([`circle_swap`]), at
/// constant density: the circle grows with `n` so that neighbouring starts stay
/// [`CROWD_SPACING`]`·r_ij` apart (chord `2R·sin(π/n)`), so a robot senses about as many
/// neighbours at the start whatever `n`. The scenario of `dvf bench`. Default parameters
/// but for `v_max` = [`CROWD_MAX_SPEED`]; the duration is the time to cross the circle at
/// that speed plus 120 s (at `n = 10 000` the circle's radius is about 6 400).
#[must_use]
pub fn crowd(n: usize) -> Scenario {
    let spacing = CROWD_SPACING * Params::default().safe_radius;
    let radius = if n < 2 {
        0.5 * spacing
    } else {
        spacing / (2.0 * crate::maths::sin(PI / n as f64))
    };
    let mut s = Scenario {
        name: format!("crowd of {n}: antipodal swap on a circle of radius {radius:.1}"),
        ..circle_swap(n, radius)
    };
    s.params.v_max = Some(CROWD_MAX_SPEED);
    s.duration = (2.0 * radius / CROWD_MAX_SPEED + 120.0).round();
    s
}

/// A [`crowd`] of `n` robots with `m` obstacles (`r_o = 1`, `R_o = 3`) evenly spaced on the
/// circle of half its radius, which the robots cross on their way to the antipodes: the
/// scenario of `dvf bench --obstacles M`. Meant for `n ≥ 10` (a smaller crowd's goals lie in
/// the obstacles' rings).
#[must_use]
pub fn crowd_with_obstacles(n: usize, m: usize) -> Scenario {
    let mut s = crowd(n);
    let half = 0.5 * s.robots.first().map_or(0.0, |r| r.start_pose().p.length());
    s.obstacles = (0..m)
        .map(|k| Obstacle {
            center: half * crate::maths::from_angle(2.0 * PI * (k as f64 + 0.5) / m as f64),
            radius: 1.0,
            influence: 3.0,
        })
        .collect();
    s
}

/// `n` robots in a vertical line at `x = −20`, `spacing` apart and facing east, swap to the
/// line at `x = 20` in reversed order (Example 3, scenario 1, for any `n`). 120 s, default
/// parameters.
#[must_use]
pub fn line_swap(n: usize, spacing: f64) -> Scenario {
    let robots = (0..n)
        .map(|k| {
            let y = spacing * (k as f64 - 0.5 * (n as f64 - 1.0));
            robot([-20.0, y, 0.0], [20.0, -y, 0.0])
        })
        .collect();
    swap(format!("{n} robots swap between two lines"), robots)
}

/// A swap of [`circle_swap`] or [`line_swap`]: 120 s at dt = 0.01, default parameters, no
/// obstacles.
fn swap(name: String, robots: Vec<RobotSpec>) -> Scenario {
    Scenario {
        planner: crate::planner::Spec::default(),
        name,
        bounds: None,
        duration: 120.0,
        dt: 0.01,
        params: Params::default(),
        independent: false,
        robots,
        obstacles: vec![],
    }
}

/// Example 4: ten robots, an obstacle with `r_o = 5`, `R_o = 10`, safe radius `r_ij = 5`,
/// `T = 25 s`. The robots start in two columns of five on the left, facing east, and end side
/// by side in one line formation on the right, all facing east; the obstacle sits between
/// them, on the paths of the middle robots.
fn example4() -> Scenario {
    let params = Params {
        safe_radius: 5.0,
        avoid_radius: 6.0,
        ..Params::default()
    };
    let robots = (0..10)
        .map(|k| {
            let col = (k / 5) as f64;
            let row = (k % 5) as f64;
            let start = [-60.0 - 20.0 * col, -40.0 + 20.0 * row, 0.0];
            // Goals in the order of the starts' heights, so that neighbours stay neighbours.
            let slot = 2.0 * row + col;
            let goal = [40.0, -67.5 + 15.0 * slot, 0.0];
            robot(start, goal)
        })
        .collect();
    Scenario {
        planner: crate::planner::Spec::default(),
        name: "Example 4: obstacle and collision avoidance into a line".into(),
        bounds: Some([-95.0, -80.0, 60.0, 80.0]),
        duration: 25.0,
        dt: 0.01,
        params,
        independent: false,
        robots,
        obstacles: vec![Obstacle {
            center: DVec2::new(-10.0, 0.0),
            radius: 5.0,
            influence: 10.0,
        }],
    }
}

/// The "real robot" the `real-` presets carry: a small differential-drive robot (the
/// TurtleBot3 Burger's published limits: 0.22 m/s, 2.84 rad/s, a footprint of radius
/// 0.105 m) scaled so that its footprint is the scene's safe radius `r_ij`.
/// Scaling lengths keeps turn rates and speeds in footprints per second: `v_max` is
/// `0.22/0.105 ≈ 2.1` safe radii per second and `ω_max` is 2.84 rad/s whatever the scale.
pub const REAL_ROBOT: RealRobot = RealRobot {
    speed: 0.22,
    turn_rate: 2.84,
    radius: 0.105,
};

/// A robot's limits as its maker gives them, in metres and seconds ([`REAL_ROBOT`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RealRobot {
    /// Top speed (m/s).
    pub speed: f64,
    /// Top turn rate (rad/s).
    pub turn_rate: f64,
    /// Radius of its footprint (m).
    pub radius: f64,
}

impl RealRobot {
    /// `(v_max, ω_max)` of this robot scaled so that its footprint is `safe_radius` long.
    #[must_use]
    pub fn limits(&self, safe_radius: f64) -> (f64, f64) {
        (self.speed * safe_radius / self.radius, self.turn_rate)
    }
}

/// `s` with the limits of [`REAL_ROBOT`] scaled to its safe radius, run for `duration` s (the
/// limited robots take longer than the paper's `T`), named as the original with "(a small
/// robot's limits)".
fn real_robot(mut s: Scenario, duration: f64) -> Scenario {
    let (v_max, omega_max) = REAL_ROBOT.limits(s.params.safe_radius);
    s.params.v_max = Some(v_max);
    s.params.omega_max = Some(omega_max);
    s.duration = duration;
    s.name = format!("{} (a small robot's limits)", s.name);
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::test;

    /// Neighbouring starts stay `CROWD_SPACING·r_ij` apart whatever the crowd's size, and the
    /// scenario is valid.
    #[test]
    fn a_crowd_keeps_its_density() {
        for n in [2, 3, 10, 1000, CROWD_MAX] {
            let s = crowd(n);
            let (a, b) = (s.robots[0].start_pose().p, s.robots[1].start_pose().p);
            crate::testing::assert_close!(a.distance(b), CROWD_SPACING, 1e-9);
            assert_eq!(s.robots.len(), n);
            if n <= 1000 {
                s.validate().unwrap();
            }
        }
    }

    #[test]
    fn crowd_names_give_crowds() {
        assert_eq!(preset("crowd-40").unwrap(), crowd(40));
        assert_eq!(preset("crowd-10000").unwrap().robots.len(), 10_000);
        for bad in [
            "crowd-",
            "crowd-0",
            "crowd-10001",
            "crowd-+5",
            "crowd-5x",
            "crowd-99999999",
        ] {
            let e = preset(bad).unwrap_err().to_string();
            assert!(e.contains("crowd-N"), "{bad}: {e}");
        }
    }

    #[test]
    fn every_preset_is_valid_and_named_uniquely() {
        for (k, p) in PRESETS.iter().enumerate() {
            p.scenario()
                .validate()
                .unwrap_or_else(|e| panic!("{}: {e}", p.name));
            assert!(PRESETS[k + 1..].iter().all(|q| q.name != p.name));
        }
        assert!(preset(DEFAULT_PRESET).is_ok());
        assert!(preset("nope")
            .unwrap_err()
            .to_string()
            .contains("table1-free-space"));
    }
}
