// Getting scenarios in and out: the URL fragment, files and URLs, and the downloads (the
// scenario as JSON, the canvas as PNG, the CSV of a whole run). Everything that arrives is
// untrusted text: it is size-capped, parsed as JSON data only and checked by the core (which
// names the offending field); nothing of it is ever HTML.

import { Playground } from './pkg/dvf.js';
import { DEFAULT_THETA0 } from './playground/view-state.js';
import { POSE_STRIDE, STATUS, STATUS_STRIDE, wasmReady } from './playground/wasm-views.js';

/** The fragment that holds a scenario starts with this. */
const FRAGMENT_PREFIX = '#s=';
/** Longest fragment accepted or written (characters): what links survive being pasted. */
export const MAX_LINK_CHARS = 64 * 1024;
/**
 * Largest scenario file imported or fetched (bytes): well above the edited 10,000-robot crowd,
 * the largest scene the page shows, as the page writes it (tests/e2e/instrument.mjs imports
 * it).
 */
export const MAX_FILE_BYTES = 32 * 1024 * 1024;
/**
 * Largest CSV the page writes (bytes, estimated up front): larger runs are refused with their
 * size and left to the command line (`dvf simulate --csv`).
 */
export const MAX_CSV_BYTES = 64 * 1024 * 1024;
/** The CSV's header: the command line's (`dvf simulate --csv`, src/bin/dvf.rs). */
export const CSV_HEADER = 't,robot,x,y,theta,v,omega';
/** Bytes per CSV row, for the estimate: seven numbers at full precision and their commas. */
const CSV_ROW_BYTES = 100;
/** A CSV export works this long at a time (ms), then lets the page draw its progress. */
const CSV_SLICE_MS = 30;

/** The fragment for a scenario object: `#s=` and the URI-encoded compact JSON. */
export function fragmentFor(scenario) {
  return FRAGMENT_PREFIX + encodeURIComponent(JSON.stringify(scenario));
}

/** The field overlays a link may ask for. */
const LINK_FIELDS = ['arrows', 'curves', 'none'];

/**
 * The view's part of a link for `v` (the element's viewState()): `&field=…&theta0=…&sensing=1
 * &robot=…&t=…&view=x0,y0,x1,y1&compare=…`, each only when it is not the default (the robot
 * numbered from 1, as on the page; `compare` the planner the scene is compared with).
 * @param {import('./dvf-playground.js').ViewState | null} v
 */
export function viewSuffix(v) {
  if (!v) return '';
  const parts = [];
  if (v.field !== 'arrows') parts.push(`field=${v.field}`);
  if (v.theta0 !== DEFAULT_THETA0) parts.push(`theta0=${v.theta0}`);
  if (v.sensing) parts.push('sensing=1');
  if (v.robot > 0) parts.push(`robot=${v.robot + 1}`);
  if (v.time > 0) parts.push(`t=${Number(v.time.toFixed(6))}`);
  if (v.box) parts.push(`view=${v.box.map((x) => Number(x.toPrecision(7))).join(',')}`);
  if (v.compare) parts.push(`compare=${v.compare}`);
  return parts.map((p) => `&${p}`).join('');
}

/** The view a link's `&key=value` parts ask for (viewSuffix's); unknown or bad parts are left out. */
function parseView(parts) {
  /** @type {Partial<import('./dvf-playground.js').ViewState>} */
  const v = {};
  for (const part of parts) {
    const [key, value = ''] = part.split('=');
    const n = Number(value);
    if (key === 'field' && LINK_FIELDS.includes(value)) v.field = /** @type {any} */ (value);
    else if (key === 'theta0' && value !== '' && Number.isFinite(n)) v.theta0 = n;
    else if (key === 'sensing') v.sensing = value === '1';
    else if (key === 'robot' && Number.isInteger(n) && n >= 1) v.robot = n - 1;
    else if (key === 't' && value !== '' && Number.isFinite(n) && n >= 0) v.time = n;
    else if (key === 'compare' && value !== '') v.compare = value;
    else if (key === 'view') {
      const box = value.split(',').map(Number);
      if (box.length === 4 && box.every(Number.isFinite)) v.box = /** @type {any} */ (box);
    }
  }
  return Object.keys(v).length ? v : null;
}

