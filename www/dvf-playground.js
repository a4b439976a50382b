// <dvf-playground>: the DVF playground as a custom element. One script tag includes it:
//
//   <script type="module" src="dvf-playground.js"></script>
//   <dvf-playground preset="example3-circle-swap" controls autoplay></dvf-playground>
//
// Attributes: preset (a preset name), src (URL of a scenario JSON file), controls (toolbar and
// side panels), autoplay, field ("arrows", "curves" or "none"), theta0 (θ(0) of the integral
// curves, degrees), sensing (draw R_s).
// API: load(scenario), scenario(), play(), pause(), reset(), step(n), worldToScreen(x, y);
// the `loaded` promise; a `change` event after each edit. See README.md, "Embedding".
//
// Every instance owns its live simulation and its requestAnimationFrame loop; the wasm module
// is initialised once per page and shared.

import init, { Playground, defaultPreset, playgroundLimits, presetScenario, presets } from './pkg/dvf.js';
import {
  FIELD_SPACING_PX, HANDLE_RADIUS_PX, POSE_STRIDE, STATUS_STRIDE, TRAIL_SETTLE_MS, TrailLayer, drawScene,
  fitCanvas, fittedCamera, handlePoint, makeView, robotColour,
} from './render.js';
import { GlyphLayer } from './glyphs.js';
import { HEADING_COLOUR, PAIR_COLOUR, POSITION_COLOUR, SAFE_COLOUR, drawPlot, makeSeries, plotSeries } from './plots.js';
import { buildLegend, buildParams, fillParams } from './panels.js';
import { MAX_SCENARIO_BYTES, download, fileStem, readScenarioFile, trajectoriesCsv } from './io.js';

/** The module is fetched and compiled once per page, whatever the number of instances. */
const WASM_READY = init().then((wasm) => ({ memory: wasm.memory, limits: playgroundLimits(), presets: presets() }));

/** Playback speeds offered (simulated seconds per wall-clock second). */
const SPEEDS = [0.25, 0.5, 1, 2, 4];
const DEFAULT_SPEED = 1;
/** A frame never advances more than this wall time (s): a hidden tab does not jump ahead. */
const MAX_FRAME_WALL_S = 0.1;
/**
 * A frame spends at most about this long stepping (ms): a crowd too large for real time plays
 * slower (the clock says by how much) rather than making every frame longer than the last.
 */
const STEP_BUDGET_MS = 20;
/** Frame work times kept for the benchmark (a ring; see `stats`). */
const WORK_SAMPLES = 600;
/** A crowd loaded from the menu has this many robots unless the N box says otherwise. */
const DEFAULT_CROWD = 1000;
const CROWD_PREFIX = 'crowd-';
/** The Step button and the S key advance this much simulated time (s). */
const STEP_TIME_S = 0.1;
/** Hit radius around robots, goals and handles (CSS px). */
const HIT_PX = 12;
/** Keyboard: arrows move the selection by this fraction of the view's smaller side. */
const KEY_MOVE_FRACTION = 0.02;
/** Keyboard: Q/E turn the selection by this angle (rad). */
const KEY_TURN_RAD = Math.PI / 36;
/** Zoom factor per wheel notch or +/- key. */
const ZOOM_STEP = 1.2;
/** At most this many field arrows per side. */
const MAX_FIELD_SIDE = 60;
/** Integral curves start from an n × n grid over the scenario's bounds. */
const CURVE_GRID = 9;
/** Undo keeps at most this many scenarios, and at most UNDO_CHARS characters of them. */
const UNDO_LIMIT = 200;
const UNDO_CHARS = 32 * 1024 * 1024;
/** Default θ(0) of the integral curves (degrees): the paper's Fig. 1. */
const DEFAULT_THETA0_DEG = 90;
/** A new obstacle's radius as a fraction of the view's smaller side; its ring is twice that. */
const NEW_OBSTACLE_FRACTION = 0.05;
/** Candidate spots tried, along a spiral about the view's centre, for a new robot. */
const ADD_ROBOT_TRIES = 400;

const TEMPLATE = `
<link rel="stylesheet" href="${new URL('playground.css', import.meta.url)}">
<div class="pg" part="root">
  <div class="toolbar" role="toolbar" aria-label="Playground controls">
    <span class="group full">
      <label>Preset <select data-id="preset" aria-label="Load a preset of the paper's examples"></select></label>
      <label data-id="crowd-box" hidden>N <input data-id="crowd-n" class="crowd-n" type="number" min="1" step="1" aria-label="Robots in the crowd"></label>
    </span>
    <span class="group">
      <button type="button" data-id="play" aria-pressed="false" title="Play / pause (Space)">Play</button>
      <button type="button" data-id="step" title="Advance 0.1 s (S)">Step</button>
      <button type="button" data-id="reset" title="Back to t = 0 at the starts (R)">Reset</button>
      <label class="full">Speed <select data-id="speed" aria-label="Playback speed"></select></label>
    </span>
    <span class="group full">
      <button type="button" data-id="undo" title="Undo (Ctrl+Z)">Undo</button>
      <button type="button" data-id="redo" title="Redo (Ctrl+Shift+Z)">Redo</button>
      <button type="button" data-id="add-robot" title="Add a robot at the centre of the view (A)">+ Robot</button>
      <button type="button" data-id="add-obstacle" title="Add an obstacle at the centre of the view (O)">+ Obstacle</button>
      <button type="button" data-id="delete" title="Delete the selected robot or obstacle (Delete)">Delete</button>
    </span>
    <span class="group">
      <label>Field <select data-id="field" aria-label="Field display">
        <option value="arrows">arrows Γ</option><option value="curves">integral curves</option><option value="none">off</option>
      </select></label>
      <label>θ(0) <input data-id="theta0" type="number" step="15" aria-label="θ(0) of the integral curves, degrees"> °</label>
      <label class="check full"><input data-id="sensing" type="checkbox"> R_s</label>
      <button type="button" data-id="fit" class="full" title="Fit the scenario in the view (F)">Fit</button>
    </span>
    <span class="group full">
      <button type="button" data-id="export-json" title="Download the scenario as JSON">Scenario JSON</button>
      <button type="button" data-id="export-png" title="Download the picture as PNG">PNG</button>
      <button type="button" data-id="export-csv" title="Download the whole run's trajectories as CSV">CSV</button>
      <button type="button" data-id="import" title="Load a scenario JSON file">Import…</button>
      <input data-id="import-file" type="file" accept=".json,application/json" hidden>
    </span>
  </div>
  <div class="message" data-id="message" role="alert" hidden></div>
  <div class="body">
    <div class="stage">
      <canvas data-id="canvas" tabindex="0" role="application"
        aria-label="Playground canvas. Drag robots, goals and obstacles; keys: Space play, S step, R reset, arrows move, Q and E turn, A add robot, O add obstacle, Delete, brackets select, F fit."></canvas>
      <div class="clock" data-id="clock"></div>
      <div class="title" data-id="title"></div>
      <div class="hint" data-id="hint"></div>
    </div>
    <aside class="side full">
      <section>
        <h3>Inspected robot</h3>
        <p class="robot-info" data-id="robot-info"></p>
        <canvas data-id="plots" aria-label="Minimum pair distance and the selected robot's errors over time"></canvas>
      </section>
      <section>
        <h3>Parameters</h3>
        <form data-id="params" class="params"></form>
      </section>
      <section>
        <h3>Legend</h3>
        <ul class="legend" data-id="legend"></ul>
        <p class="keys">Drag a robot, goal or obstacle to move it; drag a handle to turn a heading or resize a disc or ring; drag the background to pan, wheel to zoom. Keys on the canvas: Space play, S step, R reset, arrows move, Q/E turn, [ ] select, A/O add, Delete, Ctrl+Z/Ctrl+Shift+Z, +/− zoom, F fit.</p>
      </section>
    </aside>
  </div>
</div>`;

