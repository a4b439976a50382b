//! A step allocates nothing once the simulation has warmed up: a counting allocator wraps the
//! system's and counts the allocations made by this test's thread while it steps.
//! Native only (the allocator is the host's).

#![cfg(not(target_arch = "wasm32"))]

use dvf::presets::{crowd, crowd_with_obstacles};
use dvf::sim::{Neighbourhood, Simulation};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

struct Counting;

thread_local! {
    // Const-initialised: reading it allocates nothing.
    static COUNTING: Cell<bool> = const { Cell::new(false) };
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

fn count() {
    if COUNTING.with(Cell::get) {
        ALLOCATIONS.with(|a| a.set(a.get() + 1));
    }
}

// SAFETY: every call is passed on to the system allocator unchanged.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        count();
        unsafe { System.alloc(layout) }
    }
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        count();
        unsafe { System.alloc_zeroed(layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        count();
        unsafe { System.realloc(ptr, layout, new_size) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// Allocations made by `f` on this thread.
fn allocations(f: impl FnOnce()) -> usize {
    ALLOCATIONS.with(|a| a.set(0));
    COUNTING.with(|c| c.set(true));
    f();
    COUNTING.with(|c| c.set(false));
    ALLOCATIONS.with(Cell::get)
}

#[test]
fn the_counter_sees_an_allocation() {
    assert!(allocations(|| drop(std::hint::black_box(vec![1u8; 10]))) >= 1);
}

/// Once the neighbour lists have room for the swarm's neighbours, a step allocates nothing.
#[test]
fn steps_allocate_nothing() {
    for (s, way) in [
        (crowd(2000), Neighbourhood::Grid),
        (crowd_with_obstacles(500, 20), Neighbourhood::Grid),
        (crowd(300), Neighbourhood::AllPairs),
        (
            dvf::presets::preset("example4-obstacle-formation").unwrap(),
            Neighbourhood::Grid,
        ),
    ] {
        let mut sim = Simulation::with_neighbourhood(&s, way).unwrap();
        // One thread: the wasm build's step (the parallel one is below).
        sim.set_parallel(false);
        sim.step();
        // Room for the neighbour lists as they stand: a crowd that closes in still grows them
        // now and then (see the test below).
        sim.reserve_neighbours(2.0);
        let n = allocations(|| {
            for _ in 0..100 {
                sim.step();
            }
        });
        assert_eq!(n, 0, "{}: {n} allocations in 100 steps", s.name);
    }
}

/// A crowd that closes in senses ever more neighbours: the lists grow, by doubling, so a long
/// run allocates a handful of times, not once per step.
#[test]
fn growing_lists_allocate_rarely() {
    let s = crowd(1000);
    let mut sim = Simulation::new(&s).unwrap();
    sim.set_parallel(false);
    let n = allocations(|| {
        for _ in 0..1000 {
            sim.step();
        }
    });
    assert!(n <= 12, "{n} allocations in 1000 steps");
}

/// On several threads a step hands its chunks to rayon's pool, whose job queue takes a new
/// block of memory now and then: a few times in a hundred steps, never once per step. The
/// buffers of the chunks are the step's own, reused. Counted on one of the pool's two threads,
/// which runs the step's serial parts and its share of every parallel pass (called from outside
/// the pool, a step moves onto it, where this thread's counter would not see it).
#[test]
fn parallel_steps_allocate_rarely() {
    let two = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .unwrap();
    // Above the size from which a step runs on threads.
    let mut sim = Simulation::new(&crowd(dvf::sim::PARALLEL_FROM + 100)).unwrap();
    two.install(|| sim.step());
    sim.reserve_neighbours(2.0);
    let n = two.install(|| {
        allocations(|| {
            for _ in 0..100 {
                sim.step();
            }
        })
    });
    assert!(n <= 10, "{n} allocations in 100 parallel steps");
}
