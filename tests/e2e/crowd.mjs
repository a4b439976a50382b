// End-to-end test of the playground at crowd scale and of its teaching presets, on the main
// page (www/index.html) in Chromium:
// - Drag: while a robot of the 100-robot crowd is dragged, each move predicts a shorter way
//   ahead (DRAG_PREDICTION_WORK / 100 steps, src/playground/prediction.rs), and the release
//   predicts in full (to the crowd's arrival); the drag moved the robot.
// - Teaching presets: the menu offers each (`teach-*`, src/presets.rs) under a readable label;
//   chosen there, it loads, its robots never drive faster than its v_max nor turn faster than
//   its ω_max, and at its end every robot is at its goal within the tolerances.
// - Seek: a long seek (the scrubber dragged to the end of the 1,000-robot crowd) shows its
//   progress, growing; Escape, and the progress box's Cancel, stop it at a whole step, the clock
//   then stays there, and the state shown is the run's own at that time (a synchronous seek to
//   the same time from t = 0 gives the same poses, to the bit).
// - A figure's far `time`: a 1,000-robot figure with time="150" seeks in slices on load (its
//   progress shows, and the page's own requestAnimationFrame and timers run meanwhile), then
//   `loaded` resolves at t = 150 s with the poses of a synchronous `seek(150)`, to the bit; a
//   changed `time`, and `seekTo(t)`, seek the same way.
//
// Behaviour only: no time is compared with a limit (the costs are measured by
// benches/drag.mjs --robots 100 and benches/seek.mjs).
//
// Run: make test-e2e   (or: node tests/e2e/crowd.mjs after make build-wasm)

import { check, checkQuiet, frames, run, waitLoaded } from './lib.mjs';

const PG = 'dvf-playground';
/** The crowd a robot is dragged in: the most robots whose paths are predicted. */
const DRAG_CROWD = 'crowd-100';
/**
 * The look-ahead of a prediction during a drag at 100 robots (s): DRAG_PREDICTION_WORK / 100
 * steps of dt = 0.01 (src/playground/prediction.rs). The times are whole steps of dt, so the
 * comparison allows for their rounding only.
 */
const DRAG_HORIZON_S = 3;
const TIME_ROUNDING_S = 1e-9;

/** How far ahead the predicted paths look now (s), 0 when there are none. */
function horizon(page) {
  return page.evaluate((sel) => {
    const el = document.querySelector(sel);
    const times = el.cache.predictedTimes;
    return times.length ? times[times.length - 1] - el.time : 0;
  }, PG);
}

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

/** The figure with a far `time` attribute, and that time (s): 15,000 steps of the crowd. */
const FAR = 'dvf-playground#far';
const FAR_TIME_S = 150;

/**
 * Adds a 1,000-robot figure with time = FAR_TIME_S to the page, and counts the page's own
 * animation frames and timer ticks while it loads: the ones counted up to when its progress
 * first shows, and up to when `loaded` resolves.
 */
function addFarFigure(page) {
  return page.evaluate(
    ([crowd, t]) => {
      const el = document.createElement('dvf-playground');
      el.id = 'far';
      el.setAttribute('preset', crowd);
      el.setAttribute('time', String(t));
      el.setAttribute('readonly', '');
      el.style.cssText = 'display:block;width:640px;height:400px';
      const count = { frames: 0, timers: 0, loaded: false };
      const frame = () => {
        count.frames += 1;
        if (!count.loaded) requestAnimationFrame(frame);
      };
      requestAnimationFrame(frame);
      const timer = setInterval(() => {
        count.timers += 1;
      }, 20);
      window.farCount = count;
      document.body.prepend(el);
      return el.loaded.then(() => {
        count.loaded = true;
        clearInterval(timer);
      });
    },
    [SEEK_CROWD, FAR_TIME_S],
  );
}

/** The figure FAR's progress box, time and the page's counts while it shows (null when hidden). */
function farProgress(page) {
  return page.evaluate((sel) => {
    const el = document.querySelector(sel);
    const box = el?.shadowRoot.querySelector('[data-id="seek"]');
    if (!box || box.hidden) return null;
    return {
      value: box.querySelector('[data-id="seek-bar"]').value,
      text: box.querySelector('[data-id="seek-text"]').textContent,
      frames: window.farCount.frames,
      timers: window.farCount.timers,
    };
  }, FAR);
}

