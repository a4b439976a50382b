// The live simulation of one <dvf-playground> and its edits. The controller owns the wasm
// `Playground` (`pg`) and the JS model of its scenario (`model`), and creates the parts that
// work on them: the views into wasm memory, the gestures and their undo, the camera, the
// clock, the frame loop, the painter, the input, the message box, the help and the panels.
// The element creates one and calls it; input and panels change the scenario only through the
// edit methods below.
//
// The scenario: `model` is the core's scenario, read from the core (pg.scenario()) when a
// document is loaded and at the end of each gesture, and between those changed in place by
// the edit methods only, with the values the core took; nothing else writes it. A scene
// imported from the page's own JSON file is the same scene to the bit (the core reads every
// number back exactly).
//
// Edits: one method per edit (moveRobot, moveGoal, moveObstacle, resizeObstacle, setParam,
// addRobot, removeRobot, addObstacle, removeObstacle), each calling the facade's method of the
// same name, which checks only what it touches and serialises nothing; edit(scenario) replaces
// the whole scene (undo, imports, links). An edit the core refuses throws its Error (naming the
// field) and changes nothing; one it takes is made to the model in place too.
//
// Gestures (gestures.js): what a person does is begin(), any number of edits, commit(kind).
// Nothing reads or serialises the whole scenario per pointer move; commit reads the core's
// scenario once, so that the model holds the core's own values again (and the bounds it
// resolves for a scenario that has none).

import { downloadScenarioJson, fetchScenarioText } from '../io.js';
import { buildLegend } from '../panels/legend.js';
import { buildPlotsLegend } from '../panels/plots.js';
import { ParamsPanel } from '../panels/params.js';
import { ResultsPanel } from '../panels/results.js';
import { SelectionPanel } from '../panels/selection.js';
import { Toolbar } from '../panels/toolbar.js';
import { Playground, presetScenario } from '../pkg/dvf.js';
import { Camera } from '../render/camera.js';
import { changeParam } from './actions.js';
import { Clock } from './clock.js';
import { CompareMode } from './compare.js';
import { Pin } from './ghost.js';
import { Gestures } from './gestures.js';
import { Help } from './help.js';
import { Input } from './input.js';
import { FrameLoop } from './loop.js';
import { messageOf } from './message.js';
import { MessageBox } from './message-box.js';
import { Painter } from './paint.js';
import { Recorder } from './record.js';
import { SeekProgress } from './seek-progress.js';
import { DEFAULT_THETA0, validViewState, viewStateOf } from './view-state.js';
import { LiveViews, wasmFailure, wasmReady } from './wasm-views.js';

/** A `viewchange` event waits this long (ms) for the next change (a pan is many). */
const VIEW_EVENT_MS = 400;
/** Each preset's robot count and JSON text, made once per page (Controller.#presetOf). */
let presetTexts = null;

/**
 * @typedef {import('../dvf-playground.js').Scenario} Scenario
 * @typedef {{kind: 'robot' | 'goal' | 'obstacle', index: number}} Selection
 */

