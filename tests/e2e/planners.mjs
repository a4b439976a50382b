// End-to-end tests of the playground's planner menu and compare mode: the release package,
// served, in Chromium. The menu lists the planners and sets the scenario's `planner`, which
// the link, the exported JSON and the element's `planner` attribute carry; the compare mode
// draws a second planner's run over the scene and shows both runs' metrics in one table, every
// number but the compute per step equal to the command line's
// (tests/data/compare-example3-circle-swap-orca.json, written by
// `dvf compare --preset example3-circle-swap --planners dvf,orca --json` of the release build);
// a drag runs both again; the element's `compare` attribute opens it in compare mode.
// Screenshots go to test-results/ (planners-*.png).
//
// Run: make test-e2e   (or: node tests/e2e/planners.mjs after make build-wasm)

import { readFileSync } from 'node:fs';
import * as lib from './lib.mjs';
import { check, checkQuiet, frames, join, ROOT, RESULTS, run, scenarioOf, waitLoaded } from './lib.mjs';

const PG = 'dvf-playground';
const DESKTOP = { width: 1280, height: 800 };
const PHONE = { width: 390, height: 844 };
const SCENE = 'example3-circle-swap';
/** The planner compared with dvf, SCENE's own. */
const OTHER = 'orca';
/** `dvf compare --json` of SCENE with dvf and OTHER. */
const REFERENCE = JSON.parse(readFileSync(join(ROOT, 'tests', 'data', `compare-${SCENE}-${OTHER}.json`), 'utf8'));

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
async function tableValues(page, sel = PG) {
  await page.waitForSelector(`${sel} [data-id="compare-results"][data-ready]`);
  return page.evaluate((s) => {
    const out = {};
    for (const td of document.querySelector(s).shadowRoot.querySelectorAll('[data-id="compare-table"] td')) {
      out[td.dataset.planner] ??= {};
      out[td.dataset.planner][td.dataset.metric] = td.dataset.value === '' ? null : Number(td.dataset.value);
    }
    return out;
  }, sel);
}

/**
 * Whether the table's `values` hold every metric of the reference's runs, each the same
 * number (`data-value` is the shortest decimal of the f64, which parses back to it exactly),
 * but the compute per step, which is measured in the browser: there, a positive number.
 * Returns what differs, empty when nothing does.
 */