/** The live playground element. */
export class DvfPlayground extends HTMLElement {
  static get observedAttributes() {
    return ['preset', 'src', 'field', 'theta0', 'sensing'];
  }

  constructor() {
    super();
    this.attachShadow({ mode: 'open' }).innerHTML = TEMPLATE;
    const $ = (id) => this.shadowRoot.querySelector(`[data-id="${id}"]`);
    this.$ = $;
    this.canvas = $('canvas');
    this.pg = null;
    this.cache = null;
    this.camera = null;
    this.userCamera = false;
    this.selection = null;
    this.focusRobot = 0;
    this.playing = false;
    this.speed = DEFAULT_SPEED;
    this.lastFrameMs = null;
    this.undoStack = [];
    this.redoStack = [];
    this.drag = null;
    this.pendingPointer = null;
    /** Pointers down on the canvas (id → canvas point), for two-finger pinch zoom. */
    this.pointers = new Map();
    this.pinch = null;
    this.frameRequested = false;
    this.curvesKey = '';
    this.curves = null;
    /** Views into wasm memory, remade only when an array moved or the memory grew. */
    this.views = null;
    this.trailLayer = new TrailLayer();
    this.glyphLayer = new GlyphLayer();
    /** Bumped by every edit, load and reset: the trail layer redraws from scratch. */
    this.generation = 0;
    /** Mean wall time of one step (ms), for the step budget; null before the first. */
    this.stepMs = null;
    /** Simulated over wall-clock time in the last frames (1 when the speed is kept). */
    this.rate = 1;
    /**
     * Diagnostics read by the end-to-end tests: frames drawn, when the first was (ms since the
     * page's time origin), the time of the last edit with its prediction, and the work of the
     * last and the slowest frame (ms). With `rasterInWork` set, a frame's work includes the
     * rasterisation of its drawing (see rasterNow).
     */
    this.stats = {
      frames: 0, lastEditMs: 0, frameWorkMs: 0, maxFrameWorkMs: 0,
      // The work of the last WORK_SAMPLES frames (ms), a ring written at `workCount % length`.
      work: new Float64Array(WORK_SAMPLES), workCount: 0, rasterInWork: false,
    };
    let resolveLoaded;
    /** Resolves once the first scene is shown. */
    this.loaded = new Promise((r) => { resolveLoaded = r; });
    this.resolveLoaded = resolveLoaded;
    this.connected = false;
  }

  connectedCallback() {
    if (this.connected) return;
    this.connected = true;
    this.resizeObserver = new ResizeObserver(() => this.requestDraw());
    this.resizeObserver.observe(this.canvas);
    this.resizeObserver.observe(this.$('plots'));
    this.onWindowResize = () => this.requestDraw(); // devicePixelRatio changes come this way
    window.addEventListener('resize', this.onWindowResize);
    // Moved elsewhere in the document: the same simulation goes on, wired once.
    if (this.wired) {
      this.requestDraw();
      return;
    }
    this.wired = true;
    this.wire();
    this.start();
  }

  disconnectedCallback() {
    this.connected = false;
    this.playing = false;
    this.resizeObserver?.disconnect();
    window.removeEventListener('resize', this.onWindowResize);
  }

  attributeChangedCallback(name, oldValue, value) {
    if (!this.pg || oldValue === value) return;
    if (name === 'preset' && value) this.loadPreset(value);
    else if (name === 'src' && value) this.loadUrl(value);
    else this.readDisplayAttributes();
    this.requestDraw();
  }

  async start() {
    try {
      const { memory, limits, presets: list } = await WASM_READY;
      this.memory = memory;
      this.limits = limits;
      this.presetList = list;
      this.views = new WasmViews(memory);
    } catch (e) {
      this.showMessage(`Could not load the simulator (pkg/dvf_bg.wasm): ${e.message ?? e}. Build it with "make build-wasm".`);
      return;
    }
    const select = this.$('preset');
    const custom = document.createElement('option');
    custom.value = '';
    custom.textContent = '(edited or imported)';
    custom.disabled = true;
    select.append(custom);
    for (const p of this.presetList) {
      const o = document.createElement('option');
      o.value = p.name;
      o.textContent = p.name;
      o.title = p.summary;
      select.append(o);
    }
    const crowd = document.createElement('option');
    crowd.value = 'crowd';
    crowd.textContent = 'crowd of N robots';
    crowd.title = `N robots (1 to ${this.limits.crowdMax}) swap antipodally on a circle, keeping their headings`;
    select.append(crowd);
    const crowdN = this.$('crowd-n');
    crowdN.max = String(this.limits.crowdMax);
    crowdN.value = String(DEFAULT_CROWD);
    this.readDisplayAttributes();
    const src = this.getAttribute('src');
    let ok = false;
    if (src) ok = await this.loadUrl(src);
    if (!ok) ok = this.loadPreset(this.getAttribute('preset') || defaultPreset(), { quiet: Boolean(src) });
    if (!ok) this.loadPreset(defaultPreset(), { quiet: true });
    if (this.hasAttribute('autoplay')) this.play();
    this.resolveLoaded();
  }

  readDisplayAttributes() {
    const field = this.getAttribute('field');
    this.fieldMode = ['arrows', 'curves', 'none'].includes(field) ? field : 'arrows';
    const t = Number(this.getAttribute('theta0') ?? DEFAULT_THETA0_DEG);
    this.theta0Deg = Number.isFinite(t) ? t : DEFAULT_THETA0_DEG;
    this.showSensing = this.hasAttribute('sensing');
    this.$('field').value = this.fieldMode;
    this.$('theta0').value = String(this.theta0Deg);
    this.$('sensing').checked = this.showSensing;
  }

