//! The tests of the barrier: its limits, its filter and its steering.

use super::*;
use crate::se2::heading;
use crate::testing::{assert_close, test, XorShift};
use crate::unicycle::{chord, integrate};

/// The constraints derived once give the same bits as deriving them for each direction
/// ([`speed_limits`], the definition).
#[test]
fn constraints_derived_once_equal_the_limits_of_each_direction() {
    let mut rng = XorShift(0x2545_F491_4F6C_DD1D_u64);
    let mut next = move || rng.unit() * 2.0 - 1.0;
    let (dt, a, safe) = (0.01, 0.05, 2.0);
    let mut constraints = Constraints::new();
    for _ in 0..500 {
        let p = DVec2::new(next() * 5.0, next() * 5.0);
        let neighbours: Vec<DVec2> = (0..4)
            .map(|_| DVec2::new(next() * 8.0, next() * 8.0))
            .collect();
        let obstacles = [Obstacle {
            center: DVec2::new(next() * 8.0, next() * 8.0),
            radius: 1.0,
            influence: 2.0,
        }];
        constraints.derive(p, a, safe, neighbours.iter().copied(), &obstacles);
        for _ in 0..2 {
            let direction = chord(next() * 3.0, next() * 5.0, dt);
            let once = constraints.limits(direction, dt);
            let each = speed_limits(
                p,
                direction,
                dt,
                a,
                safe,
                neighbours.iter().copied(),
                &obstacles,
            );
            assert_eq!(once.lo.to_bits(), each.lo.to_bits());
            assert_eq!(once.hi.to_bits(), each.hi.to_bits());
        }
    }
}

/// A robot on an obstacle's surface (budget 0) whose step is tangent to it up to round-off
/// keeps its speed and slides along the surface, never inside the disc. Without
/// `ALONG_ROUND_OFF`, an inward component of 1e-16 would bound its speed by 0.
#[test]
fn a_step_along_a_limit_is_not_stopped_by_round_off() {
    let disc = Obstacle {
        center: DVec2::ZERO,
        radius: 4.0,
        influence: 5.0,
    };
    let (dt, a) = (0.01, 0.05);
    let on = disc.radius * (1.0 + MARGIN);
    // At (−on, 0) the tangent is ±Y; the chord leans inward (+X) by 1e-15.
    let p = DVec2::new(-on, 0.0);
    let chord = DVec2::new(1e-15, -1.0).normalize();
    let limits = speed_limits(p, chord, dt, a, 2.0, [], [&disc]);
    assert!(limits.hi.is_infinite(), "{limits:?}");
    // Driven along its heading tangent at 4 m/s, turning as a circle of the same radius
    // would, it stays outside the disc at every step.
    let params = Params {
        barrier_rate: Some(a / dt),
        ..Params::default()
    };
    let mut r = Pose::new(-on, 0.0, -std::f64::consts::FRAC_PI_2);
    let c = Command {
        v: 4.0,
        omega: 4.0 / on,
    };
    let mut travelled = 0.0;
    for _ in 0..2000 {
        let (c, _) = filter(
            &mut Constraints::new(),
            &params,
            dt,
            r,
            c,
            heading(r.theta),
            [],
            [&disc],
        );
        let next = integrate(r, c, dt);
        travelled += next.p.distance(r.p);
        r = next;
        assert!(disc.clearance(r.p) >= 0.0, "{}", disc.clearance(r.p));
    }
    // It went round (at the barrier's stop it would have travelled nothing).
    assert!(travelled > 70.0, "{travelled}");
}

/// Two robots driven straight at each other stop outside the safe distance at every step
/// and give way to the left, and a robot driven into a disc stops at its surface.
#[test]
fn head_on_robots_never_come_closer_than_the_safe_distance() {
    let (dt, a, ds) = (0.1, 0.5, 2.0);
    let p = Params {
        barrier_rate: Some(a / dt),
        safe_radius: ds / 2.0,
        ..Params::default()
    };
    let mut pi = Pose::new(-5.0, 0.0, 0.0);
    let mut pj = Pose::new(5.0, 0.0, std::f64::consts::PI);
    let wild = Command {
        v: 10.0,
        omega: 0.0,
    };
    let mut closest = f64::INFINITY;
    for _ in 0..200 {
        // Both commands from the same snapshot, as in the simulator.
        let (ci, _) = filter(
            &mut Constraints::new(),
            &p,
            dt,
            pi,
            wild,
            heading(pi.theta),
            [pj.p],
            [],
        );
        let (cj, _) = filter(
            &mut Constraints::new(),
            &p,
            dt,
            pj,
            wild,
            heading(pj.theta),
            [pi.p],
            [],
        );
        pi = integrate(pi, ci, dt);
        pj = integrate(pj, cj, dt);
        closest = closest.min(pi.p.distance(pj.p));
        assert!(pi.p.distance(pj.p) >= ds, "{}", pi.p.distance(pj.p));
    }
    // The barrier brakes, it does not freeze: each robot, held, turned left
    // (counter-clockwise) and drove off, the two on mirrored paths.
    assert!(pi.p.y > 10.0 && pj.p.y < -10.0, "{pi:?} {pj:?}");
    assert_close!((pi.p + pj.p).length(), 0.0, 1e-9);
    assert!(closest < 2.0 * ds, "{closest}");

    let disc = Obstacle {
        center: DVec2::new(3.0, 0.0),
        radius: 1.0,
        influence: 2.0,
    };
    let mut r = Pose::new(-5.0, 0.0, 0.0);
    let mut closest = f64::INFINITY;
    for _ in 0..200 {
        let (c, _) = filter(
            &mut Constraints::new(),
            &p,
            dt,
            r,
            wild,
            heading(r.theta),
            [],
            [&disc],
        );
        r = integrate(r, c, dt);
        closest = closest.min(disc.clearance(r.p));
        assert!(disc.clearance(r.p) >= 0.0);
    }
    assert!(closest < 1.0 && r.p.y > 10.0, "{closest} {r:?}");
}