/** FAR's time and poses now, then after a synchronous seek to `t` from t = 0. */
function farAgainst(page, t) {
  return page.evaluate(
    ([sel, t]) => {
      const el = document.querySelector(sel);
      const shown = { time: el.time, poses: [...el.cache.poses] };
      el.seek(t);
      const sync = { time: el.time, poses: [...el.cache.poses] };
      return { shown, sync, same: shown.time === sync.time && shown.poses.every((v, i) => v === sync.poses[i]) };
    },
    [FAR, t],
  );
}

/** The teaching presets the menu must offer, with their labels. */
const TEACHING = [
  ['teach-one-robot', 'Teaching: one robot'],
  ['teach-obstacle', 'Teaching: obstacle'],
  ['teach-two-robots', 'Teaching: two robots'],
];
/** Times (s) at which a teaching run's speeds are read, and its end. */
const SPEED_TIMES = [0.5, 2, 5, 10, 20];

/**
 * The run of the page's scene, seeked to each of `times`: the largest |v| and |ω| there, and at
 * the end whether every robot is within tol_position and tol_heading of its goal.
 */
function teachingRun(page, times) {
  return page.evaluate(
    ([sel, times]) => {
      const el = document.querySelector(sel);
      const s = el.scenario();
      let v = 0;
      let omega = 0;
      for (const t of times) {
        el.seek(t);
        const st = el.cache.status;
        const stride = st.length / s.robots.length;
        for (let i = 0; i < s.robots.length; i++) {
          v = Math.max(v, Math.abs(st[i * stride]));
          omega = Math.max(omega, Math.abs(st[i * stride + 1]));
        }
      }
      el.seek(s.duration);
      const p = el.cache.poses;
      const arrived = s.robots.every((r, i) => {
        const d = Math.abs(p[3 * i + 2] - r.goal[2]) % (2 * Math.PI);
        return (
          Math.hypot(p[3 * i] - r.goal[0], p[3 * i + 1] - r.goal[1]) <= s.params.tol_position &&
          Math.min(d, 2 * Math.PI - d) <= s.params.tol_heading
        );
      });
      return { v, omega, arrived, vMax: s.params.v_max, omegaMax: s.params.omega_max, robots: s.robots.length };
    },
    [PG, times],
  );
}