  // ---- public API -------------------------------------------------------------------------

  /**
   * Loads a scenario (object or JSON text) as a new document: time 0, view fitted, undo
   * history cleared. Throws an Error naming the offending field; the scene is kept then.
   */
  load(scenario) {
    const pg = new Playground(scenario);
    this.replace(pg, { fit: true });
    this.undoStack = [];
    this.redoStack = [];
    this.updateButtons();
  }

  /** The name of the preset shown, or null once the scene has been edited or imported. */
  presetName() {
    return this.cache?.presetName ?? null;
  }

  /** The current scenario as a plain object (edits included; the JSON scenario format). */
  scenario() {
    return this.pg ? structuredClone(this.cache.scenario) : null;
  }

  play() {
    if (!this.pg) return;
    if (this.pg.finished) this.reset();
    this.playing = true;
    this.lastFrameMs = null;
    this.updateButtons();
    this.requestDraw();
  }

  pause() {
    this.playing = false;
    this.updateButtons();
    this.requestDraw();
  }

  /** Back to t = 0 at the scenario's starts (trails cleared). */
  reset() {
    if (!this.pg) return;
    this.pg.reset();
    this.refreshCache();
    this.requestDraw();
  }

  /** Advances `n` steps of dt (default 1) and pauses. Throws for a bad `n`. */
  step(n = 1) {
    if (!this.pg) return 0;
    this.pause();
    const taken = this.pg.step(n);
    this.refreshCache();
    this.requestDraw();
    return taken;
  }

  /** Page coordinates (CSS px, like MouseEvent.pageX/pageY) of world point (x, y) in metres. */
  worldToScreen(x, y) {
    const view = this.view();
    const rect = this.canvas.getBoundingClientRect();
    return { x: rect.left + window.scrollX + view.sx(x), y: rect.top + window.scrollY + view.sy(y) };
  }

  /** Shows `text` in the element's message bar (as text, never HTML); empty hides it. */
  showMessage(text) {
    const box = this.$('message');
    box.textContent = text ?? '';
    box.hidden = !text;
  }

  /** Advances STEP_TIME_S of simulated time (at least one step). */
  stepTime() {
    if (this.pg) this.step(Math.max(1, Math.round(STEP_TIME_S / this.pg.dt)));
  }

  // ---- documents and edits ----------------------------------------------------------------

  /** Loads preset `name` as an edit (undoable); returns whether it worked. */
  loadPreset(name, { quiet = false, edit = false } = {}) {
    try {
      const pg = Playground.fromPreset(name);
      if (edit && this.pg) this.pushUndo();
      this.replace(pg, { fit: true, presetName: name });
      this.showMessage('');
      if (edit) this.emitChange('preset');
      return true;
    } catch (e) {
      if (!quiet) this.showMessage(e.message ?? String(e));
      this.showPresetName();
      return false;
    }
  }

  /** Loads a crowd of the N in the N box (as an edit); a bad N is named and changes nothing. */
  loadCrowd() {
    const box = this.$('crowd-n');
    const n = Number(box.value);
    const max = this.limits.crowdMax;
    if (!Number.isInteger(n) || n < 1 || n > max) {
      this.showMessage(`crowd: N must be a whole number from 1 to ${max}, not ${box.value || 'empty'}`);
      this.showPresetName();
      return false;
    }
    return this.loadPreset(`${CROWD_PREFIX}${n}`, { edit: true });
  }

  /** The preset menu (and N box) showing the scene's preset, or "(edited or imported)". */
  showPresetName() {
    const name = this.cache?.presetName ?? '';
    const crowd = name.startsWith(CROWD_PREFIX);
    this.$('preset').value = crowd ? 'crowd' : name;
    this.$('crowd-box').hidden = !crowd;
    if (crowd) this.$('crowd-n').value = name.slice(CROWD_PREFIX.length);
  }

  /** Fetches and loads the scenario at `url`; on failure shows why and keeps the scene. */
  async loadUrl(url) {
    try {
      const res = await fetch(url);
      if (!res.ok) throw new Error(`HTTP ${res.status}`);
      const text = await res.text();
      if (text.length > MAX_SCENARIO_BYTES) throw new Error(`the file is longer than ${MAX_SCENARIO_BYTES} bytes`);
      this.load(text);
      this.showMessage('');
      return true;
    } catch (e) {
      this.showMessage(`Could not load the scenario ${url}: ${e.message ?? e}`);
      return false;
    }
  }

  replace(pg, { fit, presetName = null }) {
    const old = this.pg;
    this.pg = pg;
    old?.free();
    this.playing = false;
    this.selection = null;
    this.focusRobot = 0;
    this.curvesKey = '';
    this.stepMs = null;
    if (fit) this.userCamera = false;
    this.refreshCache();
    this.cache.presetName = presetName
      ?? this.presetList.find((p) => sameScenario(presetScenario(p.name), this.cache.scenario))?.name
      ?? null;
    this.showPresetName();
    fillParams(this.paramInputs, this.cache.scenario.params, this.shadowRoot);
    this.updateButtons();
    this.requestDraw();
  }

  /** Applies an edited scenario object; on error shows the message and keeps the scene. */
  applyScenario(scenario) {
    const t0 = performance.now();
    try {
      this.pg.edit(JSON.stringify(scenario));
    } catch (e) {
      this.showMessage(e.message ?? String(e));
      return false;
    }
    this.stats.lastEditMs = performance.now() - t0;
    this.showMessage('');
    this.refreshCache();
    this.requestDraw();
    return true;
  }

  /** After an edit the scene is no longer the preset it came from. */
  markEdited() {
    if (!this.cache.presetName) return;
    this.cache.presetName = null;
    this.showPresetName();
  }

  /** One whole edit: snapshot for undo, apply, announce. */
  edit(mutate, kind) {
    const s = this.scenario();
    mutate(s);
    const before = this.scenarioText();
    if (!this.applyScenario(s)) return false;
    this.pushUndo(before);
    this.emitChange(kind);
    return true;
  }

  scenarioText() {
    return JSON.stringify(this.cache.scenario);
  }

  pushUndo(text = this.scenarioText()) {
    this.undoStack.push(text);
    let chars = this.undoStack.reduce((sum, t) => sum + t.length, 0);
    while (this.undoStack.length > 1 && (this.undoStack.length > UNDO_LIMIT || chars > UNDO_CHARS)) {
      chars -= this.undoStack.shift().length;
    }
    this.redoStack = [];
    this.updateButtons();
  }

  undo() {
    this.travel(this.undoStack, this.redoStack, 'undo');
  }

  redo() {
    this.travel(this.redoStack, this.undoStack, 'redo');
  }