/**
 * What a fragment asks for: `{kind: 'none'}`, `{kind: 'preset', name}` for `#name`, or
 * `{kind: 'scenario', text}` for `#s=…`, with `view` (parseView) when it has a view's part.
 * Throws an Error with a message a person can act on when the fragment is too long or not
 * decodable; the JSON itself is checked by the core.
 */
export function parseFragment(hash) {
  if (!hash || hash === '#') return { kind: 'none' };
  if (hash.length > MAX_LINK_CHARS) {
    throw new Error(
      `link: the scenario in the address is ${hash.length} characters long; at most ${MAX_LINK_CHARS} are accepted`,
    );
  }
  // A scenario's JSON is URI-encoded, so the first `&` starts the view's part.
  const [scene, ...rest] = hash.split('&');
  const view = parseView(rest);
  if (scene.startsWith(FRAGMENT_PREFIX)) {
    let text;
    try {
      text = decodeURIComponent(scene.slice(FRAGMENT_PREFIX.length));
    } catch {
      throw new Error('link: the scenario in the address is not correctly percent-encoded (was it cut short?)');
    }
    return { kind: 'scenario', text, view };
  }
  let name;
  try {
    name = decodeURIComponent(scene.slice(1));
  } catch {
    throw new Error('link: the address fragment is not correctly percent-encoded');
  }
  return { kind: 'preset', name, view };
}

