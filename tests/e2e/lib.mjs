// Shared by the end-to-end tests, the browser benchmark and the README's picture: a python3
// http.server on www/ (the RELEASE wasm package that `make build-wasm` writes), Debian's
// Chromium through playwright-core, a check list that fails the run, pixel statistics of a
// playground's canvas, the scenes and gestures that more than one of them drives, and the
// page's import graph.

import { spawn } from 'node:child_process';
import { existsSync, mkdirSync, readdirSync, readFileSync, statSync } from 'node:fs';
import { createServer } from 'node:net';
import { dirname, join, relative, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

export const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
export const WWW = join(ROOT, 'www');
export const RESULTS = join(ROOT, 'test-results');
const CHROMIUM = '/usr/bin/chromium';
const CHROMIUM_ARGS = [
  '--headless',
  '--no-sandbox',
  '--disable-gpu',
  '--disable-quic',
  '--no-first-run',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
];
const SERVER_START_TIMEOUT_MS = 10_000;
export const PAGE_TIMEOUT_MS = 20_000;
/** A pixel is "coloured" when its channels spread by more than this (greys spread ~0). */
const COLOURED_SPREAD = 60;

const failures = [];
/** Records one check; a failed one fails the run at the end. */
export function check(ok, message) {
  if (ok) console.log(`ok   ${message}`);
  else {
    console.log(`FAIL ${message}`);
    failures.push(message);
  }
}

/** A free TCP port on 127.0.0.1. */
function freePort() {
  return new Promise((resolve, reject) => {
    const srv = createServer();
    srv.unref();
    srv.on('error', reject);
    srv.listen(0, '127.0.0.1', () => {
      const { port } = srv.address();
      srv.close(() => resolve(port));
    });
  });
}

/**
 * Starts python3's http.server on folder `dir` (www/ unless told) and resolves with it and its
 * base URL once it answers (the folder must hold an index.html).
 */
export async function startServer(dir = WWW) {
  const port = await freePort();
  const server = spawn('python3', ['-m', 'http.server', String(port), '--bind', '127.0.0.1', '--directory', dir], {
    stdio: ['ignore', 'ignore', 'pipe'],
  });
  let stderr = '';
  server.stderr.on('data', (d) => {
    stderr += d;
  });
  const deadline = Date.now() + SERVER_START_TIMEOUT_MS;
  while (Date.now() < deadline) {
    if (server.exitCode !== null) throw new Error(`http.server exited: ${stderr}`);
    try {
      const res = await fetch(`http://127.0.0.1:${port}/index.html`);
      if (res.ok) return { server, base: `http://127.0.0.1:${port}` };
    } catch {
      // not listening yet
    }
    await new Promise((r) => setTimeout(r, 100));
  }
  server.kill();
  throw new Error(`http.server did not answer within ${SERVER_START_TIMEOUT_MS} ms`);
}

/**
 * Runs `body({browser, base, newPage})` against the served page and exits non-zero when a
 * check failed. `newPage(options)` opens a page that records every console error or warning,
 * page error, failed request and HTTP error into `page.problems`.
 */
export async function run(body) {
  const wasm = join(WWW, 'pkg', 'dvf_bg.wasm');
  let server;
  let browser;
  try {
    if (!existsSync(wasm)) throw new Error(`${wasm} is missing: run make build-wasm first`);
    mkdirSync(RESULTS, { recursive: true });
    const started = await startServer();
    server = started.server;
    browser = await chromium.launch({ executablePath: CHROMIUM, args: CHROMIUM_ARGS });
    const newPage = async (options = {}) => {
      const context = await browser.newContext({ acceptDownloads: true, ...options });
      const page = await context.newPage();
      page.setDefaultTimeout(PAGE_TIMEOUT_MS);
      page.problems = [];
      page.on('console', (m) => {
        if (m.type() === 'error' || m.type() === 'warning') page.problems.push(`console.${m.type()}: ${m.text()}`);
      });
      page.on('pageerror', (e) => page.problems.push(`page error: ${e.message}`));
      page.on('requestfailed', (r) => page.problems.push(`request failed: ${r.url()} ${r.failure()?.errorText}`));
      page.on('response', (r) => {
        if (r.status() >= 400) page.problems.push(`HTTP ${r.status()}: ${r.url()}`);
      });
      return page;
    };
    await body({ browser, base: started.base, newPage });
  } catch (e) {
    check(false, e.stack ?? String(e));
  } finally {
    if (browser) await browser.close();
    server?.kill();
  }
  if (failures.length) {
    console.log(`\n${failures.length} failure(s)`);
    process.exitCode = 1;
  } else {
    console.log('\nall checks passed');
  }
}

/** Checks that `page` logged no console error or warning and no page or request error. */
export function checkQuiet(page, what) {
  const p = page.problems;
  check(
    p.length === 0,
    `${what}: no console errors or warnings, no page errors${p.length ? `:\n  ${p.join('\n  ')}` : ''}`,
  );
}

/** Waits for two animation frames, so that a requested draw has happened. */
export function frames(page) {
  return page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}

/** Waits until the playground matching `selector` has shown its first scene. */
export async function waitLoaded(page, selector = 'dvf-playground') {
  await page.waitForFunction((sel) => document.querySelector(sel)?.cache, selector);
  await page.evaluate((sel) => document.querySelector(sel).loaded, selector);
  await frames(page);
}

/** The current scenario of the playground matching `selector`. */
export function scenarioOf(page, selector = 'dvf-playground') {
  return page.evaluate((sel) => document.querySelector(sel).scenario(), selector);
}

/**
 * Pixel statistics of a playground's canvas backing store: size, coloured pixels, and a
 * down-sampled copy (mean of each 8×8 block) for comparing two pictures.
 */
export function canvasStats(page, selector = 'dvf-playground') {
  return page.evaluate(
    ([sel, spread]) => {
      const c = document.querySelector(sel).shadowRoot.querySelector('[data-id="canvas"]');
      // Read through a copy, so that the page's own context never reads back (Chromium warns
      // when a context without willReadFrequently is read repeatedly).
      const copy = document.createElement('canvas');
      copy.width = c.width;
      copy.height = c.height;
      const cc = copy.getContext('2d', { willReadFrequently: true });
      cc.drawImage(c, 0, 0);
      const { data } = cc.getImageData(0, 0, c.width, c.height);
      let coloured = 0;
      const block = 8;
      const bw = Math.ceil(c.width / block);
      const bh = Math.ceil(c.height / block);
      const blocks = new Array(bw * bh).fill(0);
      for (let i = 0; i < data.length; i += 4) {
        const r = data[i],
          g = data[i + 1],
          b = data[i + 2];
        if (Math.max(r, g, b) - Math.min(r, g, b) > spread) coloured++;
        const p = i / 4;
        blocks[Math.floor(p / c.width / block) * bw + Math.floor((p % c.width) / block)] += r + g + b;
      }
      return {
        width: c.width,
        height: c.height,
        cssWidth: c.clientWidth,
        dpr: window.devicePixelRatio,
        coloured,
        blocks,
      };
    },
    [selector, COLOURED_SPREAD],
  );
}

/** Fraction of 8×8 blocks whose mean colour differs noticeably between two canvasStats. */
export function changedFraction(a, b) {
  if (a.blocks.length !== b.blocks.length) return 1;
  return a.blocks.filter((v, i) => Math.abs(v - b.blocks[i]) > 8 * 8 * 3 * 4).length / a.blocks.length;
}

/** The preset of the README's picture, the drag and the prediction figures: the paper's Example 4. */
/**
 * The import cycles among the page's own modules under `dir` (www/ by default; the wasm
 * bindings in pkg/ aside): each cycle as its files in order, relative to `dir`.
 */
export function importCycles(dir = WWW) {
  const files = [];
  const walk = (d) => {
    for (const name of readdirSync(d)) {
      const path = join(d, name);
      if (name === 'pkg') continue;
      if (statSync(path).isDirectory()) walk(path);
      else if (name.endsWith('.js')) files.push(path);
    }
  };
  walk(dir);
  const imports = new Map(
    files.map((f) => [
      f,
      [...readFileSync(f, 'utf8').matchAll(/^(?:import|export)\s[^;]*?from\s*'(\.[^']+)'/gm)]
        .map((m) => resolve(dirname(f), m[1]))
        .filter((p) => !p.includes(`${sep}pkg${sep}`)),
    ]),
  );
  const cycles = [];
  const state = new Map();
  const stack = [];
  const visit = (f) => {
    state.set(f, 'open');
    stack.push(f);
    for (const g of imports.get(f) ?? []) {
      if (state.get(g) === 'open') cycles.push([...stack.slice(stack.indexOf(g)), g].map((p) => relative(dir, p)));
      else if (!state.has(g)) visit(g);
    }
    stack.pop();
    state.set(f, 'done');
  };
  for (const f of files) if (!state.has(f)) visit(f);
  return cycles;
}

export const EXAMPLE4 = 'example4-obstacle-formation';

/**
 * The README's picture on `page` (1280×800 at scale 1): Example 4 at t = 0.7 s, as the robots
 * pass the obstacle, with the field of the robot that goes round it.
 */
export async function showReadmeScene(page, selector = 'dvf-playground') {
  await page.evaluate((sel) => {
    const el = document.querySelector(sel);
    el.step(70);
    el.focusRobot = 2;
  }, selector);
  await frames(page);
}

/**
 * Drags with the mouse from page point (x, y), `moves` moves of (dx, dy) each, and keeps the
 * button down until the moves are drawn; then releases it. Returns what the page did in the
 * meantime: the animation frames the browser produced (`frames`, over `span` s, the longest
 * gap `worst` ms between two), how often the playground redrew (`redraws`), the work of each
 * of its frames (`work`, ms), its slowest frame and its last edit (ms).
 */
export async function drag(page, [x, y], moves, [dx, dy], selector = 'dvf-playground') {
  await page.mouse.move(x, y);
  await page.mouse.down();
  // The page's own frame clock during the drag: every animation frame the browser produced.
  await page.evaluate((sel) => {
    window.dragFrames = [];
    window.dragging = true;
    const tick = (t) => {
      if (!window.dragging) return;
      window.dragFrames.push(t);
      requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
    const el = document.querySelector(sel);
    el.stats.maxFrameWorkMs = 0;
    window.redraws0 = el.stats.frames;
    window.work0 = el.stats.workCount;
  }, selector);
  for (let k = 1; k <= moves; k++) await page.mouse.move(x + k * dx, y + k * dy);
  await frames(page);
  const figures = await page.evaluate((sel) => {
    window.dragging = false;
    const t = window.dragFrames;
    let worst = 0;
    for (let k = 1; k < t.length; k++) worst = Math.max(worst, t[k] - t[k - 1]);
    const el = document.querySelector(sel);
    const { work, workCount } = el.stats;
    const drawn = [];
    for (let k = Math.max(window.work0, workCount - work.length); k < workCount; k++) drawn.push(work[k % work.length]);
    return {
      frames: t.length,
      span: (t[t.length - 1] - t[0]) / 1000,
      worst,
      redraws: el.stats.frames - window.redraws0,
      work: drawn,
      maxWork: el.stats.maxFrameWorkMs,
      edit: el.stats.lastEditMs,
    };
  }, selector);
  await page.mouse.up();
  await frames(page);
  return figures;
}

/**
 * Runs the predictions of `preset` in a Playground of its own on `page`, `runs` times each
 * after `warmup` untimed ones (as a batch: the browser's clock is coarse, 0.1 ms or worse, next
 * to one prediction). Returns the ms per prediction (`predict`), per robot move with its checks
 * and prediction (`edit`), the samples per robot and the time the prediction reached (`end`,
 * stopped early once every robot converged), and the same without stopping early, with
 * tolerances no robot meets (`full`, `fullEnd`).
 */
export function predictions(page, preset, runs, warmup) {
  return page.evaluate(
    async ([name, runs, warmup]) => {
      const dvf = await import('./pkg/dvf.js');
      const { memory } = await dvf.default(); // the page's module, initialised already
      const pg = dvf.Playground.fromPreset(name);
      /** The times of the predicted samples, read in place (see `Playground.layout`). */
      const times = () => {
        const { predictedTimes } = pg.layout();
        return new Float64Array(memory.buffer, predictedTimes.pointer, predictedTimes.length);
      };
      for (let k = 0; k < warmup; k++) pg.predict();
      let t0 = performance.now();
      for (let k = 0; k < runs; k++) pg.predict();
      const predict = (performance.now() - t0) / runs;
      t0 = performance.now();
      for (let k = 0; k < runs; k++) pg.moveRobot(0, -60 + (k % 5) * 0.3, -40, 0);
      const edit = (performance.now() - t0) / runs;
      const samples = pg.layout().predictedTimes.length;
      const end = times()[samples - 1];
      const s = pg.scenario();
      s.params.tol_position = 1e-12;
      s.params.tol_heading = 1e-12;
      pg.edit(s);
      t0 = performance.now();
      for (let k = 0; k < runs; k++) pg.predict();
      const full = (performance.now() - t0) / runs;
      const fullTimes = times();
      const fullEnd = fullTimes[fullTimes.length - 1];
      pg.free();
      return { predict, edit, samples, end, full, fullEnd };
    },
    [preset, runs, warmup],
  );
}

export { join };