  travel(from, to, kind) {
    if (!from.length || !this.pg) return;
    const text = from.pop();
    const now = this.scenarioText();
    if (this.applyScenario(JSON.parse(text))) {
      to.push(now);
      this.fixSelection();
      fillParams(this.paramInputs, this.cache.scenario.params, this.shadowRoot);
      this.emitChange(kind);
    } else {
      from.push(text);
    }
    this.updateButtons();
  }

  emitChange(kind) {
    if (kind !== 'preset') this.markEdited();
    this.dispatchEvent(new CustomEvent('change', { detail: { kind } }));
  }

  /**
   * Re-reads what the drawing needs from wasm after a step (`withScenario` false) or an edit,
   * load or reset. The arrays (poses, status, trails, …) are getters that return views into
   * wasm memory (see WasmViews), never copies; only the scenario object is rebuilt, and only
   * after an edit.
   */
  refreshCache(withScenario = true) {
    const pg = this.pg;
    if (!this.cache) this.cache = this.makeCache();
    const c = this.cache;
    if (withScenario || !c.scenario) {
      c.scenario = pg.scenario();
      this.generation += 1;
    }
    c.time = pg.time;
    c.duration = pg.duration;
    c.trailHead = pg.trailHead;
    c.historyLength = pg.historyLength;
    c.recorded = pg.trailRecorded;
    c.trailCapacity = pg.trailCapacity;
    c.predictedSamples = pg.predictedSamples;
    this.fixSelection();
  }

  /**
   * The cache object, whose arrays are views of the wasm arrays made when read. A view stays
   * valid until the memory grows, which any call into the module may do (another instance on
   * the page included), so it is re-checked on every read: a pointer read and a comparison,
   * and a new view only when the array moved or the memory grew.
   */
  makeCache() {
    const cache = { presetName: null, scenario: null };
    const lengths = {
      poses: (pg) => pg.robotCount * POSE_STRIDE,
      status: (pg) => pg.robotCount * STATUS_STRIDE,
      trails: (pg, c) => pg.robotCount * c.trailCapacity * POSE_STRIDE,
      trailLengths: (pg) => pg.robotCount,
      trailTimes: (pg, c) => c.trailCapacity,
      trailMinPair: (pg, c) => c.trailCapacity,
      predicted: (pg, c) => pg.robotCount * c.predictedSamples * POSE_STRIDE,
      predictedTimes: (pg, c) => c.predictedSamples,
      predictedMinPair: (pg, c) => c.predictedSamples,
    };
    for (const [name, length] of Object.entries(lengths)) {
      const pointer = `${name}Pointer`;
      const typed = name === 'trailLengths' ? 'u32' : 'f64';
      Object.defineProperty(cache, name === 'trailLengths' ? 'trailLens' : name, {
        enumerable: true,
        get: () => this.views[typed](name, this.pg[pointer], length(this.pg, cache)),
      });
    }
    return cache;
  }

  /** The trail rings as a view into wasm memory (no copy); valid until the next wasm call. */
  trailsView() {
    return this.cache.trails;
  }

  fixSelection() {
    const n = this.cache.scenario.robots.length;
    if (this.focusRobot >= n) this.focusRobot = n - 1;
    const sel = this.selection;
    if (!sel) return;
    const count = sel.kind === 'obstacle' ? this.cache.scenario.obstacles.length : n;
    if (sel.index >= count) this.selection = null;
  }

  // ---- view ---------------------------------------------------------------------------------

  view() {
    const w = Math.max(1, this.canvas.clientWidth);
    const h = Math.max(1, this.canvas.clientHeight);
    if (!this.userCamera || !this.camera) this.camera = fittedCamera(this.cache.scenario.bounds, w, h);
    return makeView(this.camera, w, h);
  }

  zoom(factor, px, py) {
    const view = this.view();
    const wx = view.wx(px);
    const wy = view.wy(py);
    const scale = this.camera.scale * factor;
    // Keep the world point under (px, py) fixed.
    this.camera = {
      scale,
      cx: wx - (px - view.width / 2) / scale,
      cy: wy + (py - view.height / 2) / scale,
    };
    this.userCamera = true;
    this.requestDraw();
  }

  fit() {
    this.userCamera = false;
    this.requestDraw();
  }

  // ---- frame loop ---------------------------------------------------------------------------

  requestDraw() {
    if (this.frameRequested || !this.connected) return;
    this.frameRequested = true;
    requestAnimationFrame((ms) => this.frame(ms));
  }

  frame(nowMs) {
    this.frameRequested = false;
    if (!this.pg) return;
    const workStart = performance.now();
    if (this.pendingPointer) {
      const p = this.pendingPointer;
      this.pendingPointer = null;
      this.applyDrag(p);
    }
    if (this.playing) {
      const wall = this.lastFrameMs == null ? 0 : Math.min(MAX_FRAME_WALL_S, (nowMs - this.lastFrameMs) / 1000);
      this.lastFrameMs = nowMs;
      this.stepCarry = (this.stepCarry ?? 0) + (wall * this.speed) / this.pg.dt;
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
      if (n > 0) {
        const t0 = performance.now();
        const taken = this.pg.step(n);
        if (taken > 0) {
          const per = (performance.now() - t0) / taken;
          this.stepMs = this.stepMs == null ? per : 0.8 * this.stepMs + 0.2 * per;
        }
        this.refreshCache(false);
      }
      if (this.pg.finished) {
        this.playing = false;
        this.updateButtons();
      }
    }
    this.draw();
    if (this.stats.rasterInWork) this.rasterNow();
    if (this.stats.frames === 0) this.stats.firstFrameMs = performance.now();
    this.stats.frames += 1;
    const st = this.stats;
    st.frameWorkMs = performance.now() - workStart;
    st.maxFrameWorkMs = Math.max(st.maxFrameWorkMs, st.frameWorkMs);
    st.work[st.workCount % WORK_SAMPLES] = st.frameWorkMs;
    st.workCount += 1;
    if (this.playing) this.requestDraw();
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
    sink.drawImage(this.canvas, 0, 0, 1, 1);
    sink.drawImage(this.$('plots'), 0, 0, 1, 1);
  }

