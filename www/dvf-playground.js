// <dvf-playground>: the DVF playground as a custom element. One script tag includes it:
//
//   <script type="module" src="dvf-playground.js"></script>
//   <dvf-playground preset="example3-circle-swap" controls autoplay></dvf-playground>
//
// Every instance runs its own live simulation; the wasm module is loaded once per page and
// shared. This file is the element only: its attributes, its lifecycle and its public API. The
// simulation and its edits are a controller (playground/controller.js) that the element
// creates when first connected; the modules it imports are found relative to this file. The
// types of everything below are in dvf-playground.d.ts; docs/book/src/embedding.md shows it in
// use.
//
// Importing the module defines <dvf-playground> once (a second import, or a second copy,
// does nothing) and loads nothing: the wasm module is fetched when the first element connects.
// Where there is no DOM (a server rendering the page) importing does nothing at all. Until the
// module runs, the browser shows what the tag holds (fallback content: say there that the
// figure needs JavaScript and a page served over HTTP); once it runs, the element's own box
// replaces it. A module that cannot be loaded, a bad `src` or a bad `preset` shows its message
// in the element's box, and it stays.
//
// Its attributes, methods, properties and events are declared once, with their meaning, in
// dvf-playground.d.ts; docs/book/src/embedding.md tabulates them (tests/e2e/book.mjs holds the
// table to the declarations). An attribute's change applies at once. Keys are handled anywhere
// inside the element (not while typing in a field); a key the element handles stops there: a
// figure that is not an editor (no `controls` or `editable`) handles the clock's, the view's and
// the help's keys only, a `readonly` one none. The members under "Diagnostics" in the
// declarations serve the end-to-end tests and benchmarks and are not a stable API.

import { Controller } from './playground/controller.js';
import { TEMPLATE } from './playground/template.js';
import { DEFAULT_THETA0, FIELD_MODES } from './playground/view-state.js';
import { setWasmSource } from './playground/wasm-views.js';

/** @typedef {import('./dvf-playground.js').DvfPlayground} Declared the element's declaration */

/** `loading="lazy"`: the scene loads once the element is this close (CSS px) to the viewport. */
const LAZY_MARGIN = '200px';

/**
 * The base class: HTMLElement in a browser; where there is none (a server rendering the page
 * imports this module), a stand-in, so that importing defines nothing and throws nothing.
 */
const Base = /** @type {typeof HTMLElement} */ (globalThis.HTMLElement ?? class {});

/**
 * The live playground element; tsc checks it against its declaration.
 * @implements {Declared}
 */
export class DvfPlayground extends Base {
  static get observedAttributes() {
    return [
      'preset',
      'src',
      'planner',
      'compare',
      'field',
      'theta0',
      'sensing',
      'theme',
      'time',
      'controls',
      'editable',
      'readonly',
      'loop',
      'autoplay',
    ];
  }

  /**
   * Where every element of the page loads the wasm module from (a URL, or the module's bytes):
   * set it before the first element connects (the `wasm` attribute does the same). Undefined:
   * `pkg/dvf_bg.wasm` beside this module.
   * @param {string | URL | BufferSource | undefined} source
   */
  static set wasmUrl(source) {
    DvfPlayground.#wasm = source;
    setWasmSource(source);
  }

  static get wasmUrl() {
    return DvfPlayground.#wasm;
  }

  /** @type {string | URL | BufferSource | undefined} */
  static #wasm;

  /** @type {Controller | null} created when the element is first connected */
  #controller = null;
  /** The scene the attributes ask for has been tried (loaded, or its message shown). */
  #started = false;
  /** @type {(value?: unknown) => void} */
  #resolveLoaded = () => {};
  /** @type {ResizeObserver | null} */
  #resizeObserver = null;
  /** The scene the attributes ask for is being loaded (or has been). */
  #startAsked = false;
  /** @type {IntersectionObserver | null} `loading="lazy"`: starts the scene once near the viewport */
  #nearObserver = null;
  /** @type {IntersectionObserver | null} `autoplay="visible"`: plays while on screen */
  #screenObserver = null;
  /** The element is on screen; true unless `autoplay="visible"`'s observer says otherwise. */
  #onScreen = true;
  #onWindowResize = () => this.#controller?.requestDraw();

