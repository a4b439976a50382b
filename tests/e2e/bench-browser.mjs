// The browser benchmark: milliseconds of work per frame of the playground (the steps of the
// frame, the field overlay, the trails, the drawing and its rasterisation) while a crowd plays,
// at 100, 1,000 and 10,000 robots, in headless Chromium (no GPU) on the RELEASE wasm package.
//
// Each crowd (`#crowd-N`) is first stepped part of the way (so that its trail rings hold a
// long history: the trails are what grows), then played at 1× with the field arrows on for
// PLAY_MS. The element records the work of every frame (`stats.work`, from the start of its
// requestAnimationFrame callback to the end of its drawing, which `stats.rasterInWork` makes
// the browser rasterise within the callback: Chromium records Canvas 2D calls and turns them
// into pixels later, so timing the calls alone would leave most of the cost out); the
// benchmark prints one JSON line per N with the median, 90th percentile and maximum work and
// the frames per second, and checks the median frame against the budget, 16 ms up to 1,000
// robots (a 60 Hz frame) and 50 ms at 10,000, and the 90th percentile against 1.25 times it
// (room for the noise of a shared machine; the printed figures say how much was used).
// Screenshots of each crowd go to test-results/.
//
// Run: make test-e2e   (or: node tests/e2e/frames.mjs after make build-wasm)

import { check, checkQuiet, join, RESULTS, run } from './lib.mjs';

const VIEWPORT = { width: 1280, height: 800 };
const PG = 'dvf-playground';
/** Wall time played per crowd (ms). */
const PLAY_MS = 4_000;
/**
 * Crowds, the fraction of their run stepped before playing (trail history; 10,000 robots step
 * about 5 ms each, so that crowd starts early), and the frame budget checked (ms).
 */
const CASES = [
  { robots: 100, ahead: 0.4, budgetMs: 16 },
  { robots: 1_000, ahead: 0.4, budgetMs: 16 },
  { robots: 10_000, ahead: 0.003, budgetMs: 50 },
];

/** The q-quantile of `values` (sorted copy, nearest rank). */
function quantile(values, q) {
  const s = [...values].sort((a, b) => a - b);
  return s[Math.min(s.length - 1, Math.max(0, Math.ceil(q * s.length) - 1))];
}

await run(async ({ base, newPage }) => {
  for (const { robots, ahead, budgetMs } of CASES) {
    const page = await newPage({ viewport: VIEWPORT, deviceScaleFactor: 1 });
    await page.goto(`${base}/#crowd-${robots}`);
    await page.waitForSelector('body[data-ready]');
    const loaded = await page.evaluate((sel) => document.querySelector(sel).presetName(), PG);
    check(loaded === `crowd-${robots}`, `#crowd-${robots} opens the crowd (${loaded})`);
    const prep = await page.evaluate(
      ([sel, fraction]) => {
        const el = document.querySelector(sel);
        const total = Math.round(el.pg.duration / el.pg.dt);
        el.step(Math.round(total * fraction));
        return { time: el.pg.time, duration: el.pg.duration, field: el.fieldMode, recorded: el.pg.trailRecorded };
      },
      [PG, ahead],
    );
    const result = await page.evaluate(
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
        for (let k = el.stats.workCount - count; k < el.stats.workCount; k++)
          work.push(el.stats.work[k % el.stats.work.length]);
        return { work, simulated: el.pg.time - t0, stepMs: el.stepMs, trailSamples: el.pg.trailRecorded };
      },
      [PG, PLAY_MS],
    );
    // Frames after the first: the first one after play() redraws the trail layer at most once.
    const work = result.work.slice(1);
    const median = quantile(work, 0.5);
    const p90 = quantile(work, 0.9);
    const max = Math.max(...work);
    // Frames per second of wall time (the timestamps of animation frames are those of the
    // display's beats, which a late frame still gets).
    const fps = (work.length + 1) / (PLAY_MS / 1000);
    console.log(
      `BENCH ${JSON.stringify({
        robots,
        frames: work.length + 1,
        fps: Number(fps.toFixed(1)),
        ms_per_frame_median: Number(median.toFixed(2)),
        ms_per_frame_p90: Number(p90.toFixed(2)),
        ms_per_frame_max: Number(max.toFixed(2)),
        ms_per_step: Number(result.stepMs?.toFixed(3)),
        simulated_s: Number(result.simulated.toFixed(2)),
        from_t: Number(prep.time.toFixed(1)),
        trail_samples: result.trailSamples,
      })}`,
    );
    check(work.length >= 10, `${robots} robots: the crowd played ${work.length + 1} frames in ${PLAY_MS} ms`);
    check(result.simulated > 0, `${robots} robots: the clock advanced ${result.simulated.toFixed(2)} s`);
    check(prep.field === 'arrows', `${robots} robots: the field overlay is on (${prep.field})`);
    check(
      median <= budgetMs && p90 <= 1.25 * budgetMs,
      `${robots} robots: a frame's work takes at most ${budgetMs} ms (median ${median.toFixed(1)} ms; 90th percentile ${p90.toFixed(1)} ms, limit ${1.25 * budgetMs} ms)`,
    );
    await page.screenshot({ path: join(RESULTS, `crowd-${robots}.png`) });
    checkQuiet(page, `crowd of ${robots}`);
    await page.context().close();
  }
});
