//! The passes of a step over the robots, on rayon's threads natively and on the calling thread
//! otherwise: the one place where the native and the wasm build of the step differ, since
//! WebAssembly has no threads here. Each pass is one function that takes the step's choice
//! (`threaded`) and runs the same work either way, with the same bits: each robot's result
//! lands in its own slot, and minima are exact in any order.
// The wasm build never runs a pass on threads: its `threaded` arguments are always false.
#![cfg_attr(target_arch = "wasm32", allow(unused_variables))]

use super::{Advanced, Robot, Simulation};
use crate::grid::Neighbours;
use crate::swarm::Neighbour;
use glam::DVec2;
#[cfg(not(target_arch = "wasm32"))]
use rayon::prelude::*;

/// From this many robots a step runs its passes on several threads (natively): below,
/// rayon's hand-offs cost more than they save. `benches/peer.rs` measures a crowd's step on
/// one thread and on several ("open, threads"), and `benches/crowd.rs` a step at 1,000 and
/// 10,000 robots, on either side of it.
pub const PARALLEL_FROM: usize = 2048;

/// The fewest robots a thread takes at once in the step's cheap passes (integration, the
/// sensed records, storing the evaluations, the metrics): small pieces let a thread that wakes
/// late still take its share of a pass.
#[cfg(not(target_arch = "wasm32"))]
pub(super) const CHEAP_CHUNK: usize = 256;

/// The threads a pass may run on: rayon's pool natively, the calling thread alone in wasm.
#[cfg(not(target_arch = "wasm32"))]
fn threads() -> usize {
    rayon::current_num_threads()
}

/// The threads a pass may run on: rayon's pool natively, the calling thread alone in wasm.
#[cfg(target_arch = "wasm32")]
fn threads() -> usize {
    1
}

impl Simulation {
    /// Whether this step's passes over the robots run on rayon's threads: from
    /// [`PARALLEL_FROM`] robots, on two threads or more, unless [`Self::set_parallel`] turned
    /// it off. Never in the wasm build, which has one thread.
    pub(super) fn threaded(&self) -> bool {
        self.parallel && self.robots.len() >= PARALLEL_FROM && threads() >= 2
    }

    /// Whether a step of a large crowd evaluates its robots on several threads (natively, with
    /// rayon; on by default). The same bits either way: this only chooses the cost, for
    /// instance to measure one thread against several, or for a caller that runs many
    /// simulations on the threads already.
    pub fn set_parallel(&mut self, on: bool) {
        self.parallel = on;
    }

    /// Runs `step` on one of the pool's threads when the step is threaded: from there its
    /// passes hand work to the other threads and take it back, instead of putting the calling
    /// thread to sleep and waking it at the end of each pass.
    pub(super) fn on_pool(&mut self, step: fn(&mut Self)) {
        #[cfg(not(target_arch = "wasm32"))]
        if self.threaded() && rayon::current_thread_index().is_none() {
            return rayon::scope(|_| step(self));
        }
        step(self);
    }
}

/// The neighbour lists built anew at `positions` for `reach`, on threads when `threaded`.
pub(super) fn build_lists(threaded: bool, near: &mut Neighbours, positions: &[DVec2], reach: f64) {
    #[cfg(not(target_arch = "wasm32"))]
    if threaded {
        return near.build_on_threads(positions, reach);
    }
    near.build(positions, reach);
}

/// `record` of each robot and its snapshot speed, with its index, into `out` (cleared first).
pub(super) fn sense<'a>(
    threaded: bool,
    robots: &'a [Robot],
    speeds: &'a [f64],
    record: impl Fn((usize, (&'a Robot, &'a f64))) -> Neighbour + Sync + Send,
    out: &mut Vec<Neighbour>,
) {
    #[cfg(not(target_arch = "wasm32"))]
    if threaded {
        return robots
            .par_iter()
            .zip(speeds)
            .enumerate()
            .with_min_len(CHEAP_CHUNK)
            .map(record)
            .collect_into_vec(out);
    }
    out.clear();
    out.extend(robots.iter().zip(speeds).enumerate().map(record));
}

/// `advance` of each robot's slots, with its index: whether it held for every robot.
pub(super) fn advance<'a>(
    threaded: bool,
    (robots, commands, chords, speeds): (
        &'a mut [Robot],
        &'a [crate::Command],
        &'a [DVec2],
        &'a mut [f64],
    ),
    advance: impl Fn((usize, Advanced<'a>)) -> bool + Sync + Send,
) -> bool {
    #[cfg(not(target_arch = "wasm32"))]
    if threaded {
        return robots
            .par_iter_mut()
            .zip(commands)
            .zip(chords)
            .zip(speeds)
            .enumerate()
            .with_min_len(CHEAP_CHUNK)
            .map(advance)
            .reduce(|| true, |a, b| a && b);
    }
    robots
        .iter_mut()
        .zip(commands)
        .zip(chords)
        .zip(speeds)
        .enumerate()
        .map(advance)
        .fold(true, |a, b| a & b)
}

/// Evaluates every robot ([`Simulation::evaluate_run`]), on threads when the step is threaded,
/// and returns the smallest squared distance the evaluations found to a listed robot.
pub(super) fn evaluate(sim: &mut Simulation) -> f64 {
    #[cfg(not(target_arch = "wasm32"))]
    if sim.threaded() {
        return evaluate_on_threads(sim);
    }
    sim.evaluate_here()
}

/// Evaluates every robot on the threads of rayon's pool, in chunks, each with its own buffers
/// and storing its own robots (`evaluate_run`): the same bits as one after the other (each
/// evaluation reads the snapshot only, and lands in its own slots).
#[cfg(not(target_arch = "wasm32"))]
fn evaluate_on_threads(sim: &mut Simulation) -> f64 {
    use super::evaluation::Scratch;
    let n = sim.robots.len();
    // A few chunks per thread, so that one slow chunk does not hold the others up.
    let chunks = 4 * rayon::current_num_threads();
    let size = n.div_ceil(chunks);
    let mut scratches = std::mem::take(&mut sim.scratches);
    scratches.resize_with(chunks, Scratch::default);
    for s in &mut scratches {
        s.closest2 = f64::INFINITY;
    }
    let mut slots = sim.take_slots();
    let this = &*sim;
    (
        slots.robots.par_chunks_mut(size),
        slots.commands.par_chunks_mut(size),
        slots.chords.par_chunks_mut(size),
        slots.after.par_chunks_mut(size),
        scratches.par_iter_mut(),
    )
        .into_par_iter()
        .enumerate()
        .for_each(|(k, (robots, commands, chords, after, scratch))| {
            this.evaluate_run(k * size, (robots, commands, chords, after), scratch);
        });
    sim.put_slots(slots);
    let closest2 = scratches
        .iter()
        .fold(f64::INFINITY, |m, s| m.min(s.closest2));
    sim.scratches = scratches;
    closest2
}
