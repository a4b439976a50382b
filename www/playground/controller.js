// The live simulation of one <dvf-playground> and its edits. The controller owns the wasm
// `Playground` (`pg`) and the JS model of its scenario (`model`), and holds the parts that
// work on them: the views into wasm memory, the undo history, the camera, the frame loop, the
// painter, the input and the panels. The element creates one and calls it; input and panels
// change the scenario only through the edit methods below. Over 500 lines: it is the one owner
// of the simulation and the model, and every edit and gesture keeps both in step here.
//
// Edits: one method per edit (moveRobot, moveGoal, moveObstacle, resizeObstacle, setParam,
// addRobot, removeRobot, addObstacle, removeObstacle), each calling the facade's method of the
// same name, which checks only what it touches and serialises nothing; edit(scenario) replaces
// the whole scene (undo, imports, links). An edit the core refuses throws its Error (naming the
// field) and changes nothing; one it takes is made to the model in place too.
//
// Gestures: what a person does (a drag, a key, a button, a field) is begin(), any number of
// edits, commit(kind): one undo entry (the scenario text before its first edit, if it changed)
// and one `change` event. Nothing reads or serialises the whole scenario per pointer move;
// commit reads the core's scenario once, so that the model holds the core's own values again
// (and the bounds it resolves for a scenario that has none).

import { downloadScenarioJson, fetchScenarioText } from '../io.js';
import { buildLegend } from '../panels/legend.js';
import { buildPlotsLegend } from '../panels/plots.js';
import { ParamsPanel } from '../panels/params.js';
import { ResultsPanel } from '../panels/results.js';
import { SelectionPanel } from '../panels/selection.js';
import { Toolbar } from '../panels/toolbar.js';
import { Playground, presetScenario } from '../pkg/dvf.js';
import { Camera } from '../render/camera.js';
import { readPalette, setPalette } from '../render/theme.js';
import { changeParam } from './actions.js';
import { History } from './history.js';
import { Input } from './input.js';
import { FrameLoop } from './loop.js';
import { messageOf } from './message.js';
import { Painter } from './paint.js';
import { Recorder } from './record.js';
import { LiveViews, POSE_STRIDE, wasmReady, wasmSourceName } from './wasm-views.js';

/** `seek` asks the core for at most this many steps at once (its limit per call). */
const MAX_STEPS_PER_CALL = 1_000_000;
/** A `viewchange` event waits this long (ms) for the next change (a pan is many). */
const VIEW_EVENT_MS = 400;
/** The Step button and the S key advance this much simulated time (s). */
const STEP_TIME_S = 0.1;
/** θ(0) of the integral curves until the element says otherwise (degrees): the paper's Fig. 1. */
export const DEFAULT_THETA0_DEG = 90;
/** An import's last-place fix-ups (Controller.#exactify) up to this many are made at once. */
const EXACT_AT_ONCE = 32;
/** Larger ones work this long per task (ms), so that no task of the page runs long. */
const EXACT_SLICE_MS = 30;
/** Each preset's robot count and JSON text, made once per page (Controller.#presetOf). */
let presetTexts = null;

/** The field overlays. @type {import('../dvf-playground.js').FieldMode[]} */
export const FIELD_MODES = ['arrows', 'curves', 'none'];

/**
 * @typedef {import('../dvf-playground.js').Scenario} Scenario
 * @typedef {{kind: 'robot' | 'goal' | 'obstacle', index: number}} Selection
 */

export class Controller {
  /** An import's fix-ups still to make (#exactify): {pg, edits, next}, or null. */
  #exact = null;

