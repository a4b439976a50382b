// The requestAnimationFrame loop of one playground: a frame is drawn when something asked for
// one, and every frame while the clock plays. A playing frame first steps the simulation by
// the wall time since the last one (at the playback speed), within a step budget, and records
// how long its work took for the benchmarks.

/**
 * Playback speeds offered (simulated seconds per wall-clock second): up to 32×, so that the
 * 1,000-robot crowd's 184 s pass in about a minute where its steps fit the budget below.
 */
export const SPEEDS = [0.25, 0.5, 1, 2, 4, 8, 16, 32];
export const DEFAULT_SPEED = 1;
/** A frame never advances more than this wall time (s): a hidden tab does not jump ahead. */
const MAX_FRAME_WALL_S = 0.1;
/**
 * A frame spends at most about this long stepping (ms): a crowd too large for real time plays
 * slower (the clock says by how much) rather than making every frame longer than the last.
 */
const STEP_BUDGET_MS = 20;
/**
 * A seek's slice: a frame of a seek steps for about this long (ms), under the 100 ms long-task
 * budget of tests/e2e/bench-browser.mjs, and draws the scene at most every SEEK_DRAW_MS, so
 * that a long seek runs near the pure stepping rate (benches/seek.mjs) while the page still
 * takes Escape and the Cancel button between slices (tests/e2e/crowd.mjs cancels one).
 */
const SEEK_SLICE_MS = 80;
/** A seek under way draws the scene this often (ms of wall time); its progress every frame. */
const SEEK_DRAW_MS = 500;
/** A seek shows its progress once it has run this long (ms): a short one shows nothing. */
const SEEK_SHOW_MS = 250;
/** Frame work times kept for the benchmark (a ring; see `stats`). */
const WORK_SAMPLES = 600;

/**
 * What the frame loop reads and calls: the simulation; whether the element is in a document;
 * the frame's work (the pending drag, the drawing); the clock (clock.js) it plays; whether to
 * start over at the end; what to tell once the clock stops or a seek ends; where a seek shows
 * its progress (null: none under way, or not yet long enough to show); the canvases it
 * rasterises for the benchmark.
 * @typedef {{
 *   sim: () => import('../pkg/dvf.js').Playground | null,
 *   connected: () => boolean,
 *   applyInput: () => void,
 *   draw: () => void,
 *   clock: () => import('./clock.js').Clock,
 *   looping: () => boolean,
 *   time: () => number,
 *   settled: () => void,
 *   seekProgress: (progress: {time: number, target: number, fraction: number} | null) => void,
 *   canvases: () => HTMLCanvasElement[],
 * }} LoopHost
 */

export class FrameLoop {
  /** @param {LoopHost} host */
  constructor(host) {
    this.host = host;
    this.playing = false;
    this.speed = DEFAULT_SPEED;
    /** @type {number | null} the time of the last playing frame (ms) */
    this.lastFrameMs = null;
    /** Steps owed to the clock, carried from frame to frame (a fraction of one). */
    this.stepCarry = 0;
    /** @type {number | null} mean wall time of one step (ms), for the step budget */
    this.stepMs = null;
    /** Simulated over wall-clock time in the last frames (the speed when the budget holds). */
    this.rate = 1;
    this.frameRequested = false;
    /** @type {number | null} the step count a seek goes to, frame by frame (seekTo) */
    this.seekStep = null;
    /** The seek under way: the step it started from, when it started and last drew (ms). */
    this.seekFrom = 0;
    this.seekStartMs = 0;
    this.seekDrawnMs = 0;
    /** @type {((time: number) => void)[]} who waits for the seek under way to end (whenSeekEnds) */
    this.seekWaiters = [];
    /** @type {number | null} when every robot had converged and the clock stopped (s) */
    this.convergedAt = null;
    /** @type {HTMLCanvasElement | null} */
    this.rasterSink = null;
    /**
     * Diagnostics read by the end-to-end tests and benchmarks: frames drawn, when the first
     * was (ms since the page's time origin), the time of the last edit with its prediction,
     * and the work of the last and the slowest frame (ms). With `rasterInWork` set, a frame's
     * work includes the rasterisation of its drawing (see rasterNow).
     */
    this.stats = {
      frames: 0,
      /** @type {number | undefined} */
      firstFrameMs: undefined,
      lastEditMs: 0,
      frameWorkMs: 0,
      maxFrameWorkMs: 0,
      /** The work of the last WORK_SAMPLES frames (ms), a ring written at `workCount % length`. */
      work: new Float64Array(WORK_SAMPLES),
      workCount: 0,
      rasterInWork: false,
    };
  }

