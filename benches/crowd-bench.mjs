// The crowd of `dvf bench` stepped in Node's wasm module, for `wasm.mjs` and `wasm-native.mjs`:
// the warm-up and the timed steps, with a `CrowdBench` class of an initialised module.

import { performance } from 'node:perf_hooks';

/**
 * Steps an untimed crowd of the same size for `ms` milliseconds, so that V8 has compiled the
 * hot functions with its optimising tier before anything is timed (see `wasm.mjs`).
 */
export function warmUp(CrowdBench, robots, obstacles, ms) {
  if (ms <= 0) return;
  const warm = new CrowdBench(robots, obstacles);
  try {
    for (const until = performance.now() + ms; performance.now() < until; ) warm.step(10);
  } finally {
    warm.free();
  }
}

/** Milliseconds per step of `steps` steps of a fresh crowd from t = 0, as `dvf bench` times. */
export function msPerStep(CrowdBench, robots, obstacles, steps) {
  const bench = new CrowdBench(robots, obstacles);
  try {
    const start = performance.now();
    bench.step(steps);
    return (performance.now() - start) / steps;
  } finally {
    bench.free();
  }
}