  /**
   * @param {HTMLElement} host the element: the `change` events go there
   * @param {ShadowRoot} root its shadow root, holding the template (template.js)
   */
  constructor(host, root) {
    this.host = host;
    this.root = root;
    /** The part of the template with `data-id` `id`. */
    this.$ = (id) => /** @type {any} */ (root.querySelector(`[data-id="${id}"]`));
    /** @type {HTMLCanvasElement} */
    this.canvas = this.$('canvas');
    /** @type {Playground | null} */
    this.pg = null;
    /** @type {Scenario | null} the scenario shown, kept equal to the core's (see the top) */
    this.model = null;
    /** @type {string | null} the preset shown, null once edited or imported */
    this.preset = null;
    /** @type {LiveViews | null} */
    this.views = null;
    /** @type {import('./wasm-views.js').Limits | null} */
    this.limits = null;
    /** @type {import('./wasm-views.js').PresetInfo[]} */
    this.presetList = [];
    /** The preset shown when no other is asked for. */
    this.defaultPreset = '';
    /** @type {Selection | null} */
    this.selection = null;
    /** The inspected robot: its field is drawn, the plots and the panel show it. */
    this.focusRobot = 0;
    /** @type {import('../dvf-playground.js').FieldMode} */
    this.fieldMode = 'arrows';
    this.theta0Deg = DEFAULT_THETA0_DEG;
    this.showSensing = false;
    /** Drags and keys may edit the scene (the element's `controls`/`editable`, not `readonly`). */
    this.editable = true;
    /** Keys and the pointer do nothing but the toolbar's play, pause and reset (`readonly`). */
    this.readonly = false;
    /** Starts over at the end of the run (`loop`). */
    this.looping = false;
    /** @type {ReturnType<typeof setTimeout> | null} the pending `viewchange` event */
    this.viewTimer = null;
    /** What showed the message now (showMessage's `source`). */
    this.messageSource = '';
    /** Bumped by every edit, load, reset and API step: the trail layer redraws from scratch. */
    this.generation = 0;
    this.connected = false;
    this.history = new History();
    this.camera = new Camera();
    this.loop = new FrameLoop(this);
    this.painter = new Painter(this);
    this.recorder = new Recorder(this);
    /** @type {import('./ghost.js').Ghost | null} the pinned run (ghost.js) */
    this.ghost = null;
    /** @type {Worker | null} the worker making the run to pin */
    this.pinning = null;
    this.toolbar = new Toolbar(this);
    this.params = new ParamsPanel(this.$('params'), (key, value) => changeParam(this, key, value));
    this.results = new ResultsPanel(this);
    this.selectionPanel = new SelectionPanel(this);
    /** The scene's colours from the stylesheet (render/theme.js), read by readTheme. */
    this.palette = readPalette(root.querySelector('.pg'));
    buildLegend(this.$('legend'));
    buildPlotsLegend(this.$('plots-legend'));
    // The colours are known once the stylesheet has loaded, and change with the system's theme.
    root.querySelector('link[rel="stylesheet"]')?.addEventListener('load', () => this.readTheme());
    matchMedia('(prefers-color-scheme: dark)').addEventListener('change', () => this.readTheme());
    this.$('message-close').addEventListener('click', () => this.showMessage(''));
    this.input = new Input(this);
  }

  /** Waits for the wasm module; false (and the message shown) when it cannot be loaded. */
  async ready() {
    try {
      const { memory, limits, presets, defaultPreset } = await wasmReady();
      this.limits = limits;
      this.presetList = presets;
      this.defaultPreset = defaultPreset;
      this.views = new LiveViews(memory);
    } catch (e) {
      this.showMessage(wasmFailure(e));
      return false;
    }
    this.toolbar.fillMenus(this.presetList, this.limits.crowdMax);
    return true;
  }

  /** The element is in a document: draw. */
  connect() {
    this.connected = true;
    this.readTheme();
  }

  /** The element left its document: stop playing and drawing; the simulation is kept. */
  disconnect() {
    this.connected = false;
    this.loop.playing = false;
  }

  // ---- documents ----------------------------------------------------------------------------

  /**
   * Loads a scenario (object or JSON text) as a new document: t = 0, view fitted, undo
   * cleared. Throws the core's Error naming the offending field; the scene is kept then.
   */
  load(scenario) {
    this.#replace(new Playground(scenario), null, scenario);
    this.history.clear();
    this.toolbar.update();
  }

  /**
   * Loads preset `name` (`crowd-N` included); with `edit`, as an undoable edit of the scene.
   * On a bad name shows the message (unless `quiet`), keeps the scene and returns false.
   */
  loadPreset(name, { quiet = false, edit = false } = {}) {
    try {
      const pg = Playground.fromPreset(name);
      if (edit && this.pg) this.history.push(this.text());
      this.#replace(pg, name);
      this.showMessage('');
      if (edit) this.#emit('preset');
      return true;
    } catch (e) {
      if (!quiet) this.showMessage(messageOf(e));
      this.toolbar.showPreset(this.preset);
      return false;
    }
  }

