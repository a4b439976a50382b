// The page's model: one simulated run copied out of wasm into plain typed arrays, and the
// playback time. Knows nothing of the DOM or the canvas.

import { Run } from './pkg/dvf.js';

/** Values per trajectory sample: t (s), x (m), y (m), θ (rad), v (m/s), ω (rad/s). */
export const SAMPLE_STRIDE = 6;
/** Values per pose in starts/goals: x (m), y (m), θ (rad). */
export const POSE_STRIDE = 3;
/** Values per obstacle: cx (m), cy (m), r_o (m), R_o (m). */
export const OBSTACLE_STRIDE = 4;

/**
 * Simulates the preset `name` and returns the model the renderer and the panels read.
 * Throws the core's Error (whose message names the problem) for an unknown name.
 */
export function loadPreset(name) {
  const run = Run.fromPreset(name);
  try {
    return modelFromRun(run, name);
  } finally {
    run.free();
  }
}

/** Copies everything out of a wasm `Run` so that it can be freed at once. */
function modelFromRun(run, presetName) {
  const model = {
    presetName,
    name: run.name,
    robotCount: run.robotCount,
    sampleCount: run.sampleCount,
    duration: run.duration,
    independent: run.independent,
    safeRadius: run.safeRadius,
    // [robot][sample][t, x, y, θ, v, ω], flat (see src/wasm.rs, `Run`).
    trajectories: run.trajectories(),
    starts: run.starts(),
    goals: run.goals(),
    obstacles: run.obstacles(),
    bounds: run.bounds(),
    report: run.report(),
  };
  const expected = model.robotCount * model.sampleCount * SAMPLE_STRIDE;
  if (model.trajectories.length !== expected) {
    throw new Error(`trajectory array has ${model.trajectories.length} values, expected ${expected}`);
  }
  return model;
}

/** The playback state: which run is shown and at what time. */
export function createState() {
  return {
    model: null,
    /** Shown time (s), in [0, model.duration]. */
    time: 0,
    playing: false,
  };
}

/** Index of the first value of sample `k` of robot `i` in `model.trajectories`. */
export function sampleOffset(model, i, k) {
  return (i * model.sampleCount + k) * SAMPLE_STRIDE;
}

/**
 * The last sample index `k` with `t_k ≤ t` and the fraction of the way to sample `k + 1`.
 * All robots share the sample times, so robot 0's are searched.
 */
export function locateTime(model, t) {
  const tr = model.trajectories;
  const n = model.sampleCount;
  if (n < 2 || t <= tr[0]) return { k: 0, frac: 0 };
  if (t >= tr[(n - 1) * SAMPLE_STRIDE]) return { k: n - 1, frac: 0 };
  let lo = 0;
  let hi = n - 1; // invariant: t_lo ≤ t < t_hi
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (tr[mid * SAMPLE_STRIDE] <= t) lo = mid;
    else hi = mid;
  }
  const t0 = tr[lo * SAMPLE_STRIDE];
  const t1 = tr[hi * SAMPLE_STRIDE];
  return { k: lo, frac: t1 > t0 ? (t - t0) / (t1 - t0) : 0 };
}

/** Robot `i`'s pose `{x, y, theta}` at a located time, interpolated between samples. */
export function poseAt(model, i, { k, frac }) {
  const tr = model.trajectories;
  const a = sampleOffset(model, i, k);
  if (frac === 0 || k + 1 >= model.sampleCount) {
    return { x: tr[a + 1], y: tr[a + 2], theta: tr[a + 3] };
  }
  const b = a + SAMPLE_STRIDE;
  // Heading along the shorter arc: the samples are wrapped to (−π, π].
  let dTheta = tr[b + 3] - tr[a + 3];
  dTheta -= 2 * Math.PI * Math.round(dTheta / (2 * Math.PI));
  return {
    x: tr[a + 1] + frac * (tr[b + 1] - tr[a + 1]),
    y: tr[a + 2] + frac * (tr[b + 2] - tr[a + 2]),
    theta: tr[a + 3] + frac * dTheta,
  };
}
