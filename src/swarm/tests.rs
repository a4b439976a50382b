//! The tests of the virtual obstacle ([`super::cluster`]) and of the parked formations
//! (`parked.rs`).

use super::*;
use crate::se2::heading;
use crate::testing::assert_close;
use crate::testing::{test, XorShift};
use std::f64::consts::{FRAC_PI_2, PI};

fn at(x: f64, y: f64) -> Neighbour {
    Neighbour {
        position: DVec2::new(x, y),
        speed: 1.0,
        slowest_near: SLOWEST_UNKNOWN,
    }
}

/// `within` answers as the distance does, at random and on points a few ulps from the
/// border (where the squared comparison alone would err).
#[test]
fn within_is_the_distance_compared() {
    let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15);
    let mut disagree_squared = 0;
    for k in 0..20_000 {
        let p = DVec2::new(rng.unit() * 100.0 - 50.0, rng.unit() * 100.0 - 50.0);
        let r = 0.5 + rng.unit() * 20.0;
        let angle = rng.unit() * 2.0 * PI;
        let mut q = p + r * crate::maths::from_angle(angle);
        if k % 2 == 0 {
            // Anywhere in a disc of twice the radius.
            q = p + (rng.unit() * 2.0) * (q - p);
        } else {
            // A few ulps off the border, either way.
            let nudge = (k % 7) as i64 - 3;
            q.x = f64::from_bits((q.x.to_bits() as i64 + nudge) as u64);
        }
        assert_eq!(within(q, p, r), q.distance(p) <= r, "q {q}, p {p}, r {r}");
        disagree_squared += usize::from((q.distance_squared(p) <= r * r) != (q.distance(p) <= r));
    }
    // The border cases are real: the plain squared comparison gets some of them wrong.
    assert!(disagree_squared > 0);
}

#[test]
fn exit_avoids_the_nearest_neighbour_ahead_only() {
    let ahead = at(2.0, 0.0);
    let behind = [at(-7.0, 0.5), at(-7.0, -0.5)];
    let all = [at(3.0, 1.0), ahead, behind[0], behind[1]];
    let me = Approach {
        position: DVec2::ZERO,
        motion: DVec2::X,
        field: DVec2::X,
        goal_error: DVec2::new(-20.0, 0.0),
        goal_attitude: 0.0,
        speed: 1.0,
    };
    // Paper: the centroid of all five, behind the robot.
    let c = cluster(me, all, 8.0, 1.0, Avoidance::Paper).unwrap();
    assert_close!(c.center.x, -1.8, 1e-15);
    assert_close!(c.center.y, 0.2, 1e-15);
    assert_close!(c.distance, c.center.length(), 1e-15);
    // Exit: only the nearest neighbour ahead, at the midpoint (same speeds).
    let c = cluster(me, all, 8.0, 1.0, Avoidance::Exit).unwrap();
    assert_eq!(c.center, DVec2::new(1.0, 0.0));
    assert_eq!(c.distance, 1.0);
    // Moving away from everyone: nothing to avoid.
    assert_eq!(cluster(me, behind, 8.0, 1.0, Avoidance::Exit), None);
    // Out of range.
    assert_eq!(
        cluster(me, [at(9.0, 0.0)], 8.0, 1.0, Avoidance::Paper),
        None
    );
    // The clearance to the neighbour's safe disc (2 − 1) lets a settling robot go.
    assert_eq!(c.clearance, Some(1.0));
    let c = cluster(me, all, 8.0, 1.0, Avoidance::Paper).unwrap();
    assert_eq!(c.clearance, None);
}

