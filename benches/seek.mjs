// The seek benchmark: how fast the page goes to a far time of a crowd, against the pure stepping
// rate, in headless Chromium on the RELEASE wasm package. The crowd (`--robots`, 10,000 unless
// told) is sought from t = 0 to `--to` seconds with the scrubber (a seek in slices, with its
// progress shown), then the same steps are taken synchronously by `step()` from t = 0 in
// batches (no drawing): simulated seconds per wall-clock second of each, and their ratio.
// Prints one JSON line; not part of `make test` (a time is not behaviour).
//
//   make build-wasm && node benches/seek.mjs [--robots 10000] [--to 60]

import { run, waitLoaded } from '../tests/e2e/lib.mjs';

/** The value after `--name` as a number, or `fallback`. */
function option(name, fallback) {
  const at = process.argv.indexOf(`--${name}`);
  const value = at < 0 ? fallback : Number(process.argv[at + 1]);
  if (!Number.isFinite(value) || value <= 0) throw new Error(`--${name}: expected a positive number`);
  return value;
}

const robots = option('robots', 10_000);
const to = option('to', 60);
const PG = 'dvf-playground';
/** Steps per synchronous batch of the pure stepping rate. */
const BATCH = 50;

await run(async ({ base, newPage }) => {
  const page = await newPage({ viewport: { width: 1280, height: 800 } });
  await page.goto(`${base}/index.html`);
  await waitLoaded(page, PG);
  await page.evaluate(([sel, n]) => document.querySelector(sel).loadPreset(`crowd-${n}`), [PG, robots]);
  const seek = await page.evaluate(
    ([sel, to]) =>
      new Promise((resolve) => {
        const el = document.querySelector(sel);
        const s = el.shadowRoot.querySelector('[data-id="scrubber"]');
        const { dt, duration } = el.scenario();
        // The scrubber's value is a fraction of the run (its max): `to` as near as it can be.
        s.value = String(Math.round((to / duration) * Number(s.max)));
        const target = Math.round(((Number(s.value) / Number(s.max)) * duration) / dt) * dt;
        const t0 = performance.now();
        s.dispatchEvent(new Event('input'));
        // The seek ends at its target (the time only grows on the way).
        const poll = () => {
          if (el.time < target - 1e-9) {
            setTimeout(poll, 20);
            return;
          }
          resolve({ reached: el.time, ms: performance.now() - t0 });
        };
        setTimeout(poll, 20);
      }),
    [PG, to],
  );
  const pure = await page.evaluate(
    ([sel, reached, batch]) => {
      const el = document.querySelector(sel);
      el.reset();
      const steps = Math.round(reached / el.scenario().dt);
      const t0 = performance.now();
      for (let left = steps; left > 0; left -= batch) el.pg.step(Math.min(batch, left));
      return { reached: el.pg.time, ms: performance.now() - t0 };
    },
    [PG, seek.reached, BATCH],
  );
  const seekRate = seek.reached / (seek.ms / 1000);
  const pureRate = pure.reached / (pure.ms / 1000);
  console.log(
    JSON.stringify({
      figure: 'seek',
      robots,
      to: seek.reached,
      seek_sim_s_per_s: Number(seekRate.toFixed(2)),
      stepping_sim_s_per_s: Number(pureRate.toFixed(2)),
      ratio: Number((seekRate / pureRate).toFixed(3)),
    }),
  );
  await page.context().close();
});
