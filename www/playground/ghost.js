// The comparison: a run pinned as a ghost. Pin makes the whole run of the scenario as it is
// (`Run`, in the results worker, off the page's thread) and keeps its trajectories and report;
// the canvas draws its paths faded, the plots its minimum pair distance and the inspected
// robot's position error faded, and the results panel its figures beside the current run's.
// Change a parameter or the avoidance mode and both runs show; Unpin forgets it. Crowds above
// GHOST_MAX_ROBOTS are not pinned (their paths would hide the scene).

import { messageOf } from './message.js';
import { runWorker } from './wasm-views.js';

/** The pinned run's colour, on the canvas and in the plots (wide and faded). */
export const GHOST_COLOUR = '#8b5cf6';
/** The most robots whose run can be pinned. */
export const GHOST_MAX_ROBOTS = 100;
/** Values per trajectory sample of a `Run`: t, x, y, θ, v, ω (src/wasm/run.rs). */
const SAMPLE = 6;

/**
 * A pinned run: its report, its robots' paths, and per sample its time, the minimum distance
 * between two robots (NaN for one robot or independent runs) and each robot's position error.
 */
class Ghost {
  /**
   * @param {any} report the run's report (the JSON of dvf simulate)
   * @param {Float64Array} trajectories `[robots · samples · 6]` (see src/wasm/run.rs)
   * @param {number} samples per robot
   * @param {any} scenario the scenario that was run
   */
  constructor(report, trajectories, samples, scenario) {
    this.report = report;
    this.samples = samples;
    this.robots = scenario.robots.length;
    this.name = scenario.name;
    /** Each robot's path, `[x0, y0, x1, y1, …]`. */
    this.paths = [];
    this.times = new Float64Array(samples);
    this.minPair = new Float64Array(samples).fill(Number.NaN);
    /** `[robots · samples]`: each robot's distance to its goal. */
    this.positionError = new Float64Array(this.robots * samples);
    const at = (i, k) => (i * samples + k) * SAMPLE;
    for (let i = 0; i < this.robots; i++) {
      const path = new Float64Array(2 * samples);
      const [gx, gy] = scenario.robots[i].goal;
      for (let k = 0; k < samples; k++) {
        const o = at(i, k);
        path[2 * k] = trajectories[o + 1];
        path[2 * k + 1] = trajectories[o + 2];
        this.positionError[i * samples + k] = Math.hypot(trajectories[o + 1] - gx, trajectories[o + 2] - gy);
      }
      this.paths.push(path);
    }
    for (let k = 0; k < samples; k++) this.times[k] = trajectories[at(0, k)];
    if (!scenario.independent && this.robots > 1) {
      for (let k = 0; k < samples; k++) {
        let best = Number.POSITIVE_INFINITY;
        for (let i = 0; i < this.robots; i++) {
          const a = at(i, k);
          for (let j = i + 1; j < this.robots; j++) {
            const b = at(j, k);
            best = Math.min(
              best,
              Math.hypot(trajectories[a + 1] - trajectories[b + 1], trajectories[a + 2] - trajectories[b + 2]),
            );
          }
        }
        this.minPair[k] = best;
      }
    }
  }
}

/**
 * The pin of one playground: the pinned run (`ghost`), or the worker making it (`pending`).
 */
export class Pin {
  /**
   * @param {{
   *   scenario: () => any,
   *   showMessage: (text: string) => void,
   *   changed: () => void,
   * }} host the scenario to run, the message over the canvas, and what redraws the ghost
   */
  constructor(host) {
    this.host = host;
    /** @type {Ghost | null} the pinned run */
    this.ghost = null;
    /** @type {Worker | null} the worker making the run to pin */
    this.pending = null;
  }

  /** Pins the run of the scenario as it is, or unpins the one there. */
  toggle() {
    const host = this.host;
    if (this.ghost || this.pending) {
      this.pending?.terminate();
      this.pending = null;
      this.ghost = null;
      host.changed();
      return;
    }
    const s = host.scenario();
    if (!s) return;
    if (s.robots.length > GHOST_MAX_ROBOTS) {
      host.showMessage(`Pin: runs of up to ${GHOST_MAX_ROBOTS} robots can be pinned, not ${s.robots.length}`);
      return;
    }
    const worker = runWorker();
    this.pending = worker;
    host.changed();
    worker.onmessage = (e) => {
      worker.terminate();
      if (this.pending !== worker) return;
      this.pending = null;
      if (e.data.error) host.showMessage(`Pin: ${messageOf(e.data)}`);
      else this.ghost = new Ghost(e.data.report, e.data.trajectories, e.data.samples, s);
      host.changed();
    };
    worker.postMessage({ id: 0, scenario: s, trajectories: true });
  }
}

/** Draws `ghost`'s paths faded on `ctx` through `view` (render/camera.js). */
export function drawGhost(ctx, view, ghost, colour = GHOST_COLOUR) {
  ctx.save();
  ctx.globalAlpha = 0.4;
  ctx.strokeStyle = colour;
  ctx.lineWidth = 3;
  ctx.lineJoin = 'round';
  ctx.beginPath();
  for (const path of ghost.paths) {
    ctx.moveTo(view.sx(path[0]), view.sy(path[1]));
    for (let k = 2; k < path.length; k += 2) ctx.lineTo(view.sx(path[k]), view.sy(path[k + 1]));
  }
  ctx.stroke();
  ctx.restore();
}