  draw() {
    const { ctx, width, height } = fitCanvas(this.canvas);
    const view = this.view();
    const c = this.cache;
    const field = this.fieldMode === 'arrows' ? this.sampleField(view, width, height) : null;
    const curves = this.fieldMode === 'curves' ? this.integralCurves() : null;
    // After every other call into wasm this frame (a view is valid until the memory grows):
    // the spread reads every array of the cache as a view once.
    const scene = {
      ...c,
      selection: this.selection,
      focusRobot: this.focusRobot,
      showSensing: this.showSensing,
      field: field ? this.views.f64('field', this.pg.fieldPointer, field) : null,
      curves,
      curvePoints: this.limits.curvePoints,
      trailLayer: this.trailLayer,
      glyphLayer: this.glyphLayer,
      dpr: ctx.canvas.width / width,
    };
    this.trailLayer.update(view, scene, scene.dpr, this.generation, performance.now());
    if (this.trailLayer.stale && !this.settleTimer) {
      // The trails are shown stretched while the view moves: draw them anew once it rests.
      this.settleTimer = setTimeout(() => {
        this.settleTimer = null;
        this.requestDraw();
      }, TRAIL_SETTLE_MS);
    }
    drawScene(ctx, view, scene);
    const slowed = this.playing && this.rate < this.speed * 0.995 ? ` (${this.rate.toPrecision(2)}× real time: the crowd steps slower than the clock)` : '';
    this.$('clock').textContent = `t = ${c.time.toFixed(2)} s / ${c.duration.toFixed(2)} s${this.playing ? slowed : ' (paused)'}`;
    this.$('hint').textContent = this.hintText();
    // Free text from the scenario: textContent only, never HTML.
    this.$('title').textContent = c.scenario.name;
    if (this.hasAttribute('controls')) {
      this.drawPlots(scene);
      this.showRobotInfo();
    }
  }

  hintText() {
    if (this.drag) return '';
    if (this.fieldMode === 'curves') return `integral curves of robot ${this.focusRobot + 1}'s goal field from θ(0) = ${this.theta0Deg}°`;
    if (this.fieldMode === 'arrows') return `arrows: the field Γ of robot ${this.focusRobot + 1} at its current heading`;
    return '';
  }

  sampleField(view, width, height) {
    const nx = Math.min(MAX_FIELD_SIDE, Math.max(2, Math.floor(width / FIELD_SPACING_PX)));
    const ny = Math.min(MAX_FIELD_SIDE, Math.max(2, Math.floor(height / FIELD_SPACING_PX)));
    const hx = width / nx / 2;
    const hy = height / ny / 2;
    try {
      // The values stay in wasm memory: draw() reads them through a view.
      return this.pg.refreshField(this.focusRobot, view.wx(hx), view.wy(height - hy), view.wx(width - hx), view.wy(hy), nx, ny);
    } catch (e) {
      this.showMessage(e.message ?? String(e));
      return null;
    }
  }

  integralCurves() {
    const s = this.cache.scenario;
    const g = s.robots[this.focusRobot]?.goal;
    const key = JSON.stringify([this.focusRobot, g, this.theta0Deg, s.bounds]);
    if (key !== this.curvesKey) {
      const [x0, y0, x1, y1] = s.bounds;
      try {
        this.curves = this.pg.integralCurves(this.focusRobot, (this.theta0Deg * Math.PI) / 180, x0, y0, x1, y1, CURVE_GRID);
      } catch (e) {
        this.showMessage(e.message ?? String(e));
        this.curves = null;
      }
      this.curvesKey = key;
    }
    return this.curves;
  }

  drawPlots(scene) {
    const { ctx, width, height } = fitCanvas(this.$('plots'));
    ctx.clearRect(0, 0, width, height);
    const s = this.cache.scenario;
    this.series ??= makeSeries();
    const series = plotSeries(scene, this.focusRobot, this.series);
    const half = height / 2;
    const pairLines = s.independent || s.robots.length < 2 ? [] : [
      { points: series.pastPair, colour: PAIR_COLOUR, axis: 'left' },
      { points: series.futurePair, colour: PAIR_COLOUR, axis: 'left', dashed: true },
    ];
    drawPlot(ctx, { x: 0, y: 0, w: width, h: half - 4 }, {
      title: 'min distance between two robots (m)',
      duration: scene.duration,
      time: scene.time,
      lines: pairLines,
      hline: pairLines.length ? { value: 2 * s.params.safe_radius, colour: SAFE_COLOUR, label: '2·r_ij' } : null,
    });
    drawPlot(ctx, { x: 0, y: half + 4, w: width, h: half - 4 }, {
      title: `robot ${this.focusRobot + 1}: position error (m), heading error (rad)`,
      duration: scene.duration,
      time: scene.time,
      rightLabel: 'rad',
      lines: [
        { points: series.pastPos, colour: POSITION_COLOUR, axis: 'left' },
        { points: series.futurePos, colour: POSITION_COLOUR, axis: 'left', dashed: true },
        { points: series.pastHead, colour: HEADING_COLOUR, axis: 'right' },
        { points: series.futureHead, colour: HEADING_COLOUR, axis: 'right', dashed: true },
      ],
    });
  }

  showRobotInfo() {
    const i = this.focusRobot;
    const st = this.cache.status;
    const o = i * 6;
    const avoiding = !Number.isNaN(st[o + 4]);
    // The robot's own colour beside its number, so the text and the canvas match.
    this.$('robot-info').style.borderLeftColor = robotColour(i);
    this.$('robot-info').textContent =
      `Robot ${i + 1} of ${this.cache.scenario.robots.length}: v = ${st[o].toFixed(2)} m/s, ω = ${st[o + 1].toFixed(2)} rad/s` +
      `${st[o + 2] < 1 ? ', avoiding an obstacle' : ''}${avoiding ? ', avoiding robots' : ''}.`;
  }

  updateButtons() {
    const play = this.$('play');
    play.textContent = this.playing ? 'Pause' : 'Play';
    play.setAttribute('aria-pressed', String(this.playing));
    this.$('undo').disabled = this.undoStack.length === 0;
    this.$('redo').disabled = this.redoStack.length === 0;
    this.$('delete').disabled = !this.selection;
  }

  // ---- input --------------------------------------------------------------------------------

