// <dvf-playground>: the DVF playground as a custom element. One script tag includes it:
//
//   <script type="module" src="dvf-playground.js"></script>
//   <dvf-playground preset="example3-circle-swap" controls autoplay></dvf-playground>
//
// Every instance runs its own live simulation; the wasm module is loaded once per page and
// shared. This file is the element only: its attributes, its lifecycle and its public API. The
// simulation and its edits are a controller (playground/controller.js) that the element
// creates when first connected; the modules it imports are found relative to this file. The
// types of everything below are in dvf-playground.d.ts; README.md, "Embedding", shows it in
// use.
//
// Attributes (read at start; a change applies at once):
//   preset    a preset name (default: the crate's default preset); `crowd-N` included
//   src       URL of a scenario JSON file; takes precedence over `preset`. A bad file (missing,
//             an HTML page, an invalid scenario) shows the preset instead, with a message that
//             says why and stays until the user acts (so does an unknown preset's)
//   controls  present: the full toolbar and side panels; absent: play, step, reset and the
//             field menu only, and the wheel zooms only once the canvas is focused (or with Ctrl)
//   autoplay  present: start playing once loaded (read once)
//   field     `arrows` (default), `curves` or `none`
//   theta0    θ(0) of the integral curves, in degrees (default 90)
//   sensing   present: draw the sensing circles R_s
//   theme     `light` or `dark` forces a theme; absent: the system's (prefers-color-scheme).
//             The colours are custom properties `--dvf-…` (playground.css lists them)
//
// Methods:
//   load(scenario)        a scenario object or JSON text as a new document (t = 0, view fitted,
//                         undo cleared); throws an Error naming the offending field, the scene
//                         is kept then
//   loadPreset(name)      a preset by name (`crowd-N` included); on a bad name shows the
//                         message, keeps the scene and returns false; true when loaded
//   scenario()            the current scenario (edits included) as a plain object (a copy), in
//                         the scenario format; null before the first scene
//   presetName()          the preset shown, or null once the scene has been edited or imported
//   play(), pause()       the clock (play after the end starts again from t = 0)
//   reset()               back to t = 0 at the scenario's starts, trails cleared
//   step(n = 1)           advances n steps of dt and pauses; returns the steps taken; throws
//                         for an n that is not a whole number from 0 to 10⁶
//   worldToScreen(x, y)   page coordinates {x, y} (CSS px, like pageX/pageY) of world point
//                         (x, y) in metres, for overlays
//   showMessage(text, options)
//                         shows text (as text, never HTML) over the canvas until the user acts
//                         (an edit, a load, its × button); an empty text hides it. Options:
//                         `info` (a notice, not an error), `actions` (buttons, [label, run]
//                         pairs). www/main.js reports bad links and links too long with it
//
//   viewState()           what the view shows: {field, theta0 (degrees), sensing, robot (the
//                         inspected, from 0), time (s), box ([xmin, ymin, xmax, ymax] in view
//                         once panned or zoomed, else null)}; null before the first scene
//   setViewState(state)   shows such a view (any of its fields; invalid ones are left as they
//                         are; a time is gone to as a seek). www/main.js keeps it in the link
//
// Keys: handled anywhere inside the element (not while typing in a field); a key the element
// handles stops there (stopPropagation and preventDefault): it never reaches the page.
//
// Properties:
//   loaded                a promise that resolves once the first scene is shown
//
// Events:
//   change                after each edit: a drag, a handle, a key, a parameter, a preset, an
//                         import, an undo or a redo. `event.detail.kind` says which: `robot`,
//                         `robot-heading`, `goal`, `goal-heading`, `obstacle`, `obstacle-radius`,
//                         `obstacle-influence`, `add-robot`, `add-obstacle`, `delete`,
//                         `params`, `preset`, `import`, `undo` or `redo`
//   viewchange            after the view changed (field overlay, θ(0), sensing circles,
//                         inspected robot, pan or zoom, the clock paused, a seek or a step)
//
// Diagnostics, for the end-to-end tests and benchmarks (not a stable API; null before the
// first scene):
//   pg                    the wasm `Playground` (read only: its counters and arrays)
//   cache                 what a frame reads: time, duration, trail and prediction counters,
//                         and the arrays (poses, status, trails, predicted, …) as views into
//                         wasm memory (playground/wasm-views.js, `LiveViews`)
//   trailsView()          the trail rings, `cache.trails`: a view, valid until the next call
//                         into wasm
//   view()                the world↔screen maps of the canvas now (render/camera.js)
//   camera                the camera {cx, cy, scale} (m, m, CSS px per m)
//   stats                 frames drawn, the first frame's time, each frame's work (ms), the
//                         last edit's time; `stats.rasterInWork` makes a frame's work include
//                         its rasterisation (playground/loop.js)
//   stepMs                the mean wall time of one step (ms), for the step budget
//   fieldMode             the field overlay shown: `arrows`, `curves` or `none`
//   focusRobot            the inspected robot (its field, plots and line); settable
//   plotGeometry          the two plots as last drawn: time axis ends, "now" line, ticks
//   shadowRoot            open: the parts of the template (playground/template.js) are found by
//                         their `data-id` (`canvas`, `message`, `clock`, `title`, `preset`,
//                         `crowd-n`, `undo`, `export-json`, `import-file`, …), the parameters by
//                         `input[name="k_v"]`

import { Controller, DEFAULT_THETA0_DEG, FIELD_MODES } from './playground/controller.js';
import { TEMPLATE } from './playground/template.js';

/** @typedef {import('./dvf-playground.js').DvfPlayground} Declared the element's declaration */

