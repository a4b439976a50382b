// End-to-end tests of the main page as users load it: the RELEASE wasm package in www/pkg
// (`make build-wasm`), served by python3's http.server, driven in Debian's Chromium.
// Checks: the wasm module's compressed size; no import cycle among www/'s modules; no console
// error or warning; every module preloaded; high-DPI canvas; dragging a robot bends its
// predicted path (pixels and scenario); undo/redo; presets; parameters; keyboard; the URL
// fragment round trip; bad fragments; scenario names as text; exports (JSON, CSV, PNG) and
// import. Behaviour only: no time is compared with a limit (the figures and
// their budgets are bench-browser.mjs's). Everything it writes goes to test-results/ (the
// README's picture is picture.mjs's).
//
// One session of the main page, its checks in the order a person meets them, each building on
// the state the last one left (the drag that undo takes back, the edits the copied link must
// reopen); the pages it opens beside it (bad links, a hostile name, touch) are a few lines each.
//
// Run: make test-e2e   (or: node tests/e2e/smoke.mjs after make build-wasm)

import { readFileSync } from 'node:fs';
import { constants, gzipSync } from 'node:zlib';
import {
  canvasStats,
  changedFraction,
  check,
  checkQuiet,
  drag,
  EXAMPLE4,
  frames,
  importCycles,
  join,
  predictions,
  RESULTS,
  ROOT,
  run,
  scenarioOf,
  showReadmeScene,
  waitLoaded,
} from './lib.mjs';

const VIEWPORT = { width: 1280, height: 800 };
/** High-DPI on purpose: the canvas must size its backing store by devicePixelRatio. */
const DEVICE_SCALE_FACTOR = 2;
const SECOND_PRESET = 'example3-circle-swap';
/** Mouse moves in the drag of robot 1. */
const DRAG_MOVES = 60;
/** A drawn scene has at least this many coloured device pixels. */
const MIN_COLOURED_PIXELS = 2_000;
/**
 * A drawn scene of one robot (the teaching presets) has at least this many: its body, its goal
 * and its predicted path are about 550 at this viewport, against the grey field and grid.
 */
const MIN_COLOURED_PIXELS_ONE_ROBOT = 300;
/** A real change of the picture touches at least this fraction of 8×8 blocks. */
const MIN_CHANGED_FRACTION = 0.002;
const PG = 'dvf-playground';
/**
 * The wasm module's budget as a reader downloads it: gzip at level 9 (bytes), what a server
 * sends for `Content-Encoding: gzip`. Beside the simulator, the live model and the facade, it
 * leaves room for the planners to come and a QP solver for their barrier (clarabel, built alone
 * for wasm32, gzips to about 160 KB). The module's current size is in
 * docs/book/src/performance.md. A download of the whole budget takes about 1.5 s at 1.6 Mbit/s,
 * once; the browser caches it.
 */
const MAX_WASM_GZIP_BYTES = 300_000;
/** The gzip level the budget is measured at (zlib's best compression). */
const WASM_GZIP_LEVEL = constants.Z_BEST_COMPRESSION;

/** A locator inside the playground's shadow root (Playwright's CSS pierces open shadow roots). */
const part = (page, id) => page.locator(`${PG} [data-id="${id}"]`);