/// Random pairs, random speeds and turn rates: every step keeps the pair apart, including
/// when both reverse and turn fast, and zero speed is always allowed.
#[test]
fn any_commands_keep_any_pair_apart() {
    let mut rng = XorShift(0x2545_f491_4f6c_dd1d_u64);
    let mut next = move || rng.unit();
    let (dt, a, ds) = (0.02, 0.5, 2.0);
    let p = Params {
        barrier_rate: Some(a / dt),
        safe_radius: ds / 2.0,
        ..Params::default()
    };
    for _ in 0..2000 {
        let d0 = ds + 3.0 * next();
        let mut pi = Pose::new(0.0, 0.0, 7.0 * next());
        let mut pj = Pose::new(d0, 0.0, 7.0 * next());
        for _ in 0..20 {
            let ci = Command {
                v: 400.0 * (next() - 0.5),
                omega: 100.0 * (next() - 0.5),
            };
            let cj = Command {
                v: 400.0 * (next() - 0.5),
                omega: 100.0 * (next() - 0.5),
            };
            let li = speed_limits(pi.p, chord(pi.theta, ci.omega, dt), dt, a, ds, [pj.p], []);
            assert!(li.lo <= 0.0 && li.hi >= 0.0);
            let (fi, fj) = (
                filter(
                    &mut Constraints::new(),
                    &p,
                    dt,
                    pi,
                    ci,
                    DVec2::ZERO,
                    [pj.p],
                    [],
                )
                .0,
                filter(
                    &mut Constraints::new(),
                    &p,
                    dt,
                    pj,
                    cj,
                    DVec2::ZERO,
                    [pi.p],
                    [],
                )
                .0,
            );
            pi = integrate(pi, fi, dt);
            pj = integrate(pj, fj, dt);
            assert!(pi.p.distance(pj.p) >= ds);
        }
    }
}

/// A neighbour beyond [`neighbour_reach`] of the command's speed changes nothing: random
/// robots, commands and fields among neighbours up to 30 m away (the default `α` = 5 1/s,
/// speeds up to 30 m/s so that the reach varies from 2.8 m to 14 m), filtered with every
/// neighbour and with those within the reach only, give the same bits, command and chord.
#[test]
fn neighbours_beyond_the_reach_change_nothing() {
    let mut rng = XorShift(0x9E37_79B9_7F4A_7C15_u64);
    let mut next = move || rng.unit() * 2.0 - 1.0;
    let p = Params::default();
    let dt = 0.01;
    let (mut all, mut near) = (Constraints::new(), Constraints::new());
    let mut left_out = 0;
    for _ in 0..3000 {
        let pose = Pose::new(0.0, 0.0, 4.0 * next());
        let c = Command {
            v: 30.0 * next(),
            omega: 20.0 * next(),
        };
        let field = DVec2::new(next(), next()) * 3.0;
        let neighbours: Vec<DVec2> = (0..8)
            .map(|_| DVec2::new(next(), next()) * 30.0)
            .filter(|q| q.length() > 2.0 * p.safe_radius)
            .collect();
        let reach = neighbour_reach(&p, c.v);
        let within = || neighbours.iter().copied().filter(|q| q.length() <= reach);
        left_out += neighbours.len() - within().count();
        let a = filter(
            &mut all,
            &p,
            dt,
            pose,
            c,
            field,
            neighbours.iter().copied(),
            [],
        );
        let b = filter(&mut near, &p, dt, pose, c, field, within(), []);
        assert_eq!(a.0.v.to_bits(), b.0.v.to_bits(), "{pose:?} {c:?}");
        assert_eq!(a.0.omega.to_bits(), b.0.omega.to_bits(), "{pose:?} {c:?}");
        assert_eq!(a.1, b.1);
    }
    assert!(
        left_out > 5000,
        "the reach left out only {left_out} neighbours"
    );
    assert_eq!(
        neighbour_reach(
            &Params {
                barrier_rate: None,
                ..p
            },
            10.0
        ),
        0.0
    );
}
