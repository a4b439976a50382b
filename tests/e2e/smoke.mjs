// End-to-end smoke test of the page as users load it: the RELEASE wasm package in www/pkg
// (`make build-wasm`), served by python3's http.server, driven in Debian's Chromium.
// Fails (exit 1) on any console error or warning, any page error, a blank canvas, or a preset
// switch that does not change the picture. Screenshots go to test-results/.
//
// Run: make test-e2e   (or: node tests/e2e/smoke.mjs after make build-wasm)

import { spawn } from 'node:child_process';
import { existsSync, mkdirSync } from 'node:fs';
import { createServer } from 'node:net';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const WWW = join(ROOT, 'www');
const RESULTS = join(ROOT, 'test-results');
const CHROMIUM = '/usr/bin/chromium';
const CHROMIUM_ARGS = [
  '--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync',
];
const VIEWPORT = { width: 1280, height: 800 };
/** High-DPI on purpose: the canvas must size its backing store by devicePixelRatio. */
const DEVICE_SCALE_FACTOR = 2;
const SERVER_START_TIMEOUT_MS = 10_000;
const PAGE_TIMEOUT_MS = 20_000;
/** A drawn run has at least this many coloured (robot trail) device pixels. */
const MIN_COLOURED_PIXELS = 2_000;
/** A pixel is "coloured" when its channels spread by more than this (greys spread ~0). */
const COLOURED_SPREAD = 60;
/** Two different presets differ in at least this fraction of device pixels. */
const MIN_CHANGED_FRACTION = 0.01;
const SECOND_PRESET = 'example3-circle-swap';

const failures = [];
const check = (ok, message) => {
  if (ok) console.log(`ok   ${message}`);
  else {
    console.log(`FAIL ${message}`);
    failures.push(message);
  }
};

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

/** Starts python3's http.server on www/ and resolves once it answers. */
async function startServer(port) {
  const server = spawn('python3', ['-m', 'http.server', String(port), '--bind', '127.0.0.1', '--directory', WWW], {
    stdio: ['ignore', 'ignore', 'pipe'],
  });
  let stderr = '';
  server.stderr.on('data', (d) => { stderr += d; });
  const deadline = Date.now() + SERVER_START_TIMEOUT_MS;
  while (Date.now() < deadline) {
    if (server.exitCode !== null) throw new Error(`http.server exited: ${stderr}`);
    try {
      const res = await fetch(`http://127.0.0.1:${port}/index.html`);
      if (res.ok) return server;
    } catch {
      // not listening yet
    }
    await new Promise((r) => setTimeout(r, 100));
  }
  server.kill();
  throw new Error(`http.server did not answer within ${SERVER_START_TIMEOUT_MS} ms`);
}

/** Pixel statistics of the main canvas, computed in the page on its backing store. */
function canvasStats(page) {
  return page.evaluate((spread) => {
    const c = document.getElementById('view');
    // Read through a copy, so the page's own context never reads back (Chromium warns when a
    // context without willReadFrequently is read repeatedly).
    const copy = document.createElement('canvas');
    copy.width = c.width;
    copy.height = c.height;
    const cc = copy.getContext('2d', { willReadFrequently: true });
    cc.drawImage(c, 0, 0);
    const { data } = cc.getImageData(0, 0, c.width, c.height);
    let coloured = 0;
    const bg = [data[0], data[1], data[2]];
    let nonBackground = 0;
    // Down-sampled copy for comparing two pictures: the mean of each 8×8 block's red+green+blue.
    const block = 8;
    const bw = Math.ceil(c.width / block);
    const bh = Math.ceil(c.height / block);
    const blocks = new Array(bw * bh).fill(0);
    for (let i = 0; i < data.length; i += 4) {
      const r = data[i], g = data[i + 1], b = data[i + 2];
      if (Math.max(r, g, b) - Math.min(r, g, b) > spread) coloured++;
      if (r !== bg[0] || g !== bg[1] || b !== bg[2]) nonBackground++;
      const p = i / 4;
      blocks[Math.floor(p / c.width / block) * bw + Math.floor((p % c.width) / block)] += r + g + b;
    }
    return {
      width: c.width,
      height: c.height,
      cssWidth: c.getBoundingClientRect().width,
      dpr: window.devicePixelRatio,
      coloured,
      nonBackground,
      blocks,
    };
  }, COLOURED_SPREAD);
}

