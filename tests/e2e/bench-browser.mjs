// The browser benchmark (`make bench-browser`), in headless Chromium (no GPU) on the RELEASE
// wasm package: the figures of the page and their budgets. Each figure is printed as one JSON
// line and all of them are recorded in test-results/bench-frames.json; the budgets are
// checked here only (a slower machine fails this, never `make test`).
//
// - first-frame: when the main page drew its first frame (ms after navigation started).
// - prediction: the predicted paths of Example 4 (ms per prediction, per robot move with its
//   prediction, and per prediction of the whole run).
// - drag: a robot dragged in Example 4 and in the crowds of 100 and 10,000 robots: how often
//   the playground redrew for the pointer moves (budget: at least once per two moves), the
//   page's frame rate, and the work of the playground's frames meanwhile (budget for the
//   crowds: the median frame within DRAG_FRAME_BUDGET_MS: a 60 Hz frame at 100 robots, whose
//   every move predicts the paths, as a playing crowd's at 10,000).
// - frames: milliseconds of work per frame (the steps of the frame, the field overlay, the
//   trails, the drawing and its rasterisation) while a crowd of 100, 1,000 and 10,000 robots
//   plays. Each crowd (`#crowd-N`) is first stepped part of the way (so that its trail rings
//   hold a long history: the trails are what grows), then played at 1× with the field arrows
//   on for PLAY_MS. The element records the work of every frame (`stats.work`, from the start
//   of its requestAnimationFrame callback to the end of its drawing, which `stats.rasterInWork`
//   makes the browser rasterise within the callback: Chromium records Canvas 2D calls and
//   turns them into pixels later, so timing the calls alone would leave most of the cost out).
//   Budget: the median frame within 16 ms up to 1,000 robots (a 60 Hz frame) and 50 ms at
//   10,000, the 90th percentile within 1.25 times that (room for the noise of a shared machine;
//   the figures say how much was used).
// - longest-task: the longest task of the page's main thread (a PerformanceObserver of
//   `longtask`, which reports tasks over 50 ms) in each phase of a visit: Example 4 opened,
//   edited, seeked, exported as CSV, JSON and SVG, imported; the crowds of 1,000 and 10,000
//   robots opened, edited, exported and imported. Budget: LONG_TASK_BUDGET_MS in every phase.
// Screenshots of each crowd go to test-results/.
//
// Run: make bench-browser   (or: node tests/e2e/bench-browser.mjs after make build-wasm)

import { writeFileSync } from 'node:fs';
import { check, checkQuiet, drag, EXAMPLE4, join, predictions, RESULTS, run, waitLoaded } from './lib.mjs';
import { quantile } from '../../benches/quantile.mjs';

const VIEWPORT = { width: 1280, height: 800 };
const PG = 'dvf-playground';
const RECORD = join(RESULTS, 'bench-frames.json');
/** Predictions timed (after WARMUP untimed ones). */
const PREDICTION_RUNS = 30;
const WARMUP = 5;
/** Mouse moves in a timed drag, and the move (CSS px). */
const DRAG_MOVES = 60;
const DRAG_STEP = [1.5, -1.2];
/** The median frame of a drag in a crowd of N robots (ms), by N. */
const DRAG_FRAME_BUDGET_MS = { 100: 16, 10000: 50 };
/** Wall time played per crowd (ms). */
const PLAY_MS = 4_000;
/**
 * Crowds, the fraction of their run stepped before playing (trail history; the 10,000 robots'
 * steps are the slowest, so that crowd starts early; 100 robots have all arrived by 40 % of
 * their run, where play would start again from t = 0), and the frame budget checked (ms).
 */
const CASES = [
  { robots: 100, ahead: 0.15, budgetMs: 16 },
  { robots: 1_000, ahead: 0.4, budgetMs: 16 },
  { robots: 10_000, ahead: 0.003, budgetMs: 50 },
];

/** No task of the main thread longer than this (ms) in any phase. */
const LONG_TASK_BUDGET_MS = 100;

const figures = [];
/** Prints `figure` as a JSON line and keeps it for the record. */
function report(figure) {
  console.log(JSON.stringify(figure));
  figures.push(figure);
}

/** `v` rounded to `digits` decimals, as a number. */
const round = (v, digits = 2) => Number(v.toFixed(digits));