  wire() {
    const $ = this.$;
    const speed = $('speed');
    for (const s of SPEEDS) {
      const o = document.createElement('option');
      o.value = String(s);
      o.textContent = `${s}×`;
      speed.append(o);
    }
    speed.value = String(DEFAULT_SPEED);
    speed.addEventListener('change', () => { this.speed = Number(speed.value); });
    $('preset').addEventListener('change', () => {
      if ($('preset').value === 'crowd') this.loadCrowd();
      else this.loadPreset($('preset').value, { edit: true });
    });
    $('crowd-n').addEventListener('change', () => this.loadCrowd());
    $('play').addEventListener('click', () => (this.playing ? this.pause() : this.play()));
    $('step').addEventListener('click', () => this.stepTime());
    $('reset').addEventListener('click', () => this.reset());
    $('undo').addEventListener('click', () => this.undo());
    $('redo').addEventListener('click', () => this.redo());
    $('add-robot').addEventListener('click', () => this.addRobot());
    $('add-obstacle').addEventListener('click', () => this.addObstacle());
    $('delete').addEventListener('click', () => this.deleteSelection());
    $('fit').addEventListener('click', () => this.fit());
    $('field').addEventListener('change', () => { this.fieldMode = $('field').value; this.requestDraw(); });
    $('theta0').addEventListener('change', () => {
      const v = Number($('theta0').value);
      if (Number.isFinite(v) && $('theta0').value.trim() !== '') this.theta0Deg = v;
      else $('theta0').value = String(this.theta0Deg);
      this.requestDraw();
    });
    $('sensing').addEventListener('change', () => { this.showSensing = $('sensing').checked; this.requestDraw(); });
    $('export-json').addEventListener('click', () => {
      const s = this.scenario();
      download(new Blob([`${JSON.stringify(s, null, 2)}\n`], { type: 'application/json' }), `${fileStem(s.name)}.json`);
    });
    $('export-png').addEventListener('click', () => {
      this.draw(); // the backing store holds the current frame
      this.canvas.toBlob((blob) => download(blob, `${fileStem(this.cache.scenario.name)}.png`), 'image/png');
    });
    $('export-csv').addEventListener('click', () => {
      try {
        const s = this.scenario();
        download(new Blob([trajectoriesCsv(s)], { type: 'text/csv' }), `${fileStem(s.name)}.csv`);
      } catch (e) {
        this.showMessage(e.message ?? String(e));
      }
    });
    $('import').addEventListener('click', () => $('import-file').click());
    $('import-file').addEventListener('change', async () => {
      const file = $('import-file').files?.[0];
      $('import-file').value = '';
      if (!file) return;
      try {
        const text = await readScenarioFile(file);
        const before = this.pg ? this.scenarioText() : null;
        this.load(text);
        if (before) this.undoStack.push(before);
        this.updateButtons();
        this.showMessage('');
        this.emitChange('import');
      } catch (e) {
        this.showMessage(`Could not import ${file.name}: ${e.message ?? e}`);
      }
    });
    this.paramInputs = buildParams($('params'), (key, value) => this.setParam(key, value));
    buildLegend($('legend'));

    const c = this.canvas;
    c.addEventListener('pointerdown', (e) => this.pointerDown(e));
    c.addEventListener('pointermove', (e) => this.pointerMove(e));
    c.addEventListener('pointerup', (e) => this.pointerUp(e));
    c.addEventListener('pointercancel', (e) => this.pointerUp(e));
    c.addEventListener('wheel', (e) => {
      // Embedded in text, the wheel scrolls the page unless the canvas has been clicked
      // (focused) or Ctrl is held; with the full controls it always zooms.
      const mine = this.hasAttribute('controls') || e.ctrlKey || this.shadowRoot.activeElement === c;
      if (!mine) return;
      e.preventDefault();
      const r = c.getBoundingClientRect();
      this.zoom(e.deltaY < 0 ? ZOOM_STEP : 1 / ZOOM_STEP, e.clientX - r.left, e.clientY - r.top);
    }, { passive: false });
    c.addEventListener('keydown', (e) => this.keyDown(e));
  }

  setParam(key, value) {
    if (!this.pg) return null;
    if (typeof value === 'number' && !Number.isFinite(value)) {
      fillParams(this.paramInputs, this.cache.scenario.params, { activeElement: null });
      return `params.${key}: must be a number`;
    }
    const before = this.scenarioText();
    const s = this.scenario();
    s.params[key] = value;
    try {
      this.pg.edit(JSON.stringify(s));
    } catch (e) {
      fillParams(this.paramInputs, this.cache.scenario.params, { activeElement: null });
      return e.message ?? String(e);
    }
    this.pushUndo(before);
    this.refreshCache();
    this.requestDraw();
    this.emitChange('params');
    return null;
  }

  /** Where the pointer is, in canvas CSS px. */
  local(e) {
    const r = this.canvas.getBoundingClientRect();
    return { px: e.clientX - r.left, py: e.clientY - r.top };
  }

  /** What is under canvas point (px, py): handles first, then robots, goals, obstacles. */
  hit(px, py) {
    const view = this.view();
    const s = this.cache.scenario;
    const p = this.cache.poses;
    const near = (x, y, r = HIT_PX) => Math.hypot(px - x, py - y) <= r;
    const sel = this.selection;
    if (sel && (sel.kind === 'robot' || sel.kind === 'goal')) {
      const i = sel.index;
      const rb = [view.sx(p[i * POSE_STRIDE]), view.sy(p[i * POSE_STRIDE + 1]), p[i * POSE_STRIDE + 2]];
      const g = s.robots[i].goal;
      if (near(...handlePoint(...rb), HANDLE_RADIUS_PX + 4)) return { kind: 'robot-heading', index: i };
      if (near(...handlePoint(view.sx(g[0]), view.sy(g[1]), g[2]), HANDLE_RADIUS_PX + 4)) return { kind: 'goal-heading', index: i };
    }
    if (sel?.kind === 'obstacle') {
      const o = s.obstacles[sel.index];
      const x = view.sx(o.center[0]);
      const y = view.sy(o.center[1]);
      // The nearer of the two handles: on a small obstacle they can lie within reach of both.
      const dr = Math.hypot(px - (x + o.radius * view.scale), py - y);
      const di = Math.hypot(px - (x + o.influence * view.scale), py - y);
      if (Math.min(dr, di) <= HANDLE_RADIUS_PX + 4) {
        return { kind: dr < di ? 'obstacle-radius' : 'obstacle-influence', index: sel.index };
      }
    }
    let best = null;
    const consider = (cand, d) => { if (d <= HIT_PX && (!best || d < best.d)) best = { ...cand, d }; };
    for (let i = 0; i < s.robots.length; i++) {
      consider({ kind: 'robot', index: i }, Math.hypot(px - view.sx(p[i * POSE_STRIDE]), py - view.sy(p[i * POSE_STRIDE + 1])));
      const g = s.robots[i].goal;
      consider({ kind: 'goal', index: i }, Math.hypot(px - view.sx(g[0]), py - view.sy(g[1])) + 0.5);
    }
    if (best) return best;
    for (let k = s.obstacles.length - 1; k >= 0; k--) {
      const o = s.obstacles[k];
      const d = Math.hypot(px - view.sx(o.center[0]), py - view.sy(o.center[1]));
      if (d <= Math.max(o.radius * view.scale, HIT_PX)) return { kind: 'obstacle', index: k };
    }
    return { kind: 'pan' };
  }

