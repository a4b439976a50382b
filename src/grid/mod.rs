//! Neighbourhood structures: what is near each robot, at O(N) cost for a bounded density.
//!
//! Everything in the method that couples robots has a finite reach: a robot senses the robots
//! within `R_s` (eq. `eq_nonholo_controller_co_avoid` sums over the sensed set only), and the
//! safety metrics look at pairs closer than `2·r_ij`. A grid of square cells no smaller than
//! that reach puts every robot's neighbours in its own cell and the eight around it, so a step
//! looks at a bounded number of candidates per robot instead of all `N − 1`.
//!
//! - [`Cells`] (`cells.rs`): the one cell table (points counting-sorted into hashed cells);
//!   the playground's field view queries it for the robots near each sample point;
//! - [`Neighbours`] (`neighbours.rs`): per-robot lists built on it, in ascending index, so
//!   that the neighbours reach the controller in the same order as a scan of all robots and
//!   sums over them (the centroid of eq. `eq_tilde_p_o`) give the same bits;
//! - [`ObstacleCells`] (`obstacles.rs`): the obstacles near any point, hashed the same way;
//! - [`closest_pair_below`], [`min_pair_distance`] (`pairs.rs`): pair queries.
//!
//! Rebuilds allocate nothing once the buffers have grown to the swarm's size.

mod cells;
mod neighbours;
mod obstacles;
mod pairs;

pub use cells::Cells;
pub use neighbours::Neighbours;
pub use obstacles::{Candidates, ObstacleCells};
pub use pairs::{closest_pair_below, min_pair_distance};

/// Up to this many robots a scan over all pairs costs less than building cells (the paper's
/// examples have ten): [`Neighbours::build`] and every other robot query below it scan.
pub const FEW_ROBOTS: usize = 32;

/// Up to this many obstacles, [`ObstacleCells`] lists them all for every point: testing them
/// costs less than finding a cell.
pub const FEW_OBSTACLES: usize = 8;

#[cfg(test)]
mod tests {
    use super::cells::floor;
    use super::*;
    use crate::testing::test;
    use crate::testing::XorShift;
    use glam::DVec2;

    /// Every list equals the scan over all robots, in the same (ascending) order.
    fn check(points: &[DVec2], reach: f64) {
        let mut g = Neighbours::new();
        g.build(points, reach);
        for (i, p) in points.iter().enumerate() {
            let scan: Vec<u32> = (0..points.len())
                .filter(|&j| j != i && points[j].distance_squared(*p) <= reach * reach)
                .map(|j| j as u32)
                .collect();
            assert_eq!(g.of(i), &scan[..], "robot {i} at {p:?}");
        }
        // Found on threads, the same lists: three threads (twelve chunks, some of them empty
        // for the smaller sets), built twice so that the second build reuses the chunks'
        // buffers from a different reach.
        #[cfg(not(target_arch = "wasm32"))]
        {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(3)
                .build()
                .unwrap();
            let mut t = Neighbours::new();
            pool.install(|| {
                t.build_on_threads(points, 2.0 * reach + 1.0);
                t.build_on_threads(points, reach);
            });
            for i in 0..points.len() {
                assert_eq!(t.of(i), g.of(i), "robot {i}, on threads");
            }
        }
    }

    #[test]
    fn lists_equal_the_scan_over_all_pairs() {
        let mut rng = XorShift(0x9E37_79B9_7F4A_7C15_u64);
        let mut next = move || rng.unit();
        for (n, side, reach) in [
            (300, 100.0, 7.0),
            (50, 1e6, 3.0),
            (80, 5.0, 20.0),
            (400, 1e7, 1e-3),
            (200, 50.0, 0.5),
        ] {
            let points: Vec<DVec2> = (0..n)
                .map(|_| DVec2::new(next() * side, next() * side))
                .collect();
            check(&points, reach);
        }
        // Points exactly at the reach, on cell borders, coincident, and non-finite.
        let mut points: Vec<DVec2> = (0..10).map(|k| DVec2::new(2.0 * k as f64, 0.0)).collect();
        points.push(DVec2::new(4.0, 0.0));
        points.push(DVec2::new(f64::NAN, 1.0));
        points.push(DVec2::new(f64::INFINITY, 1.0));
        check(&points, 2.0);
        check(&points, 0.0);
        check(&[], 1.0);
        check(&[DVec2::ZERO], 1.0);
        // The same cases in rows far apart: more robots than the scan takes, so the cells.
        let rows: Vec<DVec2> = (0..4)
            .flat_map(|r| {
                points
                    .iter()
                    .map(move |p| *p + DVec2::new(0.0, 100.0 * r as f64))
            })
            .collect();
        assert!(rows.len() > FEW_ROBOTS);
        check(&rows, 2.0);
        check(&rows, 0.0);
    }

