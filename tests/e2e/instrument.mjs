// End-to-end tests of the playground as an instrument (the defects a first visit finds, the
// themes, time, results and editing by number): the release package, served, in Chromium.
// Behaviour only; screenshots go to test-results/ (instrument-*.png).
//
// Run: make test-e2e   (or: node tests/e2e/instrument.mjs after make build-wasm)

import { copyFileSync, readFileSync } from 'node:fs';
import * as lib from './lib.mjs';
import { check, checkQuiet, EXAMPLE4, frames, join, RESULTS, run, scenarioOf, waitLoaded } from './lib.mjs';

const PG = 'dvf-playground';
const DESKTOP = { width: 1280, height: 800 };
const PHONE = { width: 390, height: 844 };
/** Touch targets on a phone are at least this tall (CSS px; the platforms ask for about 44). */
const TOUCH_PX = 44;
/** WCAG's contrast for body text. */
const MIN_CONTRAST = 4.5;

const part = (page, id, sel = PG) => page.locator(`${sel} [data-id="${id}"]`);
const messageShown = (page, sel = PG) =>
  page.evaluate((s) => !document.querySelector(s).shadowRoot.querySelector('[data-id="message"]').hidden, sel);
const messageText = (page, sel = PG) =>
  page.evaluate((s) => document.querySelector(s).shadowRoot.querySelector('[data-id="message"]').textContent, sel);
const canvasRect = (page, sel = PG) =>
  page.evaluate((s) => {
    const r = document.querySelector(s).shadowRoot.querySelector('[data-id="canvas"]').getBoundingClientRect();
    return [r.x, r.y, r.width, r.height];
  }, sel);
/** Page point of world point (x, y) of the playground `sel`, in viewport coordinates. */
const screenOf = (page, x, y, sel = PG) =>
  page.evaluate(
    ([s, x, y]) => {
      const p = document.querySelector(s).worldToScreen(x, y);
      return [p.x - window.scrollX, p.y - window.scrollY];
    },
    [sel, x, y],
  );

/** Relative luminance contrast of two `rgb(…)` colours. */
function contrast(a, b) {
  const lum = (c) => {
    const [r, g, bl] = c
      .match(/[\d.]+/g)
      .slice(0, 3)
      .map((v) => {
        const s = Number(v) / 255;
        return s <= 0.03928 ? s / 12.92 : ((s + 0.055) / 1.055) ** 2.4;
      });
    return 0.2126 * r + 0.7152 * g + 0.0722 * bl;
  };
  const [hi, lo] = [lum(a), lum(b)].sort((x, y) => y - x);
  return (hi + 0.05) / (lo + 0.05);
}

/** The text colour of the first element matching `css` in the shadow root, and the background behind it. */
function colours(page, css, sel = PG) {
  return page.evaluate(
    ([s, css]) => {
      let e = document.querySelector(s).shadowRoot.querySelector(css);
      const fg = getComputedStyle(e).color;
      let bg = 'rgba(0, 0, 0, 0)';
      while (e) {
        const b = getComputedStyle(e).backgroundColor;
        if (!b.startsWith('rgba(0, 0, 0, 0)') && b !== 'transparent') {
          bg = b;
          break;
        }
        e = e.parentElement ?? /** @type {any} */ (e.getRootNode()).host ?? null;
      }
      return { fg, bg: bg === 'rgba(0, 0, 0, 0)' ? getComputedStyle(document.body).backgroundColor : bg };
    },
    [sel, css],
  );
}

/** Opens the main page on `fragment` and waits for it. */
async function openMain(newPage, base, fragment = '', options = {}) {
  const page = await newPage({ viewport: DESKTOP, ...options });
  await page.goto(`${base}/${fragment}`);
  await waitLoaded(page);
  await page.waitForSelector('body[data-ready]');
  return page;
}

/** Loads the crowd of `n` through the toolbar. */
async function loadCrowd(page, n) {
  await part(page, 'preset').selectOption('crowd');
  await part(page, 'crowd-n').fill(String(n));
  await part(page, 'crowd-n').press('Enter');
  await page.waitForFunction(([s, n]) => document.querySelector(s).scenario().robots.length === n, [PG, n]);
}

/** Edits the scene from the parameters panel: k_v = 1.5. */
async function editScene(page) {
  const kv = page.locator(`${PG} input[name="k_v"]`);
  await kv.fill('1.5');
  await kv.press('Enter');
  await frames(page);
}

/** Runs one group of checks; an exception in it fails that group only. */
async function section(what, body) {
  try {
    await body();
  } catch (e) {
    check(false, `${what}: ${e.stack ?? e}`);
  }
}