  pointerDown(e) {
    if (!this.pg || e.button > 0) return;
    this.canvas.focus({ preventScroll: true });
    const { px, py } = this.local(e);
    this.pointers.set(e.pointerId, { px, py });
    if (this.pointers.size === 2) {
      // A second finger: whatever the first started becomes a pinch (zoom and pan).
      this.cancelDrag();
      const [a, b] = [...this.pointers.values()];
      this.view();
      this.pinch = { distance: Math.hypot(a.px - b.px, a.py - b.py) || 1, camera: { ...this.camera }, mid: [(a.px + b.px) / 2, (a.py + b.py) / 2] };
      return;
    }
    if (this.pointers.size > 2) return;
    const target = this.hit(px, py);
    if (target.kind === 'robot' || target.kind === 'goal' || target.kind === 'obstacle') {
      this.selection = { kind: target.kind, index: target.index };
      if (target.kind !== 'obstacle') this.focusRobot = target.index;
    }
    const view = this.view();
    const s = this.cache.scenario;
    let anchor = [0, 0];
    if (target.kind === 'robot') anchor = [this.cache.poses[target.index * POSE_STRIDE], this.cache.poses[target.index * POSE_STRIDE + 1]];
    if (target.kind === 'goal') anchor = s.robots[target.index].goal;
    if (target.kind === 'obstacle') anchor = s.obstacles[target.index].center;
    this.drag = {
      ...target,
      pointerId: e.pointerId,
      before: this.scenarioText(),
      offset: [view.wx(px) - anchor[0], view.wy(py) - anchor[1]],
      last: { px, py },
      moved: false,
    };
    this.canvas.setPointerCapture(e.pointerId);
    this.updateButtons();
    this.requestDraw();
  }

  pointerMove(e) {
    if (this.pointers.has(e.pointerId)) this.pointers.set(e.pointerId, this.local(e));
    if (this.pinch && this.pointers.size === 2) {
      this.applyPinch();
      return;
    }
    if (!this.drag || e.pointerId !== this.drag.pointerId) return;
    // Coalesced: the newest position is applied once per animation frame.
    this.pendingPointer = this.local(e);
    this.requestDraw();
  }

  pointerUp(e) {
    this.pointers.delete(e.pointerId);
    if (this.pinch) {
      if (this.pointers.size < 2) this.pinch = null;
      if (this.canvas.hasPointerCapture(e.pointerId)) this.canvas.releasePointerCapture(e.pointerId);
      return;
    }
    if (!this.drag || e.pointerId !== this.drag.pointerId) return;
    if (this.pendingPointer) {
      this.applyDrag(this.pendingPointer);
      this.pendingPointer = null;
    }
    const d = this.drag;
    this.drag = null;
    if (this.canvas.hasPointerCapture(e.pointerId)) this.canvas.releasePointerCapture(e.pointerId);
    if (d.moved && d.kind !== 'pan') {
      if (this.scenarioText() !== d.before) this.pushUndo(d.before);
      this.emitChange(d.kind);
    }
    this.requestDraw();
  }

  /** Ends a drag without keeping it: the scene goes back to where the drag began. */
  cancelDrag() {
    const d = this.drag;
    if (!d) return;
    this.drag = null;
    this.pendingPointer = null;
    if (d.moved && d.kind !== 'pan' && this.scenarioText() !== d.before) this.applyScenario(JSON.parse(d.before));
  }

  /** Two pointers: the camera scales with their distance about their midpoint, and follows it. */
  applyPinch() {
    const [a, b] = [...this.pointers.values()];
    const p = this.pinch;
    const scale = p.camera.scale * (Math.hypot(a.px - b.px, a.py - b.py) / p.distance);
    const w = this.canvas.clientWidth;
    const h = this.canvas.clientHeight;
    // The world point under the first midpoint stays under the current midpoint.
    const wx = p.camera.cx + (p.mid[0] - w / 2) / p.camera.scale;
    const wy = p.camera.cy - (p.mid[1] - h / 2) / p.camera.scale;
    const mx = (a.px + b.px) / 2;
    const my = (a.py + b.py) / 2;
    this.camera = { scale, cx: wx - (mx - w / 2) / scale, cy: wy + (my - h / 2) / scale };
    this.userCamera = true;
    this.requestDraw();
  }

  /** Applies the drag in progress for the pointer at canvas point (px, py). */
  applyDrag({ px, py }) {
    const d = this.drag;
    if (!d) return;
    const view = this.view();
    const wx = view.wx(px);
    const wy = view.wy(py);
    d.moved = true;
    if (d.kind === 'pan') {
      this.camera = { ...this.camera, cx: this.camera.cx - (px - d.last.px) / view.scale, cy: this.camera.cy + (py - d.last.py) / view.scale };
      this.userCamera = true;
      d.last = { px, py };
      return;
    }
    const i = d.index;
    const p = this.cache.poses;
    const s = this.scenario();
    const t0 = performance.now();
    try {
      if (d.kind === 'robot') {
        this.pg.moveRobot(i, wx - d.offset[0], wy - d.offset[1], p[i * POSE_STRIDE + 2]);
      } else if (d.kind === 'robot-heading') {
        const x = p[i * POSE_STRIDE];
        const y = p[i * POSE_STRIDE + 1];
        this.pg.moveRobot(i, x, y, Math.atan2(wy - y, wx - x));
      } else {
        if (d.kind === 'goal') {
          s.robots[i].goal = [wx - d.offset[0], wy - d.offset[1], s.robots[i].goal[2]];
        } else if (d.kind === 'goal-heading') {
          const g = s.robots[i].goal;
          g[2] = Math.atan2(wy - g[1], wx - g[0]);
        } else if (d.kind === 'obstacle') {
          s.obstacles[i].center = [wx - d.offset[0], wy - d.offset[1]];
        } else if (d.kind === 'obstacle-radius') {
          const o = s.obstacles[i];
          const r = Math.max(Math.hypot(wx - o.center[0], wy - o.center[1]), 1e-3);
          if (o.influence <= r) o.influence = r + (o.influence - o.radius);
          o.radius = r;
        } else if (d.kind === 'obstacle-influence') {
          const o = s.obstacles[i];
          o.influence = Math.max(Math.hypot(wx - o.center[0], wy - o.center[1]), o.radius * 1.01);
        }
        this.pg.edit(JSON.stringify(s));
      }
      this.stats.lastEditMs = performance.now() - t0;
      this.showMessage('');
    } catch (e) {
      this.showMessage(e.message ?? String(e));
    }
    this.refreshCache();
  }

