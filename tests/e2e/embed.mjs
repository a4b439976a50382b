// End-to-end test of www/embed.html: two <dvf-playground> instances in running text, each
// with its own simulation (one draws integral curves, the other plays a two-robot swap).
// Checks that both draw, that they are independent (playing or dragging one leaves the other
// alone), the element API (load, scenario, play, pause, reset, step, worldToScreen, change
// event), that the declarations' `Params` (www/dvf-playground.d.ts) are the core's parameter
// table, and that nothing is logged to the console. Screenshots go to test-results/.
//
// Run: make test-e2e   (or: node tests/e2e/embed.mjs after make build-wasm)

import { readFileSync } from 'node:fs';
import {
  canvasStats,
  changedFraction,
  check,
  checkQuiet,
  frames,
  join,
  RESULTS,
  run,
  scenarioOf,
  WWW,
  waitLoaded,
} from './lib.mjs';

/** The TypeScript type of a parameter of each kind of the core's table (src/params.rs). */
const TYPE_OF_KIND = { number: 'number', optional: 'number | null', mode: 'Avoidance' };

/**
 * The fields of interface `name` in declarations `text`: `[{key, type, doc}]`, each with the
 * doc comment above it.
 */
function interfaceFields(text, name) {
  const body = text.match(new RegExp(`export interface ${name} \\{([\\s\\S]*?)\\n\\}`))?.[1] ?? '';
  return [...body.matchAll(/\/\*\*([\s\S]*?)\*\/\s*(\w+)\??: ([^;]+);/g)].map(([, doc, key, type]) => ({
    key,
    type: type.trim(),
    doc,
  }));
}

const VIEWPORT = { width: 1100, height: 900 };
const FIELD = '#field';
const SWAP = '#swap';

