//! Criterion benchmarks on the crowd of `dvf bench` (N robots swapping across a circle at
//! constant density), N ∈ {10, 100, 1000, 10000}: the goal field of every robot (eq.
//! `eq_Gamma_body`), the controller of every robot with the neighbours it senses, and a whole
//! simulation step (neighbour search, controllers, barrier, integration, metrics).
//!
//! Not part of `make test`; run with `cargo bench --bench crowd` (a few minutes on 2 cores),
//! or one group with e.g. `cargo bench --bench crowd -- step`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use dvf::field::goal_field_at;
use dvf::grid::Neighbours;
use dvf::presets::crowd;
use dvf::{command, Params, Pose, Simulation};
use glam::DVec2;
use std::hint::black_box;
use std::time::Duration;

const SIZES: [usize; 4] = [10, 100, 1000, 10_000];

/// The crowd's start and goal poses.
fn poses(n: usize) -> (Vec<Pose>, Vec<Pose>) {
    let s = crowd(n);
    s.robots
        .iter()
        .map(|r| (r.start_pose(), r.goal_pose()))
        .unzip()
}

fn field(c: &mut Criterion) {
    let mut g = c.benchmark_group("field");
    for n in SIZES {
        let (starts, goals) = poses(n);
        g.throughput(Throughput::Elements(n as u64));
        g.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| {
                let mut sum = DVec2::ZERO;
                for (p, q) in starts.iter().zip(&goals) {
                    sum += goal_field_at(*p, *q);
                }
                black_box(sum)
            });
        });
    }
    g.finish();
}

fn controller(c: &mut Criterion) {
    let params = Params::default();
    let mut g = c.benchmark_group("controller");
    for n in SIZES {
        let (starts, goals) = poses(n);
        let positions: Vec<DVec2> = starts.iter().map(|p| p.p).collect();
        let mut near = Neighbours::new();
        near.build(&positions, params.sense_radius);
        let sensed: Vec<Vec<DVec2>> = (0..n)
            .map(|i| near.of(i).iter().map(|&j| positions[j as usize]).collect())
            .collect();
        g.throughput(Throughput::Elements(n as u64));
        g.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| {
                let mut sum = 0.0;
                for i in 0..n {
                    let cmd = command(&params, starts[i], goals[i], &[], &sensed[i]);
                    sum += cmd.v + cmd.omega;
                }
                black_box(sum)
            });
        });
    }
    g.finish();
}

fn step(c: &mut Criterion) {
    let mut g = c.benchmark_group("step");
    g.sample_size(10).measurement_time(Duration::from_secs(5));
    for n in SIZES {
        let sim = Simulation::new(&crowd(n)).unwrap();
        g.throughput(Throughput::Elements(n as u64));
        g.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            // Each sample starts from the same state: the crowd at t = 0.
            b.iter_batched_ref(
                || sim.clone(),
                Simulation::step,
                criterion::BatchSize::LargeInput,
            );
        });
    }
    g.finish();
}

criterion_group!(benches, field, controller, step);
criterion_main!(benches);