  /** Fetches and loads the scenario at `url`; on failure shows why, keeps the scene, false. */
  async loadUrl(url) {
    try {
      this.load(await fetchScenarioText(url));
      this.showMessage('');
      return true;
    } catch (e) {
      this.showMessage(`Could not load the scenario ${url}: ${messageOf(e)}`);
      return false;
    }
  }

  /**
   * Loads an imported scenario text as a new document that Undo takes back; throws as load.
   * A large file's last-place fix-ups (#exactify) go on a slice per task after the scene is
   * shown; the `import` event comes once they are done.
   */
  async importScenario(text) {
    const before = this.pg ? this.text() : null;
    this.#replace(new Playground(text), null, text, true);
    this.history.clear();
    if (before) this.history.push(before);
    this.toolbar.update();
    this.showMessage('');
    await this.#applyExact();
    this.#emit('import');
  }

  /**
   * Shows `pg` in place of the scene. With `wanted` (what the core read), its numbers are set
   * exactly (#exactify): at once, or with `defer` and more than EXACT_AT_ONCE of them, in
   * slices (#applyExact).
   */
  #replace(pg, presetName, wanted = null, defer = false) {
    const old = this.pg;
    this.pg = pg;
    old?.free();
    this.#exact = null;
    this.model = pg.scenario();
    if (wanted) {
      const edits = this.#exactify(wanted, this.model);
      if (defer && edits.length > EXACT_AT_ONCE) {
        this.#exact = { pg, edits, next: 0 };
      } else if (edits.length) {
        this.#runEdits(edits, 0, edits.length);
        this.model = pg.scenario();
      }
    }
    this.views.attach(pg);
    this.loop.newScene();
    this.selection = null;
    this.focusRobot = 0;
    this.painter.newScene();
    this.camera.fit();
    this.generation += 1;
    this.preset = presetName ?? this.#presetOf(this.model);
    this.toolbar.showPreset(this.preset);
    this.params.fill(this.model, this.root.activeElement);
    this.toolbar.update();
    this.results.stale();
    this.requestDraw();
  }

  /**
   * Runs `edits[from..to)` (#exactify's), stopping at one the core refuses (a value it takes
   * only a hair away: the core's values stay); returns where it stopped, `edits.length` then.
   */
  #runEdits(edits, from, to) {
    let k = from;
    try {
      for (; k < to; k++) edits[k]();
    } catch {
      return edits.length;
    }
    return k;
  }

  /**
   * Applies the pending fix-ups (#exact) EXACT_SLICE_MS at a time, a task each, the first after
   * the task that made the scene.
   */
  async #applyExact() {
    const job = this.#exact;
    while (job && this.#exact === job) {
      await new Promise((resolve) => setTimeout(resolve, 0));
      if (this.#exact !== job) return;
      const end = performance.now() + EXACT_SLICE_MS;
      while (job.next < job.edits.length && performance.now() < end) {
        job.next = this.#runEdits(job.edits, job.next, job.next + 1);
      }
      if (job.next >= job.edits.length) {
        this.#endExact();
        return;
      }
    }
  }

  /**
   * Applies whatever fix-ups are pending at once: before anything reads the scenario, steps
   * the clock or edits (the fix-ups are moves at t = 0 by index).
   */
  flushExact() {
    const job = this.#exact;
    if (!job) return;
    job.next = this.#runEdits(job.edits, job.next, job.edits.length);
    this.#endExact();
  }

  #endExact() {
    this.#exact = null;
    this.model = this.pg.scenario();
    this.#changed();
  }

  /** The name of the preset whose scenario `model` is, or null (presetTexts, compared as JSON). */
  #presetOf(model) {
    presetTexts ??= new Map(
      this.presetList.map((p) => {
        const s = presetScenario(p.name);
        return [p.name, { robots: s.robots.length, text: JSON.stringify(s) }];
      }),
    );
    const same = [...presetTexts].filter(([, p]) => p.robots === model.robots.length);
    if (!same.length) return null;
    const text = JSON.stringify(model);
    return same.find(([, p]) => p.text === text)?.[0] ?? null;
  }

  /**
   * After the core read scenario `wanted` (object or JSON text): the few numbers it read a unit
   * in the last place off (its fast number parser rounds twice; www/exact-json.js writes digits
   * it reads exactly wherever there are such digits) are set to the very values through the
   * fine-grained edits, so that a scene exported and imported is the same scene to the bit.
   * `s` is the scenario the core read (pg.scenario()); returns those edits, to be run in order
   * (#runEdits): the 10,000-robot crowd has about a hundred, half a millisecond each.
   */
  #exactify(wanted, s) {
    /** @type {(() => void)[]} */
    const edits = [];
    let w = wanted;
    try {
      if (typeof w === 'string') w = JSON.parse(w);
    } catch {
      return edits;
    }
    if (!Array.isArray(w?.robots) || w.robots.length !== s.robots.length) return edits;
    const pg = this.pg;
    const pose = (p, n) => Array.isArray(p) && p.length === n && p.every((v) => typeof v === 'number');
    const differs = (a, b) => a.some((v, j) => v !== b[j]);
    w.robots.forEach((r, i) => {
      const have = s.robots[i];
      if (pose(r.start, 3) && differs(r.start, have.start))
        edits.push(() => pg.moveRobot(i, r.start[0], r.start[1], r.start[2]));
      if (pose(r.goal, 3) && differs(r.goal, have.goal))
        edits.push(() => pg.moveGoal(i, r.goal[0], r.goal[1], r.goal[2]));
    });
    (Array.isArray(w.obstacles) ? w.obstacles : []).forEach((o, k) => {
      const have = s.obstacles[k];
      if (!have) return;
      if (pose(o.center, 2) && differs(o.center, have.center))
        edits.push(() => pg.moveObstacle(k, o.center[0], o.center[1]));
      const r = typeof o.radius === 'number' ? o.radius : have.radius;
      const infl = typeof o.influence === 'number' ? o.influence : have.influence;
      if (r !== have.radius || infl !== have.influence) edits.push(() => pg.resizeObstacle(k, r, infl));
    });
    for (const [key, v] of Object.entries(w.params ?? {})) {
      if (typeof v === 'number' && key in s.params && s.params[key] !== v) edits.push(() => pg.setParam(key, v));
    }
    for (const key of ['duration', 'dt']) {
      if (typeof w[key] === 'number' && s[key] !== w[key]) edits.push(() => pg.setParam(key, w[key]));
    }
    return edits;
  }

  /** The current scenario as a plain object (a copy), or null before the first scene. */
  scenario() {
    this.flushExact();
    return this.pg ? structuredClone(this.model) : null;
  }

  /** Offers the scenario as a JSON file (io.js); a message says why when it cannot be written. */
  async exportJson() {
    if (!this.pg) return;
    this.flushExact();
    try {
      await downloadScenarioJson(this.model);
    } catch (e) {
      this.showMessage(`Scenario JSON: ${messageOf(e)}`);
    }
  }

  /** The scenario's JSON text: what undo keeps. */
  text() {
    this.flushExact();
    return JSON.stringify(this.model);
  }

  /** The preset shown, or null once the scene has been edited or imported. */
  presetName() {
    return this.pg ? this.preset : null;
  }

  // ---- the clock ----------------------------------------------------------------------------

  play() {
    if (!this.pg) return;
    this.flushExact();
    if (this.atEnd()) this.reset();
    this.loop.play();
    this.toolbar.update();
    this.requestDraw();
  }

  pause() {
    this.loop.pause();
    this.toolbar.update();
    this.viewChanged();
    this.requestDraw();
  }

  togglePlay() {
    if (this.loop.playing) this.pause();
    else this.play();
  }

  /** Back to t = 0 at the scenario's starts (trails cleared). */
  reset() {
    if (!this.pg) return;
    this.loop.seekStep = null;
    this.loop.convergedAt = null;
    this.rewind();
    this.viewChanged();
  }

  /** Back to t = 0 for a seek (which goes on from there). */
  rewind() {
    this.flushExact();
    this.pg.reset();
    this.#changed();
  }

  /** Goes to time `t` (s) of the run, in slices (FrameLoop.seekTo); the scrubber, the plots. */
  seekTo(t) {
    if (!this.pg || !Number.isFinite(t)) return;
    this.flushExact();
    this.loop.seekTo(t);
    this.toolbar.update();
  }

  /** Whether the run is at its end: t = duration, or every robot at its goal (the clock stops). */
  atEnd() {
    return Boolean(this.pg) && (this.pg.finished || this.allConverged());
  }

  /**
   * Whether every robot is within the tolerances of its goal now (tol_position, tol_heading:
   * the prediction's test, src/playground/prediction.rs), when the clock stops.
   */
  allConverged() {
    const s = this.model;
    const p = this.views.poses;
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
    if (!this.pg) return 0;
    this.flushExact();
    this.pause();
    this.loop.seekStep = null;
    const taken = this.pg.step(n);
    this.#changed();
    this.#clockMoved();
    this.viewChanged();
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
    if (!this.pg) return 0;
    this.flushExact();
    this.pause();
    // Synchronous: a seek in slices under way (the scrubber's, FrameLoop.seekTo) ends here.
    this.loop.seekStep = null;
    this.loop.convergedAt = null;
    this.pg.reset();
    const target = Math.min(Math.max(t, 0), this.pg.duration);
    // A whole number of steps; the tolerance keeps 6 / 0.01 from rounding down to 599 steps.
    const steps = Math.floor(target / this.pg.dt + 1e-9);
    for (let left = steps; left > 0; ) {
      const taken = this.pg.step(Math.min(left, MAX_STEPS_PER_CALL));
      if (taken === 0) break;
      left -= taken;
    }
    this.#changed();
    this.#clockMoved();
    this.viewChanged();
    return this.views.time;
  }

  /** Advances STEP_TIME_S of simulated time (at least one step). */
  stepTime() {
    if (this.pg) this.step(Math.max(1, Math.round(STEP_TIME_S / this.pg.dt)));
  }

  /** Advances `n` steps for the frame loop (which keeps playing); returns the steps taken. */
  advance(n) {
    this.flushExact();
    const taken = this.pg.step(n);
    this.views.refresh();
    if (taken > 0) this.#clockMoved();
    return taken;
  }

  /** Tells the page the clock moved: a `tick`, and `finished` when the run reached its end. */
  #clockMoved() {
    const time = this.views.time;
    this.host.dispatchEvent(new CustomEvent('tick', { detail: { time } }));
    if (this.pg.finished) this.finished();
  }

  /**
   * The `finished` event: at t = duration, and when the playing clock stops because every
   * robot is at its goal before then (FrameLoop.advance).
   */
  finished() {
    this.host.dispatchEvent(new CustomEvent('finished', { detail: { time: this.views.time } }));
  }

  // ---- edits (see the top of the file) ------------------------------------------------------

  /** Moves robot `i` to (x, y, θ): its start at t = 0, where it is now (a nudge) later. */
  moveRobot(i, x, y, theta) {
    const atStart = this.views.time === 0;
    this.#edit(atStart, () => this.pg.moveRobot(i, x, y, theta));
    if (atStart) this.model.robots[i].start = [x, y, theta];
    this.#changed();
  }

  /** Moves robot `i`'s goal to (x, y, θ). */
  moveGoal(i, x, y, theta) {
    this.#edit(true, () => this.pg.moveGoal(i, x, y, theta));
    this.model.robots[i].goal = [x, y, theta];
    this.#changed();
  }

  /** Moves obstacle `k`'s centre to (x, y). */
  moveObstacle(k, x, y) {
    this.#edit(true, () => this.pg.moveObstacle(k, x, y));
    this.model.obstacles[k].center = [x, y];
    this.#changed();
  }

  /** Gives obstacle `k` disc radius `radius` (r_o) and influence radius `influence` (R_o). */
  resizeObstacle(k, radius, influence) {
    this.#edit(true, () => this.pg.resizeObstacle(k, radius, influence));
    Object.assign(this.model.obstacles[k], { radius, influence });
    this.#changed();
  }

  /**
   * Sets parameter `name` to `value` (a number, null for "none", or the avoidance mode), or
   * the scenario's `duration` or `dt`.
   */
  setParam(name, value) {
    this.#edit(true, () => this.pg.setParam(name, value));
    if (name === 'duration' || name === 'dt') this.model[name] = value;
    else this.model.params[name] = value;
    this.#changed();
  }

  /** Adds a robot from `start` to `goal` ([x, y, θ] each); returns its index. */
  addRobot([sx, sy, stheta], [gx, gy, gtheta]) {
    this.#edit(true, () => this.pg.addRobot(sx, sy, stheta, gx, gy, gtheta));
    this.model.robots.push({ start: [sx, sy, stheta], goal: [gx, gy, gtheta] });
    this.#changed();
    return this.model.robots.length - 1;
  }

  /** Removes robot `i`; the robots after it move down one index. */
  removeRobot(i) {
    this.#edit(true, () => this.pg.removeRobot(i));
    this.model.robots.splice(i, 1);
    this.#changed();
  }

  /** Adds `obstacle` ({center, radius, influence}); returns its index. */
  addObstacle({ center: [x, y], radius, influence }) {
    this.#edit(true, () => this.pg.addObstacle(x, y, radius, influence));
    this.model.obstacles.push({ center: [x, y], radius, influence });
    this.#changed();
    return this.model.obstacles.length - 1;
  }

  /** Removes obstacle `k`; the obstacles after it move down one index. */
  removeObstacle(k) {
    this.#edit(true, () => this.pg.removeObstacle(k));
    this.model.obstacles.splice(k, 1);
    this.#changed();
  }

  /** Replaces the whole scenario (object or JSON text): undo, imports and links. */
  edit(scenario) {
    this.#edit(true, () => this.pg.edit(scenario));
    this.model = this.pg.scenario();
    this.#changed();
  }

  /**
   * Makes the facade's `call` for an edit, timed for the benchmarks (`stats.lastEditMs`);
   * before it, when the edit changes the `scenario` (not a nudge at t > 0), the gesture keeps
   * the scenario as it was for undo. The call throws the core's Error and changes nothing, or
   * succeeds: then, and only then, the caller updates the model.
   */
  #edit(scenario, call) {
    this.flushExact();
    if (scenario) this.history.willChange(() => this.text());
    const t0 = performance.now();
    call();
    this.loop.stats.lastEditMs = performance.now() - t0;
  }

  /** After the simulation changed. */
  #changed() {
    this.generation += 1;
    this.views.refresh();
    this.#fixSelection();
    this.requestDraw();
  }

  // ---- gestures -------------------------------------------------------------------------------

  /** Starts a gesture (a drag, a key, a button); one begun within another joins it. */
  begin() {
    this.flushExact();
    this.history.begin();
  }

  /** Ends the gesture: one undo entry if it changed the scenario, one `change` event of `kind`. */
  commit(kind) {
    const before = this.history.end();
    if (before) {
      this.model = this.pg.scenario();
      this.#fixSelection();
      if (this.text() !== before) this.history.push(before);
      this.toolbar.update();
    }
    this.#emit(kind);
  }

  /** Ends the gesture without keeping it: the scenario goes back to where it began. */
  cancel() {
    const before = this.history.end();
    if (!before || this.text() === before) return;
    this.#apply(before);
  }

  /**
   * One gesture of the edits `edits()` makes, of `kind`: on an error shows the message, keeps
   * the scene and returns false.
   */
  change(kind, edits) {
    this.begin();
    try {
      edits();
    } catch (e) {
      this.cancel();
      this.showMessage(messageOf(e));
      return false;
    }
    this.showMessage('');
    this.commit(kind);
    return true;
  }

  undo() {
    this.#travel('undo');
  }

  redo() {
    this.#travel('redo');
  }

  #travel(direction) {
    if (!this.pg) return;
    const now = () => this.text();
    if (this.history.travel(direction, now, (text) => this.#apply(text))) {
      this.params.fill(this.model, this.root.activeElement);
      this.#emit(direction);
    }
    this.toolbar.update();
  }

  /** Applies scenario text `text` (from the history); false with the message when refused. */
  #apply(text) {
    try {
      this.edit(JSON.parse(text));
      this.showMessage('');
      return true;
    } catch (e) {
      this.showMessage(messageOf(e));
      return false;
    }
  }

  /** Tells the page: a `change` event of `kind`; the scene is no longer a preset but after one. */
  #emit(kind) {
    if (kind !== 'preset') this.results.stale();
    if (kind !== 'preset' && this.preset) {
      this.preset = null;
      this.toolbar.showPreset(null);
    }
    this.host.dispatchEvent(new CustomEvent('change', { detail: { kind } }));
  }

  #fixSelection() {
    const n = this.model.robots.length;
    if (this.focusRobot >= n) this.focusRobot = n - 1;
    const sel = this.selection;
    if (!sel) return;
    const count = sel.kind === 'obstacle' ? this.model.obstacles.length : n;
    if (sel.index >= count) this.selection = null;
  }

  // ---- what the frame reads -------------------------------------------------------------------

  /** The world↔screen maps of the canvas now (render/camera.js). */
  view() {
    const w = Math.max(1, this.canvas.clientWidth);
    const h = Math.max(1, this.canvas.clientHeight);
    return this.camera.view(this.model.bounds, w, h);
  }

  /** Page coordinates (CSS px, like pageX/pageY) of world point (x, y) in metres. */
  worldToScreen(x, y) {
    const view = this.view();
    const rect = this.canvas.getBoundingClientRect();
    return { x: rect.left + window.scrollX + view.sx(x), y: rect.top + window.scrollY + view.sy(y) };
  }

  /** Zooms by `factor` about canvas point (px, py). */
  zoom(factor, px, py) {
    this.camera.zoomAbout(this.view(), factor, px, py);
    this.viewChanged();
    this.requestDraw();
  }

  /** Fits the scenario's bounds in the view. */
  fit() {
    this.camera.fit();
    this.viewChanged();
    this.requestDraw();
  }

  /** The field overlay, θ(0) of the curves (degrees) and the sensing circles. */
  setDisplay({ field, theta0Deg, sensing }) {
    this.fieldMode = field;
    this.theta0Deg = theta0Deg;
    this.showSensing = sensing;
    this.toolbar.showDisplay(this);
    this.viewChanged();
    this.requestDraw();
  }

  /**
   * Shows `text` over the canvas (as text, never HTML) until the user acts (an edit, a load,
   * the × button) or a newer message replaces it; empty hides it. `info` marks a notice rather
   * than an error; `actions` are buttons `[label, run]` beside the text; `source` names what
   * showed it, for clearMessage.
   * @param {string} text
   * @param {{info?: boolean, actions?: [string, () => void][], source?: string}} [options]
   */
  showMessage(text, { info = false, actions = [], source = '' } = {}) {
    const box = this.$('message');
    this.$('message-text').textContent = text ?? '';
    const buttons = actions.map(([label, run]) => {
      const b = document.createElement('button');
      b.type = 'button';
      b.textContent = label;
      b.addEventListener('click', () => {
        this.showMessage('');
        run();
      });
      return b;
    });
    this.$('message-actions').replaceChildren(...buttons);
    box.classList.toggle('info', info);
    box.hidden = !text;
    this.messageSource = text ? source : '';
  }

  /** Hides the message if `source` showed it. */
  clearMessage(source) {
    if (this.messageSource === source) this.showMessage('');
  }

  /**
   * What the view shows, for a link (www/main.js): the field overlay, θ(0) (degrees), the
   * sensing circles, the inspected robot, the time (s) and, once the user panned or zoomed,
   * the world box in view ([xmin, ymin, xmax, ymax], m).
   * @returns {import('../dvf-playground.js').ViewState}
   */
  viewState() {
    const v = this.view();
    return {
      field: this.fieldMode,
      theta0: this.theta0Deg,
      sensing: this.showSensing,
      robot: this.focusRobot,
      time: this.views.time,
      box: this.camera.user ? [v.wx(0), v.wy(v.height), v.wx(v.width), v.wy(0)] : null,
    };
  }

  /**
   * Shows the view `state` (viewState's fields, each optional): what is not valid for this
   * scene (a robot that does not exist, a box that is not one, a time past the end) is left
   * as it is. A time is gone to as a seek.
   * @param {Partial<import('../dvf-playground.js').ViewState>} state
   */
  setViewState(state) {
    if (!this.pg || !state) return;
    const { field, theta0, sensing, robot, time, box } = state;
    this.setDisplay({
      field: FIELD_MODES.includes(field) ? field : this.fieldMode,
      theta0Deg: Number.isFinite(theta0) ? theta0 : this.theta0Deg,
      sensing: typeof sensing === 'boolean' ? sensing : this.showSensing,
    });
    if (Number.isInteger(robot) && robot >= 0 && robot < this.model.robots.length) this.focusRobot = robot;
    if (Array.isArray(box) && box.length === 4 && box.every(Number.isFinite) && box[2] > box[0] && box[3] > box[1]) {
      const w = Math.max(1, this.canvas.clientWidth);
      const h = Math.max(1, this.canvas.clientHeight);
      const scale = Math.min(w / (box[2] - box[0]), h / (box[3] - box[1]));
      this.camera.state = { cx: (box[0] + box[2]) / 2, cy: (box[1] + box[3]) / 2, scale };
      this.camera.user = true;
    }
    if (Number.isFinite(time) && time > 0 && time <= this.pg.duration) this.seekTo(time);
    this.requestDraw();
  }

  /** The view changed (display, camera, inspected robot, time at rest): one `viewchange` soon. */
  viewChanged() {
    if (this.viewTimer) clearTimeout(this.viewTimer);
    this.viewTimer = setTimeout(() => {
      this.viewTimer = null;
      this.host.dispatchEvent(new CustomEvent('viewchange'));
    }, VIEW_EVENT_MS);
  }

  /** Whether the help overlay is shown. */
  helpShown() {
    return !this.$('help-panel').hidden;
  }

  /** Shows the help overlay (the controls and keys), hides it, or (no `show`) toggles it. */
  toggleHelp(show = !this.helpShown()) {
    this.$('help-panel').hidden = !show;
    if (show) this.$('help-close').focus({ preventScroll: true });
    else this.canvas.focus({ preventScroll: true });
  }

  /** Reads the theme's colours again (the stylesheet, the `theme` attribute, the system's). */
  readTheme() {
    const theme = this.host.getAttribute('theme');
    const dark = theme === 'dark' || (theme !== 'light' && matchMedia('(prefers-color-scheme: dark)').matches);
    const pg = this.root.querySelector('.pg');
    pg.classList.toggle('dark', dark);
    this.palette = readPalette(pg);
    setPalette(this.palette);
    const p = this.palette;
    this.painter.plots.colours = { text: p.plotText, axis: p.plotAxis, pair: p.plotPair };
    this.painter.newTheme();
    buildLegend(this.$('legend'));
    this.requestDraw();
  }

  requestDraw() {
    this.loop.requestDraw();
  }
}