await run(async ({ base, newPage }) => {
  const page = await newPage({ viewport: VIEWPORT, deviceScaleFactor: 2 });
  await page.goto(`${base}/embed.html`);
  await waitLoaded(page, FIELD);
  await waitLoaded(page, SWAP);
  await page.screenshot({ path: join(RESULTS, 'embed.png'), fullPage: true });

  const field = await scenarioOf(page, FIELD);
  const swap = await scenarioOf(page, SWAP);
  check(
    field.robots.length === 1 && swap.robots.length === 2,
    'the two instances load their own scenario files (src attribute)',
  );
  const count = await page.locator('dvf-playground').count();
  check(count === 2, `the page embeds ${count} instances`);
  const toolbarHidden = await page.locator(`${FIELD} [data-id="add-robot"]`).isHidden();
  check(toolbarHidden, 'without the controls attribute the editing toolbar is hidden');

  // The curves instance draws purple integral curves; the swap instance plays on its own.
  const curves = await canvasStats(page, FIELD);
  check(curves.coloured > 5_000, `the first instance draws integral curves (${curves.coloured} coloured pixels)`);
  await page.waitForFunction((sel) => document.querySelector(sel).cache.time > 0.5, SWAP);
  const fieldTime = await page.evaluate((sel) => document.querySelector(sel).cache.time, FIELD);
  check(fieldTime === 0, 'autoplay plays the second instance only');

  // θ(0) changes the family of curves.
  const t0 = page.locator(`${FIELD} [data-id="theta0"]`);
  await t0.fill('-1.5708');
  await t0.press('Enter');
  await frames(page);
  const turned = await canvasStats(page, FIELD);
  check(
    changedFraction(curves, turned) > 0.02,
    `θ(0) = −π/2 turns the curves (${(changedFraction(curves, turned) * 100).toFixed(1)} % of blocks)`,
  );
  await page.screenshot({ path: join(RESULTS, 'embed-theta-minus-90.png'), fullPage: true });

  // The API: pause, reset, step(n), play; worldToScreen points at the robot; change events.
  await page.evaluate((sel) => {
    const el = document.querySelector(sel);
    el.pause();
    el.reset();
  }, SWAP);
  const stepped = await page.evaluate((sel) => {
    const el = document.querySelector(sel);
    el.step(100);
    return el.cache.time;
  }, SWAP);
  check(Math.abs(stepped - 1) < 1e-9, `step(100) advances 100 steps of 0.01 s (t = ${stepped})`);
  await page.evaluate((sel) => document.querySelector(sel).reset(), SWAP);
  await page.evaluate((sel) => {
    const el = document.querySelector(sel);
    window.changes = 0;
    el.addEventListener('change', () => {
      window.changes += 1;
    });
  }, SWAP);
  const robot = swap.robots[0].start;
  await page.locator(SWAP).scrollIntoViewIfNeeded();
  const at = await page.evaluate(
    ([sel, x, y]) => document.querySelector(sel).worldToScreen(x, y),
    [SWAP, robot[0], robot[1]],
  );
  const scroll = await page.evaluate(() => [window.scrollX, window.scrollY]);
  const before = await canvasStats(page, SWAP);
  const fieldBefore = await scenarioOf(page, FIELD);
  await page.mouse.move(at.x - scroll[0], at.y - scroll[1]);
  await page.mouse.down();
  for (let k = 1; k <= 10; k++) await page.mouse.move(at.x - scroll[0] + k, at.y - scroll[1] - 4 * k);
  await page.mouse.up();
  await frames(page);
  const dragged = await scenarioOf(page, SWAP);
  const after = await canvasStats(page, SWAP);
  check(
    dragged.robots[0].start[1] > robot[1] + 1,
    `worldToScreen finds robot 1 and a drag moves it (y ${robot[1]} → ${dragged.robots[0].start[1].toFixed(2)})`,
  );
  check(changedFraction(before, after) > 0.002, 'the drag changes the picture');
  check((await page.evaluate(() => window.changes)) === 1, 'one change event per drag');
  check(
    JSON.stringify(await scenarioOf(page, FIELD)) === JSON.stringify(fieldBefore),
    'the other instance is untouched',
  );

  // load(): a good scenario replaces the scene; a bad one throws the core's message and keeps it.
  const result = await page.evaluate((sel) => {
    const el = document.querySelector(sel);
    let error = '';
    try {
      el.load({ robots: [{ start: [0, 0, 0], goal: [5, 5, 0] }], dt: Number.NaN });
    } catch (e) {
      error = e.message;
    }
    const kept = el.scenario().robots.length;
    el.load({
      name: 'three',
      robots: [
        [0, 0],
        [5, 0],
        [0, 5],
      ].map(([x, y]) => ({ start: [x, y, 0], goal: [x + 10, y, 0] })),
    });
    el.play();
    return { error, kept, now: el.scenario().robots.length };
  }, SWAP);
  check(
    result.error.startsWith('dt:') && result.kept === 2 && result.now === 3,
    `load() rejects NaN with "${result.error}", keeps the scene, then loads three robots`,
  );
  await page.waitForFunction((sel) => document.querySelector(sel).cache.time > 0.3, SWAP);
  // Moved elsewhere in the page, an instance keeps its simulation and its single wiring.
  const moved = await page.evaluate((sel) => {
    const el = document.querySelector(sel);
    el.pause();
    const t = el.cache.time;
    const home = el.parentElement;
    document.body.append(el);
    home.prepend(el);
    window.changes = 0;
    el.shadowRoot.querySelector('[data-id="add-robot"]').click();
    return { t, after: el.cache.time, robots: el.scenario().robots.length, changes: window.changes };
  }, SWAP);
  check(
    moved.after === moved.t && moved.robots === 4 && moved.changes === 1,
    `a moved instance keeps its time (${moved.t.toFixed(2)} s) and adds one robot per click with one change event`,
  );
  await page.screenshot({ path: join(RESULTS, 'embed-after-api.png'), fullPage: true });

  // The declarations' Params are the core's table: the same keys, each of
  // the type of its kind, its unit in its doc comment.
  const table = await page.evaluate(() => import('./pkg/dvf.js').then((m) => m.parameters()));
  const declared = interfaceFields(readFileSync(join(WWW, 'dvf-playground.d.ts'), 'utf8'), 'Params');
  const byKey = new Map(declared.map((f) => [f.key, f]));
  const wrong = table.rows
    .filter((r) => {
      const f = byKey.get(r.name);
      return !f || f.type !== TYPE_OF_KIND[r.kind] || (r.unit && !f.doc.includes(`(${r.unit})`));
    })
    .map((r) => r.name);
  check(
    declared.length === table.rows.length && wrong.length === 0,
    `www/dvf-playground.d.ts declares Params as the core's table of ${table.rows.length} parameters (${declared.length} declared; wrong or missing: ${wrong.join(', ') || 'none'})`,
  );
  const avoidance =
    readFileSync(join(WWW, 'dvf-playground.d.ts'), 'utf8').match(/export type Avoidance =([^;]+);/)?.[1] ?? '';
  const modes = [...avoidance.matchAll(/'(\w+)'/g)].map((m) => m[1]);
  check(
    [...modes].sort().join() === [...table.modes].sort().join(),
    `the declared Avoidance modes are the core's (${modes.join(', ')})`,
  );
  checkQuiet(page, 'embed page');
});