export class Controller {
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
    /** θ(0) of the integral curves (rad). */
    this.theta0 = DEFAULT_THETA0;
    this.showSensing = false;
    /** Drags and keys may edit the scene (the element's `controls`/`editable`, not `readonly`). */
    this.editable = true;
    /** Keys and the pointer do nothing but the toolbar's play, pause and reset (`readonly`). */
    this.readonly = false;
    /** Starts over at the end of the run (`loop`). */
    this.looping = false;
    /** @type {ReturnType<typeof setTimeout> | null} the pending `viewchange` event */
    this.viewTimer = null;
    /** Bumped by every edit, load, reset and API step: the trail layer redraws from scratch. */
    this.generation = 0;
    this.connected = false;
    this.gestures = new Gestures({
      hasScene: () => this.pg !== null,
      text: () => this.text(),
      reread: () => {
        this.model = this.pg.scenario();
        this.#fixSelection();
      },
      apply: (scenario) => this.edit(scenario),
      showMessage: (text) => this.showMessage(text),
      filled: () => this.params.fill(this.root.activeElement),
      shown: () => this.toolbar.update(),
      emit: (kind) => this.#emit(kind),
    });
    /** The undo stack (history.js), which the gestures keep. */
    this.history = this.gestures.history;
    this.camera = new Camera();
    this.messages = new MessageBox({
      box: this.$('message'),
      text: this.$('message-text'),
      actions: this.$('message-actions'),
      close: this.$('message-close'),
    });
    this.help = new Help(this.$('help-panel'), this.$('help-close'), this.canvas);
    this.loop = new FrameLoop({
      sim: () => this.pg,
      connected: () => this.connected,
      applyInput: () => this.input.applyPending(),
      draw: () => this.painter.draw(),
      clock: () => this.clock,
      looping: () => this.looping,
      time: () => this.views.time,
      settled: () => {
        this.toolbar.update();
        this.viewChanged();
      },
      seekProgress: (progress) => this.seekProgress.show(progress),
      canvases: () => [this.canvas, this.$('plots')],
    });
    this.seekProgress = new SeekProgress(this.$('seek'), () => this.clock.cancelSeek());
    this.clock = new Clock({
      sim: () => this.pg,
      scenario: () => this.model,
      time: () => this.views.time,
      poses: () => this.views.poses,
      loop: this.loop,
      changed: () => this.#changed(),
      refresh: () => this.views.refresh(),
      shown: () => this.toolbar.update(),
      viewChanged: () => this.viewChanged(),
      requestDraw: () => this.requestDraw(),
      emit: (type, detail) => host.dispatchEvent(new CustomEvent(type, { detail })),
    });
    /** @type {Painter} */
    this.painter = new Painter(this);
    this.recorder = new Recorder({
      canvas: this.canvas,
      name: () => this.model.name,
      messages: this.messages,
      shown: () => this.toolbar.update(),
      requestDraw: () => this.requestDraw(),
    });
    this.pin = new Pin({
      scenario: () => this.scenario(),
      showMessage: (text) => this.showMessage(text),
      changed: () => {
        this.results.showGhost();
        this.requestDraw();
      },
    });
    /** The planner menu and the compare mode (compare.js). */
    this.compare = new CompareMode(this);
    /** @type {Toolbar} */
    this.toolbar = new Toolbar(this);
    /** @type {ParamsPanel} */
    this.params = new ParamsPanel(
      this.$('params'),
      (key, value) => changeParam(this, key, value),
      () => this.model,
    );
    this.results = new ResultsPanel({
      $: this.$,
      active: () => host.hasAttribute('controls'),
      scenario: () => this.model,
      pin: this.pin,
      showMessage: (text, options) => this.showMessage(text, options),
      goTo: (mark) => {
        this.inspect(mark.robots[0]);
        this.clock.seekTo(mark.time);
      },
      requestDraw: () => this.requestDraw(),
    });
    this.selectionPanel = new SelectionPanel({
      form: this.$('selection'),
      title: this.$('selection-title'),
      selection: () => this.selection,
      scenario: () => this.model,
      pose: (i) => this.views.pose(i),
      time: () => this.views.time,
      focused: () => root.activeElement,
      change: (kind, edits) => this.gestures.change(kind, edits),
      edits: this,
      message: () => this.$('message-text').textContent,
      showMessage: (text) => this.showMessage(text),
    });
    buildLegend(this.$('legend'));
    buildPlotsLegend(this.$('plots-legend'));
    // The colours are known once the stylesheet has loaded, and change with the system's theme.
    root.querySelector('link[rel="stylesheet"]')?.addEventListener('load', () => this.readTheme());
    matchMedia('(prefers-color-scheme: dark)').addEventListener('change', () => this.readTheme());
    /** @type {Input} */
    this.input = new Input(this);
  }

  /** Waits for the wasm module; false (and the message shown) when it cannot be loaded. */
  async ready() {
    try {
      const { memory, limits, presets, defaultPreset, parameters, planners } = await wasmReady();
      this.params.build(parameters);
      this.compare.fillMenus(planners);
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
    this.#replace(new Playground(scenario), null);
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

  /** Loads an imported scenario text as a new document that Undo takes back; throws as load. */
  importScenario(text) {
    const before = this.pg ? this.text() : null;
    this.#replace(new Playground(text), null);
    this.history.clear();
    if (before) this.history.push(before);
    this.toolbar.update();
    this.showMessage('');
    this.#emit('import');
  }

  /** Shows `pg` in place of the scene, with the scenario the core read as the model. */
  #replace(pg, presetName) {
    const old = this.pg;
    this.pg = pg;
    old?.free();
    this.model = pg.scenario();
    this.views.attach(pg);
    this.loop.newScene();
    this.selection = null;
    this.focusRobot = 0;
    this.painter.newScene();
    this.camera.fit();
    this.generation += 1;
    this.preset = presetName ?? this.#presetOf(this.model);
    this.toolbar.showPreset(this.preset);
    this.params.fill(this.root.activeElement);
    this.toolbar.update();
    this.results.stale();
    this.compare.stale();
    this.requestDraw();
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

  /** The current scenario as a plain object (a copy), or null before the first scene. */
  scenario() {
    return this.pg ? structuredClone(this.model) : null;
  }

  /** Offers the scenario as a JSON file (io.js); a message says why when it cannot be written. */
  async exportJson() {
    if (!this.pg) return;
    try {
      await downloadScenarioJson(this.model);
    } catch (e) {
      this.showMessage(`Scenario JSON: ${messageOf(e)}`);
    }
  }

  /** The scenario's JSON text: what undo keeps. */
  text() {
    return JSON.stringify(this.model);
  }

  /** The preset shown, or null once the scene has been edited or imported. */
  presetName() {
    return this.pg ? this.preset : null;
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
    this.compare.stale();
    this.requestDraw();
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

  /** Selects robot, goal or obstacle `sel` (what the panel edits and the keys move), or none. */
  select(sel) {
    this.selection = sel;
  }

  /** Inspects robot `i`: its field is drawn, the plots and the panel show it. */
  inspect(i) {
    this.focusRobot = i;
  }

  /**
   * What input may do and how the run ends (the element's `readonly`, `controls`/`editable`
   * and `loop`).
   */
  setModes({ readonly, editable, looping }) {
    this.readonly = readonly;
    this.editable = editable;
    this.looping = looping;
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

  /** The field overlay, θ(0) of the curves (rad) and the sensing circles. */
  setDisplay({ field, theta0, sensing }) {
    this.fieldMode = field;
    this.theta0 = theta0;
    this.showSensing = sensing;
    this.toolbar.showDisplay(this);
    this.viewChanged();
    this.requestDraw();
  }

  /** Shows `text` over the canvas, or hides it for an empty one (MessageBox.show). */
  showMessage(text, options) {
    this.messages.show(text, options);
  }

  /** What the view shows, for a link (view-state.js). */
  viewState() {
    const display = { field: this.fieldMode, theta0: this.theta0, sensing: this.showSensing };
    return viewStateOf(this.view(), display, this.focusRobot, this.views.time, this.camera.user, this.compare.planner);
  }

  /** Shows what of view `state` is valid for this scene (view-state.js); a time as a seek. */
  setViewState(state) {
    if (!this.pg || !state) return;
    const shown = { field: this.fieldMode, theta0: this.theta0, sensing: this.showSensing };
    const { display, inspect, camera, seek, compare } = validViewState(state, shown, {
      robots: this.model.robots.length,
      duration: this.pg.duration,
      width: this.canvas.clientWidth,
      height: this.canvas.clientHeight,
    });
    this.setDisplay(display);
    if (inspect !== null) this.focusRobot = inspect;
    if (camera) {
      this.camera.state = camera;
      this.camera.user = true;
    }
    if (seek !== null) this.clock.seekTo(seek);
    if (compare !== undefined) this.compare.set(compare);
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

  /** Reads the theme's colours again (the stylesheet, the `theme` attribute, the system's). */
  readTheme() {
    const theme = this.host.getAttribute('theme');
    const dark = theme === 'dark' || (theme !== 'light' && matchMedia('(prefers-color-scheme: dark)').matches);
    this.painter.readTheme(this.root.querySelector('.pg'), dark);
    this.generation += 1;
    buildLegend(this.$('legend'));
    this.requestDraw();
  }

  requestDraw() {
    this.loop.requestDraw();
  }
}
