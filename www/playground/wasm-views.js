// The wasm module and typed-array views into its memory. The module is fetched and compiled
// once per page, whatever the number of playgrounds. This is the ONLY module that reads the
// addresses (pointers) of the simulation's arrays and knows their layouts (strides): every
// other module indexes arrays with the strides exported here.

import init, { defaultPreset, parameters, planners, playgroundLimits, presets } from '../pkg/dvf.js';
import { messageOf, useParameters } from './message.js';

// The records of the flat arrays come from the module (`playgroundLimits()`, src/wasm/mod.rs),
// set once it is initialised: ES module bindings are live, so every importer sees them. Nothing
// reads them before wasmReady() resolves (drawing starts after the first load).
/** Values per pose in `poses`, `trails` and `predicted`: x, y, θ (m, m, rad). */
export let POSE_STRIDE = 0;
/** Values per robot in `status`, at the offsets of STATUS. */
export let STATUS_STRIDE = 0;
/**
 * Offsets in a robot's `status` record: speed, turn rate, the obstacle keep Π ς_i (below 1
 * near an obstacle), the robot keep ς_c, and the virtual obstacle (NaN when there is none).
 * @type {{v: number, omega: number, obstacleKeep: number, robotKeep: number, virtualX: number, virtualY: number}}
 */
export const STATUS = { v: 0, omega: 0, obstacleKeep: 0, robotKeep: 0, virtualX: 0, virtualY: 0 };
/** Values per field sample: x, y, Γx, Γy. */
export let FIELD_STRIDE = 0;
/** Values per point of an integral curve: x, y. */
export let CURVE_POINT_STRIDE = 0;
/** Values per trajectory sample of a `Run`: t, x, y, θ, v, ω. */
export let SAMPLE_STRIDE = 0;

/**
 * @typedef {{
 *   trailCapacity: number, predictionSamples: number, curvePoints: number, maxGridSide: number,
 *   maxCurveSide: number, maxRobots: number, maxPredictedRobots: number, crowdMax: number,
 *   poseStride: number, statusStride: number, statusFields: string[], fieldStride: number,
 *   curveStride: number, sampleStride: number,
 * }} Limits  the playground's limits and layouts (`playgroundLimits()`)
 * @typedef {{name: string, summary: string}} PresetInfo
 * @typedef {{name: string, title: string, source: string, avoids: string}} PlannerInfo
 */

/**
 * The module beside the bindings. The same literal as wasm-pack's own default in pkg/dvf.js,
 * so that a bundler copies (or inlines) one file for both; the single-file build drops that
 * one (package/build.mjs), so that the module is inlined once.
 */
const defaultWasmUrl = () => new URL('../pkg/dvf_bg.wasm', import.meta.url);
/**
 * Where the module comes from: undefined for `pkg/dvf_bg.wasm` beside the bindings, or a URL
 * (string or URL, resolved against the page), or the module's bytes.
 * @type {string | URL | BufferSource | undefined}
 */
let wasmSource;
/**
 * @type {Promise<{memory: WebAssembly.Memory, limits: Limits, presets: PresetInfo[], defaultPreset: string,
 *   parameters: {rows: import('../panels/params.js').Parameter[], modes: string[]}, planners: PlannerInfo[]}> | null}
 */
let ready = null;

/**
 * Points the page at the module's `source` (a URL or the bytes) for the first load; false
 * (and nothing changed) once loading has begun, since the module is loaded once per page.
 * @param {string | URL | BufferSource | undefined} source
 */
export function setWasmSource(source) {
  if (ready) return false;
  wasmSource = source;
  return true;
}

/** Where the module is loaded from: the page's URL or bytes, else the default (an absolute URL). */
function wasmSourceNow() {
  if (wasmSource === undefined) return defaultWasmUrl();
  if (typeof wasmSource === 'string' || wasmSource instanceof URL) return new URL(String(wasmSource), document.baseURI);
  return wasmSource;
}

