// Getting scenarios in and out: the URL fragment, files and URLs, and the downloads (the
// scenario as JSON, the canvas as PNG, the CSV of a whole run). Everything that arrives is
// untrusted text: it is size-capped, parsed as JSON data only and checked by the core (which
// names the offending field); nothing of it is ever HTML.

import { Run } from './pkg/dvf.js';
import { SAMPLE_STRIDE } from './playground/wasm-views.js';

/** The fragment that holds a scenario starts with this. */
export const FRAGMENT_PREFIX = '#s=';
/** Longest fragment, fetched or imported file accepted (characters / bytes). */
export const MAX_SCENARIO_BYTES = 64 * 1024;

/** The fragment for a scenario object: `#s=` and the URI-encoded compact JSON. */
export function fragmentFor(scenario) {
  return FRAGMENT_PREFIX + encodeURIComponent(JSON.stringify(scenario));
}

/**
 * What a fragment asks for: `{kind: 'none'}`, `{kind: 'preset', name}` for `#name`, or
 * `{kind: 'scenario', text}` for `#s=…`. Throws an Error with a message a person can act on
 * when the fragment is too long or not decodable; the JSON itself is checked by the core.
 */
export function parseFragment(hash) {
  if (!hash || hash === '#') return { kind: 'none' };
  if (hash.length > MAX_SCENARIO_BYTES) {
    throw new Error(
      `link: the scenario in the address is ${hash.length} characters long; at most ${MAX_SCENARIO_BYTES} are accepted`,
    );
  }
  if (hash.startsWith(FRAGMENT_PREFIX)) {
    let text;
    try {
      text = decodeURIComponent(hash.slice(FRAGMENT_PREFIX.length));
    } catch {
      throw new Error('link: the scenario in the address is not correctly percent-encoded (was it cut short?)');
    }
    return { kind: 'scenario', text };
  }
  let name;
  try {
    name = decodeURIComponent(hash.slice(1));
  } catch {
    throw new Error('link: the address fragment is not correctly percent-encoded');
  }
  return { kind: 'preset', name };
}

/** Offers `blob` as a download named `filename`. */
function download(blob, filename) {
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
function fileStem(name) {
  const stem = String(name)
    .toLowerCase()
    .replace(/[^a-z0-9]+/g, '-')
    .replace(/^-+|-+$/g, '');
  return stem.slice(0, 60) || 'scenario';
}

/**
 * The trajectories of a whole run of `scenario` from its starts as CSV, one row per robot and
 * sample: `robot,t,x,y,theta,v,omega` (robot numbered from 0; s, m, m, rad, m/s, rad/s).
 */
function trajectoriesCsv(scenario) {
  const run = new Run(scenario);
  try {
    const tr = run.trajectories();
    const n = run.robotCount;
    const samples = run.sampleCount;
    const rows = ['robot,t,x,y,theta,v,omega'];
    for (let i = 0; i < n; i++) {
      for (let k = 0; k < samples; k++) {
        const o = (i * samples + k) * SAMPLE_STRIDE;
        rows.push(`${i},${tr[o]},${tr[o + 1]},${tr[o + 2]},${tr[o + 3]},${tr[o + 4]},${tr[o + 5]}`);
      }
    }
    return `${rows.join('\n')}\n`;
  } finally {
    run.free();
  }
}

/** Reads an imported file as text, refusing files over the cap before reading them. */
export async function readScenarioFile(file) {
  if (file.size > MAX_SCENARIO_BYTES) {
    throw new Error(
      `import: ${file.name} is ${file.size} bytes; a scenario file may be at most ${MAX_SCENARIO_BYTES} bytes`,
    );
  }
  return file.text();
}

/** Fetches the scenario text at `url`; throws for an HTTP error or a text over the cap. */
export async function fetchScenarioText(url) {
  const res = await fetch(url);
  if (!res.ok) throw new Error(`HTTP ${res.status}`);
  const text = await res.text();
  if (text.length > MAX_SCENARIO_BYTES) throw new Error(`the file is longer than ${MAX_SCENARIO_BYTES} bytes`);
  return text;
}

/** Offers `scenario` as a JSON file that `dvf simulate` reads. */
export function downloadScenarioJson(scenario) {
  const text = `${JSON.stringify(scenario, null, 2)}\n`;
  download(new Blob([text], { type: 'application/json' }), `${fileStem(scenario.name)}.json`);
}

/** Offers the trajectories of a whole run of `scenario` from its starts as CSV. */
export function downloadTrajectoriesCsv(scenario) {
  download(new Blob([trajectoriesCsv(scenario)], { type: 'text/csv' }), `${fileStem(scenario.name)}.csv`);
}

/** Offers the picture on `canvas` as a PNG named after the scenario `name`. */
export function downloadCanvasPng(canvas, name) {
  canvas.toBlob((blob) => download(blob, `${fileStem(name)}.png`), 'image/png');
}