await run(async ({ base, newPage }) => {
  const wasm = readFileSync(join(ROOT, 'www', 'pkg', 'dvf_bg.wasm'));
  const gzipBytes = gzipSync(wasm, { level: WASM_GZIP_LEVEL }).length;
  console.log(`SIZE www/pkg/dvf_bg.wasm: ${wasm.length} bytes, ${gzipBytes} bytes gzipped (level ${WASM_GZIP_LEVEL})`);
  const cycles = importCycles();
  check(
    cycles.length === 0,
    `www/'s modules import no cycle (${cycles.map((c) => c.join(' → ')).join('; ') || 'none'})`,
  );
  check(
    gzipBytes <= MAX_WASM_GZIP_BYTES,
    `the release wasm module gzipped at level ${WASM_GZIP_LEVEL} is at most ${MAX_WASM_GZIP_BYTES} bytes (${gzipBytes})`,
  );
  const page = await newPage({ viewport: VIEWPORT, deviceScaleFactor: DEVICE_SCALE_FACTOR });
  await page.goto(`${base}/`);
  await waitLoaded(page);
  await page.waitForSelector('body[data-ready]');
  const defaultName = await page.evaluate(() => import('./pkg/dvf.js').then((m) => m.defaultPreset()));
  check(
    (await part(page, 'preset').inputValue()) === defaultName,
    `the page opens on the default preset (${defaultName})`,
  );
  await page.screenshot({ path: join(RESULTS, 'main-default.png') });

  // Every module of the page is in index.html's modulepreload list (fetched in parallel, none
  // discovered one import after another).
  const late = await page.evaluate(() => {
    const preloaded = new Set([...document.querySelectorAll('link[rel="modulepreload"]')].map((l) => l.href));
    return performance
      .getEntriesByType('resource')
      .filter((r) => r.name.endsWith('.js') && !r.name.endsWith('/main.js') && !preloaded.has(r.name))
      .map((r) => new URL(r.name).pathname);
  });
  check(late.length === 0, `index.html preloads every module (not preloaded: ${late.join(', ') || 'none'})`);
  const a = await canvasStats(page);
  check(
    a.dpr === DEVICE_SCALE_FACTOR && Math.abs(a.width - a.cssWidth * a.dpr) <= 1,
    `canvas backing store follows devicePixelRatio (${a.width} px for ${a.cssWidth} CSS px at ${a.dpr}×)`,
  );
  check(a.coloured >= MIN_COLOURED_PIXELS, `the scene is drawn (${a.coloured} coloured pixels)`);
  check(await part(page, 'message').isHidden(), 'no message shown');
  const clock = await part(page, 'clock').textContent();
  check(clock.startsWith('t = 0.00 s / 25.00 s'), `the time is shown ("${clock}")`);
  const legend = await page.locator(`${PG} [data-id="legend"] li`).count();
  check(legend >= 10, `the legend explains ${legend} marks`);

  // --- The prediction of the ten-robot example: it stops once every robot has converged,
  // and runs the whole scenario when no robot can (bench-browser.mjs times it). ---
  const predicted = await predictions(page, EXAMPLE4, 1, 0);
  check(
    predicted.samples >= 2 && predicted.end < 25 && predicted.fullEnd === 25,
    `the prediction stops once every robot has converged (t = ${predicted.end.toFixed(2)} s), and runs the whole run when asked to`,
  );

  // --- Drag robot 1 at t = 0: its start moves and its predicted path bends. ---
  const before = await scenarioOf(page);
  const predictedBefore = await page.evaluate((sel) => Array.from(document.querySelector(sel).cache.predicted), PG);
  const [sx, sy] = before.robots[0].start;
  const from = await page.evaluate(([sel, x, y]) => document.querySelector(sel).worldToScreen(x, y), [PG, sx, sy]);
  const scroll = await page.evaluate(() => [window.scrollX, window.scrollY]);
  const fx = from.x - scroll[0];
  const fy = from.y - scroll[1];
  // The simulation's whole scenario is read back once per drag, not once per pointer move.
  await page.evaluate((sel) => {
    const pg = document.querySelector(sel).pg;
    window.wholeScenario = { reads: 0, edits: 0 };
    for (const [name, count] of [
      ['scenario', 'reads'],
      ['edit', 'edits'],
    ]) {
      const call = pg[name];
      pg[name] = (...args) => {
        window.wholeScenario[count] += 1;
        return call.apply(pg, args);
      };
    }
  }, PG);
  const dragged = await drag(page, [fx, fy], DRAG_MOVES, [1.5, -1.2]);
  check(
    dragged.redraws >= 2,
    `the playground redraws while the pointer moves (${dragged.redraws} times for ${DRAG_MOVES} moves)`,
  );
  const whole = await page.evaluate(() => window.wholeScenario);
  check(
    whole.reads === 1 && whole.edits === 0,
    `a drag of ${DRAG_MOVES} moves reads the whole scenario back once (${whole.reads}) and replaces it never (${whole.edits})`,
  );
  await page.screenshot({ path: join(RESULTS, 'main-after-drag.png') });
  const after = await scenarioOf(page);
  const b = await canvasStats(page);
  const predictedAfter = await page.evaluate((sel) => Array.from(document.querySelector(sel).cache.predicted), PG);
  // The pointer went right and up on screen: right and up in the world (y up).
  check(
    after.robots[0].start[0] > sx && after.robots[0].start[1] > sy,
    `dragging robot 1 moves its start in scenario() (${before.robots[0].start.slice(0, 2).map((v) => v.toFixed(1))} → ${after.robots[0].start.slice(0, 2).map((v) => v.toFixed(1))})`,
  );
  check(
    JSON.stringify(after.robots.slice(1)) === JSON.stringify(before.robots.slice(1)),
    'the other robots are unchanged',
  );
  const n = before.robots.length;
  const samples = predictedBefore.length / n / 3;
  const lastOf = (arr, i) => arr.slice((i * samples + samples - 10) * 3, (i * samples + samples - 10) * 3 + 2);
  check(
    predictedAfter[0] !== predictedBefore[0] &&
      JSON.stringify(lastOf(predictedAfter, 0)) !== JSON.stringify(lastOf(predictedBefore, 0)),
    "robot 1's predicted path starts at the new place and runs differently",
  );
  const changed = changedFraction(a, b);
  check(changed >= MIN_CHANGED_FRACTION, `the drag changes the picture (${(changed * 100).toFixed(2)} % of blocks)`);
  const hash = await page.evaluate(() => location.hash);
  check(hash.startsWith('#s='), `the address holds the edited scenario (${hash.length} characters)`);

  // --- Undo and redo. ---
  await part(page, 'undo').click();
  check(
    JSON.stringify((await scenarioOf(page)).robots[0]) === JSON.stringify(before.robots[0]),
    'undo brings the start back',
  );
  await part(page, 'redo').click();
  check(
    JSON.stringify((await scenarioOf(page)).robots[0]) === JSON.stringify(after.robots[0]),
    'redo applies the drag again',
  );

  // --- Handles: a selected robot's heading handle turns it; an obstacle's handles resize it. ---
  const screenOf = (x, y) =>
    page.evaluate(
      ([sel, wx, wy]) => {
        const p = document.querySelector(sel).worldToScreen(wx, wy);
        return [p.x - window.scrollX, p.y - window.scrollY];
      },
      [PG, x, y],
    );
  const dragFromTo = async ([x0, y0], [x1, y1]) => {
    await page.mouse.move(x0, y0);
    await page.mouse.down();
    for (let k = 1; k <= 8; k++) await page.mouse.move(x0 + ((x1 - x0) * k) / 8, y0 + ((y1 - y0) * k) / 8);
    await page.mouse.up();
    await frames(page);
  };
  const r2 = (await scenarioOf(page)).robots[1].start;
  const [bx, by] = await screenOf(r2[0], r2[1]);
  await page.mouse.click(bx, by);
  await frames(page);
  await page.screenshot({ path: join(RESULTS, 'main-robot-selected.png') });
  // The handle sits 30 CSS px ahead of the robot (heading 0: to the right); drag it upwards.
  await dragFromTo([bx + 30, by], [bx, by - 40]);
  const turned = (await scenarioOf(page)).robots[1].start[2];
  check(Math.abs(turned - Math.PI / 2) < 0.2, `the heading handle turns robot 2 to ${turned.toFixed(2)} rad (≈ π/2)`);
  const ob = (await scenarioOf(page)).obstacles[0];
  const [ox, oy] = await screenOf(ob.center[0], ob.center[1]);
  await page.mouse.click(ox, oy);
  await frames(page);
  const [ex] = await screenOf(ob.center[0] + ob.radius, ob.center[1]);
  await dragFromTo([ex, oy], [ex + 15, oy]);
  const [ix] = await screenOf(ob.center[0] + ob.influence, ob.center[1]);
  await dragFromTo([ix, oy], [ix + 30, oy]);
  const resized = (await scenarioOf(page)).obstacles[0];
  check(
    resized.radius > ob.radius + 1 && resized.influence > ob.influence + 2 && resized.center[0] === ob.center[0],
    `the obstacle's handles resize r_o ${ob.radius} → ${resized.radius.toFixed(2)} and R_o ${ob.influence} → ${resized.influence.toFixed(2)}`,
  );
  await page.screenshot({ path: join(RESULTS, 'main-obstacle-resized.png') });

  // --- Pan and zoom: the wheel zooms about the pointer, dragging the background pans. ---
  const camera0 = await page.evaluate((sel) => ({ ...document.querySelector(sel).camera }), PG);
  const [cx, cy] = await screenOf(-120, -70);
  await page.mouse.move(cx, cy);
  await page.mouse.wheel(0, -300);
  await frames(page);
  const camera1 = await page.evaluate((sel) => ({ ...document.querySelector(sel).camera }), PG);
  await dragFromTo([cx, cy], [cx + 80, cy]);
  const camera2 = await page.evaluate((sel) => ({ ...document.querySelector(sel).camera }), PG);
  check(
    camera1.scale > camera0.scale && camera2.cx < camera1.cx && JSON.stringify(await scenarioOf(page)).length > 0,
    `the wheel zooms (${camera0.scale.toFixed(2)} → ${camera1.scale.toFixed(2)} px/m) and dragging the background pans`,
  );
  await page.screenshot({ path: join(RESULTS, 'main-zoomed.png') });
  await page.keyboard.press('f');
  for (let k = 0; k < 3; k++) await part(page, 'undo').click();
  check(
    JSON.stringify(await scenarioOf(page)) === JSON.stringify(after),
    'three undos take back the resizes and the turn',
  );

  // --- The URL round trip: the copied address opens the same scene in a new page. ---
  const url = await page.evaluate(() => location.href);
  const copy = await newPage({ viewport: VIEWPORT });
  await copy.goto(url);
  await waitLoaded(copy);
  await copy.waitForSelector('body[data-ready]');
  const reopened = await scenarioOf(copy);
  check(
    JSON.stringify(reopened) === JSON.stringify(await scenarioOf(page)),
    'a copied link reopens exactly the same scenario',
  );
  checkQuiet(copy, 'reopened page');

  // --- Bad fragments: a message, the default scene, no console error. ---
  const defaultScenario = await page.evaluate(
    (name) => import('./pkg/dvf.js').then((m) => m.presetScenario(name)),
    defaultName,
  );
  const badLinks = [
    ['truncated JSON', `#s=${encodeURIComponent('{"robots":[{"start":[0,0,0]')}`, 'not valid JSON'],
    ['bad percent-encoding', '#s=%E0%A4%A', 'percent-encoded'],
    [
      'a negative radius',
      `#s=${encodeURIComponent('{"robots":[{"start":[0,0,0],"goal":[5,5,0]}],"obstacles":[{"center":[9,9],"radius":-1,"influence":2}]}')}`,
      "obstacle 1's radius",
    ],
    ['an oversized fragment', `#s=${'x'.repeat(70 * 1024)}`, 'at most'],
    ['an unknown preset', '#no-such-preset', 'no preset named'],
  ];
  for (const [what, fragment, expected] of badLinks) {
    const bad = await newPage({ viewport: VIEWPORT });
    await bad.goto(`${base}/${fragment}`);
    await waitLoaded(bad);
    await bad.waitForSelector('body[data-ready]');
    const message = await part(bad, 'message').textContent();
    const shown = await scenarioOf(bad);
    check(
      message.includes(expected) && JSON.stringify(shown) === JSON.stringify(defaultScenario),
      `a link with ${what} shows "${message.slice(0, 90)}…" and the default scene`,
    );
    if (what === 'truncated JSON') await bad.screenshot({ path: join(RESULTS, 'main-bad-link.png') });
    await bad.context().close();
  }

  // --- A scenario name is text, never HTML. ---
  const hostile = '<img src=x onerror="window.pwned=1">Robots & <b>bold</b>';
  const xss = await newPage({ viewport: VIEWPORT });
  await xss.goto(
    `${base}/#s=${encodeURIComponent(JSON.stringify({ name: hostile, robots: [{ start: [0, 0, 0], goal: [10, 5, 1] }] }))}`,
  );
  await waitLoaded(xss);
  await xss.waitForSelector('body[data-ready]');
  const title = await part(xss, 'title').textContent();
  const imgs = await xss.evaluate(
    (sel) => document.querySelector(sel).shadowRoot.querySelectorAll('img, b').length,
    PG,
  );
  check(
    title === hostile && imgs === 0 && !(await xss.evaluate(() => window.pwned)),
    'a scenario name from a link is shown as text',
  );
  checkQuiet(xss, 'page with a hostile name');
  await xss.context().close();

  // --- Presets: the menu switches the scene; every preset draws. ---
  await part(page, 'preset').selectOption(SECOND_PRESET);
  await frames(page);
  const c = await canvasStats(page);
  check((await scenarioOf(page)).name.includes('antipodal'), `the preset menu loads ${SECOND_PRESET}`);
  check(
    changedFraction(b, c) > 0.01,
    `switching preset changes the picture (${(changedFraction(b, c) * 100).toFixed(1)} % of blocks)`,
  );
  const names = await page.evaluate(() => import('./pkg/dvf.js').then((m) => m.presets().map((p) => p.name)));
  for (const preset of names) {
    await part(page, 'preset').selectOption(preset);
    await frames(page);
    await page.screenshot({ path: join(RESULTS, `preset-${preset}.png`) });
    const s = await canvasStats(page);
    const robots = await page.evaluate((sel) => document.querySelector(sel).robotCount, PG);
    const least = robots === 1 ? MIN_COLOURED_PIXELS_ONE_ROBOT : MIN_COLOURED_PIXELS;
    check(
      s.coloured >= least && (await part(page, 'message').isHidden()),
      `preset ${preset} draws without a message (${s.coloured} coloured pixels)`,
    );
    check(await part(page, 'crowd-box').isHidden(), `preset ${preset}: the crowd's N box is hidden`);
  }

  // --- The crowd: N in the page, the link names it, a bad N is refused, an edit unnames it. ---
  await part(page, 'preset').selectOption('crowd');
  await page.waitForFunction((sel) => document.querySelector(sel).presetName() === 'crowd-1000', PG);
  check(await part(page, 'crowd-box').isVisible(), 'choosing the crowd shows its N box (1,000 robots by default)');
  await part(page, 'crowd-n').fill('2500');
  await part(page, 'crowd-n').dispatchEvent('change');
  await frames(page);
  const crowd = await page.evaluate((sel) => {
    const el = document.querySelector(sel);
    return { robots: el.scenario().robots.length, hash: location.hash, predicted: el.cache.predictedSamples };
  }, PG);
  check(
    crowd.robots === 2500 && crowd.hash === '#crowd-2500' && crowd.predicted === 0,
    `N = 2500 loads a crowd of ${crowd.robots}, the address is ${crowd.hash}, no predicted paths (${crowd.predicted} samples)`,
  );
  await page.screenshot({ path: join(RESULTS, 'main-crowd-2500.png') });
  const crowdPicture = await canvasStats(page);
  check(crowdPicture.coloured >= MIN_COLOURED_PIXELS, `the crowd draws (${crowdPicture.coloured} coloured pixels)`);
  for (const bad of ['0', '10001', '2.5']) {
    await part(page, 'crowd-n').fill(bad);
    await part(page, 'crowd-n').dispatchEvent('change');
    const msg = await part(page, 'message').textContent();
    const kept = await page.evaluate((sel) => document.querySelector(sel).scenario().robots.length, PG);
    check(
      msg.includes('N must be a whole number from 1 to 10000') && kept === 2500,
      `N = ${bad} is refused with a message and the crowd of 2500 stays`,
    );
  }
  await part(page, 'add-robot').click();
  await frames(page);
  const edited = await page.evaluate((sel) => {
    const el = document.querySelector(sel);
    return { name: el.presetName(), robots: el.scenario().robots.length, hash: location.hash.slice(0, 3) };
  }, PG);
  check(
    edited.name === null &&
      edited.robots === 2501 &&
      (await part(page, 'preset').inputValue()) === '' &&
      edited.hash === '',
    `adding a robot makes the crowd an edited scene (menu "(edited or imported)", ${edited.robots} robots, no fragment: the JSON is longer than a link may be)`,
  );
  await part(page, 'undo').click();
  await part(page, 'preset').selectOption(SECOND_PRESET);

  // --- Parameters: a bad value shows the core's message in the panel's names and keeps the
  // scenario's value; the typed text stays for the user to fix. ---
  const kv = page.locator(`${PG} input[name="k_v"]`);
  await kv.fill('-1');
  await kv.press('Enter');
  await kv.blur();
  const paramError = await page.locator(`${PG} [data-id="params"] .param-error`).textContent();
  check(
    paramError.startsWith('k_v: must be positive') &&
      (await scenarioOf(page)).params.k_v === 1 &&
      (await kv.inputValue()) === '-1',
    `k_v = -1 is refused with "${paramError}", the scenario keeps 1 and the field the typed text`,
  );
  await kv.fill('1.5');
  await kv.press('Enter');
  check(
    (await scenarioOf(page)).params.k_v === 1.5 &&
      (await page.locator(`${PG} [data-id="params"] .param-error`).isHidden()),
    'k_v = 1.5 applies',
  );
  const vmax = page.locator(`${PG} input[name="v_max"]`);
  await vmax.fill('3');
  await vmax.press('Enter');
  check((await scenarioOf(page)).params.v_max === 3, 'the speed saturation v_max can be set');
  await vmax.fill('');
  await vmax.press('Enter');
  check((await scenarioOf(page)).params.v_max === null, 'an empty v_max removes the saturation');

  // --- Keyboard: the canvas takes focus and plays, steps and resets from keys. ---
  await part(page, 'preset').selectOption(SECOND_PRESET);
  await part(page, 'canvas').focus();
  await page.keyboard.press('s');
  const afterStep = await page.evaluate((sel) => document.querySelector(sel).cache.time, PG);
  await page.keyboard.press(' ');
  await page.waitForFunction((sel) => document.querySelector(sel).cache.time > 1, PG);
  await page.keyboard.press(' ');
  await frames(page);
  await page.screenshot({ path: join(RESULTS, 'main-playing.png') });
  const playedTo = await page.evaluate((sel) => document.querySelector(sel).cache.time, PG);
  const trail = await page.evaluate((sel) => {
    const el = document.querySelector(sel);
    const view = el.trailsView(); // the ring, read in place in wasm memory
    const cap = el.cache.trailCapacity;
    const newest = (el.cache.trailHead - 1 + cap) % cap;
    return {
      len: el.cache.trailLens[0],
      same: view[newest * 3] === el.cache.poses[0] && view[newest * 3 + 1] === el.cache.poses[1],
    };
  }, PG);
  check(
    trail.len > 10 && trail.same,
    `playing fills robot 1's trail (${trail.len} samples), its newest sample the pose now`,
  );
  await page.keyboard.press('r');
  const resetTo = await page.evaluate((sel) => document.querySelector(sel).cache.time, PG);
  check(
    afterStep > 0 && playedTo > 1 && resetTo === 0,
    `keys S, Space and R step (t = ${afterStep}), play (t = ${playedTo.toFixed(2)}) and reset`,
  );
  const presetStart = (
    await page.evaluate((n) => import('./pkg/dvf.js').then((m) => m.presetScenario(n)), SECOND_PRESET)
  ).robots[0].start;
  await page.keyboard.press(']');
  await page.keyboard.press('ArrowUp');
  const moved = await scenarioOf(page);
  check(
    moved.robots[0].start[1] > presetStart[1] && moved.robots[0].start[0] === presetStart[0],
    `] selects robot 1 and ArrowUp moves its start up (${presetStart[1].toFixed(2)} → ${moved.robots[0].start[1].toFixed(2)})`,
  );
  await page.keyboard.press('a');
  check((await scenarioOf(page)).robots.length === moved.robots.length + 1, 'key A adds a robot');
  await page.keyboard.press('Delete');
  check((await scenarioOf(page)).robots.length === moved.robots.length, 'Delete removes the selected robot');
  const focusOutline = await part(page, 'canvas').evaluate((el) => getComputedStyle(el).outlineStyle);
  check(focusOutline !== 'none', `the focused canvas shows a focus outline (${focusOutline})`);

  // --- Exports: scenario JSON, trajectories CSV, canvas PNG. ---
  await part(page, 'preset').selectOption(EXAMPLE4);
  const current = await scenarioOf(page);
  const [jsonDownload] = await Promise.all([page.waitForEvent('download'), part(page, 'export-json').click()]);
  const jsonText = readFileSync(await jsonDownload.path(), 'utf8');
  const checked = await page.evaluate(
    (text) =>
      import('./pkg/dvf.js').then((m) => {
        try {
          return { ok: true, s: m.checkScenario(text) };
        } catch (e) {
          return { ok: false, error: e.message };
        }
      }),
    jsonText,
  );
  check(
    checked.ok && JSON.stringify(checked.s) === JSON.stringify(current),
    `the exported JSON (${jsonDownload.suggestedFilename()}) passes the crate's checks and is the scenario shown`,
  );
  const [csvDownload] = await Promise.all([page.waitForEvent('download'), part(page, 'export-csv').click()]);
  const csv = readFileSync(await csvDownload.path(), 'utf8')
    .trim()
    .split('\n');
  // The command line's format (src/bin/dvf.rs, write_csv): a row per robot every dt, and the
  // run's end where `Run` (the run `dvf simulate` makes) ends it, within 1e-9 m (the same
  // simulation; the bound only allows for a different order of summation).
  const expected = await page.evaluate(
    (s) =>
      import('./pkg/dvf.js').then((m) => {
        const r = new m.Run(s);
        const tr = r.trajectories();
        const last = (r.sampleCount - 1) * 6;
        const ends = [];
        for (let i = 0; i < r.robotCount; i++)
          ends.push([tr[i * r.sampleCount * 6 + last + 1], tr[i * r.sampleCount * 6 + last + 2]]);
        const rows = (Math.round(s.duration / s.dt) + 1) * r.robotCount;
        r.free();
        return { rows, ends };
      }),
    current,
  );
  const cols = csv
    .slice(1)
    .every((line) => line.split(',').length === 7 && line.split(',').every((v) => Number.isFinite(Number(v))));
  const lastRows = csv.slice(-current.robots.length).map((line) => line.split(',').map(Number));
  const endMiss = Math.max(
    ...lastRows.map(([, i, x, y]) => Math.hypot(x - expected.ends[i][0], y - expected.ends[i][1])),
  );
  check(
    csv[0] === 't,robot,x,y,theta,v,omega' && csv.length - 1 === expected.rows && cols && endMiss <= 1e-9,
    `the CSV has the command line's header and ${csv.length - 1} rows of 7 numbers (expected ${expected.rows}), ending where the run ends (${endMiss.toExponential(1)} m)`,
  );
  const [pngDownload] = await Promise.all([page.waitForEvent('download'), part(page, 'export-png').click()]);
  const png = readFileSync(await pngDownload.path());
  const signature = [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a].every((v, i) => png[i] === v);
  const pngWidth = png.readUInt32BE(16);
  check(
    signature && pngWidth === a.width,
    `the PNG has the PNG signature and the canvas' ${pngWidth} device pixels of width (${png.length} bytes)`,
  );

  // --- Import: a bad file shows a message and keeps the scene; a good one loads. ---
  const shownBefore = await scenarioOf(page);
  await part(page, 'import-file').setInputFiles({
    name: 'broken.json',
    mimeType: 'application/json',
    buffer: Buffer.from('{"robots": [{"start": [0, 0, 0], "goal": [1, 2]}]}'),
  });
  await page.waitForFunction(
    (sel) => !document.querySelector(sel).shadowRoot.querySelector('[data-id="message"]').hidden,
    PG,
  );
  const importMessage = await part(page, 'message').textContent();
  check(
    importMessage.includes("robot 1's goal") && JSON.stringify(await scenarioOf(page)) === JSON.stringify(shownBefore),
    `a bad import shows "${importMessage}" and keeps the scene`,
  );
  await part(page, 'import-file').setInputFiles({
    name: 'two.json',
    mimeType: 'application/json',
    buffer: Buffer.from(readFileSync(join(ROOT, 'www', 'scenarios', 'two-robot-swap.json'))),
  });
  await page.waitForFunction((sel) => document.querySelector(sel).scenario().robots.length === 2, PG);
  check(await part(page, 'message').isHidden(), 'a good import loads the file and clears the message');

  // --- The canvas follows the window, and two fingers pinch-zoom (real touch input). ---
  await page.setViewportSize({ width: 900, height: 700 });
  await page.waitForFunction(
    ([sel, w]) => {
      const c = document.querySelector(sel).shadowRoot.querySelector('[data-id="canvas"]');
      return c.width !== w && Math.abs(c.width - c.clientWidth * devicePixelRatio) <= 1;
    },
    [PG, a.width],
  );
  const small = await canvasStats(page);
  check(small.width < a.width, `the canvas follows a smaller window (${a.width} → ${small.width} device px wide)`);
  await page.screenshot({ path: join(RESULTS, 'main-900x700.png') });
  await page.setViewportSize(VIEWPORT);
  const touch = await newPage({ viewport: VIEWPORT, hasTouch: true });
  await touch.goto(`${base}/`);
  await waitLoaded(touch);
  const cdp = await touch.context().newCDPSession(touch);
  const box = await touch.locator(`${PG} [data-id="canvas"]`).boundingBox();
  const mx = box.x + box.width * 0.3;
  const my = box.y + box.height * 0.85;
  const scale0 = await touch.evaluate((sel) => {
    const el = document.querySelector(sel);
    el.view();
    return el.camera.scale;
  }, PG);
  const fingers = (d) => [
    { x: mx - d, y: my, id: 1 },
    { x: mx + d, y: my, id: 2 },
  ];
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: fingers(20) });
  for (let d = 25; d <= 80; d += 5)
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: fingers(d) });
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  await frames(touch);
  const scale1 = await touch.evaluate((sel) => document.querySelector(sel).camera.scale, PG);
  check(
    scale1 > scale0 * 3,
    `a two-finger pinch zooms in (${scale0.toFixed(2)} → ${scale1.toFixed(2)} px/m) without moving anything`,
  );
  const untouched = await scenarioOf(touch);
  check(JSON.stringify(untouched) === JSON.stringify(defaultScenario), 'the pinch left the scenario alone');
  checkQuiet(touch, 'touch page');
  await touch.context().close();

  checkQuiet(page, 'main page');

  // --- The README's picture (picture.mjs writes it to docs/): draws without a message. ---
  const shot = await newPage({ viewport: VIEWPORT, deviceScaleFactor: 1 });
  await shot.goto(`${base}/`);
  await waitLoaded(shot);
  await showReadmeScene(shot);
  await shot.screenshot({ path: join(RESULTS, 'readme-playground.png') });
  checkQuiet(shot, 'README screenshot page');
});