  constructor() {
    super();
    this.attachShadow({ mode: 'open' }).innerHTML = TEMPLATE;
    /** Resolves once the first scene is shown, or its failure message. */
    this.loaded = new Promise((resolve) => {
      this.#resolveLoaded = resolve;
    });
  }

  connectedCallback() {
    // Moved elsewhere in the document, the element keeps its controller and simulation.
    const first = !this.#controller;
    if (first && this.hasAttribute('wasm')) setWasmSource(new URL(this.getAttribute('wasm'), document.baseURI));
    this.#controller ??= new Controller(this, this.shadowRoot);
    const c = this.#controller;
    this.#readModes();
    c.connect();
    // The drawing follows the canvases' CSS boxes and the screen's density (which changes
    // come with a window resize).
    this.#resizeObserver = new ResizeObserver(() => c.requestDraw());
    this.#resizeObserver.observe(c.canvas);
    this.#resizeObserver.observe(c.$('plots'));
    window.addEventListener('resize', this.#onWindowResize);
    this.#observeScreen();
    if (this.#startAsked) return;
    if (this.getAttribute('loading') === 'lazy' && typeof IntersectionObserver !== 'undefined') this.#startWhenNear();
    else this.#start();
  }

  disconnectedCallback() {
    this.#controller?.disconnect();
    this.#resizeObserver?.disconnect();
    this.#nearObserver?.disconnect();
    this.#nearObserver = null;
    this.#screenObserver?.disconnect();
    this.#screenObserver = null;
    window.removeEventListener('resize', this.#onWindowResize);
  }

  attributeChangedCallback(name, oldValue, value) {
    const c = this.#controller;
    if (oldValue === value) return;
    // The theme applies at once, scene or not (a connected element has read it already).
    if (name === 'theme') {
      if (c?.connected) c.readTheme();
      return;
    }
    if (!this.#started || !c?.views) return;
    if (name === 'preset' && value) this.#loadPreset(value) && this.#applyPlanner();
    else if (name === 'src' && value) c.loadUrl(value).then((ok) => ok && this.#applyPlanner());
    else if (name === 'planner' && value) c.compare.setPlanner(value);
    else if (name === 'compare') c.compare.set(value);
    else if (name === 'time') this.#seekAttribute();
    else if (name === 'autoplay') this.#observeScreen();
    else this.#readDisplayAttributes();
    this.#readModes();
    c.requestDraw();
  }

  /** `loading="lazy"`: loads the scene once the element comes within LAZY_MARGIN of the viewport. */
  #startWhenNear() {
    this.#nearObserver = new IntersectionObserver(
      (entries) => {
        if (!entries.some((e) => e.isIntersecting)) return;
        this.#nearObserver?.disconnect();
        this.#nearObserver = null;
        this.#start();
      },
      { rootMargin: LAZY_MARGIN },
    );
    this.#nearObserver.observe(this);
  }

  /** `autoplay="visible"`: watches whether the element is on screen, to play and pause it. */
  #observeScreen() {
    if (this.getAttribute('autoplay') !== 'visible' || this.#screenObserver) return;
    if (typeof IntersectionObserver === 'undefined') return;
    this.#onScreen = false;
    this.#screenObserver = new IntersectionObserver((entries) => {
      const onScreen = entries[entries.length - 1].isIntersecting;
      if (onScreen === this.#onScreen) return;
      this.#onScreen = onScreen;
      if (this.#started) this.#autoplay();
    });
    this.#screenObserver.observe(this);
  }

  /** `autoplay`: plays once loaded; `autoplay="visible"`: plays while on screen. */
  #autoplay() {
    const c = this.#controller;
    if (!c?.pg || !this.hasAttribute('autoplay')) return;
    if (this.getAttribute('autoplay') !== 'visible') c.clock.play();
    else if (!this.#onScreen) c.clock.pause();
    // Back on screen: plays on, but a run at its end starts over only with `loop`.
    else if (!c.clock.atEnd() || c.looping) c.clock.play();
  }

  /** Loads the scene the attributes ask for, then resolves `loaded`. */
  async #start() {
    this.#startAsked = true;
    const c = this.#controller;
    if (!(await c.ready())) {
      this.#resolveLoaded();
      return;
    }
    this.#started = true;
    this.#readDisplayAttributes();
    const src = this.getAttribute('src');
    // A bad `src` or `preset` shows its message and stays (no other scene instead).
    const ok = src ? await c.loadUrl(src) : this.#loadPreset(this.getAttribute('preset') || c.defaultPreset);
    if (ok) {
      this.#applyPlanner();
      // `compare`: the element opens in compare mode against that planner.
      if (this.hasAttribute('compare')) c.compare.set(this.getAttribute('compare'));
      // `loaded` tells of the scene at its `time`; autoplay plays on from there.
      await this.#seekAttribute();
      this.#autoplay();
    }
    this.#resolveLoaded();
  }

  /**
   * `planner`: part of the scene that `preset` or `src` loads, set on it as it loads (not an
   * undoable edit); an unknown name shows the message and keeps the scene's own planner.
   */
  #applyPlanner() {
    const c = this.#controller;
    const planner = this.getAttribute('planner');
    if (!planner || !c.compare.setPlanner(planner)) return;
    c.history.clear();
    c.toolbar.update();
  }

  /** Loads preset `name`; a bad one shows its message in place of the scene. */
  #loadPreset(name) {
    return this.#controller.loadPreset(name);
  }

