// End-to-end test of the book (`make docs` writes target/book/): every chapter of
// docs/book/src/SUMMARY.md opens in Chromium with no console message, and every figure in it
// (loaded lazily, as the reader scrolls to it) drew. Every figure with a `time` attribute shows
// the state of `dvf simulate --csv` at that time: each robot's pose equal to the trajectory's
// row at that step.
//
// Run: make test-e2e   (or: node tests/e2e/book.mjs after make docs)

import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { canvasStats, check, checkQuiet, ROOT, run, startServer, waitLoaded } from './lib.mjs';

const BOOK = join(ROOT, 'target', 'book');
const SUMMARY = join(ROOT, 'docs', 'book', 'src', 'SUMMARY.md');
const CSV_DIR = join(ROOT, 'target', 'book-check');
/**
 * A figure drew when more than this many of its canvas pixels are coloured: an empty canvas
 * has none, the sparsest figure (one robot, its goal and a grey obstacle) about 140.
 */
const DREW_PIXELS = 100;
/**
 * The page runs the crate compiled to wasm, `dvf simulate` the same code natively, with the same
 * f64 arithmetic and the same maths library (src/maths.rs): the same bits, so the poses must be
 * equal (README, "The book"). The CSV writes each number so that it reads back to its bits.
 */
const POSE_TOLERANCE = 0;

if (!existsSync(join(BOOK, 'index.html'))) throw new Error(`${BOOK} is missing: run make docs first`);
const chapters = [...readFileSync(SUMMARY, 'utf8').matchAll(/\]\(([\w-]+)\.md\)/g)].map((m) => `${m[1]}.html`);

/** `dvf simulate --preset NAME --csv` once per preset: rows `[t, robot, x, y, θ]`. */
const trajectories = new Map();
function trajectory(preset) {
  if (!trajectories.has(preset)) {
    mkdirSync(CSV_DIR, { recursive: true });
    const csv = join(CSV_DIR, `${preset}.csv`);
    execFileSync('cargo', ['run', '--quiet', '--', 'simulate', '--preset', preset, '--csv', csv], {
      cwd: ROOT,
      stdio: ['ignore', 'ignore', 'inherit'],
    });
    const rows = readFileSync(csv, 'utf8')
      .trim()
      .split('\n')
      .slice(1)
      .map((line) => line.split(',').map(Number));
    trajectories.set(preset, rows);
  }
  return trajectories.get(preset);
}

await run(async ({ newPage }) => {
  const { server, base } = await startServer(BOOK);
  let figures = 0;
  let timed = 0;
  let worst = 0;
  try {
    for (const chapter of chapters) {
      const page = await newPage({ viewport: { width: 1200, height: 900 } });
      await page.goto(`${base}/${chapter}`);
      const count = await page.evaluate(() => {
        const all = document.querySelectorAll('dvf-playground');
        all.forEach((el, k) => {
          el.dataset.check = String(k);
        });
        return all.length;
      });
      for (let k = 0; k < count; k++) {
        const sel = `dvf-playground[data-check="${k}"]`;
        await page.locator(sel).scrollIntoViewIfNeeded();
        await waitLoaded(page, sel);
        const { coloured } = await canvasStats(page, sel);
        const attrs = await page.evaluate((sel) => {
          const el = document.querySelector(sel);
          return { preset: el.getAttribute('preset'), time: el.getAttribute('time'), src: el.getAttribute('src') };
        }, sel);
        const what = `${chapter} figure ${k + 1} (${attrs.preset ?? attrs.src}${attrs.time ? ` at t = ${attrs.time} s` : ''})`;
        check(coloured > DREW_PIXELS, `${what} drew (${coloured} coloured pixels)`);
        figures += 1;
        if (attrs.time === null || !attrs.preset) continue;
        const shown = await page.evaluate((sel) => {
          const el = document.querySelector(sel);
          return { time: el.time, dt: el.scenario().dt, poses: [...el.cache.poses] };
        }, sel);
        const rows = trajectory(attrs.preset).filter((r) => Math.abs(r[0] - shown.time) < shown.dt / 2);
        let diff = rows.length === shown.poses.length / 3 ? 0 : Number.POSITIVE_INFINITY;
        for (const [, robot, x, y, theta] of rows) {
          const p = shown.poses.slice(3 * robot, 3 * robot + 3);
          const dTheta = Math.abs(Math.atan2(Math.sin(p[2] - theta), Math.cos(p[2] - theta)));
          diff = Math.max(diff, Math.abs(p[0] - x), Math.abs(p[1] - y), dTheta);
        }
        check(
          diff <= POSE_TOLERANCE && Math.abs(shown.time - Number(attrs.time)) < shown.dt / 2,
          `${what}: the poses are dvf simulate's at t = ${shown.time} s (largest difference ${diff.toExponential(1)})`,
        );
        timed += 1;
        worst = Math.max(worst, diff);
      }
      checkQuiet(page, chapter);
      await page.context().close();
    }
    console.log(
      `${chapters.length} chapters, ${figures} figures, ${timed} at a time; largest pose difference ${worst.toExponential(1)}`,
    );
  } finally {
    server.kill();
  }
});