  play() {
    this.playing = true;
    this.lastFrameMs = null;
    this.endSeek();
    this.convergedAt = null;
  }

  /**
   * Goes to time `t` (s) of the run: from the start again when `t` is behind, then forward in
   * slices of the step budget, one per frame (a crowd's long seek never blocks the page). The
   * edits made at t > 0 are nudges of that run only: a seek replays the scenario.
   */
  seekTo(t) {
    const pg = this.host.sim();
    this.playing = false;
    this.convergedAt = null;
    const target = Math.max(0, Math.min(Math.round(pg.duration / pg.dt), Math.round(t / pg.dt)));
    if (target < Math.round(pg.time / pg.dt)) this.host.clock().rewind();
    // A seek that moves its target (the scrubber dragged on) goes on from where it began.
    if (this.seekStep == null) {
      this.seekFrom = Math.round(pg.time / pg.dt);
      this.seekStartMs = performance.now();
      this.seekDrawnMs = this.seekStartMs;
    }
    this.seekFrom = Math.min(this.seekFrom, Math.round(pg.time / pg.dt));
    this.seekStep = target;
    this.requestDraw();
  }

  /** Whether a seek (seekTo) is under way. */
  get seeking() {
    return this.seekStep != null;
  }

  /**
   * A promise of the time (s) where the seek under way ends: reached, cancelled, or stopped by
   * another move of the clock (play, step, a synchronous seek, a new scene); at once when none.
   * @returns {Promise<number>}
   */
  whenSeekEnds() {
    if (this.seekStep == null) return Promise.resolve(this.host.sim() ? this.host.time() : 0);
    return new Promise((resolve) => this.seekWaiters.push(resolve));
  }

  /** No seek under way any more: tells those waiting for it (whenSeekEnds) the time now. */
  endSeek() {
    this.seekStep = null;
    if (this.seekWaiters.length === 0) return;
    const waiters = this.seekWaiters;
    this.seekWaiters = [];
    const time = this.host.sim() ? this.host.time() : 0;
    for (const resolve of waiters) resolve(time);
  }

  /** Ends the seek under way where it is: a whole step of the run, shown and told as at rest. */
  cancelSeek() {
    if (this.seekStep == null) return;
    this.endSeek();
    this.host.settled();
    this.requestDraw();
  }

  pause() {
    this.playing = false;
  }

  /** A new simulation: stopped, and its step cost not yet known. */
  newScene() {
    this.playing = false;
    this.stepMs = null;
    this.endSeek();
    this.convergedAt = null;
  }

  /** Asks for a frame (one at a time, and none while the element is out of the document). */
  requestDraw() {
    if (this.frameRequested || !this.host.connected()) return;
    this.frameRequested = true;
    requestAnimationFrame((ms) => this.frame(ms));
  }

  frame(nowMs) {
    const host = this.host;
    // What the frame's own work asks for (an edit of the drag it applies) is drawn by it.
    try {
      if (!host.sim()) return;
      const workStart = performance.now();
      host.applyInput();
      // A seek under way draws the scene every SEEK_DRAW_MS only: its frames are for stepping.
      let drawScene = true;
      if (this.seekStep != null) {
        this.seek();
        drawScene = this.seekStep == null || workStart - this.seekDrawnMs >= SEEK_DRAW_MS;
        if (drawScene) this.seekDrawnMs = workStart;
      }
      this.showSeek(workStart);
      if (this.playing) this.advance(nowMs);
      if (drawScene) host.draw();
      if (this.stats.rasterInWork) this.rasterNow();
      const st = this.stats;
      if (st.frames === 0) st.firstFrameMs = performance.now();
      st.frames += 1;
      st.frameWorkMs = performance.now() - workStart;
      st.maxFrameWorkMs = Math.max(st.maxFrameWorkMs, st.frameWorkMs);
      st.work[st.workCount % WORK_SAMPLES] = st.frameWorkMs;
      st.workCount += 1;
    } finally {
      this.frameRequested = false;
    }
    if (this.playing || this.seekStep != null) this.requestDraw();
  }