/** Drags robot 1 of the playground on `page` and reports the figures as `name`. */
async function benchDrag(page, name) {
  const start = await page.evaluate((sel) => {
    const el = document.querySelector(sel);
    const [x, y] = el.scenario().robots[0].start;
    const p = el.worldToScreen(x, y);
    return [p.x - window.scrollX, p.y - window.scrollY];
  }, PG);
  const d = await drag(page, start, DRAG_MOVES, DRAG_STEP);
  const robots = await page.evaluate((sel) => document.querySelector(sel).scenario().robots.length, PG);
  report({
    bench: 'drag',
    scene: name,
    robots,
    moves: DRAG_MOVES,
    redraws: d.redraws,
    fps: round((d.frames - 1) / d.span, 1),
    longest_gap_ms: round(d.worst, 1),
    ms_per_frame_median: round(quantile(d.work, 0.5)),
    ms_per_frame_max: round(d.maxWork),
    last_edit_ms: round(d.edit),
  });
  check(
    d.redraws >= DRAG_MOVES / 2,
    `${name}: the playground redraws at least once per two pointer moves (${d.redraws} for ${DRAG_MOVES})`,
  );
  return d;
}

await run(async ({ base, newPage, browser }) => {
  // --- The main page: first frame, predictions, a drag in Example 4. ---
  const page = await newPage({ viewport: VIEWPORT, deviceScaleFactor: 1 });
  await page.goto(`${base}/`);
  await waitLoaded(page);
  const first = await page.evaluate((sel) => {
    const nav = performance.getEntriesByType('navigation')[0];
    return { frame: document.querySelector(sel).stats.firstFrameMs, loaded: nav.domContentLoadedEventEnd };
  }, PG);
  report({
    bench: 'first-frame',
    first_frame_ms: round(first.frame, 0),
    dom_content_loaded_ms: round(first.loaded, 0),
  });
  const p = await predictions(page, EXAMPLE4, PREDICTION_RUNS, WARMUP);
  report({
    bench: 'prediction',
    scene: EXAMPLE4,
    runs: PREDICTION_RUNS,
    to_s: round(p.end),
    ms_per_prediction: round(p.predict),
    ms_per_robot_move: round(p.edit),
    samples_per_robot: p.samples,
    whole_run_to_s: round(p.fullEnd),
    ms_per_whole_run_prediction: round(p.full),
  });
  await benchDrag(page, EXAMPLE4);
  checkQuiet(page, 'main page');
  await page.context().close();

  // --- Crowds: a drag in the largest, then each one playing. ---
  for (const { robots, ahead, budgetMs } of CASES) {
    const crowd = await newPage({ viewport: VIEWPORT, deviceScaleFactor: 1 });
    await crowd.goto(`${base}/#crowd-${robots}`);
    await crowd.waitForSelector('body[data-ready]');
    const loaded = await crowd.evaluate((sel) => document.querySelector(sel).presetName(), PG);
    check(loaded === `crowd-${robots}`, `#crowd-${robots} opens the crowd (${loaded})`);
    const dragBudget = DRAG_FRAME_BUDGET_MS[robots];
    if (dragBudget !== undefined) {
      const d = await benchDrag(crowd, `crowd-${robots}`);
      const median = quantile(d.work, 0.5);
      check(
        median <= dragBudget,
        `crowd-${robots}: a frame of a drag takes at most ${dragBudget} ms (median ${median.toFixed(1)} ms)`,
      );
      await crowd.evaluate(([sel, name]) => document.querySelector(sel).loadPreset(name), [PG, loaded]);
    }
    const prep = await crowd.evaluate(
      ([sel, fraction]) => {
        const el = document.querySelector(sel);
        const total = Math.round(el.pg.duration / el.pg.dt);
        el.step(Math.round(total * fraction));
        return { time: el.pg.time, field: el.fieldMode };
      },
      [PG, ahead],
    );
    const result = await crowd.evaluate(
      async ([sel, playMs]) => {
        const el = document.querySelector(sel);
        const before = el.stats.workCount;
        const t0 = el.pg.time;
        el.stats.rasterInWork = true;
        el.play();
        await new Promise((r) => setTimeout(r, playMs));
        el.pause();
        const count = Math.min(el.stats.workCount - before, el.stats.work.length);
        const work = [];
        for (let k = el.stats.workCount - count; k < el.stats.workCount; k++) {
          work.push(el.stats.work[k % el.stats.work.length]);
        }
        return { work, simulated: el.pg.time - t0, stepMs: el.stepMs, trailSamples: el.cache.recorded };
      },
      [PG, PLAY_MS],
    );
    // Frames after the first: the first one after play() redraws the trail layer at most once.
    const work = result.work.slice(1);
    const median = quantile(work, 0.5);
    const p90 = quantile(work, 0.9);
    // Frames per second of wall time (the timestamps of animation frames are those of the
    // display's beats, which a late frame still gets).
    report({
      bench: 'frames',
      robots,
      frames: work.length + 1,
      fps: round((work.length + 1) / (PLAY_MS / 1000), 1),
      ms_per_frame_median: round(median),
      ms_per_frame_p90: round(p90),
      ms_per_frame_max: round(Math.max(...work)),
      budget_ms: budgetMs,
      ms_per_step: round(result.stepMs ?? Number.NaN, 3),
      simulated_s: round(result.simulated),
      from_t: round(prep.time, 1),
      trail_samples: result.trailSamples,
    });
    check(work.length >= 10, `${robots} robots: the crowd played ${work.length + 1} frames in ${PLAY_MS} ms`);
    check(result.simulated > 0, `${robots} robots: the clock advanced ${result.simulated.toFixed(2)} s`);
    check(prep.field === 'arrows', `${robots} robots: the field overlay is on (${prep.field})`);
    check(
      median <= budgetMs && p90 <= 1.25 * budgetMs,
      `${robots} robots: a frame's work takes at most ${budgetMs} ms (median ${median.toFixed(1)} ms; 90th percentile ${p90.toFixed(1)} ms, limit ${1.25 * budgetMs} ms)`,
    );
    await crowd.screenshot({ path: join(RESULTS, `crowd-${robots}.png`) });
    checkQuiet(crowd, `crowd of ${robots}`);
    await crowd.context().close();
  }
  await longestTasks(base, newPage);
  writeFileSync(
    RECORD,
    `${JSON.stringify({ date: new Date().toISOString(), browser: browser.version(), figures }, null, 2)}\n`,
  );
  console.log(`recorded ${figures.length} figures in ${RECORD}`);
});