  keyDown(e) {
    if (!this.pg) return;
    const mod = e.ctrlKey || e.metaKey;
    const key = e.key;
    let handled = true;
    if (mod && (key === 'z' || key === 'Z')) {
      if (e.shiftKey) this.redo();
      else this.undo();
    } else if (mod && key === 'y') this.redo();
    else if (mod) handled = false;
    else if (key === ' ') (this.playing ? this.pause() : this.play());
    else if (key === 's' || key === 'S') this.stepTime();
    else if (key === 'r' || key === 'R') this.reset();
    else if (key === 'a' || key === 'A') this.addRobot();
    else if (key === 'o' || key === 'O') this.addObstacle();
    else if (key === 'Delete' || key === 'Backspace') this.deleteSelection();
    else if (key === 'f' || key === 'F') this.fit();
    else if (key === '+' || key === '=') this.zoom(ZOOM_STEP, this.canvas.clientWidth / 2, this.canvas.clientHeight / 2);
    else if (key === '-' || key === '_') this.zoom(1 / ZOOM_STEP, this.canvas.clientWidth / 2, this.canvas.clientHeight / 2);
    else if (key === '[' || key === ']') this.cycleSelection(key === ']' ? 1 : -1);
    else if (key === 'g' || key === 'G') this.toggleGoalSelection();
    else if (key === 'Escape') this.selection = null;
    else if (key.startsWith('Arrow') && this.selection) {
      const view = this.view();
      const stepM = (KEY_MOVE_FRACTION * Math.min(view.width, view.height)) / view.scale;
      const dx = key === 'ArrowLeft' ? -stepM : key === 'ArrowRight' ? stepM : 0;
      const dy = key === 'ArrowDown' ? -stepM : key === 'ArrowUp' ? stepM : 0;
      this.nudge(dx, dy, 0);
    } else if ((key === 'q' || key === 'Q' || key === 'e' || key === 'E') && this.selection) {
      this.nudge(0, 0, key.toLowerCase() === 'q' ? KEY_TURN_RAD : -KEY_TURN_RAD);
    } else handled = false;
    if (handled) {
      e.preventDefault();
      this.updateButtons();
      this.requestDraw();
    }
  }

  /** Moves / turns the selection from the keyboard, as one edit. */
  nudge(dx, dy, dTheta) {
    const sel = this.selection;
    const i = sel.index;
    if (sel.kind === 'robot') {
      const p = this.cache.poses;
      const before = this.scenarioText();
      try {
        this.pg.moveRobot(i, p[i * 3] + dx, p[i * 3 + 1] + dy, p[i * 3 + 2] + dTheta);
      } catch (e) {
        this.showMessage(e.message ?? String(e));
        return;
      }
      this.showMessage('');
      this.refreshCache();
      if (this.scenarioText() !== before) this.pushUndo(before);
      this.emitChange('robot');
    } else if (sel.kind === 'goal') {
      this.edit((s) => {
        const g = s.robots[i].goal;
        s.robots[i].goal = [g[0] + dx, g[1] + dy, g[2] + dTheta];
      }, 'goal');
    } else if (sel.kind === 'obstacle') {
      this.edit((s) => {
        const o = s.obstacles[i];
        o.center = [o.center[0] + dx, o.center[1] + dy];
      }, 'obstacle');
    }
  }

  cycleSelection(dir) {
    const n = this.cache.scenario.robots.length;
    const i = this.selection && this.selection.kind !== 'obstacle' ? (this.selection.index + dir + n) % n : 0;
    this.selection = { kind: 'robot', index: i };
    this.focusRobot = i;
  }

  toggleGoalSelection() {
    const sel = this.selection;
    if (!sel || sel.kind === 'obstacle') return;
    this.selection = { kind: sel.kind === 'robot' ? 'goal' : 'robot', index: sel.index };
  }

  addRobot() {
    const view = this.view();
    const span = Math.min(view.width, view.height) / view.scale;
    const x = view.wx(view.width / 2);
    const y = view.wy(view.height / 2);
    const n = this.cache.scenario.robots.length;
    const ok = this.edit((s) => {
      // The first start/goal pair along a widening spiral about the view's centre that keeps
      // clear of every robot and obstacle ring, so that repeated clicks add robots side by
      // side instead of one on top of another (which the core refuses).
      const gap = 3 * (s.params?.safe_radius ?? 1);
      const free = (p, key, ring) => s.robots.every((r) => Math.hypot(r[key][0] - p[0], r[key][1] - p[1]) >= gap)
        && s.obstacles.every((o) => Math.hypot(o.center[0] - p[0], o.center[1] - p[1]) > (ring ? o.influence : o.radius) + gap);
      let start = [x - 0.2 * span, y - 0.1 * span];
      let goal = [x + 0.2 * span, y + 0.1 * span];
      for (let k = 0; k < ADD_ROBOT_TRIES; k++) {
        const a = k * 2.4; // radians: the golden angle spreads the tries evenly
        const r = gap * Math.sqrt(k);
        const s0 = [x - 0.2 * span + r * Math.cos(a), y - 0.1 * span + r * Math.sin(a)];
        const g0 = [x + 0.2 * span + r * Math.cos(a), y + 0.1 * span + r * Math.sin(a)];
        if (free(s0, 'start', false) && free(g0, 'goal', true)) {
          [start, goal] = [s0, g0];
          break;
        }
      }
      s.robots.push({ start: [...start, 0], goal: [...goal, 0] });
    }, 'add-robot');
    if (ok) {
      this.selection = { kind: 'robot', index: n };
      this.focusRobot = n;
    }
  }

  addObstacle() {
    const view = this.view();
    const r = (NEW_OBSTACLE_FRACTION * Math.min(view.width, view.height)) / view.scale;
    const k = this.cache.scenario.obstacles.length;
    const ok = this.edit((s) => {
      s.obstacles.push({ center: [view.wx(view.width / 2), view.wy(view.height / 2)], radius: r, influence: 2 * r });
    }, 'add-obstacle');
    if (ok) this.selection = { kind: 'obstacle', index: k };
  }

  deleteSelection() {
    const sel = this.selection;
    if (!sel) return;
    const ok = this.edit((s) => {
      if (sel.kind === 'obstacle') s.obstacles.splice(sel.index, 1);
      else s.robots.splice(sel.index, 1);
    }, 'delete');
    if (ok) {
      this.selection = null;
      this.focusRobot = 0;
    }
  }
}

/**
 * Typed-array views into wasm memory by name, remade only when the memory grew (its buffer
 * changed), the array moved or its length changed: no allocation in a steady frame.
 */
class WasmViews {
  constructor(memory) {
    this.memory = memory;
    this.byName = new Map();
  }

  f64(name, pointer, length) {
    return this.view(name, Float64Array, pointer, length);
  }

  u32(name, pointer, length) {
    return this.view(name, Uint32Array, pointer, length);
  }

  view(name, Type, pointer, length) {
    const buffer = this.memory.buffer;
    const v = this.byName.get(name);
    if (v && v.buffer === buffer && v.byteOffset === pointer && v.length === length) return v;
    const made = new Type(buffer, pointer, length);
    this.byName.set(name, made);
    return made;
  }
}

function sameScenario(a, b) {
  return JSON.stringify(a) === JSON.stringify(b);
}

if (!customElements.get('dvf-playground')) customElements.define('dvf-playground', DvfPlayground);