/**
 * The live playground element; tsc checks it against its declaration.
 * @implements {Declared}
 */
export class DvfPlayground extends HTMLElement {
  static get observedAttributes() {
    return ['preset', 'src', 'field', 'theta0', 'sensing', 'theme'];
  }

  /** @type {Controller | null} created when the element is first connected */
  #controller = null;
  /** @type {(value?: unknown) => void} */
  #resolveLoaded = () => {};
  /** @type {ResizeObserver | null} */
  #resizeObserver = null;
  #onWindowResize = () => this.#controller?.requestDraw();

  constructor() {
    super();
    this.attachShadow({ mode: 'open' }).innerHTML = TEMPLATE;
    /** Resolves once the first scene is shown. */
    this.loaded = new Promise((resolve) => {
      this.#resolveLoaded = resolve;
    });
  }

  connectedCallback() {
    // Moved elsewhere in the document, the element keeps its controller and simulation.
    const first = !this.#controller;
    this.#controller ??= new Controller(this, this.shadowRoot);
    const c = this.#controller;
    c.connect();
    // The drawing follows the canvases' CSS boxes and the screen's density (which changes
    // come with a window resize).
    this.#resizeObserver = new ResizeObserver(() => c.requestDraw());
    this.#resizeObserver.observe(c.canvas);
    this.#resizeObserver.observe(c.$('plots'));
    window.addEventListener('resize', this.#onWindowResize);
    if (first) this.#start();
  }

  disconnectedCallback() {
    this.#controller?.disconnect();
    this.#resizeObserver?.disconnect();
    window.removeEventListener('resize', this.#onWindowResize);
  }

  attributeChangedCallback(name, oldValue, value) {
    const c = this.#controller;
    if (!c?.pg || oldValue === value) return;
    if (name === 'theme') c.readTheme();
    else if (name === 'preset' && value) c.loadPreset(value);
    else if (name === 'src' && value) c.loadUrl(value);
    else this.#readDisplayAttributes();
    c.requestDraw();
  }

  /** Loads the scene the attributes ask for, then resolves `loaded`. */
  async #start() {
    const c = this.#controller;
    if (!(await c.ready())) return;
    this.#readDisplayAttributes();
    const src = this.getAttribute('src');
    const preset = this.getAttribute('preset') || c.defaultPreset;
    let ok = src ? await c.loadUrl(src) : c.loadPreset(preset);
    if (!ok) {
      // The message stays, saying what is shown instead, until the user acts.
      const why = c.$('message-text').textContent;
      const fallback = src && c.loadPreset(preset, { quiet: true }) ? preset : c.defaultPreset;
      if (fallback === c.defaultPreset) c.loadPreset(fallback, { quiet: true });
      c.showMessage(`${why}\nShowing the preset ${fallback} instead.`);
      ok = true;
    }
    if (this.hasAttribute('autoplay')) c.play();
    this.#resolveLoaded();
  }

  #readDisplayAttributes() {
    const field = FIELD_MODES.find((mode) => mode === this.getAttribute('field'));
    const theta0 = Number(this.getAttribute('theta0') ?? DEFAULT_THETA0_DEG);
    this.#controller.setDisplay({
      field: field ?? 'arrows',
      theta0Deg: Number.isFinite(theta0) ? theta0 : DEFAULT_THETA0_DEG,
      sensing: this.hasAttribute('sensing'),
    });
  }

  /** The controller, for a method that needs one. */
  #connected() {
    if (!this.#controller) throw new Error('dvf-playground: the element is not in a document yet');
    return this.#controller;
  }

  // ---- methods ------------------------------------------------------------------------------

  load(scenario) {
    this.#connected().load(scenario);
  }

  loadPreset(name) {
    return this.#connected().loadPreset(name);
  }

  scenario() {
    return this.#controller?.scenario() ?? null;
  }

  presetName() {
    return this.#controller?.presetName() ?? null;
  }

  play() {
    this.#controller?.play();
  }

  pause() {
    this.#controller?.pause();
  }

  reset() {
    this.#controller?.reset();
  }

  step(n = 1) {
    return this.#controller?.step(n) ?? 0;
  }

  worldToScreen(x, y) {
    return this.#connected().worldToScreen(x, y);
  }

  showMessage(text, options) {
    this.#controller?.showMessage(text, options);
  }

  viewState() {
    return this.#controller?.pg ? this.#controller.viewState() : null;
  }

  setViewState(state) {
    this.#controller?.setViewState(state);
  }

  // ---- diagnostics --------------------------------------------------------------------------

  get pg() {
    return this.#controller?.pg ?? null;
  }

  get cache() {
    return this.#controller?.pg ? this.#controller.views : null;
  }

  trailsView() {
    return this.cache?.trails ?? null;
  }

  view() {
    return this.#connected().view();
  }

  get camera() {
    return this.#controller?.camera.state ?? null;
  }

  get stats() {
    return this.#controller?.loop.stats ?? null;
  }

  get stepMs() {
    return this.#controller?.loop.stepMs ?? null;
  }

  get fieldMode() {
    return this.#controller?.fieldMode ?? null;
  }

  get focusRobot() {
    return this.#controller?.focusRobot ?? null;
  }

  get plotGeometry() {
    return this.#controller?.pg ? this.#controller.painter.plots.geometry : null;
  }

  set focusRobot(i) {
    const c = this.#connected();
    c.focusRobot = i;
    c.requestDraw();
  }
}

if (!customElements.get('dvf-playground')) customElements.define('dvf-playground', DvfPlayground);
