// The planner menu and the compare mode of a playground. The planner menu sets the scenario's
// `planner` (one undoable edit; the live run re-predicts with it). The compare menu names a
// second planner: the scene as it is now then runs to its end twice in the results worker,
// once with the scenario's planner and once with the second one (the same scene, robots,
// limits and barrier: only `planner` differs). The canvas draws the second run overlaid, its
// paths faded and its robots at the clock's time as outlined discs in COMPARE_COLOUR; a legend over the canvas says
// which is which; the results panel shows both runs' figures in one table
// (panels/compare-table.js), which the worker computes with the module's `compare()`: the
// numbers of `dvf compare --json` for the same scene, the compute per step measured in this
// browser. Every edit (a drag included) runs both again: one run at a time,
// the newest scene next. Scenes above GHOST_MAX_ROBOTS robots are not compared (their paths
// would hide the scene).

import { compareTable } from '../panels/compare-table.js';
import { el } from '../panels/dom.js';
import { GHOST_MAX_ROBOTS } from './ghost.js';
import { messageOf } from './message.js';
import { compare } from '../pkg/dvf.js';
import { runWorker } from './wasm-views.js';

/** The compared run's colour on the canvas, in the legend and in the table's head. */
export const COMPARE_COLOUR = '#ea580c';
/** Values per trajectory sample of a `Run`: t, x, y, θ, v, ω (src/wasm/run.rs). */
const SAMPLE = 6;

/**
 * The name of a scenario's `planner` (a name, an object with its name and gains, or absent
 * for DVF).
 * @param {any} planner
 */
export function plannerName(planner) {
  if (typeof planner === 'string') return planner;
  return planner?.name ?? 'dvf';
}

/**
 * The compared planner's run as the canvas draws it: its trajectories (the table's figures
 * come from the module's `compare()`, not from these samples).
 */
export class ComparedRun {
  /**
   * @param {string} planner
   * @param {Float64Array} trajectories `[robots · samples · 6]` (src/wasm/run.rs)
   * @param {number} samples per robot
   */
  constructor(planner, trajectories, samples) {
    this.planner = planner;
    this.trajectories = trajectories;
    this.samples = samples;
    this.robots = samples > 0 ? trajectories.length / (samples * SAMPLE) : 0;
  }

  /** The sample at or before time `t` (s): samples are evenly spaced from t = 0. */
  sampleAt(t) {
    const n = this.samples;
    const end = this.trajectories[(n - 1) * SAMPLE];
    if (!(end > 0)) return 0;
    return Math.max(0, Math.min(n - 1, Math.floor((t / end) * (n - 1) + 1e-9)));
  }
}

/**
 * What the compare mode uses of the controller: its parts by `data-id`, the scenario, its
 * gestures and edits, the clock's time, the message and redraws.
 * @typedef {Pick<import('./controller.js').Controller, '$' | 'edit' | 'gestures' | 'model'
 *   | 'pg' | 'requestDraw' | 'scenario' | 'showMessage' | 'viewChanged' | 'views'>} CompareHost
 */

export class CompareMode {
  /** @param {CompareHost} c */
  constructor(c) {
    this.c = c;
    /** @type {import('./wasm-views.js').PlannerInfo[]} */
    this.list = [];
    /** @type {string | null} the second planner, or null: no comparison */
    this.planner = null;
    /**
     * The comparison shown: the module's `compare()` of the scene with both planners (the JSON
     * of `dvf compare --json`) and the second planner's run to draw; null while none is.
     * @type {{ comparison: any, ghost: ComparedRun } | null}
     */
    this.runs = null;
    /** @type {Worker | null} */
    this.worker = null;
    /** The newest request; a reply to an older one is dropped. */
    this.id = 0;
    /** A run is in the worker; `dirty`: the scene changed since it began. */
    this.busy = false;
    this.dirty = false;
    /** @type {string | null} why the scene is not compared (too many robots, an error) */
    this.note = null;
    /** The scenario and second planner of the runs shown or under way, as text: a step, a seek or a reset runs nothing. */
    this.key = '';
    c.$('planner').addEventListener('change', (e) => this.setPlanner(e.target.value));
    c.$('compare').addEventListener('change', (e) => this.set(e.target.value || null));
  }

  /** Fills both menus with `list` (the wasm module's `planners()`). */
  fillMenus(list) {
    this.list = list;
    const option = (p) => {
      const o = el('option', p.name);
      o.value = p.name;
      o.title = `${p.title}; avoids ${p.avoids}. ${p.source}`;
      return o;
    };
    const none = el('option', 'off');
    none.value = '';
    this.c.$('planner').replaceChildren(...list.map(option));
    this.c.$('compare').replaceChildren(none, ...list.map(option));
  }

  /** Whether `name` is a planner of the menu. */
  known(name) {
    return this.list.some((p) => p.name === name);
  }

  /**
   * Sets the scenario's planner to `name` (its default gains), one undoable edit; an unknown
   * name throws the core's Error naming `planner`, and the scene is kept.
   */
  setPlanner(name) {
    const c = this.c;
    if (!c.pg || plannerName(c.model.planner) === name) return true;
    return c.gestures.change('planner', () => c.edit({ ...c.model, planner: name }));
  }