/// `cluster`'s first pass for neighbours that move gives the answer of its pass over all
/// (the nearest to circle, by place and squared distance, no parked robot), and leaves the
/// answer to it where a neighbour in range is at rest: random crowds around a robot, with
/// equally near neighbours, neighbours on the range's border and robots at rest among them.
#[test]
fn the_pass_for_neighbours_that_move_is_the_pass_over_all() {
    let mut rng = crate::testing::XorShift(0x2545_F491_4F6C_DD1D);
    let (range, safe) = (8.0, 2.0);
    let (mut agreed, mut left) = (0, 0);
    for k in 0..5_000 {
        let me = Approach {
            motion: crate::maths::from_angle(rng.unit() * 2.0 * PI),
            field: crate::maths::from_angle(rng.unit() * 2.0 * PI),
            ..eastbound()
        };
        let count = 1 + (rng.next_u64() % 12) as usize;
        let mut neighbours: Vec<Neighbour> = (0..count)
            .map(|_| Neighbour {
                // On a coarse lattice, so that some are equally near; some on the border.
                position: if rng.unit() < 0.1 {
                    range * crate::maths::from_angle(rng.unit() * 2.0 * PI)
                } else {
                    DVec2::new(
                        (rng.unit() * 20.0 - 10.0).round(),
                        (rng.unit() * 20.0 - 10.0).round(),
                    )
                },
                speed: 1.0 + rng.unit(),
                slowest_near: SLOWEST_UNKNOWN,
            })
            .collect();
        if k % 3 == 0 {
            let j = (rng.next_u64() as usize) % count;
            neighbours[j].speed = 0.0;
        }
        let exit = nearest_exit(me, neighbours.iter().copied(), range, safe);
        match nearest_moving(me, neighbours.iter().copied(), range) {
            Some((nearest2, at)) => {
                agreed += 1;
                assert_eq!(nearest2.to_bits(), exit.0.to_bits(), "{neighbours:?}");
                if nearest2.is_finite() {
                    assert_eq!(at, exit.1, "{neighbours:?}");
                }
                assert_eq!(exit.2, f64::INFINITY);
            }
            None => {
                left += 1;
                assert!(neighbours
                    .iter()
                    .any(|n| n.speed == 0.0 && within(n.position, me.position, range)));
            }
        }
    }
    // Both cases seen often.
    assert!(agreed > 1_000 && left > 500, "{agreed} {left}");
}

/// A robot at the origin heading east at 2 m/s to a goal 10 m ahead.
fn eastbound() -> Approach {
    Approach {
        position: DVec2::ZERO,
        motion: DVec2::X,
        field: DVec2::X,
        goal_error: DVec2::new(-10.0, 0.0),
        goal_attitude: 0.0,
        speed: 2.0,
    }
}

/// A neighbour at rest beside the straight way to the goal is let go (a slot between
/// parked robots can be reached); one in the way is not; a moving one never is.
#[test]
fn a_parked_neighbour_aside_of_the_way_is_let_go() {
    let me = eastbound();
    let parked = |y: f64| Neighbour {
        position: DVec2::new(5.0, y),
        speed: 0.0,
        slowest_near: SLOWEST_UNKNOWN,
    };
    let safe = 2.0;
    let c = |y| cluster(me, [parked(y)], 8.0, safe, Avoidance::Exit).unwrap();
    assert_eq!(c(0.5).aside, 0.0); // in the way
    assert_eq!(c(2.0).aside, 0.0); // exactly the safe distance from the way
    assert!(c(2.5).aside > 0.0 && c(2.5).aside < 1.0); // the smooth band
    assert!(cluster(me, [parked(3.0)], 8.0, safe, Avoidance::Exit).is_none()); // clear
    let moving = Neighbour {
        speed: 2.0,
        slowest_near: SLOWEST_UNKNOWN,
        ..parked(3.0)
    };
    assert_eq!(
        cluster(me, [moving], 8.0, safe, Avoidance::Exit)
            .unwrap()
            .aside,
        0.0
    );
    assert_close!(
        segment_distance(DVec2::new(5.0, 3.0), DVec2::ZERO, me.goal()),
        3.0,
        0.0
    );
    assert_close!(
        segment_distance(DVec2::new(13.0, 4.0), DVec2::ZERO, me.goal()),
        5.0,
        0.0
    );
    assert_close!(
        segment_distance(DVec2::new(1.0, 1.0), DVec2::ZERO, DVec2::ZERO),
        2f64.sqrt(),
        0.0
    );
}