/**
 * The longest task of each phase of a visit (see the top); a phase ends once its work is done
 * and the page has been idle for a moment.
 */
async function longestTasks(base, newPage) {
  const page = await newPage({ viewport: VIEWPORT });
  await page.goto(`${base}/`);
  await waitLoaded(page);
  await page.evaluate(() => {
    window.longest = {};
    window.phase = 'open';
    new PerformanceObserver((list) => {
      for (const e of list.getEntries()) {
        window.longest[window.phase] = Math.max(window.longest[window.phase] ?? 0, e.duration);
      }
    }).observe({ type: 'longtask', buffered: true });
  });
  const part = (id) => page.locator(`${PG} [data-id="${id}"]`);
  const phase = async (name, body) => {
    await page.evaluate((n) => {
      window.phase = n;
    }, name);
    await body();
    await page.waitForTimeout(600);
  };
  const edit = async () => {
    const kv = page.locator(`${PG} input[name="k_v"]`);
    await kv.fill('1.5');
    await kv.press('Enter');
  };
  const exportImport = async (label) => {
    let file = '';
    await phase(`${label} export JSON`, async () => {
      const [d] = await Promise.all([page.waitForEvent('download'), part('export-json').click()]);
      file = await d.path();
    });
    await phase(`${label} import`, () => part('import-file').setInputFiles(file));
    await phase(`${label} SVG`, async () => {
      await Promise.all([page.waitForEvent('download'), part('export-svg').click()]);
    });
  };
  await phase('Example 4 edit', edit);
  await phase('Example 4 seek', () => part('scrubber').fill('700'));
  await phase('Example 4 CSV', async () => {
    await Promise.all([page.waitForEvent('download'), part('export-csv').click()]);
  });
  await exportImport('Example 4');
  for (const n of [1000, 10000]) {
    await phase(`crowd-${n} open`, async () => {
      await part('preset').selectOption('crowd');
      await part('crowd-n').fill(String(n));
      await part('crowd-n').press('Enter');
    });
    await phase(`crowd-${n} edit`, edit);
    await exportImport(`crowd-${n}`);
  }
  const longest = await page.evaluate(() => window.longest);
  report({ figure: 'longest-task', unit: 'ms', phases: longest, budget_ms: LONG_TASK_BUDGET_MS });
  for (const [name, ms] of Object.entries(longest)) {
    check(ms <= LONG_TASK_BUDGET_MS, `${name}: no task longer than ${LONG_TASK_BUDGET_MS} ms (${ms.toFixed(0)} ms)`);
  }
  checkQuiet(page, 'the visit of the longest tasks');
  await page.context().close();
}