async function main() {
  const wasm = join(WWW, 'pkg', 'dvf_bg.wasm');
  if (!existsSync(wasm)) throw new Error(`${wasm} is missing: run make build-wasm first`);
  mkdirSync(RESULTS, { recursive: true });

  const port = await freePort();
  const server = await startServer(port);
  let browser;
  try {
    browser = await chromium.launch({ executablePath: CHROMIUM, args: CHROMIUM_ARGS });
    const context = await browser.newContext({ viewport: VIEWPORT, deviceScaleFactor: DEVICE_SCALE_FACTOR });
    const page = await context.newPage();
    page.setDefaultTimeout(PAGE_TIMEOUT_MS);
    const messages = [];
    page.on('console', (m) => {
      if (m.type() === 'error' || m.type() === 'warning') messages.push(`console.${m.type()}: ${m.text()}`);
    });
    page.on('pageerror', (e) => messages.push(`page error: ${e.message}`));
    page.on('requestfailed', (r) => messages.push(`request failed: ${r.url()} ${r.failure()?.errorText}`));
    page.on('response', (r) => {
      if (r.status() >= 400) messages.push(`HTTP ${r.status()}: ${r.url()}`);
    });

    await page.goto(`http://127.0.0.1:${port}/`);
    await page.waitForSelector('body[data-preset]');
    const first = await page.evaluate(() => import('./pkg/dvf.js').then((m) => m.defaultPreset()));
    const shown = await page.getAttribute('body', 'data-preset');
    check(shown === first, `the page opens on the default preset (${shown})`);
    // Two animation frames: the draw requested on load has happened.
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    await page.screenshot({ path: join(RESULTS, 'default-preset.png') });

    const a = await canvasStats(page);
    check(a.dpr === DEVICE_SCALE_FACTOR && Math.abs(a.width - a.cssWidth * a.dpr) <= 1,
      `canvas backing store follows devicePixelRatio (${a.width} px for ${a.cssWidth} CSS px at ${a.dpr}×)`);
    check(a.coloured >= MIN_COLOURED_PIXELS, `default preset ${first} draws trails (${a.coloured} coloured pixels)`);
    check(a.nonBackground > a.width * a.height * 0.05, `canvas is not blank (${a.nonBackground} non-background pixels)`);
    const name = await page.textContent('#scenario-name');
    check(name.length > 0, `scenario name shown: "${name}"`);
    const rows = await page.locator('#robots tr').count();
    check(rows > 0, `report lists ${rows} robots`);
    check(await page.isHidden('#error'), 'no error banner');

    // Scrub to the start: robots move to their start poses, the picture changes.
    await page.locator('#time').fill('0');
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    const label = await page.textContent('#time-label');
    check(label.startsWith('t = 0.00 s'), `time slider scrubs to the start ("${label}")`);
    await page.screenshot({ path: join(RESULTS, 'default-preset-t0.png') });

    await page.selectOption('#preset', SECOND_PRESET);
    await page.waitForSelector(`body[data-preset="${SECOND_PRESET}"]`);
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    await page.screenshot({ path: join(RESULTS, 'second-preset.png') });
    const b = await canvasStats(page);
    const changed = a.blocks.filter((v, i) => Math.abs(v - b.blocks[i]) > 8 * 8 * 3 * 4).length / a.blocks.length;
    check(b.coloured >= MIN_COLOURED_PIXELS, `${SECOND_PRESET} draws trails (${b.coloured} coloured pixels)`);
    check(changed >= MIN_CHANGED_FRACTION, `switching preset changes the picture (${(changed * 100).toFixed(1)} % of blocks)`);

    // Every preset runs and draws; one screenshot each, for looking at.
    const names = await page.evaluate(() => import('./pkg/dvf.js').then((m) => m.presets().map((p) => p.name)));
    for (const preset of names) {
      await page.selectOption('#preset', preset);
      await page.waitForSelector(`body[data-preset="${preset}"]`);
      await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
      await page.screenshot({ path: join(RESULTS, `preset-${preset}.png`) });
      const s = await canvasStats(page);
      check(s.coloured >= MIN_COLOURED_PIXELS && (await page.isHidden('#error')),
        `preset ${preset} draws without error (${s.coloured} coloured pixels)`);
    }

    check(messages.length === 0, `no console errors or warnings, no page errors${messages.length ? `:\n  ${messages.join('\n  ')}` : ''}`);
  } finally {
    if (browser) await browser.close();
    server.kill();
  }
}

main()
  .catch((e) => {
    failures.push(e.stack ?? String(e));
    console.log(`FAIL ${e.stack ?? e}`);
  })
  .finally(() => {
    if (failures.length) {
      console.log(`\n${failures.length} failure(s)`);
      process.exitCode = 1;
    } else {
      console.log('\nall checks passed');
    }
  });