/// A parked neighbour in the way is circled when it stands alone and passed when another
/// parked robot stands within the range of it (a parked formation); a moving one is always
/// circled.
#[test]
fn parked_formations_are_passed() {
    let me = eastbound();
    let parked = |x: f64, y: f64| Neighbour {
        position: DVec2::new(x, y),
        speed: 0.0,
        slowest_near: SLOWEST_UNKNOWN,
    };
    let c = |ns: &[Neighbour]| cluster(me, ns.iter().copied(), 8.0, 2.0, Avoidance::Exit);
    assert!(c(&[parked(4.0, 0.5)]).is_some());
    assert!(c(&[parked(4.0, 0.5), parked(4.0, 5.5)]).is_none());
    // Another parked robot beyond the range of it: alone again.
    assert!(c(&[parked(4.0, 0.5), parked(4.0, 9.0)]).is_some());
    let moving = Neighbour {
        speed: 2.0,
        slowest_near: SLOWEST_UNKNOWN,
        ..parked(4.0, 0.5)
    };
    assert!(c(&[moving, parked(4.0, 5.5)]).is_some());
}

/// A robot near a robot of a parked formation lets go of the moving neighbour it would
/// circle: wholly within `SQUEEZED` safe distances of it, not at all beyond another half;
/// a lone parked robot, or robots that move, squeeze nothing.
#[test]
fn squeezed_among_parked_robots_a_robot_circles_no_one() {
    let me = eastbound();
    let safe = 2.0;
    let moving = Neighbour {
        speed: 2.0,
        ..at(4.0, 0.5)
    };
    // A parked robot behind the robot (never circled itself), `d` away, with another
    // parked robot 3 m beyond it.
    let parked = |d: f64, speed: f64| {
        [-d, -d - 3.0].map(|x| Neighbour {
            position: DVec2::new(x, 0.0),
            speed,
            slowest_near: SLOWEST_UNKNOWN,
        })
    };
    let squeezed = |d: f64, speed: f64, avoidance| {
        let [a, b] = parked(d, speed);
        cluster(me, [moving, a, b], 8.0, safe, avoidance)
            .unwrap()
            .squeezed
    };
    assert_eq!(squeezed(0.9 * SQUEEZED * safe, 0.0, Avoidance::Exit), 1.0);
    assert_eq!(squeezed(SQUEEZED * safe, 0.0, Avoidance::Exit), 1.0);
    let band = squeezed((SQUEEZED + 0.25) * safe, 0.0, Avoidance::Exit);
    assert!(band > 0.0 && band < 1.0, "{band}");
    assert_eq!(squeezed((SQUEEZED + 0.6) * safe, 0.0, Avoidance::Exit), 0.0);
    // Parked robots that move (as fast as the robot) are no formation.
    assert_eq!(squeezed(SQUEEZED * safe, 2.0, Avoidance::Exit), 0.0);
    // A lone parked robot.
    let [lone, _] = parked(SQUEEZED * safe, 0.0);
    let c = cluster(me, [moving, lone], 8.0, safe, Avoidance::Exit).unwrap();
    assert_eq!(c.squeezed, 0.0);
    // The paper's avoidance has no such rule.
    assert_eq!(squeezed(SQUEEZED * safe, 0.0, Avoidance::Paper), 0.0);
}

