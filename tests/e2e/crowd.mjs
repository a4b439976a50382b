// End-to-end test of the playground at crowd scale and of its teaching presets, on the main
// page (www/index.html) in Chromium:
// - Seek: a long seek (the scrubber dragged to the end of the 1,000-robot crowd) shows its
//   progress, growing; Escape, and the progress box's Cancel, stop it at a whole step, the clock
//   then stays there, and the state shown is the run's own at that time (a synchronous seek to
//   the same time from t = 0 gives the same poses, to the bit).
//
// Behaviour only: no time is compared with a limit (the rates are measured by
// benches/seek.mjs).
//
// Run: make test-e2e   (or: node tests/e2e/crowd.mjs after make build-wasm)

import { check, checkQuiet, frames, run, waitLoaded } from './lib.mjs';

const PG = 'dvf-playground';
/** The crowd a long seek crosses: 18,400 steps to its end, seconds of stepping in wasm. */
const SEEK_CROWD = 'crowd-1000';

/** The shadow part with `data-id` `id` of the page's playground. */
function part(page, id) {
  return page.locator(`${PG} >> [data-id="${id}"]`);
}

/** The seek's progress box as shown: hidden or not, its bar and its text. */
function seekShown(page) {
  return page.evaluate((sel) => {
    const root = document.querySelector(sel).shadowRoot;
    const box = root.querySelector('[data-id="seek"]');
    return {
      hidden: box.hidden,
      value: root.querySelector('[data-id="seek-bar"]').value,
      text: root.querySelector('[data-id="seek-text"]').textContent,
    };
  }, PG);
}

/** Drags the scrubber to its end: a seek in slices to the end of the run. */
function scrubToEnd(page) {
  return page.evaluate((sel) => {
    const s = document.querySelector(sel).shadowRoot.querySelector('[data-id="scrubber"]');
    s.focus();
    s.value = s.max;
    s.dispatchEvent(new Event('input'));
  }, PG);
}

/** Starts a long seek, waits for its progress to show and grow, and returns what it showed. */
async function longSeek(page, what) {
  await page.evaluate((sel) => document.querySelector(sel).reset(), PG);
  await scrubToEnd(page);
  await page.waitForFunction((sel) => {
    const box = document.querySelector(sel).shadowRoot.querySelector('[data-id="seek"]');
    return !box.hidden;
  }, PG);
  const first = await seekShown(page);
  await page.waitForFunction(
    ([sel, v]) => document.querySelector(sel).shadowRoot.querySelector('[data-id="seek-bar"]').value > v,
    [PG, first.value],
  );
  const later = await seekShown(page);
  check(
    /Going to t = 184\.0 s/.test(first.text) && later.value > first.value && later.value < 1,
    `${what}: the seek shows its progress ("${first.text}", then ${(later.value * 100).toFixed(0)} %)`,
  );
}

/** Checks that the seek stopped at a whole step, stays there, and shows the run's own state. */
async function checkStopped(page, what) {
  const stopped = await page.evaluate((sel) => {
    const el = document.querySelector(sel);
    return { time: el.time, dt: el.scenario().dt, poses: [...el.cache.poses] };
  }, PG);
  const shown = await seekShown(page);
  await new Promise((r) => setTimeout(r, 300));
  await frames(page);
  const after = await page.evaluate((sel) => document.querySelector(sel).time, PG);
  const steps = stopped.time / stopped.dt;
  check(
    shown.hidden && after === stopped.time && stopped.time > 0 && stopped.time < 184,
    `${what}: the seek stops at t = ${stopped.time} s and the clock stays there (t = ${after} s), the progress hidden`,
  );
  check(Math.abs(steps - Math.round(steps)) < 1e-6, `${what}: it stopped at a whole step (${steps.toFixed(6)})`);
  const again = await page.evaluate(
    ([sel, t]) => {
      const el = document.querySelector(sel);
      el.seek(t);
      return { time: el.time, poses: [...el.cache.poses] };
    },
    [PG, stopped.time],
  );
  const same = again.time === stopped.time && again.poses.every((v, i) => v === stopped.poses[i]);
  check(
    same,
    `${what}: the state shown is the run's at t = ${stopped.time} s (a seek from t = 0 gives the same poses)`,
  );
}

await run(async ({ base, newPage }) => {
  const page = await newPage({ viewport: { width: 1280, height: 800 } });
  await page.goto(`${base}/index.html`);
  await waitLoaded(page, PG);

  // --- A long seek: progress, Escape, Cancel. ---
  await page.evaluate(([sel, name]) => document.querySelector(sel).loadPreset(name), [PG, SEEK_CROWD]);
  await frames(page);
  await longSeek(page, `${SEEK_CROWD}, Escape`);
  await page.keyboard.press('Escape');
  await frames(page);
  await checkStopped(page, `${SEEK_CROWD}, Escape`);
  await longSeek(page, `${SEEK_CROWD}, Cancel`);
  await part(page, 'seek-cancel').click();
  await frames(page);
  await checkStopped(page, `${SEEK_CROWD}, Cancel`);
  checkQuiet(page, 'the crowd page');
  await page.context().close();
});