/** The module's URL as the page asks for it, for messages. */
function wasmSourceName() {
  const source = wasmSourceNow();
  return source instanceof URL && source.protocol !== 'data:' ? source.href : 'the inlined module';
}

/**
 * A module worker that runs scenarios to their end (results-worker.js: the results panel, a
 * pinned run), handed the module the page loads (its URL or bytes) with its first message.
 */
export function runWorker() {
  const worker = new Worker(new URL('./results-worker.js', import.meta.url), { type: 'module' });
  const source = wasmSourceNow();
  worker.postMessage({ wasm: source instanceof URL ? source.href : source });
  return worker;
}

/**
 * The module, initialised once per page on first call (never at import: a page, or a server
 * rendering one, that imports the element loads nothing until an element asks): its memory,
 * limits, presets, default preset, parameter table (which the messages take their names from)
 * and planners.
 */
export function wasmReady() {
  ready ??= init({ module_or_path: wasmSourceNow() }).then((wasm) => {
    /** @type {Limits} */
    const limits = playgroundLimits();
    POSE_STRIDE = limits.poseStride;
    STATUS_STRIDE = limits.statusStride;
    FIELD_STRIDE = limits.fieldStride;
    CURVE_POINT_STRIDE = limits.curveStride;
    SAMPLE_STRIDE = limits.sampleStride;
    limits.statusFields.forEach((name, offset) => {
      STATUS[name] = offset;
    });
    const table = parameters();
    useParameters(table.rows);
    return {
      memory: wasm.memory,
      limits,
      presets: presets(),
      defaultPreset: defaultPreset(),
      parameters: table,
      planners: planners(),
    };
  });
  return ready;
}

/**
 * One buffer of `Playground.layout()`: `length` elements at byte `pointer`, `stride` per item.
 * @typedef {{pointer: number, length: number, stride: number}} Buffer
 */

/**
 * What a frame reads of a live simulation: its counters and its arrays.
 * @typedef {{
 *   time: number, duration: number, trailHead: number, historyLength: number, recorded: number,
 *   trailCapacity: number, predictedSamples: number, poses: Float64Array, status: Float64Array,
 *   trails: Float64Array, trailLens: Uint32Array, trailTimes: Float64Array,
 *   trailMinPair: Float64Array, predicted: Float64Array, predictedTimes: Float64Array,
 *   predictedMinPair: Float64Array,
 * }} Frame
 */

/**
 * One live `Playground` as a frame reads it: its counters, re-read by `refresh()` after every
 * step or edit, and its arrays as views into wasm memory, never copies. A view stays valid
 * until the memory grows, which any call into the module may do (another playground on the
 * page included), so every read re-checks it: a pointer read and a comparison, and a new view
 * only when the array moved, its length changed or the memory grew. No allocation in a steady
 * frame.
 */
export class LiveViews {
  /** @param {WebAssembly.Memory} memory */
  constructor(memory) {
    this.memory = memory;
    /** @type {import('../pkg/dvf.js').Playground | null} */
    this.pg = null;
    /** @type {Map<string, Float64Array | Uint32Array>} */
    this.byName = new Map();
    this.robots = 0;
    this.time = 0;
    this.duration = 0;
    this.trailHead = 0;
    this.historyLength = 0;
    this.recorded = 0;
    this.trailCapacity = 0;
    this.predictedSamples = 0;
    /** @type {Record<string, any> | null} the module's layout of every buffer */
    this.layout = null;
  }

  /** Reads `pg` from now on. */
  attach(pg) {
    this.pg = pg;
    this.refresh();
  }

  /** Re-reads the counters (after a step, an edit, a load or a reset). */
  refresh() {
    const pg = this.pg;
    const layout = pg.layout();
    this.layout = layout;
    this.robots = layout.poses.length / layout.poses.stride;
    this.time = pg.time;
    this.duration = pg.duration;
    this.trailHead = layout.trailHead;
    this.historyLength = layout.historyLength;
    this.recorded = layout.trailRecorded;
    this.trailCapacity = layout.trailTimes.length;
    this.predictedSamples = layout.predictedTimes.length;
  }

