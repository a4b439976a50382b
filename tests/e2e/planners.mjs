// End-to-end tests of the playground's planner menu and compare mode: the release package,
// served, in Chromium. The menu lists the planners and sets the scenario's `planner`, which
// the link, the exported JSON and the element's `planner` attribute carry; the compare mode
// draws a second planner's run over the scene and shows both runs' figures in one table, equal
// to the command line's (tests/data/compare-example3-circle-swap.json, its `made_by` says how
// it was written); a drag runs both again. Screenshots go to test-results/ (planners-*.png).
//
// Run: make test-e2e   (or: node tests/e2e/planners.mjs after make build-wasm)

import { readFileSync } from 'node:fs';
import * as lib from './lib.mjs';
import { check, checkQuiet, frames, join, ROOT, RESULTS, run, scenarioOf, waitLoaded } from './lib.mjs';

const PG = 'dvf-playground';
const DESKTOP = { width: 1280, height: 800 };
const PHONE = { width: 390, height: 844 };
const SCENE = 'example3-circle-swap';
/** `dvf simulate`'s reports of SCENE with dvf and dvf-paper, and their path lengths. */
const REFERENCE = JSON.parse(readFileSync(join(ROOT, 'tests', 'data', `compare-${SCENE}.json`), 'utf8'));

const part = (page, id, sel = PG) => page.locator(`${sel} [data-id="${id}"]`);

async function openMain(newPage, fragment, viewport = DESKTOP) {
  const page = await newPage({ viewport });
  await page.goto(fragment);
  await waitLoaded(page);
  await page.waitForSelector('body[data-ready]');
  return page;
}

/** A copy of the live run's predicted poses (x, y, θ of every robot, from now on). */
const predicted = (page) => page.evaluate((s) => Array.from(document.querySelector(s).cache.predicted), PG);

/** The compare table's cells as {planner: {metric: value}} (null for none), once it is ready. */
async function tableValues(page) {
  await page.waitForSelector(`${PG} [data-id="compare-results"][data-ready]`);
  return page.evaluate((s) => {
    const out = {};
    for (const td of document.querySelector(s).shadowRoot.querySelectorAll('[data-id="compare-table"] td')) {
      out[td.dataset.planner] ??= {};
      out[td.dataset.planner][td.dataset.metric] = td.dataset.value === '' ? null : Number(td.dataset.value);
    }
    return out;
  }, PG);
}

/** The figures of a reference run, as the table names them (see www/panels/compare-table.js). */
function expected({ report, path_length }) {
  const arrived = report.robots.filter((r) => r.converged_at != null);
  return {
    arrivals: arrived.length,
    last_arrival: arrived.length === report.robots.length ? Math.max(...arrived.map((r) => r.converged_at)) : null,
    path_length,
    min_pair: report.min_pair_distance,
    min_clearance: report.min_obstacle_clearance,
    violations: report.violations,
  };
}

async function section(what, body) {
  try {
    await body();
  } catch (e) {
    check(false, `${what}: ${e.stack ?? e}`);
  }
}