    /// `list_all_near` answers exactly whether the lists built at the old positions hold every
    /// robot now within the reach of the robot asked about, whenever the others have moved
    /// less than the skin: each robot moved by up to half the skin, a few by up to the whole,
    /// and the robot asked about anywhere near. The answer is compared with the lists
    /// themselves, robot by robot (an exact comparison of sets).
    #[test]
    fn lists_around_a_moved_robot_are_checked_exactly() {
        let mut rng = XorShift(0x51_7CC1_B727_220A_u64);
        let mut next = move || rng.unit();
        let (reach, skin) = (3.0, 0.75);
        let built = reach + skin;
        let (mut kept, mut missed) = (0, 0);
        for (n, side) in [(200, 40.0), (400, 30.0), (100, 200.0)] {
            let was: Vec<DVec2> = (0..n)
                .map(|_| DVec2::new(next() * side, next() * side))
                .collect();
            let mut g = Neighbours::new();
            g.build(&was, built);
            for round in 0..40 {
                // Every robot a little, one in ten up to (not beyond) the whole skin.
                let mut now: Vec<DVec2> = was
                    .iter()
                    .map(|&p| {
                        let far = if next() < 0.1 { skin } else { 0.5 * skin };
                        let (a, r) = (next() * std::f64::consts::TAU, next() * far * 0.999);
                        p + r * DVec2::new(a.cos(), a.sin())
                    })
                    .collect();
                let j = round % n;
                // The robot asked about by up to three reaches.
                let (a, r) = (next() * std::f64::consts::TAU, next() * 3.0 * reach);
                now[j] = was[j] + r * DVec2::new(a.cos(), a.sin());
                let all_listed = (0..n).all(|i| {
                    i == j
                        || now[i].distance_squared(now[j]) > reach * reach
                        || g.of(j).contains(&(i as u32))
                });
                assert_eq!(
                    g.list_all_near(&was, |i| now[i], j, reach, built),
                    all_listed,
                    "{n} robots in {side}, round {round}"
                );
                if all_listed {
                    kept += 1;
                } else {
                    missed += 1;
                }
            }
        }
        // Both answers were asked for.
        assert!(kept > 10 && missed > 10, "kept {kept}, missed {missed}");
        // The scan over all pairs keeps no cells: rebuild.
        let few = [DVec2::ZERO, DVec2::X];
        let mut g = Neighbours::new();
        g.build(&few, built);
        assert!(!g.list_all_near(&few, |i| few[i], 0, reach, built));
    }