  /** `[robots · 3]`: x, y, θ now. */
  get poses() {
    return this.f64('poses', this.layout.poses);
  }

  /** `[robots · 6]`: see STATUS. */
  get status() {
    return this.f64('status', this.layout.status);
  }

  /** `[robots · trailCapacity · 3]`: one ring of past poses per robot. */
  get trails() {
    return this.f64('trails', this.layout.trails);
  }

  /** `[robots]`: samples held in each robot's ring. */
  get trailLens() {
    return this.u32('trailLens', this.layout.trailLengths);
  }

  /** `[trailCapacity]`: time of each ring slot (s). */
  get trailTimes() {
    return this.f64('trailTimes', this.layout.trailTimes);
  }

  /** `[trailCapacity]`: smallest distance between two robots at each ring slot (m, NaN: none). */
  get trailMinPair() {
    return this.f64('trailMinPair', this.layout.trailMinPair);
  }

  /** `[robots · predictedSamples · 3]`: the predicted poses from now on. */
  get predicted() {
    return this.f64('predicted', this.layout.predicted);
  }

  /** `[predictedSamples]`: time of each predicted sample (s). */
  get predictedTimes() {
    return this.f64('predictedTimes', this.layout.predictedTimes);
  }

  /** `[predictedSamples]`: predicted smallest distance between two robots (m, NaN: none). */
  get predictedMinPair() {
    return this.f64('predictedMinPair', this.layout.predictedMinPair);
  }

  /** Robot `i`'s pose now, [x, y, θ]. */
  pose(i) {
    const p = this.poses;
    const o = i * POSE_STRIDE;
    return [p[o], p[o + 1], p[o + 2]];
  }

  /** The last field samples (`refreshField`), `length` values. */
  field(length) {
    const field = this.pg.layout().field;
    return this.f64('field', { pointer: field.pointer, length, stride: field.stride });
  }

  /**
   * Every counter and array once, as a plain object: read after every other call into wasm
   * of the frame, since a call may grow the memory and detach the views.
   * @returns {Frame}
   */
  read() {
    return {
      time: this.time,
      duration: this.duration,
      trailHead: this.trailHead,
      historyLength: this.historyLength,
      recorded: this.recorded,
      trailCapacity: this.trailCapacity,
      predictedSamples: this.predictedSamples,
      poses: this.poses,
      status: this.status,
      trails: this.trails,
      trailLens: this.trailLens,
      trailTimes: this.trailTimes,
      trailMinPair: this.trailMinPair,
      predicted: this.predicted,
      predictedTimes: this.predictedTimes,
      predictedMinPair: this.predictedMinPair,
    };
  }

  /** @param {string} name @param {Buffer} b */
  f64(name, b) {
    return /** @type {Float64Array} */ (this.view(name, Float64Array, b.pointer, b.length));
  }

  /** @param {string} name @param {Buffer} b */
  u32(name, b) {
    return /** @type {Uint32Array} */ (this.view(name, Uint32Array, b.pointer, b.length));
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
export function wasmFailure(e) {
  if (typeof WebAssembly === 'object' && !hasWasmSimd()) {
    return 'This browser cannot run the simulator: it needs WebAssembly with 128-bit SIMD (Chrome or Edge 91, Firefox 89, Safari 16.4 or later).';
  }
  if (globalThis.location?.protocol === 'file:') {
    return 'This page was opened from a file (file://), and browsers load the simulator (WebAssembly) only over HTTP. Serve the folder over HTTP, e.g. run "python3 -m http.server" in it and open http://localhost:8000/.';
  }
  return `Could not load the simulator (${wasmSourceName()}): ${messageOf(e)}. Serve dvf_bg.wasm with the package, or point the element at it with its wasm attribute.`;
}
