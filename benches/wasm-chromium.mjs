// `benches/wasm.mjs` in headless Chromium: times the crowd scenario of the release package in
// a page served from www/, and prints
// {"robots": N, "steps": S, "obstacles": M, "ms_per_step": x, "engine": "chromium"}.
//
//   make build-wasm && node benches/wasm-chromium.mjs --robots 1000 --steps 200 [--obstacles 0] [--warmup MS]
//
// As in Node, an untimed crowd of the same size steps for MS milliseconds first (500 by
// default), so that the timed one runs in the engine's optimising tier (Chromium takes longer to
// get there than Node, so the warm-up is by time rather than by steps), and the timed crowd
// starts at t = 0. The page's clock (`performance.now`) is coarsened to 0.1 ms, a small part of
// S steps.

import { run } from '../tests/e2e/lib.mjs';
import { option } from './options.mjs';

const robots = option('robots', 1000);
const steps = option('steps', 100);
const obstacles = option('obstacles', 0);
const warmup = option('warmup', 500);
if (steps < 1) {
  console.error(`steps: must be at least 1, not ${steps}`);
  process.exit(2);
}

await run(async ({ base, newPage }) => {
  const page = await newPage();
  // Any page of the site, so that the module loads from the same origin.
  await page.goto(`${base}/pkg/dvf.d.ts`);
  const ms = await page.evaluate(
    async ({ robots, steps, obstacles, warmup }) => {
      const dvf = await import('/pkg/dvf.js');
      await dvf.default();
      if (warmup > 0) {
        const warm = new dvf.CrowdBench(robots, obstacles);
        for (const until = performance.now() + warmup; performance.now() < until; ) warm.step(10);
        warm.free();
      }
      const bench = new dvf.CrowdBench(robots, obstacles);
      const start = performance.now();
      bench.step(steps);
      const ms = (performance.now() - start) / steps;
      bench.free();
      return ms;
    },
    { robots, steps, obstacles, warmup },
  );
  console.log(
    `{"robots": ${robots}, "steps": ${steps}, "obstacles": ${obstacles}, "ms_per_step": ${ms}, "engine": "chromium"}`,
  );
});