/**
 * Whether this engine runs WebAssembly's 128-bit SIMD, which the simulator's module is built
 * with: a module of one function that splats a constant into a vector and counts its bits (the
 * test the npm package wasm-feature-detect makes).
 */
function hasWasmSimd() {
  const probe = [
    0, 97, 115, 109, 1, 0, 0, 0, 1, 5, 1, 96, 0, 1, 123, 3, 2, 1, 0, 10, 10, 1, 8, 0, 65, 0, 253, 15, 253, 98, 11,
  ];
  try {
    return WebAssembly.validate(new Uint8Array(probe));
  } catch {
    return false;
  }
}

/** The message for a module that could not be loaded, with what to do about it. */
function wasmFailure(e) {
  if (typeof WebAssembly === 'object' && !hasWasmSimd()) {
    return 'This browser cannot run the simulator: it needs WebAssembly with 128-bit SIMD (Chrome or Edge 91, Firefox 89, Safari 16.4 or later).';
  }
  if (globalThis.location?.protocol === 'file:') {
    return 'This page was opened from a file (file://), and browsers load the simulator (WebAssembly) only over HTTP. Serve the folder over HTTP, e.g. run "python3 -m http.server" in it and open http://localhost:8000/.';
  }
  return `Could not load the simulator (${wasmSourceName()}): ${messageOf(e)}. Serve dvf_bg.wasm with the package, or point the element at it with its wasm attribute.`;
}