  /**
   * Compares the scene with planner `name` (null or empty: no comparison). An unknown name
   * shows the core's message, naming `compare`, keeps the mode as it is and returns false.
   */
  set(name) {
    const planner = name || null;
    if (planner && !this.known(planner)) {
      this.c.showMessage(this.#unknown(planner));
      return false;
    }
    if (planner === this.planner) return true;
    this.planner = planner;
    this.runs = null;
    this.key = '';
    this.stale();
    this.c.viewChanged();
    return true;
  }

  /**
   * The core's message for a planner name it does not know: the module's `compare()` refuses
   * the name before it runs anything, naming it `planners[0]`, which here is `compare`.
   */
  #unknown(name) {
    try {
      compare(this.c.scenario(), [name]);
    } catch (e) {
      return messageOf(e).replace(/^planners\[0\]/, 'compare');
    }
    return `compare: unknown planner "${name}"`;
  }

  /** The scene changed (or the second planner): the menus show it, and both runs are made anew. */
  stale() {
    const c = this.c;
    if (!c.pg) return;
    c.$('planner').value = plannerName(c.model.planner);
    c.$('compare').value = this.planner ?? '';
    if (!this.planner) {
      this.worker?.terminate();
      this.worker = null;
      this.busy = false;
      this.runs = null;
      this.show();
      return;
    }
    const robots = c.model.robots.length;
    if (robots > GHOST_MAX_ROBOTS) {
      this.runs = null;
      this.note = `Compare runs scenes of up to ${GHOST_MAX_ROBOTS} robots; this one has ${robots.toLocaleString('en')}.`;
      this.show();
      return;
    }
    const key = `${this.planner} ${JSON.stringify(c.model)}`;
    if (key === this.key) return;
    if (this.busy) {
      this.dirty = true;
      return;
    }
    this.key = key;
    this.#start();
  }

  /**
   * Runs the scene in the worker twice: the comparison of both planners (the table), and the
   * second planner's run with its trajectories (the canvas); then shows them (and again if the
   * scene changed meanwhile).
   */
  #start() {
    const c = this.c;
    const s = c.scenario();
    // The scenario's own planner keeps its gains; the second runs with its defaults.
    const own = s.planner ?? 'dvf';
    const second = /** @type {string} */ (this.planner);
    const id = ++this.id;
    this.busy = true;
    this.dirty = false;
    this.note = null;
    this.worker ??= runWorker();
    /** @type {any} */
    let comparison = null;
    /** @type {ComparedRun | null} */
    let ghost = null;
    this.worker.onmessage = (e) => {
      if (e.data.id !== id || id !== this.id || !this.busy) return;
      if (e.data.error) {
        this.#done(id, null, `Could not compare ${plannerName(own)} with ${second}: ${messageOf(e.data)}`);
        return;
      }
      if (e.data.comparison) comparison = e.data.comparison;
      else ghost = new ComparedRun(second, e.data.trajectories, e.data.samples);
      if (comparison && ghost) this.#done(id, { comparison, ghost }, null);
    };
    this.worker.postMessage({ id, scenario: s, compare: [own, second] });
    this.worker.postMessage({ id, scenario: { ...s, planner: second }, trajectories: true });
    if (!this.runs) this.show();
  }

  #done(id, runs, note) {
    this.busy = false;
    if (id !== this.id) return;
    this.runs = runs;
    this.note = note;
    this.show();
    this.c.requestDraw();
    if (this.dirty) this.stale();
  }

  /** The legend over the canvas and the table in the results panel. */
  show() {
    const c = this.c;
    const legend = c.$('compare-legend');
    const box = c.$('compare-results');
    legend.hidden = box.hidden = !this.planner;
    delete box.dataset.ready;
    if (!this.planner) return;
    const own = plannerName(c.model.planner);
    const compared = el('span', `${this.planner}: orange`, 'compare-key');
    compared.style.setProperty('--key', COMPARE_COLOUR);
    legend.replaceChildren(el('span', `${own}: live, the robots' colours`, 'compare-key live'), compared);
    if (this.note) box.replaceChildren(el('p', this.note, 'muted'));
    else if (!this.runs) box.replaceChildren(el('p', `Running the scene with ${own} and ${this.planner}…`, 'muted'));
    else {
      box.replaceChildren(...compareTable(this.runs.comparison, COMPARE_COLOUR));
      box.dataset.ready = '';
    }
  }

  /** Draws the second planner's run on `ctx` through `view`: its paths, and its robots at time `t`. */
  draw(ctx, view, t) {
    const run = this.runs?.ghost;
    if (!this.planner || !run || run.planner !== this.planner) return;
    const tr = run.trajectories;
    const n = run.samples;
    const radius = Math.max(this.c.model.params.safe_radius * view.scale, 4);
    ctx.save();
    ctx.strokeStyle = COMPARE_COLOUR;
    ctx.lineJoin = 'round';
    ctx.lineWidth = 2;
    ctx.globalAlpha = 0.55;
    ctx.beginPath();
    for (let i = 0; i < run.robots; i++) {
      const o = i * n * SAMPLE;
      ctx.moveTo(view.sx(tr[o + 1]), view.sy(tr[o + 2]));
      for (let k = 1; k < n; k++) ctx.lineTo(view.sx(tr[o + k * SAMPLE + 1]), view.sy(tr[o + k * SAMPLE + 2]));
    }
    ctx.stroke();
    ctx.globalAlpha = 1;
    const k = run.sampleAt(t);
    for (let i = 0; i < run.robots; i++) {
      const o = (i * n + k) * SAMPLE;
      const x = view.sx(tr[o + 1]);
      const y = view.sy(tr[o + 2]);
      const th = tr[o + 3];
      ctx.beginPath();
      ctx.arc(x, y, radius, 0, 2 * Math.PI);
      ctx.stroke();
      ctx.beginPath();
      ctx.moveTo(x, y);
      ctx.lineTo(x + 1.6 * radius * Math.cos(th), y - 1.6 * radius * Math.sin(th));
      ctx.stroke();
    }
    ctx.restore();
  }
}