await run(async ({ base, newPage }) => {
  const page = await newPage({ viewport: { width: 1280, height: 800 } });
  await page.goto(`${base}/index.html`);
  await waitLoaded(page, PG);

  // --- The teaching presets, chosen in the menu. ---
  for (const [name, label] of TEACHING) {
    const offered = await page.evaluate(
      ([sel, name]) => {
        const o = document.querySelector(sel).shadowRoot.querySelector(`[data-id="preset"] option[value="${name}"]`);
        return o?.textContent ?? null;
      },
      [PG, name],
    );
    check(offered === label, `the menu offers ${name} as "${offered}"`);
    await part(page, 'preset').selectOption(name);
    await page.waitForFunction(([sel, name]) => document.querySelector(sel).presetName() === name, [PG, name]);
    const r = await teachingRun(page, SPEED_TIMES);
    check(
      r.vMax <= 2 && r.omegaMax <= 1 && r.v > 0 && r.v <= r.vMax && r.omega <= r.omegaMax,
      `${name}: ${r.robots} robot(s) drive at up to ${r.v.toFixed(2)} m/s and turn at up to ${r.omega.toFixed(2)} rad/s (v_max ${r.vMax}, ω_max ${r.omegaMax})`,
    );
    check(r.arrived, `${name}: every robot is at its goal at the end of the run`);
  }

  // --- A drag in the 100-robot crowd: a shorter prediction per move, a full one on release. ---
  await page.evaluate(([sel, name]) => document.querySelector(sel).loadPreset(name), [PG, DRAG_CROWD]);
  await frames(page);
  const full = await horizon(page);
  const start = await page.evaluate((sel) => {
    const el = document.querySelector(sel);
    const [x, y] = el.scenario().robots[0].start;
    return { world: [x, y], screen: el.worldToScreen(x, y) };
  }, PG);
  await page.mouse.move(start.screen.x, start.screen.y);
  await page.mouse.down();
  const during = [];
  for (let k = 1; k <= 6; k++) {
    await page.mouse.move(start.screen.x - 3 * k, start.screen.y + k);
    await frames(page);
    during.push(await horizon(page));
  }
  await page.mouse.up();
  await frames(page);
  const released = await horizon(page);
  const moved = await page.evaluate((sel) => document.querySelector(sel).scenario().robots[0].start, PG);
  check(
    full > DRAG_HORIZON_S && during.every((h) => h > 0 && h <= DRAG_HORIZON_S + TIME_ROUNDING_S),
    `${DRAG_CROWD}: while a robot is dragged each move predicts ${DRAG_HORIZON_S} s ahead at most (${during.map((h) => h.toFixed(2)).join(', ')} s; ${full.toFixed(2)} s before)`,
  );
  check(
    released > DRAG_HORIZON_S,
    `${DRAG_CROWD}: the release predicts in full again (${released.toFixed(2)} s ahead)`,
  );
  check(
    moved[0] < start.world[0] - 0.1,
    `${DRAG_CROWD}: the drag moved robot 1 (x ${start.world[0].toFixed(2)} → ${moved[0].toFixed(2)})`,
  );

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

  // --- A figure's far `time`: sliced on load and on change, the page responsive. ---
  const farLoaded = addFarFigure(page);
  await page.waitForFunction((sel) => {
    const box = document.querySelector(sel)?.shadowRoot.querySelector('[data-id="seek"]');
    return box && !box.hidden;
  }, FAR);
  const first = await farProgress(page);
  await page.waitForFunction(
    ([sel, v]) => document.querySelector(sel).shadowRoot.querySelector('[data-id="seek-bar"]').value > v + 0.2,
    [FAR, first.value],
  );
  const later = await farProgress(page);
  check(
    first && later && /Going to t = 150\.0 s/.test(first.text) && later.value > first.value && later.value < 1,
    `time="${FAR_TIME_S}" on a ${SEEK_CROWD} figure seeks in slices with its progress ("${first?.text}", then ${((later?.value ?? 0) * 100).toFixed(0)} %)`,
  );
  check(
    later && later.frames - first.frames >= 3 && later.timers - first.timers >= 3,
    `the page answers while it seeks: ${later.frames - first.frames} of its animation frames and ${later.timers - first.timers} of its timer ticks ran`,
  );
  await farLoaded;
  const atLoad = await farAgainst(page, FAR_TIME_S);
  check(
    Math.abs(atLoad.shown.time - FAR_TIME_S) < TIME_ROUNDING_S && atLoad.same && (await farProgress(page)) === null,
    `loaded resolves at t = ${atLoad.shown.time} s with the poses of a synchronous seek(${FAR_TIME_S}), the progress hidden`,
  );
  // A changed `time` seeks in slices too (the synchronous seek above left the clock there).
  const changed = FAR_TIME_S - 50;
  await page.evaluate(([sel, t]) => document.querySelector(sel).setAttribute('time', String(t)), [FAR, changed]);
  await page.waitForFunction(
    (sel) => document.querySelector(sel).shadowRoot.querySelector('[data-id="seek"]').hidden === false,
    FAR,
  );
  await page.waitForFunction(
    ([sel, t]) =>
      Math.abs(document.querySelector(sel).time - t) < 1e-6 &&
      document.querySelector(sel).shadowRoot.querySelector('[data-id="seek"]').hidden,
    [FAR, changed],
  );
  const atChange = await farAgainst(page, changed);
  check(atChange.same, `time="${changed}" set later seeks in slices to the poses of a synchronous seek(${changed})`);
  const reached = await page.evaluate(([sel, t]) => document.querySelector(sel).seekTo(t), [FAR, changed + 0.004]);
  const bad = await page.evaluate(
    (sel) =>
      document
        .querySelector(sel)
        .seekTo('x')
        .then(
          () => '',
          (e) => e.message,
        ),
    FAR,
  );
  check(
    Math.abs(reached - changed) < TIME_ROUNDING_S && /time must be a number/.test(bad),
    `seekTo(${changed + 0.004}) resolves to t = ${reached} s; seekTo('x') rejects: "${bad}"`,
  );
  checkQuiet(page, 'the crowd page');
  await page.context().close();
});