function differences(values) {
  const out = [];
  for (const run of REFERENCE.planners) {
    const got = values[run.planner] ?? {};
    for (const [k, v] of Object.entries(run.metrics)) {
      if (k === 'ms_per_step' ? !(got[k] > 0) : got[k] !== v) out.push(`${run.planner} ${k}: ${got[k]} (CLI ${v})`);
    }
  }
  return out;
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

  // ---- The element's `compare` attribute: it opens in compare mode, with the CLI's numbers.
  await section('compare attribute', async () => {
    const page = await newPage({ viewport: DESKTOP });
    await page.goto(`${base}/embed.html`);
    await page.evaluate(
      ([scene, other]) => {
        document.body.insertAdjacentHTML(
          'beforeend',
          `<dvf-playground id="c" preset="${scene}" planner="dvf" compare="${other}" controls></dvf-playground>` +
            `<dvf-playground id="d" preset="${scene}" compare="rrt" controls></dvf-playground>`,
        );
      },
      [SCENE, OTHER],
    );
    await waitLoaded(page, '#c');
    await waitLoaded(page, '#d');
    const values = await tableValues(page, '#c');
    const state = await page.evaluate(() => document.querySelector('#c').viewState().compare);
    const diff = differences(values);
    check(
      state === OTHER && diff.length === 0,
      `compare="${OTHER}" opens the element in compare mode, its table the CLI's numbers (${diff.join('; ')})`,
    );
    const d = await page.evaluate(() => {
      const el = document.querySelector('#d');
      return {
        compare: el.viewState().compare,
        message: el.shadowRoot.querySelector('[data-id="message-text"]').textContent,
        hidden: el.shadowRoot.querySelector('[data-id="compare-results"]').hidden,
      };
    });
    check(
      d.compare === null &&
        d.hidden &&
        d.message.startsWith('compare: unknown planner "rrt"') &&
        d.message.includes('move-to-pose'),
      `an unknown compare attribute shows the core's message and compares nothing (${d.message})`,
    );
    await page.evaluate(() => document.querySelector('#d').setAttribute('compare', 'avf'));
    await tableValues(page, '#d');
    const avf = await page.evaluate(() => document.querySelector('#d').viewState().compare);
    await page.evaluate(() => document.querySelector('#d').removeAttribute('compare'));
    const off = await page.evaluate(() => {
      const el = document.querySelector('#d');
      return el.viewState().compare === null && el.shadowRoot.querySelector('[data-id="compare-results"]').hidden;
    });
    check(avf === 'avf' && off, 'setting the attribute compares with that planner; removing it ends the comparison');
    await page.screenshot({ path: join(RESULTS, 'planners-compare-attribute.png'), fullPage: true });
    checkQuiet(page, 'compare attribute');
    await page.context().close();
  });

  // ---- Compare mode: two runs drawn, one table equal to the command line's, a drag runs both.
  await section('compare', async () => {
    const page = await openMain(newPage, `${base}/#${SCENE}`);
    const plain = await lib.canvasStats(page);
    await part(page, 'compare').selectOption(OTHER);
    const values = await tableValues(page);
    await frames(page);
    const drawn = lib.changedFraction(plain, await lib.canvasStats(page));
    const legend = await part(page, 'compare-legend').textContent();
    check(
      drawn > 0.002 &&
        (await part(page, 'compare-legend').isVisible()) &&
        /dvf: live/.test(legend) &&
        legend.includes(OTHER),
      `compare mode draws the second run (${(drawn * 100).toFixed(1)} % of blocks) and the legend names both (${legend})`,
    );
    const diff = differences(values);
    check(
      diff.length === 0,
      `the table holds every metric of dvf compare --json, the same numbers but the compute per step (${diff.join('; ')})`,
    );
    const approximate = await page.evaluate(
      (s) =>
        [...document.querySelector(s).shadowRoot.querySelectorAll('td')].some((td) => td.textContent.startsWith('≈')),
      PG,
    );
    check(!approximate, 'no figure of the table is marked approximate');
    await page.screenshot({ path: join(RESULTS, 'planners-compare-desktop.png') });
    const [svg] = await Promise.all([page.waitForEvent('download'), part(page, 'export-svg').click()]);
    const svgText = readFileSync(await svg.path(), 'utf8');
    check(/#ea580c/i.test(svgText), 'the SVG export draws the compared run too');

    const state = await page.evaluate((s) => document.querySelector(s).viewState().compare, PG);
    await page.waitForFunction((o) => location.hash.includes(`&compare=${o}`), OTHER);
    check(state === OTHER, 'viewState() and the link name the compared planner');
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
      ([s, old, o]) => {
        const td = document
          .querySelector(s)
          .shadowRoot.querySelector(
            `[data-id="compare-results"][data-ready] td[data-metric="path_length"][data-planner="${o}"]`,
          );
        return td && Number(td.dataset.value) !== old;
      },
      [PG, values[OTHER].path_length, OTHER],
    );
    check(true, 'a dragged robot runs both planners again (the compared path length changes)');
    checkQuiet(page, 'compare');
    await page.context().close();

    const again = await openMain(newPage, link);
    await tableValues(again);
    check((await part(again, 'compare').inputValue()) === OTHER, 'the link opens the compare mode');
    await part(again, 'compare').selectOption('');
    await frames(again);
    check(await part(again, 'compare-results').isHidden(), 'compare off hides the table and the legend');
    checkQuiet(again, 'compare link');
    await again.context().close();

    const crowd = await openMain(newPage, `${base}/#crowd-200&compare=dvf-paper`);
    const note = await part(crowd, 'compare-results').textContent();
    check(
      /up to 100 robots; this one has 200/.test(note) && (await part(crowd, 'compare').inputValue()) === 'dvf-paper',
      `a scene above 100 robots is not compared, and the table says why (${note})`,
    );
    checkQuiet(crowd, 'crowd');
    await crowd.context().close();

    // The longest planner names, in both columns.
    const phone = await openMain(newPage, `${base}/#${SCENE}&compare=move-to-pose`, PHONE);
    await part(phone, 'planner').selectOption('clf-cbf');
    await phone.waitForSelector(`${PG} [data-id="compare-results"][data-ready] th[data-planner="clf-cbf"]`);
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
