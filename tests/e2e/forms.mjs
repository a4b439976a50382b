// End-to-end tests of what the playground's forms and canvas say: the numbers in the "By
// number" boxes (rounded to what a box shows whole, exact on focus, never changed by the
// rounding), the messages of the number fields (what is wrong with the typed text, one message
// per limit, in the panel's names), θ(0) in radians, round new obstacles and no "-0.00", the
// R_s < 2·r_ij warning, the marks of a run's violations and their count over the canvas, Pin
// for the crowds it refuses, the plots' tick labels, and the header's link to the book. The
// release package in www/pkg (`make build-wasm`), served by python3's http.server, driven in
// Debian's Chromium. Behaviour only; everything it writes goes to test-results/.
//
// Run: make test-e2e   (or: node tests/e2e/forms.mjs after make build-wasm)

import { execFileSync } from 'node:child_process';
import { check, checkQuiet, frames, join, RESULTS, ROOT, run, scenarioOf, waitLoaded } from './lib.mjs';

const VIEWPORT = { width: 1280, height: 800 };
const PG = 'dvf-playground';
/** The colour of a violation's mark (www/render/marks.js) and how far a pixel may be from it. */
const MARK_RGB = [220, 38, 38];
const MARK_COLOUR_TOLERANCE = 40;
/** A mark is seen when at least this many of its pixels are near its place (its ring alone has ~80). */
const MIN_MARK_PIXELS = 40;

/** A locator inside the playground's shadow root (Playwright's CSS pierces open shadow roots). */
const part = (page, id) => page.locator(`${PG} [data-id="${id}"]`);

/** Runs one item's checks; an exception fails the item and the others still run. */
async function item(name, body) {
  console.log(`-- ${name}`);
  try {
    await body();
  } catch (e) {
    check(false, `${name}: ${e.message.split('\n')[0]}`);
  }
}

/** Robot 1 at a start whose numbers do not fit a box: x ≈ −8.7e−7, y ≈ 7, θ with 10 digits. */
const ODD_START = [-8.744123456e-7, 6.9999999999, 0.1234567891];
const ODD_SCENE = {
  name: 'numbers',
  robots: [
    { start: ODD_START, goal: [20, 0, 0] },
    { start: [0, -20, 0], goal: [20, -20, 0] },
  ],
  duration: 20,
};
/** Two robots head-on, blind to each other (R_s < 2·r_ij, no barrier): they collide near (0, 0). */
const COLLISION = {
  name: 'collision',
  robots: [
    { start: [-10, 0, 0], goal: [10, 0, 0] },
    { start: [10, 0.2, Math.PI], goal: [-10, 0.2, Math.PI] },
  ],
  params: { safe_radius: 1, avoid_radius: 1.5, sense_radius: 0.5, barrier_rate: null },
  duration: 20,
};