  /** One frame's slice of a seek (seekTo): SEEK_SLICE_MS of stepping, one step while its cost is unknown. */
  seek() {
    const pg = this.host.sim();
    const left = this.seekStep - Math.round(pg.time / pg.dt);
    const fit = this.stepMs == null ? 1 : Math.max(1, Math.floor(SEEK_SLICE_MS / this.stepMs));
    if (left > 0) this.timedAdvance(Math.min(left, fit));
    if (left <= Math.min(left, fit) || pg.finished) {
      this.endSeek();
      this.host.settled();
    }
  }

  /** Shows the progress of the seek under way once it has run SEEK_SHOW_MS, or none. */
  showSeek(nowMs) {
    const pg = this.host.sim();
    if (this.seekStep == null || nowMs - this.seekStartMs < SEEK_SHOW_MS) {
      this.host.seekProgress(null);
      return;
    }
    const now = Math.round(pg.time / pg.dt);
    const span = Math.max(1, this.seekStep - this.seekFrom);
    this.host.seekProgress({
      time: pg.time,
      target: this.seekStep * pg.dt,
      fraction: Math.min(1, Math.max(0, (now - this.seekFrom) / span)),
    });
  }

  /** Steps `n` for the clock, keeping the mean cost of a step for the budget. */
  timedAdvance(n) {
    const t0 = performance.now();
    const taken = this.host.clock().advance(n);
    if (taken > 0) {
      const per = (performance.now() - t0) / taken;
      this.stepMs = this.stepMs == null ? per : 0.8 * this.stepMs + 0.2 * per;
    }
  }

  /** Steps the simulation for a playing frame at `nowMs`. */
  advance(nowMs) {
    const host = this.host;
    const pg = host.sim();
    const clock = host.clock();
    const wall = this.lastFrameMs == null ? 0 : Math.min(MAX_FRAME_WALL_S, (nowMs - this.lastFrameMs) / 1000);
    this.lastFrameMs = nowMs;
    this.stepCarry += (wall * this.speed) / pg.dt;
    let n = Math.floor(this.stepCarry);
    this.stepCarry -= n;
    // The step budget: what does not fit is dropped, and the clock shows the slower rate.
    const fit = this.stepMs == null ? 1 : Math.max(1, Math.floor(STEP_BUDGET_MS / this.stepMs));
    if (n > fit) {
      this.rate = (fit / n) * this.speed;
      n = fit;
      this.stepCarry = 0;
    } else if (n > 0) {
      this.rate = this.speed;
    }
    if (n > 0) this.timedAdvance(n);
    // The run ends at t = duration, or once every robot is at its goal within the tolerances
    // (which the page hears as `finished` too; at t = duration, Clock.advance sent it).
    const converged = !pg.finished && clock.allConverged();
    if (converged) clock.finished();
    if (pg.finished || converged) {
      // `loop`: start over (the clock keeps playing from t = 0).
      if (host.looping()) clock.reset();
      else {
        this.playing = false;
        if (converged) this.convergedAt = host.time();
        host.settled();
      }
    }
  }

  /**
   * Makes the browser rasterise this frame's drawing now rather than after the callback, by
   * using both canvases as images (for the benchmark, so that the work it times includes the
   * pixels: Chromium records Canvas 2D calls and rasterises them later).
   */
  rasterNow() {
    if (!this.rasterSink) {
      this.rasterSink = document.createElement('canvas');
      this.rasterSink.width = 1;
      this.rasterSink.height = 1;
    }
    const sink = this.rasterSink.getContext('2d');
    for (const canvas of this.host.canvases()) sink.drawImage(canvas, 0, 0, 1, 1);
  }
}