  /**
   * `time`: the state at that time, simulated from t = 0 in slices (a crowd's long seek shows
   * its progress and never blocks the page). Resolves once the seek ends.
   */
  async #seekAttribute() {
    const c = this.#controller;
    const attr = this.getAttribute('time');
    if (attr === null || !c.pg) return;
    const t = Number(attr);
    if (attr.trim() === '' || !Number.isFinite(t))
      c.showMessage(`time="${attr}": the time must be a number of seconds`);
    else await c.clock.seekSliced(t);
  }

  /** `controls`, `editable`, `readonly` and `loop`: what input may do, and the end of the run. */
  #readModes() {
    const readonly = this.hasAttribute('readonly');
    this.#controller.setModes({
      readonly,
      editable: !readonly && (this.hasAttribute('controls') || this.hasAttribute('editable')),
      looping: this.hasAttribute('loop'),
    });
  }

  #readDisplayAttributes() {
    const field = FIELD_MODES.find((mode) => mode === this.getAttribute('field'));
    const theta0 = Number(this.getAttribute('theta0') ?? DEFAULT_THETA0);
    this.#controller.setDisplay({
      field: field ?? 'arrows',
      theta0: Number.isFinite(theta0) ? theta0 : DEFAULT_THETA0,
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

  get robotCount() {
    return this.#controller?.pg ? this.#controller.model.robots.length : 0;
  }

  exportJson() {
    return this.#controller?.exportJson() ?? Promise.resolve();
  }

  play() {
    this.#controller?.clock.play();
  }

  pause() {
    this.#controller?.clock.pause();
  }

  reset() {
    this.#controller?.clock.reset();
  }

  step(n = 1) {
    return this.#controller?.clock.step(n) ?? 0;
  }

  seek(t) {
    return this.#controller?.clock.seek(t) ?? 0;
  }

  async seekTo(t) {
    return (await this.#controller?.clock.seekSliced(t)) ?? 0;
  }

  get time() {
    return this.#controller?.pg ? this.#controller.views.time : 0;
  }

  get playing() {
    return Boolean(this.#controller?.pg && this.#controller.loop.playing);
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
    c.inspect(i);
    c.requestDraw();
  }
}

// Defined once, however often the module is imported (two copies of it included); nothing
// where there is no DOM.
if (globalThis.customElements && !customElements.get('dvf-playground')) {
  customElements.define('dvf-playground', DvfPlayground);
}