await run(async ({ base, newPage }) => {
  const page = await newPage({ viewport: VIEWPORT });
  await page.goto(`${base}/`);
  await waitLoaded(page);
  await page.waitForSelector('body[data-ready]');

  /** The text of `input` fits in its box (its font, its width less its padding). */
  const fits = (id) =>
    page.evaluate(
      ([sel, name]) => {
        const input = document.querySelector(sel).shadowRoot.querySelector(`input[name="${name}"]`);
        const style = getComputedStyle(input);
        const ctx = document.createElement('canvas').getContext('2d');
        ctx.font = `${style.fontStyle} ${style.fontWeight} ${style.fontSize} ${style.fontFamily}`;
        const room = input.clientWidth - Number.parseFloat(style.paddingLeft) - Number.parseFloat(style.paddingRight);
        return { text: input.value, width: ctx.measureText(input.value).width, room };
      },
      [PG, id],
    );
  const load = async (scenario) => {
    await page.evaluate(([sel, s]) => document.querySelector(sel).load(s), [PG, scenario]);
    await frames(page);
  };
  const clickWorld = async (x, y) => {
    const p = await page.evaluate(([sel, x, y]) => document.querySelector(sel).worldToScreen(x, y), [PG, x, y]);
    await page.mouse.click(p.x, p.y);
    await frames(page);
  };
  const box = (name) => page.locator(`${PG} input[name="${name}"]`);
  const errorText = (form) => page.locator(`${PG} [data-id="${form}"] .param-error`).textContent();

  await item('by-number boxes', async () => {
    await load(ODD_SCENE);
    await clickWorld(0, 7);
    const x = await fits('selection-x');
    check(x.width <= x.room, `x = −8.744e−7 fits its box: "${x.text}" (${x.width.toFixed(1)} of ${x.room} px)`);
    check(
      Math.abs(Number(x.text) - ODD_START[0]) <= 1e-8,
      `x's box shows the value rounded, not another ("${x.text}", within 1e-8 m)`,
    );
    const y = await fits('selection-y');
    check(y.text === '7', `y = 6.9999999999 shows "7" (${y.text})`);
    const theta = await fits('selection-theta');
    check(theta.width <= theta.room, `θ fits its box ("${theta.text}")`);
    await box('selection-x').focus();
    await frames(page);
    const focused = await box('selection-x').inputValue();
    check(Number(focused) === ODD_START[0], `on focus the x box shows the exact value (${focused})`);
    await box('selection-y').focus();
    await frames(page);
    const after = (await scenarioOf(page)).robots[0].start;
    check(
      after[0] === ODD_START[0] && after[1] === ODD_START[1] && after[2] === ODD_START[2],
      `a blur without an edit changes no value (${after.join(', ')})`,
    );
    check((await box('selection-x').inputValue()) === x.text, 'after the blur x shows its rounded text again');
    await box('selection-y').fill('8');
    await box('selection-y').press('Enter');
    await frames(page);
    const moved = (await scenarioOf(page)).robots[0].start;
    check(
      moved[0] === ODD_START[0] && moved[1] === 8 && moved[2] === ODD_START[2],
      `typing y = 8 moves y only, x and θ keep their exact values (${moved.join(', ')})`,
    );
  });

  await item('number fields say what is wrong', async () => {
    await page.evaluate((sel) => document.querySelector(sel).loadPreset('example4-obstacle-formation'), PG);
    await frames(page);
    const said = {};
    for (const typed of ['abc', 'NaN', '1e400', '2e6', '1e6']) {
      await box('duration').fill(typed);
      await box('duration').press('Enter');
      await frames(page);
      said[typed] = await errorText('params');
      check(
        (await box('duration').inputValue()) === typed,
        `T = ${typed}: the typed text stays (${await box('duration').inputValue()})`,
      );
      check(
        !/duration|params\.|a value is needed/.test(said[typed]),
        `T = ${typed}: the message uses the panel's names and does not ask for a value: "${said[typed]}"`,
      );
    }
    check(/^T: not a number/.test(said.abc), `T = abc says "not a number": "${said.abc}"`);
    check(/^T: not a number/.test(said.NaN), `T = NaN says "not a number": "${said.NaN}"`);
    check(/^T: too large/.test(said['1e400']), `T = 1e400 says "too large": "${said['1e400']}"`);
    check(
      said['2e6'] === said['1e6'] && /at most 3600 s/.test(said['1e6']),
      `T = 2·10⁶ and T = 10⁶ give one message with the unit: "${said['2e6']}" / "${said['1e6']}"`,
    );
    check(said['1e400'].endsWith(said['1e6'].slice(3)), `T = 1e400 names the same limit: "${said['1e400']}"`);
    await box('duration').fill('40');
    await box('duration').press('Enter');
    await frames(page);
    await box('k_a').fill('2e6');
    await box('k_a').press('Enter');
    await frames(page);
    const ka = await errorText('params');
    check(/^k_a: must be at most 1e6 1\/s/.test(ka), `k_a = 2·10⁶ names its limit with the panel's unit: "${ka}"`);
    await box('k_a').fill('10');
    await box('k_a').press('Enter');
    await frames(page);
    await clickWorld(...(await scenarioOf(page)).robots[0].start.slice(0, 2));
    for (const [typed, expected] of [
      ['abc', /^x: not a number/],
      ['1e400', /^x: too large, must be at most 1e6 m in magnitude/],
      ['2e6', /^x: must be at most 1e6 m in magnitude/],
    ]) {
      await box('selection-x').fill(typed);
      await box('selection-x').press('Enter');
      await frames(page);
      const text = await errorText('selection');
      check(expected.test(text), `selection x = ${typed}: "${text}"`);
      check((await box('selection-x').inputValue()) === typed, `selection x = ${typed}: the typed text stays`);
    }
    await page.keyboard.press('Escape');
  });

  await item('θ(0) in radians', async () => {
    await page.evaluate((sel) => document.querySelector(sel).loadPreset('example4-obstacle-formation'), PG);
    await part(page, 'field').selectOption('curves');
    await frames(page);
    const theta0 = await part(page, 'theta0').inputValue();
    check(Math.abs(Number(theta0) - Math.PI / 2) < 1e-3, `θ(0) shows π/2 in radians (${theta0})`);
    const hint = await part(page, 'hint').textContent();
    check(/θ\(0\) = 1\.57 rad/.test(hint), `the hint gives θ(0) in rad: "${hint}"`);
    const degrees = await page.evaluate((sel) => {
      const root = document.querySelector(sel).shadowRoot;
      const texts = [root.textContent];
      for (const e of root.querySelectorAll('*')) {
        for (const a of ['title', 'aria-label', 'placeholder']) texts.push(e.getAttribute(a) ?? '');
      }
      return texts.filter((t) => /°|degree/i.test(t));
    }, PG);
    check(
      degrees.length === 0,
      `no text, tooltip or label of the playground speaks of degrees (${degrees.join(' | ')})`,
    );
    await part(page, 'theta0').fill('-1.5708');
    await part(page, 'theta0').press('Enter');
    await frames(page);
    const view = await page.evaluate((sel) => document.querySelector(sel).viewState(), PG);
    check(view.theta0 === -1.5708, `θ(0) is typed in radians (viewState θ(0) = ${view.theta0})`);
    await part(page, 'theta0').fill('abc');
    await part(page, 'theta0').press('Enter');
    await frames(page);
    const message = await part(page, 'message-text').textContent();
    check(
      /θ\(0\): not a number/.test(message) && (await part(page, 'theta0').inputValue()) === 'abc',
      `θ(0) = abc keeps the text and says what is wrong: "${message}"`,
    );
    await part(page, 'field').selectOption('arrows');
  });

  await item('round new obstacles, no "-0.00"', async () => {
    await page.evaluate((sel) => document.querySelector(sel).loadPreset('example4-obstacle-formation'), PG);
    await frames(page);
    for (let k = 0; k < 3; k++) await part(page, 'add-obstacle').click();
    const obstacles = (await scenarioOf(page)).obstacles.slice(-3);
    for (const o of obstacles) {
      const round = (v, places) => Math.abs(v * 10 ** places - Math.round(v * 10 ** places)) < 1e-9;
      check(
        Number(o.radius.toPrecision(2)) === o.radius && o.influence === 2 * o.radius,
        `a new obstacle's radius is round (r_o = ${o.radius}, R_o = ${o.influence})`,
      );
      check(
        round(o.center[0], 1) && round(o.center[1], 1) && String(o.center).length <= 16,
        `a new obstacle's centre is on a round grid (${o.center.join(', ')})`,
      );
    }
    await part(page, 'undo').click();
    await part(page, 'undo').click();
    await part(page, 'undo').click();
    // The inspected robot's line over a whole run: a speed or turn rate rounding to zero is "0.00".
    const negativeZero = await page.evaluate(async (sel) => {
      const el = document.querySelector(sel);
      const seen = [];
      const info = el.shadowRoot.querySelector('[data-id="robot-info"]');
      const frame = () => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
      for (let k = 0; k < 40; k++) {
        el.step(50);
        for (let i = 0; i < el.robotCount; i++) {
          el.focusRobot = i;
          await frame();
          if (/-0\.00\b/.test(info.textContent)) seen.push(info.textContent);
        }
      }
      return seen;
    }, PG);
    check(
      negativeZero.length === 0,
      `no "-0.00" in the inspected robot's line over the run (${negativeZero[0] ?? 'none'})`,
    );
    const fixed = await page.evaluate(async () => (await import('./panels/format.js')).fixed(-0.001, 2));
    check(fixed === '0.00', `−0.001 at two decimals reads "0.00" (${fixed})`);
  });

  await item('R_s < 2·r_ij warns', async () => {
    await page.evaluate((sel) => document.querySelector(sel).loadPreset('example4-obstacle-formation'), PG);
    await frames(page);
    const warning = part(page, 'gain-warning');
    const before = (await warning.isVisible()) ? await warning.textContent() : '';
    check(!/R_s/.test(before), `R_s = 20 m with r_ij = 5 m: no R_s warning ("${before}")`);
    await box('sense_radius').fill('8');
    await box('sense_radius').press('Enter');
    await frames(page);
    const text = (await warning.isVisible()) ? await warning.textContent() : '';
    check(/R_s < 2·r_ij/.test(text), `R_s = 8 m < 2·r_ij = 10 m warns: "${text}"`);
    await part(page, 'undo').click();
  });

  await item('violations marked on the canvas', async () => {
    await load(COLLISION);
    const button = part(page, 'violations');
    await button.waitFor({ state: 'visible' });
    const label = await button.textContent();
    const where = await page.locator(`${PG} [data-id="results"]`).textContent();
    check(/^⚠ \d+ violations?: go to t = [\d.]+ s$/.test(label), `the violation count is over the canvas: "${label}"`);
    check(
      /where: robots 1 and 2 [\d.]+ m apart at t = [\d.]+ s/.test(where),
      `the results say where (${where.match(/where: robots 1 and 2 [\d.]+ m apart at t = [\d.]+ s/)?.[0]})`,
    );
    const inView = await button.boundingBox();
    check(
      inView && inView.y >= 0 && inView.y + inView.height <= VIEWPORT.height,
      `the count is visible without scrolling (at y = ${inView?.y.toFixed(0)} px)`,
    );
    const markTime = Number(label.match(/t = ([\d.]+) s/)[1]);
    /** Pixels of the mark's colour within 30 px of the world point (0, 0.1), where the robots meet. */
    const markPixels = () =>
      page.evaluate(
        ([sel, rgb, tolerance]) => {
          const el = document.querySelector(sel);
          const c = el.shadowRoot.querySelector('[data-id="canvas"]');
          const rect = c.getBoundingClientRect();
          const p = el.worldToScreen(0, 0.1);
          const dpr = c.width / c.clientWidth;
          const copy = document.createElement('canvas');
          copy.width = c.width;
          copy.height = c.height;
          const cc = copy.getContext('2d', { willReadFrequently: true });
          cc.drawImage(c, 0, 0);
          const x0 = Math.round((p.x - window.scrollX - rect.left - 30) * dpr);
          const y0 = Math.round((p.y - window.scrollY - rect.top - 30) * dpr);
          const { data } = cc.getImageData(x0, y0, Math.round(60 * dpr), Math.round(60 * dpr));
          let n = 0;
          for (let i = 0; i < data.length; i += 4) {
            if (Math.hypot(data[i] - rgb[0], data[i + 1] - rgb[1], data[i + 2] - rgb[2]) < tolerance) n++;
          }
          return n;
        },
        [PG, MARK_RGB, MARK_COLOUR_TOLERANCE],
      );
    const marked = await markPixels();
    check(marked >= MIN_MARK_PIXELS, `the canvas marks where the robots collide (${marked} pixels of the mark)`);
    await page.screenshot({ path: join(RESULTS, 'forms-violation-mark.png') });
    await button.click();
    await frames(page);
    const state = await page.evaluate((sel) => {
      const el = document.querySelector(sel);
      return { time: el.time, robot: el.focusRobot, dt: el.scenario().dt };
    }, PG);
    check(
      Math.abs(state.time - markTime) <= state.dt + 0.005 && (state.robot === 0 || state.robot === 1),
      `the count's button goes to the violation (t = ${state.time.toFixed(3)} s, mark at ${markTime} s, robot ${state.robot + 1} inspected)`,
    );
    await page.screenshot({ path: join(RESULTS, 'forms-violation-there.png') });
    await page.evaluate((sel) => document.querySelector(sel).loadPreset('example4-obstacle-formation'), PG);
    await frames(page);
    check(await button.isHidden(), 'a scene without violations shows no count');
    // An intrusion into an obstacle, from a recorded run made by hand: robot 2 is 0.8 m inside
    // the disc at t = 0.2 s, robot 1 never near it; the robots stay 10 m apart (no pair mark).
    const intrusion = await page.evaluate(async () => {
      const { findViolations } = await import('./playground/violations.js');
      const row = (t, x, y) => [t, x, y, 0, 0, 0];
      const trajectories = new Float64Array([
        ...row(0, 0, 10),
        ...row(0.1, 1, 10),
        ...row(0.2, 2, 10),
        ...row(0, 3, 0),
        ...row(0.1, 4, 0),
        ...row(0.2, 5.2, 0),
      ]);
      const scenario = {
        robots: [{}, {}],
        obstacles: [{ center: [5, 0], radius: 1, influence: 2 }],
        params: { safe_radius: 1 },
      };
      return findViolations(trajectories, 3, scenario, { min_pair_distance: 10, min_obstacle_clearance: -0.8 });
    });
    const m = intrusion[0];
    check(
      intrusion.length === 1 &&
        m.kind === 'obstacle' &&
        m.robots[0] === 1 &&
        m.obstacle === 0 &&
        m.time === 0.2 &&
        Math.abs(m.distance - 0.8) < 1e-12 &&
        m.x === 5.2,
      `an obstacle intrusion is marked at the robot, its time and depth (${JSON.stringify(intrusion)}; depth to 1e-12 m: one subtraction)`,
    );
  });

  await item('Pin for the crowds it refuses', async () => {
    await page.evaluate((sel) => document.querySelector(sel).loadPreset('crowd-1000'), PG);
    await frames(page);
    const pin = part(page, 'pin');
    const title = await pin.getAttribute('title');
    check(await pin.isDisabled(), `Pin is disabled for the crowd of 1,000 ("${title}")`);
    check(/up to 100 robots/.test(title ?? ''), 'its title says why');
    await page.evaluate((sel) => document.querySelector(sel).loadPreset('example4-obstacle-formation'), PG);
    await frames(page);
    check(await pin.isEnabled(), 'Pin is offered for Example 4 (10 robots)');
  });

  await item('plot ticks', async () => {
    /** Each value label of the plots as drawn: its text, and whether it fits left of its axis. */
    const labels = () =>
      page.evaluate((sel) => {
        const el = document.querySelector(sel);
        const ctx = document.createElement('canvas').getContext('2d');
        ctx.font = '10.5px system-ui, sans-serif';
        return el.plotGeometry.map((g) => ({
          left: (g.valueLabels ?? g.valueTicks.map(String)).map((t) => ({
            t,
            clear: g.x0 - 3 - ctx.measureText(t).width >= 0,
          })),
          labelled: (g.valueLabels ?? []).length,
          right: g.rightLabels ?? [],
          count: g.valueTicks.length,
        }));
      }, PG);
    await load({
      name: 'far',
      robots: [
        { start: [0, 0, 0], goal: [15000, 0, 0] },
        { start: [0, 50, 0], goal: [15000, 50, 0] },
      ],
      params: { k_a: 3 },
      duration: 60,
    });
    const far = await labels();
    const left = far.flatMap((g) => g.left);
    check(
      left.length > 0 && far.every((g) => g.labelled === g.count),
      `every value tick has a label (${left.map((l) => l.t).join(' ')})`,
    );
    check(
      left.every((l) => l.clear),
      `labels up to 15000 m fit left of the axis (clipped: ${
        left
          .filter((l) => !l.clear)
          .map((l) => l.t)
          .join(' ') || 'none'
      })`,
    );
    await load({ name: 'small heading', robots: [{ start: [0, 0, 1e-4], goal: [0, 0, 0] }], duration: 2 });
    const small = (await labels())[1].right;
    check(
      small.length >= 3 && new Set(small).size === small.length,
      `heading errors of 1e-4 rad get distinct ticks (${small.join(' ')})`,
    );
    const tick = await page.evaluate(async () => (await import('./panels/plots.js')).tickLabels([0, 0.00025, 0.0005]));
    check(new Set(tick).size === 3, `ticks 0, 2.5e-4, 5e-4 read apart (${tick.join(' ')})`);
  });

  await item('the book link after make serve', async () => {
    const recipe = execFileSync('make', ['-n', 'serve'], { cwd: ROOT, encoding: 'utf8' });
    check(/mdbook build/.test(recipe), '`make serve` builds the book');
    check(
      /^ln -sfn \.\.\/target\/book www\/book$/m.test(recipe),
      '`make serve` links the book into www/ whatever was built before',
    );
    const header = await page.locator('header').textContent();
    check(
      !/after make docs/.test(header),
      `the header's book link needs no other step ("${header.trim().slice(-60)}")`,
    );
  });

  checkQuiet(page, 'the forms page');
});