await run(async ({ base, newPage }) => {
  // ---- Defect 1: a big edited scene saves to a file and opens again; the link says why not.
  await section('big scenes', async () => {
    const page = await openMain(newPage, base);
    for (const n of [1000, 10000]) {
      await loadCrowd(page, n);
      await editScene(page);
      const edited = await scenarioOf(page);
      const shown = await messageShown(page);
      const text = await messageText(page);
      check(
        shown && /too (big|long) for a link/.test(text) && text.includes('Scenario JSON'),
        `an edited crowd of ${n} says that it is too big for a link and offers the file ("${text.slice(0, 100)}")`,
      );
      const [download] = await Promise.all([page.waitForEvent('download'), part(page, 'export-json').click()]);
      const path = await download.path();
      await part(page, 'preset').selectOption(EXAMPLE4);
      const importStart = Date.now();
      await part(page, 'import-file').setInputFiles(path);
      await page.waitForFunction(([s, n]) => document.querySelector(s).scenario().robots.length === n, [PG, n]);
      console.log(`  the crowd of ${n} imported in ${Date.now() - importStart} ms`);
      const back = await scenarioOf(page);
      // The file's numbers as JavaScript reads them are the core's: the export writes the
      // shortest digits and the core reads them back to the same bits, with no pass after.
      const file = JSON.parse(readFileSync(path, 'utf8'));
      check(
        JSON.stringify(file) === JSON.stringify(back),
        `the numbers of the exported crowd of ${n} are the numbers the core imported, to the bit`,
      );
      if (JSON.stringify(back) !== JSON.stringify(edited)) {
        const a = JSON.stringify(back);
        const b = JSON.stringify(edited);
        let k = 0;
        while (a[k] === b[k]) k++;
        console.log(`  differ at ${k}: ${a.slice(k - 80, k + 80)}\n  against ${b.slice(k - 80, k + 80)}`);
      }
      check(
        JSON.stringify(back) === JSON.stringify(edited),
        `the exported crowd of ${n} (${readFileSync(path).length} bytes) imports back to the same scenario`,
      );
    }
    checkQuiet(page, 'big scenes');
    await page.context().close();
  });

  // ---- Defect 2: the CSV is the command line's format; a crowd's is refused with its size.
  await section('CSV', async () => {
    const page = await openMain(newPage, base);
    const s = await scenarioOf(page);
    const [dl] = await Promise.all([page.waitForEvent('download'), part(page, 'export-csv').click()]);
    const rows = readFileSync(await dl.path(), 'utf8')
      .trim()
      .split('\n');
    const times = [...new Set(rows.slice(1).map((r) => Number(r.split(',')[0])))];
    const steps = Math.round(s.duration / s.dt);
    // The times are written as `dvf simulate --csv` writes them: the decimal k·dt, exactly
    // (`0.35`, never `0.35000000000000003`), so a reader's `t == 0.35` holds.
    const decimals = (String(s.dt).split('.')[1] ?? '').length;
    const noisy = times.filter((t, k) => String(t) !== String(Number((k * s.dt).toFixed(decimals))));
    check(
      rows[0] === 't,robot,x,y,theta,v,omega' &&
        rows[1].startsWith('0,0,') &&
        rows[2].startsWith('0,1,') &&
        times.length === steps + 1 &&
        noisy.length === 0 &&
        rows.length - 1 === (steps + 1) * s.robots.length,
      `the CSV is t,robot,… with a row per robot at every decimal k·dt (${times.length} times, ${rows.length - 1} rows, ${noisy.length} not decimal: ${noisy.slice(0, 3)})`,
    );
    await loadCrowd(page, 1000);
    let downloaded = false;
    page.on('download', () => {
      downloaded = true;
    });
    await part(page, 'export-csv').click();
    await frames(page);
    const text = await messageText(page);
    check(
      !downloaded && /\d+(\.\d+)? [MG]B/.test(text) && text.includes('dvf simulate'),
      `the crowd's CSV is refused up front with its size ("${text.slice(0, 120)}")`,
    );
    checkQuiet(page, 'CSV');
    await page.context().close();
  });

  // ---- Defect 3: a bad src or preset keeps its message (and shows no other scene instead:
  // tests/e2e/figures.mjs), so `loaded` resolves with no scene to wait for.
  for (const [what, attrs, expected] of [
    ['a src that is missing', { src: 'scenarios/no-such-file.json' }, 'HTTP 404'],
    ['a src that is an HTML page', { src: 'index.html' }, 'HTML'],
    ['an unknown preset', { preset: 'no-such-preset' }, 'no preset named'],
  ]) {
    await section(what, async () => {
      const page = await newPage({ viewport: DESKTOP });
      await page.goto(`${base}/embed.html`);
      await waitLoaded(page, '#swap');
      await page.evaluate((attrs) => {
        const el = document.createElement('dvf-playground');
        el.id = 'bad';
        for (const [k, v] of Object.entries(attrs)) el.setAttribute(k, v);
        document.body.prepend(el);
      }, attrs);
      await page.evaluate(() => document.getElementById('bad').loaded);
      await page.waitForTimeout(300);
      await frames(page);
      const text = await messageText(page, '#bad');
      check(
        (await messageShown(page, '#bad')) && text.includes(expected),
        `${what} keeps its message after loading ("${text.slice(0, 100)}")`,
      );
      await page.context().close();
    });
  }

  // ---- Defect 4: a message over the canvas never moves it; a drag lands where released.
  await section('drag', async () => {
    const page = await openMain(newPage, base);
    const s = await scenarioOf(page);
    const rect0 = await canvasRect(page);
    const [sx, sy] = s.robots[0].start;
    const o = s.obstacles[0];
    const from = await screenOf(page, sx, sy);
    const onObstacle = await screenOf(page, o.center[0], o.center[1]);
    const to = await screenOf(page, sx, sy - 3);
    await page.mouse.move(...from);
    await page.mouse.down();
    for (let k = 1; k <= 10; k++) {
      await page.mouse.move(
        from[0] + ((onObstacle[0] - from[0]) * k) / 10,
        from[1] + ((onObstacle[1] - from[1]) * k) / 10,
      );
    }
    await frames(page);
    const during = await messageShown(page);
    const robotMsg = await messageText(page);
    check(
      /robot 1\b/.test(robotMsg) && /obstacle 1\b/.test(robotMsg) && !robotMsg.includes('['),
      `messages number robots and obstacles from 1, as the panels do ("${robotMsg.slice(0, 90)}")`,
    );
    const rect1 = await canvasRect(page);
    for (let k = 1; k <= 10; k++) {
      await page.mouse.move(
        onObstacle[0] + ((to[0] - onObstacle[0]) * k) / 10,
        onObstacle[1] + ((to[1] - onObstacle[1]) * k) / 10,
      );
    }
    await frames(page);
    await page.mouse.up();
    await frames(page);
    const after = await scenarioOf(page);
    const [ex, ey] = after.robots[0].start;
    const landed = await screenOf(page, ex, ey);
    // Where released, within 1.5 CSS px (the pointer's rounding to whole pixels).
    const miss = Math.hypot(landed[0] - to[0], landed[1] - to[1]);
    check(
      during && JSON.stringify(rect0) === JSON.stringify(rect1),
      `a refused position shows its message over the canvas without moving it (${rect0} → ${rect1})`,
    );
    check(
      miss <= 1.5 && !(await messageShown(page)),
      `the robot lands where released (${miss.toFixed(2)} px off) and no message stays`,
    );
    checkQuiet(page, 'drag over an obstacle');
    await page.context().close();
  });

  // ---- Defect 5: keys work anywhere in the element and stop there.
  await section('keys', async () => {
    const page = await openMain(newPage, base);
    await page.evaluate(() => {
      window.leaked = [];
      document.addEventListener('keydown', (e) => window.leaked.push(e.key));
    });
    const robots = async () => (await scenarioOf(page)).robots.length;
    const n0 = await robots();
    await part(page, 'add-robot').click();
    const n1 = await robots();
    await page.keyboard.press('Control+z');
    const n2 = await robots();
    check(n1 === n0 + 1 && n2 === n0, `Ctrl+Z after "+ Robot" undoes the add (${n0} → ${n1} → ${n2})`);
    await part(page, 'preset').selectOption('example3-circle-swap');
    await page.keyboard.press('a');
    const n3 = await robots();
    await page.keyboard.press('Delete');
    const n4 = await robots();
    check(n3 === 7 && n4 === 6, `after choosing a preset, A adds and Delete removes a robot (${n3}, ${n4})`);
    await page.keyboard.press('s');
    const t = await page.evaluate((s) => document.querySelector(s).cache.time, PG);
    await page.keyboard.press('r');
    const t0 = await page.evaluate((s) => document.querySelector(s).cache.time, PG);
    check(t > 0 && t0 === 0, `S and R step and reset from the toolbar (t = ${t}, then ${t0})`);
    const kv = page.locator(`${PG} input[name="k_v"]`);
    await kv.focus();
    await page.keyboard.press('a');
    check((await robots()) === 6, 'typing A in a parameter field adds no robot');
    const leaked = await page.evaluate(() => window.leaked);
    check(
      !leaked.some((k) => ['z', 'Z', 'Delete', 's', 'r'].includes(k)),
      `the keys the element handles do not reach the page (the page saw: ${leaked.join(' ') || 'none'})`,
    );
    checkQuiet(page, 'keys');
    await page.context().close();
  });

  // ---- Defect 6: parameter messages speak of the labels, keep the text, go when fixed.
  await section('parameters', async () => {
    const page = await openMain(newPage, base);
    const field = (name) => page.locator(`${PG} input[name="${name}"]`);
    const error = () => part(page, 'params').locator('.param-error');
    await field('avoid_radius').fill('-1');
    await field('avoid_radius').press('Enter');
    const msg = await error().textContent();
    check(
      msg.includes('R_c') && !msg.includes('params.') && (await field('avoid_radius').inputValue()) === '-1',
      `a refused R_c names R_c and keeps the typed text ("${msg}")`,
    );
    await field('k_v').fill('2');
    await field('k_v').press('Enter');
    const red = await page.locator(`${PG} [aria-invalid="true"]`).count();
    check(
      red === 0 && (await error().isHidden()),
      `a valid value elsewhere clears the marks and the message (${red} red)`,
    );
    check(
      (await field('dt').count()) === 1 && (await field('duration').count()) === 1,
      'dt and the duration are editable',
    );
    await field('dt').fill('0.02');
    await field('dt').press('Enter');
    check((await scenarioOf(page)).dt === 0.02, 'dt is set from its field');
    checkQuiet(page, 'parameters');
    await page.context().close();
  });

  // ---- Defect 7: layout on a phone, at 800 px, on a dark page, with a long clock.
  await section('layout', async () => {
    const phone = await newPage({ viewport: PHONE, isMobile: true, hasTouch: true, deviceScaleFactor: 2 });
    await phone.goto(`${base}/`);
    await waitLoaded(phone);
    const boxes = await phone.evaluate((s) => {
      const root = document.querySelector(s).shadowRoot;
      const r = (id) => root.querySelector(`[data-id="${id}"]`).getBoundingClientRect().toJSON();
      const small = [...root.querySelectorAll('button, select, input')]
        .filter((e) => e.offsetParent !== null && e.type !== 'checkbox' && e.type !== 'range')
        .map((e) => [e.dataset.id ?? e.name, e.getBoundingClientRect().height])
        .filter(([, h]) => h < 44);
      return { clock: r('clock'), title: r('title'), canvas: r('canvas'), small };
    }, PG);
    const overlap =
      boxes.clock.right > boxes.title.left &&
      boxes.title.right > boxes.clock.left &&
      boxes.clock.bottom > boxes.title.top &&
      boxes.title.bottom > boxes.clock.top;
    await phone.screenshot({ path: join(RESULTS, 'instrument-phone.png') });
    check(!overlap, 'on a phone the clock and the title do not overlap');
    check(
      boxes.canvas.height >= PHONE.height / 2,
      `on a phone the canvas gets most of the height (${boxes.canvas.height} of ${PHONE.height} px)`,
    );
    check(
      boxes.small.length === 0,
      `on a phone every control is at least ${TOUCH_PX} px tall (smaller: ${boxes.small.map(([id, h]) => `${id} ${h}`).join(', ') || 'none'})`,
    );
    checkQuiet(phone, 'phone');
    await phone.context().close();

    // An element 800 px wide (with its side panel) in a wider page, and a page 800 px wide.
    const narrow = await newPage({ viewport: DESKTOP });
    await narrow.goto(`${base}/embed.html`);
    await waitLoaded(narrow, '#swap');
    await narrow.evaluate(() => {
      const el = document.createElement('dvf-playground');
      el.id = 'narrow';
      el.setAttribute('controls', '');
      el.style.width = '800px';
      document.body.prepend(el);
    });
    await waitLoaded(narrow, '#narrow');
    const cut = await narrow.evaluate((s) => {
      const root = document.querySelector(s).shadowRoot;
      return [...root.querySelectorAll('.params input')]
        .filter((e) => e.getBoundingClientRect().width < 64)
        .map((e) => `${e.name} ${e.getBoundingClientRect().width.toFixed(0)}`);
    }, '#narrow');
    check(
      cut.length === 0,
      `at 800 px every parameter box shows six characters (narrower: ${cut.join(', ') || 'none'})`,
    );
    await narrow.context().close();

    const dark = await newPage({ viewport: DESKTOP });
    await dark.goto(`${base}/embed.html`);
    await waitLoaded(dark, '#swap');
    await dark.addStyleTag({ content: 'body { background: #111; color: #eee } dvf-playground { color: #eee }' });
    await dark.evaluate(() => {
      const el = document.createElement('dvf-playground');
      el.id = 'dark';
      el.setAttribute('controls', '');
      document.body.prepend(el);
    });
    await waitLoaded(dark, '#dark');
    for (const css of ['.param-name', '.toolbar label', '.legend span', 'h3']) {
      const { fg, bg } = await colours(dark, css, '#dark');
      const k = contrast(fg, bg);
      check(k >= MIN_CONTRAST, `on a dark page "${css}" is readable (contrast ${k.toFixed(1)}: ${fg} on ${bg})`);
    }
    await dark.screenshot({ path: join(RESULTS, 'instrument-dark-host.png') });
    await dark.context().close();
  });

  // ---- Defect 8: the plots say which line is which, their "now" lines line up, ticks.
  await section('plots', async () => {
    const page = await openMain(newPage, base);
    await page.evaluate((s) => document.querySelector(s).step(500), PG);
    await frames(page);
    const legend = await part(page, 'plots-legend')
      .textContent()
      .catch(() => '');
    check(
      legend.includes('position error') && legend.includes('heading error'),
      `the plots have a legend ("${legend}")`,
    );
    // The "now" lines read off the pixels too (the plots' canvas holds both, one above the
    // other; the line is NOW_COLOUR, #2563eb): where the blue columns of each half are.
    const nowColumns = await part(page, 'plots').evaluate((el) => {
      const canvas = el.tagName === 'CANVAS' ? el : el.querySelector('canvas');
      const { width, height } = canvas;
      const px = canvas.getContext('2d').getImageData(0, 0, width, height).data;
      const centre = (y0, y1) => {
        let sum = 0;
        let weight = 0;
        for (let y = y0; y < y1; y++) {
          for (let x = 0; x < width; x++) {
            const o = 4 * (y * width + x);
            const [r, g, b] = [px[o], px[o + 1], px[o + 2]];
            if (b > 180 && r < 110 && g < 160 && b - r > 120) {
              sum += x;
              weight += 1;
            }
          }
        }
        return weight > 10 ? sum / weight : Number.NaN;
      };
      return [centre(0, height >> 1), centre(height >> 1, height)].map((x) => (x * canvas.clientWidth) / width);
    });
    check(
      nowColumns.every(Number.isFinite) && Math.abs(nowColumns[0] - nowColumns[1]) < 1,
      `the two plots' "now" lines line up on the screen (x = ${nowColumns.map((x) => x.toFixed(1)).join(', ')} CSS px)`,
    );
    const geometry = await page.evaluate((s) => document.querySelector(s).plotGeometry ?? null, PG);
    check(
      geometry?.length === 2 && Math.abs(geometry[0].nowX - geometry[1].nowX) < 0.5,
      `the two plots' "now" lines line up (${geometry?.map((g) => g.nowX.toFixed(1)).join(', ')})`,
    );
    check(
      geometry?.every((g) => g.timeTicks.length >= 3 && g.valueTicks.length >= 3),
      `the axes have ticks between their ends (${geometry?.map((g) => `${g.timeTicks.length}/${g.valueTicks.length}`).join(', ')})`,
    );
    checkQuiet(page, 'plots');
    await page.context().close();
  });

  // ---- Defect 9: the small ones.
  await section('small', async () => {
    const page = await openMain(newPage, base);
    const border = () => part(page, 'robot-info').evaluate((e) => getComputedStyle(e).borderLeftColor);
    const first = await border();
    await part(page, 'add-robot').click();
    await frames(page);
    const eleventh = await border();
    check(first !== eleventh, `robot 11 has a colour of its own (${eleventh} against ${first})`);
    await part(page, 'add-obstacle').click();
    await part(page, 'add-obstacle').click();
    const obs = (await scenarioOf(page)).obstacles;
    const [a, b] = obs.slice(-2);
    const gap = Math.hypot(a.center[0] - b.center[0], a.center[1] - b.center[1]);
    check(
      gap > a.influence + b.influence,
      `a second "+ Obstacle" lands clear of the first (${gap.toFixed(2)} m apart)`,
    );
    const labels = await part(page, 'preset').evaluate((s) =>
      [...s.options].filter((o) => o.value.startsWith('example')).map((o) => o.textContent),
    );
    check(
      labels.length > 0 && labels.every((l) => /^Example \d/.test(l)),
      `the preset menu shows names, not slugs (${labels.join('; ')})`,
    );
    const legend = await part(page, 'legend').textContent();
    check(legend.includes('outside the bounds'), 'the legend explains the grey outside the bounds');
    await part(page, 'preset').selectOption('table1-free-space');
    await frames(page);
    const [ox, oy] = await screenOf(page, 0, 0);
    const picked = [];
    for (let k = 0; k < 3; k++) {
      await page.mouse.click(ox, oy);
      picked.push(await page.evaluate((s) => document.querySelector(s).focusRobot, PG));
    }
    check(
      new Set(picked).size === 3,
      `clicks on robots on top of one another pick each in turn (${picked.join(', ')})`,
    );
    checkQuiet(page, 'small defects');
    await page.context().close();
  });
  // ---- Themes: the system's, the attribute's, the page's custom properties; px sizes.
  await section('themes', async () => {
    const bg = (page, sel = PG) =>
      page.evaluate((s) => {
        const c = document.querySelector(s).shadowRoot.querySelector('[data-id="canvas"]');
        const copy = document.createElement('canvas');
        copy.width = 1;
        copy.height = 1;
        copy.getContext('2d').drawImage(c, 2, 2, 1, 1, 0, 0, 1, 1);
        return [...copy.getContext('2d').getImageData(0, 0, 1, 1).data.slice(0, 3)];
      }, sel);
    const lum = ([r, g, b]) => (r + g + b) / 3;
    const light = await openMain(newPage, base);
    const dark = await openMain(newPage, base, '', { colorScheme: 'dark' });
    const l = await bg(light);
    const d = await bg(dark);
    check(lum(l) > 150 && lum(d) < 80, `prefers-color-scheme picks the theme (canvas corner ${l} light, ${d} dark)`);
    await dark.screenshot({ path: join(RESULTS, 'instrument-dark.png') });
    await light.evaluate((s) => document.querySelector(s).setAttribute('theme', 'dark'), PG);
    await frames(light);
    const forced = await bg(light);
    check(lum(forced) < 80, `theme="dark" forces the dark theme (${forced})`);
    await dark.evaluate((s) => document.querySelector(s).setAttribute('theme', 'light'), PG);
    await frames(dark);
    const forcedLight = await bg(dark);
    check(lum(forcedLight) > 150, `theme="light" forces the light theme under a dark system (${forcedLight})`);
    await light.evaluate(
      (s) => document.querySelector(s).style.setProperty('--dvf-canvas-background', 'rgb(200, 0, 0)'),
      PG,
    );
    await light.evaluate((s) => document.querySelector(s).setAttribute('theme', 'light'), PG);
    await frames(light);
    const custom = await bg(light);
    check(custom[0] > 150 && custom[1] < 60, `--dvf-canvas-background colours the canvas (${custom})`);
    const h0 = await part(light, 'play').evaluate((e) => e.getBoundingClientRect().height);
    await light.addStyleTag({ content: 'html { font-size: 40px }' });
    await frames(light);
    const h1 = await part(light, 'play').evaluate((e) => e.getBoundingClientRect().height);
    check(h0 === h1, `the element's sizes do not follow the page's root font size (${h0} and ${h1} px)`);
    checkQuiet(light, 'themes (light)');
    checkQuiet(dark, 'themes (dark)');
    await light.context().close();
    await dark.context().close();
  });

  // ---- Time: the scrubber, a click on a plot, the stop once every robot is at its goal.
  await section('time', async () => {
    const page = await openMain(newPage, base);
    const time = () => page.evaluate((s) => document.querySelector(s).cache.time, PG);
    // A seek starts over from t = 0 at once and the clock is drawn on the next frame: wait
    // until the time has left `was`, the seek has ended and the clock shows the time reached.
    const settled = (was) =>
      page.waitForFunction(
        ([s, was]) => {
          const el = document.querySelector(s);
          const clock = el.shadowRoot.querySelector('[data-id="clock"]').textContent;
          const t = el.cache.time;
          return t !== was && !clock.includes('going') && clock.includes(`t = ${t.toFixed(2)} s`);
        },
        [PG, was],
      );
    const scrubber = part(page, 'scrubber');
    const start = await time();
    await scrubber.fill('500');
    await settled(start);
    const s = await scenarioOf(page);
    const half = await time();
    // The scrubber has 1,000 positions: the time is within one step of the middle.
    check(Math.abs(half - s.duration / 2) <= s.dt * 1.01, `the scrubber goes to the middle of the run (t = ${half})`);
    const box = await part(page, 'plots').boundingBox();
    const g = await page.evaluate((s) => document.querySelector(s).plotGeometry, PG);
    await page.mouse.click(box.x + g[0].x0 + (g[0].x1 - g[0].x0) * 0.2, box.y + box.height * 0.75);
    await settled(half);
    const fifth = await time();
    // A click lands on a whole CSS pixel of the axis: within one pixel's worth of time.
    const pxTime = s.duration / (g[0].x1 - g[0].x0);
    check(
      Math.abs(fifth - s.duration * 0.2) <= pxTime + s.dt,
      `a click on a plot goes to that time (t = ${fifth}, asked ${s.duration * 0.2})`,
    );
    const speeds = await part(page, 'speed').evaluate((e) => [...e.options].map((o) => Number(o.value)));
    check(Math.max(...speeds) >= 16, `the speeds go up to ${Math.max(...speeds)}×`);
    await part(page, 'speed').selectOption('32');
    await part(page, 'play').click();
    await page.waitForFunction(
      (s) =>
        !document.querySelector(s).cache ||
        document.querySelector(s).shadowRoot.querySelector('[data-id="play"]').textContent === 'Play',
      PG,
      { timeout: 30_000 },
    );
    const stopped = await time();
    const clock = await part(page, 'clock').textContent();
    check(
      stopped < s.duration && clock.includes('every robot at its goal'),
      `the run stops once every robot has converged ("${clock}")`,
    );
    checkQuiet(page, 'time');
    await page.context().close();
  });

  // ---- Results: what dvf simulate reports, copyable as JSON; editing by number.
  await section('results', async () => {
    const page = await openMain(newPage, base, '', { permissions: ['clipboard-read', 'clipboard-write'] });
    await page.waitForSelector(`${PG} [data-id="results"][data-ready]`);
    const text = await part(page, 'results').textContent();
    check(
      /10 of 10 robots converged/.test(text) && text.includes('violations'),
      `the results panel shows the report ("${text.slice(0, 80)}")`,
    );
    await part(page, 'copy-results').click();
    const copied = JSON.parse(await page.evaluate(() => navigator.clipboard.readText()));
    const expected = await page.evaluate(
      (s) =>
        import('./pkg/dvf.js').then((m) => {
          const r = new m.Run(document.querySelector(s).scenario());
          const rep = r.report();
          r.free();
          return rep;
        }),
      PG,
    );
    check(
      JSON.stringify(copied) === JSON.stringify(expected),
      'Copy JSON puts the report of dvf simulate on the clipboard',
    );
    // By number: a key on the canvas (] selects robot 1, Escape nothing), then a value typed.
    const byNumber = async (key, name, value) => {
      await part(page, 'canvas').focus();
      await page.keyboard.press(key);
      await frames(page);
      const input = page.locator(`${PG} input[name="selection-${name}"]`);
      await input.fill(value);
      await input.press('Enter');
    };
    await byNumber(']', 'x', '-70');
    const moved = (await scenarioOf(page)).robots[0].start[0];
    check(moved === -70, `the selected robot's x is set by number (${moved})`);
    await byNumber('Escape', 'xmax', '120');
    check((await scenarioOf(page)).bounds[2] === 120, 'with nothing selected, the bounds are set by number');
    checkQuiet(page, 'results');
    await page.context().close();
  });
  // ---- Help: ? shows the controls and keys over the canvas, Escape closes it.
  await section('help', async () => {
    const page = await openMain(newPage, base);
    await part(page, 'canvas').focus();
    await page.keyboard.press('?');
    const shown = await part(page, 'help-panel').isVisible();
    const text = await part(page, 'help-panel').textContent();
    await page.screenshot({ path: join(RESULTS, 'instrument-help.png') });
    await page.keyboard.press('Escape');
    const hidden = await part(page, 'help-panel').isHidden();
    await part(page, 'help').click();
    const again = await part(page, 'help-panel').isVisible();
    check(
      shown && text.includes('Space') && text.includes('Ctrl+Z') && hidden && again,
      'the ? key and button show the controls and keys; Escape closes them',
    );
    checkQuiet(page, 'help');
    await page.context().close();
  });
  // ---- The view in the link: field mode, θ(0), R_s, the inspected robot, the time, the box.
  await section('view in the link', async () => {
    const asked = '&field=curves&theta0=45&sensing=1&robot=3&t=5&view=-50,-40,50,40';
    const page = await openMain(newPage, base, `#${EXAMPLE4}${asked}`);
    await page.waitForFunction((s) => document.querySelector(s).viewState().time > 4.9, PG);
    await frames(page);
    const v = await page.evaluate((s) => document.querySelector(s).viewState(), PG);
    const s = await scenarioOf(page);
    // The box shown holds the box asked for, about the same centre (rounding: 1e-6 m).
    const holds =
      v.box && v.box[0] <= -50 + 1e-6 && v.box[2] >= 50 - 1e-6 && v.box[1] <= -40 + 1e-6 && v.box[3] >= 40 - 1e-6;
    const centred = v.box && Math.abs(v.box[0] + v.box[2]) < 1e-6 && Math.abs(v.box[1] + v.box[3]) < 1e-6;
    check(
      v.field === 'curves' &&
        v.theta0 === 45 &&
        v.sensing &&
        v.robot === 2 &&
        Math.abs(v.time - 5) <= s.dt &&
        holds &&
        centred,
      `a link opens its view (${JSON.stringify(v)})`,
    );
    await part(page, 'field').selectOption('none');
    await part(page, 'canvas').focus();
    await page.keyboard.press(']');
    await page.waitForFunction(() => location.hash.includes('field=none'));
    const hash = await page.evaluate(() => location.hash);
    const copy = await openMain(newPage, base, hash);
    await copy.waitForFunction((s) => document.querySelector(s).viewState().time > 4.9, PG);
    const w = await copy.evaluate((s) => document.querySelector(s).viewState(), PG);
    const v2 = await page.evaluate((s) => document.querySelector(s).viewState(), PG);
    check(
      w.field === 'none' && w.robot === v2.robot && Math.abs(w.time - v2.time) <= s.dt && w.theta0 === 45,
      `the address keeps the view for a copied link (${hash.split('&').slice(1).join('&')})`,
    );
    checkQuiet(page, 'view in the link');
    checkQuiet(copy, 'view in the copied link');
    await page.context().close();
    await copy.context().close();
  });
  // ---- Recording: a PNG at 4× with the title and time stamped in; an SVG; a WebM video.
  await section('recording', async () => {
    const page = await openMain(newPage, base);
    const cssWidth = await part(page, 'canvas').evaluate((e) => e.clientWidth);
    await part(page, 'png-scale').selectOption('4');
    const [png] = await Promise.all([page.waitForEvent('download'), part(page, 'export-png').click()]);
    copyFileSync(await png.path(), join(RESULTS, 'instrument-4x.png'));
    const bytes = readFileSync(await png.path());
    const width = bytes.readUInt32BE(16);
    check(width === cssWidth * 4, `the PNG at 4× is ${width} px wide for ${cssWidth} CSS px`);
    // SVG: the picture as vectors, mark for mark (the same painters: render/svg.js).
    const svgOf = async (p) => {
      const [d] = await Promise.all([p.waitForEvent('download'), part(p, 'export-svg').click()]);
      const text = readFileSync(await d.path(), 'utf8');
      return p.evaluate((t) => {
        const doc = new DOMParser().parseFromString(t, 'image/svg+xml');
        const root = doc.documentElement;
        const texts = [...doc.querySelectorAll('text')];
        return {
          ok: root.nodeName === 'svg' && !doc.querySelector('parsererror'),
          width: Number(root.getAttribute('width')),
          trailColours: new Set(
            [...doc.querySelectorAll('path[stroke-width="2.5"]')].map((e) => e.getAttribute('stroke')),
          ).size,
          texts: texts.map((e) => e.textContent),
          // Each number is drawn twice, its halo (stroked) under it (filled): the filled ones.
          numbers: texts
            .filter((e) => /600 11px/.test(e.getAttribute('style') ?? '') && e.getAttribute('fill') !== 'none')
            .map((e) => e.textContent),
        };
      }, text);
    };
    await page.evaluate((s) => document.querySelector(s).seek(10), PG);
    const svg = await svgOf(page);
    const title = await page.evaluate((s) => document.querySelector(s).scenario().name, PG);
    check(
      svg.ok && svg.width === cssWidth && svg.trailColours === 10 && svg.texts.some((t) => t.startsWith(title)),
      `SVG: a well-formed picture ${svg.width} px wide (canvas ${cssWidth}) with the 10 robots' trails (${svg.trailColours} colours) and the title stamped in`,
    );
    // Robot numbers: Example 4's safe discs are wide enough on screen to number its robots;
    // a crowd fitted in the view is not numbered until zoomed in.
    check(
      svg.numbers.length === 10 && svg.numbers.includes('1') && svg.numbers.includes('10'),
      `Example 4's robots are numbered from 1 on the canvas (${svg.numbers.join(' ')})`,
    );
    await loadCrowd(page, 100);
    const fitted = await svgOf(page);
    const x = await page.evaluate((s) => document.querySelector(s).scenario().robots[0].start, PG);
    await page.evaluate(
      ([s, [x0, y0]]) => document.querySelector(s).setViewState({ box: [x0 - 6, y0 - 4, x0 + 6, y0 + 4] }),
      [PG, x],
    );
    const zoomed = await svgOf(page);
    check(
      fitted.ok && fitted.numbers.length === 0 && zoomed.numbers.includes('1'),
      `a crowd of 100 is numbered only when zoomed in (${fitted.numbers.length} numbers fitted; zoomed: ${zoomed.numbers.join(' ')})`,
    );
    await part(page, 'preset').selectOption(EXAMPLE4);
    await part(page, 'record').click();
    await part(page, 'play').click();
    await page.waitForFunction((s) => document.querySelector(s).cache.time > 1.5, PG);
    const progress = await messageText(page);
    const [video] = await Promise.all([page.waitForEvent('download'), part(page, 'record').click()]);
    const webm = readFileSync(await video.path());
    check(
      webm.readUInt32BE(0) === 0x1a45dfa3 && webm.length > 1000 && /Recording: \d/.test(progress),
      `Record makes a WebM file (${webm.length} bytes, ${video.suggestedFilename()}) and shows its progress ("${progress.slice(0, 40)}")`,
    );
    checkQuiet(page, 'recording');
    await page.context().close();
  });
  // ---- Guidance: a warning beside gains known to fail.
  await section('gain warnings', async () => {
    const page = await openMain(newPage, base);
    const warning = part(page, 'gain-warning');
    const none = await warning.isHidden();
    const ka = page.locator(`${PG} input[name="k_a"]`);
    await ka.fill('1.5');
    await ka.press('Enter');
    const stall = (await warning.isVisible()) && (await warning.textContent()).includes('k_a ≤ 2·k_ω');
    const kv = page.locator(`${PG} input[name="k_v"]`);
    await kv.fill('3');
    await kv.press('Enter');
    const lag = (await warning.textContent()).includes('k_v > k_ω');
    await part(page, 'canvas').focus();
    await page.keyboard.press('Control+z');
    await page.keyboard.press('Control+z');
    const gone = await warning.isHidden();
    check(
      none && stall && lag && gone,
      'k_a ≤ 2·k_ω and k_v > k_ω are warned of beside the gains, and the warning goes with them',
    );
    checkQuiet(page, 'gain warnings');
    await page.context().close();
  });
  // ---- Comparison: a run pinned as a ghost, the scene changed, both runs and results.
  await section('comparison', async () => {
    const page = await openMain(newPage, base);
    await page.waitForSelector(`${PG} [data-id="results"][data-ready]`);
    const before = await lib.canvasStats(page);
    await part(page, 'pin').click();
    await page.waitForFunction(
      (s) => document.querySelector(s).shadowRoot.querySelector('[data-id="pin"]').textContent === 'Unpin',
      PG,
    );
    await frames(page);
    const pinned = await lib.canvasStats(page);
    const drawn = lib.changedFraction(before, pinned);
    await page.locator(`${PG} select[name="avoidance"]`).selectOption('paper');
    await page.waitForSelector(`${PG} [data-id="results"][data-ready]`);
    const ghostText = await part(page, 'pinned').textContent();
    const currentText = await part(page, 'results').textContent();
    await page.screenshot({ path: join(RESULTS, 'instrument-comparison.png') });
    check(
      drawn > 0.002 &&
        ghostText.includes('Pinned run') &&
        /robots converged/.test(ghostText) &&
        /robots converged/.test(currentText),
      `a pinned run shows faded (${(drawn * 100).toFixed(1)} % of blocks) and its results beside the changed run's`,
    );
    await part(page, 'pin').click();
    await frames(page);
    check(await part(page, 'pinned').isHidden(), 'Unpin forgets the pinned run');
    checkQuiet(page, 'comparison');
    await page.context().close();
  });
});