/** Offers `blob` as a download named `filename`. */
export function downloadBlob(blob, filename) {
  const url = URL.createObjectURL(blob);
  const a = document.createElement('a');
  a.href = url;
  a.download = filename;
  a.style.display = 'none';
  document.body.append(a);
  a.click();
  a.remove();
  // The download has started from the URL by now; free it a little later.
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

/** A file name from a scenario name: letters, digits and dashes only. */
export function fileStem(name) {
  const stem = String(name)
    .toLowerCase()
    .replace(/[^a-z0-9]+/g, '-')
    .replace(/^-+|-+$/g, '');
  return stem.slice(0, 60) || 'scenario';
}

/** `bytes` as a person reads it: "3.2 MB". */
export function formatBytes(bytes) {
  if (bytes >= 1e9) return `${(bytes / 1e9).toFixed(1)} GB`;
  if (bytes >= 1e6) return `${(bytes / 1e6).toFixed(1)} MB`;
  return `${Math.max(1, Math.round(bytes / 1e3))} KB`;
}

/** The rows and the estimated bytes of the CSV of a whole run of `scenario`. */
export function csvSize(scenario) {
  const rows = (Math.round(scenario.duration / scenario.dt) + 1) * scenario.robots.length;
  return { rows, bytes: rows * CSV_ROW_BYTES };
}

/**
 * The time of step `steps` of size `dt` as `dvf simulate --csv` writes it (src/sim/run.rs,
 * `step_time`): `dt`'s shortest decimal `m / 10^d` times `steps`, with `m` and `10^d` exact, so
 * that one rounding gives the nearest number to the decimal (`0.35`, not the binary product's
 * `0.35000000000000003`). A `dt` that has no such decimal gets the binary product.
 * @param {number} steps
 * @param {number} dt
 * @returns {number}
 */
export function stepTime(steps, dt) {
  const EXACT = 2 ** 53;
  let scale = 1;
  for (let d = 0; d <= 22; d++) {
    const m = Math.round(dt * scale);
    if (m > EXACT) break;
    if (m / scale === dt) {
      const units = steps * m;
      return units <= EXACT ? units / scale : steps * dt;
    }
    scale *= 10;
  }
  return steps * dt;
}

/**
 * The trajectories of a whole run of `scenario` from its starts as CSV text pieces, in the
 * command line's format: CSV_HEADER, then for every step (t = 0 first, the end last) one row
 * per robot, `t,robot,x,y,theta,v,omega` (robot numbered from 0; s, m, m, rad, m/s, rad/s).
 * Works in slices of CSV_SLICE_MS so that the page stays responsive; `progress(fraction)`
 * after each; resolves null once `signal` is aborted.
 * @param {any} scenario
 * @param {{progress?: (fraction: number) => void, signal?: AbortSignal}} [options]
 * @returns {Promise<string[] | null>}
 */
export async function trajectoriesCsv(scenario, { progress = () => {}, signal } = {}) {
  const { memory } = await wasmReady();
  const pg = new Playground(scenario);
  try {
    const n = scenario.robots.length;
    const steps = Math.round(pg.duration / pg.dt);
    const pieces = [`${CSV_HEADER}\n`];
    let poses = new Float64Array(0);
    let status = new Float64Array(0);
    const views = () => {
      const { poses: p, status: st } = pg.layout();
      poses = new Float64Array(memory.buffer, p.pointer, p.length);
      status = new Float64Array(memory.buffer, st.pointer, st.length);
    };
    views();
    for (let k = 0; k <= steps; ) {
      const t0 = performance.now();
      const rows = [];
      while (k <= steps && performance.now() - t0 < CSV_SLICE_MS) {
        if (k > 0) {
          pg.step(1);
          if (poses.buffer !== memory.buffer || poses.length === 0) views();
        }
        const t = stepTime(k, pg.dt);
        for (let i = 0; i < n; i++) {
          const o = i * POSE_STRIDE;
          const q = i * STATUS_STRIDE;
          rows.push(
            `${t},${i},${poses[o]},${poses[o + 1]},${poses[o + 2]},${status[q + STATUS.v]},${status[q + STATUS.omega]}`,
          );
        }
        k += 1;
      }
      pieces.push(`${rows.join('\n')}\n`);
      progress(Math.min(1, k / (steps + 1)));
      await new Promise((r) => setTimeout(r, 0));
      if (signal?.aborted) return null;
    }
    return pieces;
  } finally {
    pg.free();
  }
}

/** Reads an imported file as text, refusing files over the cap before reading them. */
export async function readScenarioFile(file) {
  if (file.size > MAX_FILE_BYTES) {
    throw new Error(
      `import: ${file.name} is ${formatBytes(file.size)}; a scenario file may be at most ${formatBytes(MAX_FILE_BYTES)}`,
    );
  }
  return file.text();
}

/**
 * Fetches the scenario text at `url`; throws for an HTTP error, an HTML page (a wrong address
 * that a server answers with its own page) or a text over the cap.
 */
export async function fetchScenarioText(url) {
  const res = await fetch(url);
  if (!res.ok) throw new Error(`HTTP ${res.status} ${res.statusText}`.trim());
  const text = await res.text();
  if (text.length > MAX_FILE_BYTES) throw new Error(`the file is longer than ${formatBytes(MAX_FILE_BYTES)}`);
  if ((res.headers.get('content-type') ?? '').includes('html') || /^\s*</.test(text)) {
    throw new Error('the address gives an HTML page, not a scenario JSON file (is the address right?)');
  }
  return text;
}

/**
 * Offers `scenario` as a JSON file that `dvf simulate` reads (and the page imports as the
 * same scene: JSON's shortest digits, which the core reads back exactly).
 */
export function downloadScenarioJson(scenario) {
  const text = `${JSON.stringify(scenario, null, 2)}\n`;
  downloadBlob(new Blob([text], { type: 'application/json' }), `${fileStem(scenario.name)}.json`);
}

/** Offers CSV text `pieces` (trajectoriesCsv) as a file named after `scenario`. */
export function downloadCsv(pieces, scenario) {
  downloadBlob(new Blob(pieces, { type: 'text/csv' }), `${fileStem(scenario.name)}.csv`);
}