/// A robot steps away from a neighbour that presses on it, by at most the step in all,
/// and leaves alone the neighbours `reach` away or more.
#[test]
fn a_robot_makes_room_for_a_neighbour_that_presses_on_it() {
    let (safe, reach, step) = (2.0, PRESSED, ROOM);
    let room = |ns: &[Neighbour]| make_room(DVec2::ZERO, ns.iter().copied(), safe, reach, step);
    assert_eq!(room(&[at(-2.0, 0.0)]), DVec2::new(ROOM, 0.0));
    assert_eq!(room(&[at(0.0, PRESSED)]), DVec2::ZERO);
    assert_eq!(room(&[at(3.0, 0.0), at(0.0, -9.0)]), DVec2::ZERO);
    let between = room(&[at(2.3, 0.0)]);
    assert!(between.x < 0.0 && between.x > -ROOM && between.y == 0.0);
    // Pressed from two sides at once: still at most one step.
    let both = room(&[at(-2.0, 0.0), at(0.0, -2.0)]);
    // One rounding of the length of (step/√2, step/√2).
    assert_close!(both.length(), ROOM, 1e-15);
    assert_close!(both.x, both.y, 1e-15);
}

/// A neighbour at rest is circled about itself, one moving alike about the midpoint.
#[test]
fn the_virtual_obstacle_divides_the_gap_by_speed() {
    let p = DVec2::ZERO;
    let parked = Neighbour {
        position: DVec2::new(4.0, 0.0),
        speed: 0.0,
        slowest_near: SLOWEST_UNKNOWN,
    };
    let o = virtual_obstacle_between(p, 2.0, parked);
    assert_close!(o.x, 4.0 * 2.001 / 2.002, 1e-12);
    let alike = Neighbour {
        speed: 2.0,
        slowest_near: SLOWEST_UNKNOWN,
        ..parked
    };
    assert_eq!(
        virtual_obstacle_between(p, 2.0, alike),
        DVec2::new(2.0, 0.0)
    );
    // Both at rest: the midpoint, not 0/0.
    assert_eq!(
        virtual_obstacle_between(p, 0.0, parked),
        DVec2::new(2.0, 0.0)
    );
}

/// [`Cluster::distance`] with [`Avoidance::Exit`], taken as the neighbour's distance times
/// the share of the way, is the distance from the robot to the virtual obstacle, within
/// the rounding of the latter: `|p_i − p̃_o|` rounds the positions (about an ulp of the
/// largest coordinate, twice, for `p̃_o` and for the difference) where the product rounds
/// only lengths of the order of `d` (three or four half-ulps of `d`). Eight machine
/// epsilons of the coordinates and of `d` cover both, with room.
#[test]
fn the_distance_to_the_virtual_obstacle_is_a_share_of_the_neighbours() {
    let mut rng = XorShift(0x2545_F491_4F6C_DD1D);
    for _ in 0..10_000 {
        let scale = [1.0, 100.0, 10_000.0][(rng.unit() * 3.0) as usize];
        let p = DVec2::new(rng.range(-scale, scale), rng.range(-scale, scale));
        let d = rng.range(0.05, 7.95);
        let to = heading(rng.heading());
        // Both moving (a neighbour at rest aside of the way could be let go), the robot
        // heading for it: it is the one circled.
        let speed = rng.range(0.0, 20.0);
        let n = Neighbour {
            position: p + d * to,
            speed: speed * rng.range(0.2, 2.2),
            slowest_near: f64::INFINITY,
        };
        let me = Approach {
            position: p,
            motion: to,
            field: to,
            goal_error: DVec2::new(-1000.0, 0.0),
            goal_attitude: 0.0,
            speed,
        };
        let c = cluster(me, [n], 8.0, 2.0, Avoidance::Exit).expect("the neighbour is ahead");
        let tol = 8.0 * f64::EPSILON * (p.abs().max_element() + n.position.abs().max_element() + d);
        assert_close!(c.distance, p.distance(c.center), tol);
    }
}

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
    let gi = tangent_field(pi, heading(0.0), o, None);
    let gj = tangent_field(pj, heading(PI), o, None);
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
        let g = tangent_field(p, heading(t), DVec2::new(-0.5, 0.3), None);
        assert_close!(g.dot(p - DVec2::new(-0.5, 0.3)), 0.0, 1e-12);
        assert!(g.dot(heading(t + FRAC_PI_2)) >= 0.0);
    }
}
