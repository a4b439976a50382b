// The clock of one playground: play, pause, step, seek and reset, and the `tick` and
// `finished` events. It steps the simulation the controller holds and tells the controller,
// through the callbacks it is given, that the state changed; the frame loop (loop.js) plays it.

import { POSE_STRIDE } from './wasm-views.js';

/** `seek` asks the core for at most this many steps at once (its limit per call). */
const MAX_STEPS_PER_CALL = 1_000_000;
/** The Step button and the S key advance this much simulated time (s). */
const STEP_TIME_S = 0.1;

/**
 * What the clock reads and whom it tells.
 * @typedef {{
 *   sim: () => import('../pkg/dvf.js').Playground | null,
 *   scenario: () => import('../dvf-playground.js').Scenario,
 *   time: () => number,
 *   poses: () => Float64Array,
 *   loop: import('./loop.js').FrameLoop,
 *   changed: () => void,
 *   refresh: () => void,
 *   shown: () => void,
 *   viewChanged: () => void,
 *   requestDraw: () => void,
 *   emit: (type: 'tick' | 'finished', detail: {time: number}) => void,
 * }} ClockHost
 */

/**
 * The steps of dt a seek to time `t` (s) takes from t = 0, `t` clamped to [0, duration]: a
 * whole number; the tolerance keeps 6 / 0.01 from rounding down to 599 steps.
 * @param {number} t
 * @param {import('../pkg/dvf.js').Playground} pg
 */
function wholeSteps(t, pg) {
  return Math.floor(Math.min(Math.max(t, 0), pg.duration) / pg.dt + 1e-9);
}

export class Clock {
  /** @param {ClockHost} host */
  constructor(host) {
    this.host = host;
  }

  play() {
    const { sim, loop, shown, requestDraw } = this.host;
    if (!sim()) return;
    if (this.atEnd()) this.reset();
    loop.play();
    shown();
    requestDraw();
  }

  pause() {
    this.host.loop.pause();
    this.host.shown();
    this.host.viewChanged();
    this.host.requestDraw();
  }

  togglePlay() {
    if (this.host.loop.playing) this.pause();
    else this.play();
  }

  /** Back to t = 0 at the scenario's starts (trails cleared). */
  reset() {
    if (!this.host.sim()) return;
    this.host.loop.endSeek();
    this.host.loop.convergedAt = null;
    this.rewind();
    this.host.viewChanged();
  }

  /** Back to t = 0 for a seek (which goes on from there). */
  rewind() {
    this.host.sim().reset();
    this.host.changed();
  }

  /** Goes to time `t` (s) of the run, in slices (FrameLoop.seekTo); the scrubber, the plots. */
  seekTo(t) {
    if (!this.host.sim() || !Number.isFinite(t)) return;
    this.host.loop.seekTo(t);
    this.host.shown();
  }

  /**
   * Shows the state at time `t` (s, clamped to [0, duration]) as `seek` does, from t = 0 and
   * the same whole number of steps, but in slices (FrameLoop.seekTo), with the progress box and
   * its Cancel: the page stays responsive through a long seek. Returns a promise of the time
   * where the seek ends (FrameLoop.whenSeekEnds). Throws for a `t` that is not a number.
   * @returns {Promise<number>}
   */
  seekSliced(t) {
    if (typeof t !== 'number' || Number.isNaN(t))
      throw new Error(`seek: the time must be a number of seconds, not ${t}`);
    const pg = this.host.sim();
    if (!pg) return Promise.resolve(0);
    // No step to take: at once (no frame needed, so that it ends out of the document too).
    if (wholeSteps(t, pg) === 0) return Promise.resolve(this.seek(t));
    this.pause();
    this.host.loop.convergedAt = null;
    this.rewind();
    this.host.loop.seekTo(wholeSteps(t, pg) * pg.dt);
    this.host.shown();
    return this.host.loop.whenSeekEnds();
  }

  /** Whether a seek in slices (seekTo) is under way. */
  seeking() {
    return this.host.loop.seeking;
  }

  /** Ends the seek under way at the step it reached (Escape, the progress bar's Cancel). */
  cancelSeek() {
    this.host.loop.cancelSeek();
    this.host.shown();
  }

  /** Whether the run is at its end: t = duration, or every robot at its goal (the clock stops). */
  atEnd() {
    const pg = this.host.sim();
    return Boolean(pg) && (pg.finished || this.allConverged());
  }

  /**
   * Whether every robot is within the tolerances of its goal now (tol_position, tol_heading:
   * the prediction's test, src/playground/prediction.rs), when the clock stops.
   */
  allConverged() {
    const s = this.host.scenario();
    const p = this.host.poses();
    const { tol_position: tolP, tol_heading: tolH } = s.params;
    for (let i = 0; i < s.robots.length; i++) {
      const g = s.robots[i].goal;
      const o = i * POSE_STRIDE;
      if (Math.hypot(p[o] - g[0], p[o + 1] - g[1]) > tolP) return false;
      const d = Math.abs(p[o + 2] - g[2]) % (2 * Math.PI);
      if (Math.min(d, 2 * Math.PI - d) > tolH) return false;
    }
    return s.robots.length > 0;
  }

  /** Advances `n` steps of dt and pauses; returns the steps taken. Throws for a bad `n`. */
  step(n = 1) {
    const pg = this.host.sim();
    if (!pg) return 0;
    this.pause();
    this.host.loop.endSeek();
    const taken = pg.step(n);
    this.host.changed();
    this.#moved();
    this.host.viewChanged();
    return taken;
  }

  /**
   * Shows the state at time `t` (s, clamped to [0, duration]): from t = 0, the whole way
   * simulated, so that the state is the one a run reaches at that time; paused. Returns the
   * time reached (a whole number of steps). Throws for a `t` that is not a number.
   */
  seek(t) {
    if (typeof t !== 'number' || Number.isNaN(t))
      throw new Error(`seek: the time must be a number of seconds, not ${t}`);
    const pg = this.host.sim();
    if (!pg) return 0;
    this.pause();
    // Synchronous: a seek in slices under way (the scrubber's, FrameLoop.seekTo) ends here.
    this.host.loop.endSeek();
    this.host.loop.convergedAt = null;
    pg.reset();
    const steps = wholeSteps(t, pg);
    for (let left = steps; left > 0; ) {
      const taken = pg.step(Math.min(left, MAX_STEPS_PER_CALL));
      if (taken === 0) break;
      left -= taken;
    }
    this.host.changed();
    this.#moved();
    this.host.viewChanged();
    return this.host.time();
  }

  /** Advances STEP_TIME_S of simulated time (at least one step). */
  stepTime() {
    const pg = this.host.sim();
    if (pg) this.step(Math.max(1, Math.round(STEP_TIME_S / pg.dt)));
  }

  /** Advances `n` steps for the frame loop (which keeps playing); returns the steps taken. */
  advance(n) {
    const taken = this.host.sim().step(n);
    this.host.refresh();
    if (taken > 0) this.#moved();
    return taken;
  }

  /** Tells the page the clock moved: a `tick`, and `finished` when the run reached its end. */
  #moved() {
    this.host.emit('tick', { time: this.host.time() });
    if (this.host.sim().finished) this.finished();
  }

  /**
   * The `finished` event: at t = duration, and when the playing clock stops because every
   * robot is at its goal before then (FrameLoop.advance).
   */
  finished() {
    this.host.emit('finished', { time: this.host.time() });
  }
}