    /// The closest pair below a limit and the smallest distance are those of the scan over
    /// all pairs (same pair, same bits), on random points of several densities.
    #[test]
    fn pair_queries_equal_the_scan() {
        let mut rng = XorShift(0x2545_F491_4F6C_DD1D_u64);
        let mut next = move || rng.unit();
        let mut search = Neighbours::new();
        for (n, side) in [(2, 10.0), (40, 10.0), (300, 100.0), (500, 1e5), (60, 1e7)] {
            let points: Vec<DVec2> = (0..n)
                .map(|_| DVec2::new(next() * side, next() * side))
                .collect();
            let mut scan = f64::INFINITY;
            for j in 0..n {
                for i in 0..j {
                    scan = scan.min(points[i].distance(points[j]));
                }
            }
            assert_eq!(
                min_pair_distance(&points, 1.0, &mut search),
                scan,
                "{n} in {side}"
            );
            for limit in [0.5 * scan, scan, 1.5 * scan, side / 10.0, 2.0 * side] {
                let brute = points.iter().enumerate().find_map(|(j, b)| {
                    points[..j].iter().enumerate().find_map(|(i, a)| {
                        let d = a.distance(*b);
                        (d < limit).then_some((i, j, d))
                    })
                });
                assert_eq!(
                    closest_pair_below(&points, limit),
                    brute,
                    "{n} in {side}, {limit}"
                );
            }
        }
        assert!(min_pair_distance(&[DVec2::ONE], 1.0, &mut search).is_nan());
        assert!(min_pair_distance(&[DVec2::ONE, DVec2::NAN], 1.0, &mut search).is_nan());
        assert_eq!(closest_pair_below(&[DVec2::ONE, DVec2::ONE], 0.0), None);
    }

    /// The obstacle cells list, for any point, every obstacle whose surface is within the
    /// reach, in ascending order, with no repeats; the same set as a scan, after the caller's
    /// distance test.
    #[test]
    fn obstacle_cells_cover_the_reach() {
        use crate::Obstacle;
        let mut rng = XorShift(0x1234_5678_9ABC_DEF1_u64);
        let mut next = move || rng.unit();
        for (m, side, reach, rmax) in [
            (40, 200.0, 20.0, 8.0),
            (200, 1_000.0, 5.0, 3.0),
            (10, 100.0, 0.5, 60.0),
            (30, 1e6, 20.0, 1e4),
        ] {
            let obstacles: Vec<Obstacle> = (0..m)
                .map(|_| {
                    let radius = 0.1 + next() * rmax;
                    Obstacle {
                        center: DVec2::new(next() * side, next() * side),
                        radius,
                        influence: 2.0 * radius,
                    }
                })
                .collect();
            let cells = ObstacleCells::build(&obstacles, reach);
            for _ in 0..2_000 {
                let p = DVec2::new(next() * side * 1.1 - 0.05 * side, next() * side);
                let near: Vec<usize> = cells.near(p).collect();
                assert!(near.windows(2).all(|w| w[0] < w[1]), "{near:?}");
                let got: Vec<usize> = near
                    .into_iter()
                    .filter(|&k| obstacles[k].clearance(p) <= reach)
                    .collect();
                let scan: Vec<usize> = (0..m)
                    .filter(|&k| obstacles[k].clearance(p) <= reach)
                    .collect();
                assert_eq!(got, scan, "{p:?}, reach {reach}");
            }
        }
        let all = ObstacleCells::all(3);
        assert_eq!(
            all.near(DVec2::new(1e7, -1e7)).collect::<Vec<_>>(),
            [0, 1, 2]
        );
        assert_eq!(ObstacleCells::build(&[], 5.0).near(DVec2::ZERO).count(), 0);
    }

    #[test]
    fn floor_is_the_library_floor() {
        for x in [
            0.0,
            -0.0,
            0.5,
            -0.5,
            1.0,
            -1.0,
            -1e-300,
            2.5e15,
            -2.5e15 - 0.5,
            9.3e18,
            -9.3e18,
            f64::MAX,
            f64::MIN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ] {
            assert_eq!(floor(x), x.floor() as i64, "{x}");
        }
    }

    #[test]
    fn a_rebuild_reuses_the_buffers() {
        let points: Vec<DVec2> = (0..100)
            .map(|k| DVec2::new((k % 10) as f64, (k / 10) as f64))
            .collect();
        let mut g = Neighbours::new();
        g.build(&points, 1.5);
        let (start, order, list, ptr) = g.buffers();
        let scaled: Vec<DVec2> = points.iter().map(|p| *p * 0.999).collect();
        g.build(&scaled, 1.5);
        let (start_now, order_now, list_now, ptr_now) = g.buffers();
        assert_eq!(order, order_now);
        assert_eq!(list, list_now);
        assert_eq!(ptr, ptr_now);
        assert!(start_now >= start);
    }
}