await run(async ({ base, newPage }) => {
  // ---- The menu: the planners listed, a choice changes the run, the link and the file keep it.
  await section('menu', async () => {
    const page = await openMain(newPage, `${base}/#${SCENE}`);
    const names = await page.evaluate(
      (s) => [...document.querySelector(s).shadowRoot.querySelector('[data-id="planner"]').options].map((o) => o.value),
      PG,
    );
    check(
      names[0] === 'dvf' && names.includes('dvf-paper'),
      `the planner menu lists the planners, dvf first (${names.join(', ')})`,
    );
    const before = await predicted(page);
    await part(page, 'planner').selectOption('dvf-paper');
    await page.waitForFunction((s) => document.querySelector(s).scenario().planner === 'dvf-paper', PG);
    await frames(page);
    const after = await predicted(page);
    // The predictions stop once every robot has arrived: dvf's is shorter than dvf-paper's.
    const moved = before.length !== after.length || before.some((v, i) => Math.abs(v - after[i]) > 1e-6);
    check(moved, "choosing dvf-paper sets the scenario's planner and changes the predicted paths");
    await page.waitForFunction(() => decodeURIComponent(location.hash).includes('"planner":"dvf-paper"'));
    const link = page.url();
    const [download] = await Promise.all([page.waitForEvent('download'), part(page, 'export-json').click()]);
    const exported = JSON.parse(readFileSync(await download.path(), 'utf8'));
    check(exported.planner === 'dvf-paper', 'the exported scenario JSON names the planner');
    await page.keyboard.press('Control+z');
    await page.waitForFunction((s) => (document.querySelector(s).scenario().planner ?? 'dvf') === 'dvf', PG);
    check((await part(page, 'planner').inputValue()) === 'dvf', 'undo takes the planner back, and the menu shows it');
    checkQuiet(page, 'menu');
    await page.context().close();

    const again = await openMain(newPage, link);
    const planner = (await scenarioOf(again)).planner;
    const shown = await part(again, 'planner').inputValue();
    check(planner === 'dvf-paper' && shown === 'dvf-paper', 'the link opens the scene with its planner, in the menu');
    checkQuiet(again, 'the link');
    await again.context().close();
  });

  // ---- The element's `planner` attribute, good and bad.
  await section('attribute', async () => {
    const page = await newPage({ viewport: DESKTOP });
    await page.goto(`${base}/embed.html`);
    await page.evaluate((scene) => {
      document.body.insertAdjacentHTML(
        'beforeend',
        `<dvf-playground id="a" preset="${scene}" planner="dvf-paper" controls></dvf-playground>` +
          `<dvf-playground id="b" preset="${scene}" planner="rrt" controls></dvf-playground>`,
      );
    }, SCENE);
    await waitLoaded(page, '#a');
    await waitLoaded(page, '#b');
    const a = await page.evaluate(() => {
      const el = document.querySelector('#a');
      return { planner: el.scenario().planner, undo: el.shadowRoot.querySelector('[data-id="undo"]').disabled };
    });
    check(a.planner === 'dvf-paper' && a.undo, 'planner="dvf-paper" sets the loaded scene\'s planner, not as an undo');
    const b = await page.evaluate(() => {
      const el = document.querySelector('#b');
      return {
        planner: el.scenario().planner ?? 'dvf',
        message: el.shadowRoot.querySelector('[data-id="message-text"]').textContent,
      };
    });
    check(
      b.planner === 'dvf' && b.message.startsWith('planner: unknown planner "rrt"') && b.message.includes('dvf-paper'),
      `an unknown planner attribute keeps the scene's planner and says so (${b.message})`,
    );
    await page.evaluate(() => document.querySelector('#b').setAttribute('planner', 'dvf-paper'));
    const changed = await page.evaluate(() => document.querySelector('#b').scenario().planner);
    check(changed === 'dvf-paper', 'changing the attribute sets the planner');
    checkQuiet(page, 'attribute');
    await page.context().close();
  });

  // ---- Compare mode: two runs drawn, one table equal to the command line's, a drag runs both.
  await section('compare', async () => {
    const page = await openMain(newPage, `${base}/#${SCENE}`);
    const plain = await lib.canvasStats(page);
    await part(page, 'compare').selectOption('dvf-paper');
    const values = await tableValues(page);
    await frames(page);
    const drawn = lib.changedFraction(plain, await lib.canvasStats(page));
    const legend = await part(page, 'compare-legend').textContent();
    check(
      drawn > 0.002 &&
        (await part(page, 'compare-legend').isVisible()) &&
        /dvf: live/.test(legend) &&
        /dvf-paper/.test(legend),
      `compare mode draws the second run (${(drawn * 100).toFixed(1)} % of blocks) and the legend names both (${legend})`,
    );
    for (const ref of REFERENCE.runs) {
      const want = expected(ref);
      const got = values[ref.planner] ?? {};
      // The same sums in the same order as the reference's: the path length to 1e-12 relative
      // (the reference parsed back from the CSV's shortest decimals is the same f64).
      const same = Object.entries(want).every(([k, v]) =>
        k === 'path_length' ? Math.abs(got[k] - v) <= 1e-12 * v : got[k] === v,
      );
      check(same, `the table's ${ref.planner} column equals dvf simulate's (${JSON.stringify(got)})`);
    }
    const exact = await page.evaluate(
      (s) => document.querySelector(s).shadowRoot.querySelector('td[data-metric="path_length"]').textContent,
      PG,
    );
    check(!exact.startsWith('≈'), `a run kept at every step shows its path length as it is (${exact})`);
    await page.screenshot({ path: join(RESULTS, 'planners-compare-desktop.png') });
    const [svg] = await Promise.all([page.waitForEvent('download'), part(page, 'export-svg').click()]);
    const svgText = readFileSync(await svg.path(), 'utf8');
    check(/#ea580c/i.test(svgText), 'the SVG export draws the compared run too');

    const state = await page.evaluate((s) => document.querySelector(s).viewState().compare, PG);
    await page.waitForFunction(() => location.hash.includes('&compare=dvf-paper'));
    check(state === 'dvf-paper', 'viewState() and the link name the compared planner');
    const link = page.url();

    // Robot 1's start dragged: both runs again.
    const goal = (await scenarioOf(page)).robots[0].start;
    const at = await page.evaluate(
      ([s, x, y]) => {
        const p = document.querySelector(s).worldToScreen(x, y);
        return [p.x - window.scrollX, p.y - window.scrollY];
      },
      [PG, goal[0], goal[1]],
    );
    await lib.drag(page, at, 10, [0, 6]);
    await page.waitForFunction(
      ([s, old]) => {
        const td = document
          .querySelector(s)
          .shadowRoot.querySelector(
            '[data-id="compare-results"][data-ready] td[data-metric="path_length"][data-planner="dvf-paper"]',
          );
        return td && Number(td.dataset.value) !== old;
      },
      [PG, values['dvf-paper'].path_length],
    );
    check(true, 'a dragged robot runs both planners again (the compared path length changes)');
    checkQuiet(page, 'compare');
    await page.context().close();

    const again = await openMain(newPage, link);
    await tableValues(again);
    check((await part(again, 'compare').inputValue()) === 'dvf-paper', 'the link opens the compare mode');
    await part(again, 'compare').selectOption('');
    await frames(again);
    check(await part(again, 'compare-results').isHidden(), 'compare off hides the table and the legend');
    checkQuiet(again, 'compare link');
    await again.context().close();

    // A run of more steps than the samples it keeps (src/wasm/run.rs): its path length is marked.
    const long = await openMain(newPage, `${base}/#table2-obstacles&compare=dvf-paper`);
    await tableValues(long);
    const cell = (page) =>
      page.evaluate(
        (s) =>
          document.querySelector(s).shadowRoot.querySelector('td[data-metric="path_length"][data-planner="dvf-paper"]')
            .textContent,
        PG,
      );
    check((await cell(long)).startsWith('≈ '), `a sampled path length is marked approximate (${await cell(long)})`);
    checkQuiet(long, 'long run');
    await long.context().close();

    const crowd = await openMain(newPage, `${base}/#crowd-200&compare=dvf-paper`);
    const note = await part(crowd, 'compare-results').textContent();
    check(
      /up to 100 robots; this one has 200/.test(note) && (await part(crowd, 'compare').inputValue()) === 'dvf-paper',
      `a scene above 100 robots is not compared, and the table says why (${note})`,
    );
    checkQuiet(crowd, 'crowd');
    await crowd.context().close();

    const phone = await openMain(newPage, `${base}/#${SCENE}&compare=dvf-paper`, PHONE);
    await tableValues(phone);
    await frames(phone);
    await phone.screenshot({ path: join(RESULTS, 'planners-compare-phone.png'), fullPage: true });
    const fits = await phone.evaluate((s) => {
      const root = document.querySelector(s).shadowRoot;
      const table = root.querySelector('[data-id="compare-table"]').getBoundingClientRect();
      return table.right <= window.innerWidth + 0.5 && root.querySelector('.pg').scrollWidth <= window.innerWidth;
    }, PG);
    check(fits, 'on a phone (390 × 844) the compare table fits the width');
    checkQuiet(phone, 'phone');
    await phone.context().close();
  });
});
