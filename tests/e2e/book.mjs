// End-to-end test of the book (`make docs` writes target/book/): every chapter of
// docs/book/src/SUMMARY.md opens in Chromium with no console message, and every figure in it
// (loaded lazily, as the reader scrolls to it) drew. Every figure with a `time` attribute shows
// the state of `dvf simulate --csv` at that time: each robot's pose equal to the trajectory's
// row at that step. The API table of docs/book/src/embedding.md names exactly the attributes,
// public members and events that www/dvf-playground.d.ts declares, and every `html` and `js`
// block of that chapter and of README.md loads, with the package the book holds, and draws.
//
// Run: make test-e2e   (or: node tests/e2e/book.mjs after make docs)

import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
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
 * equal (docs/book/src/tests.md). The CSV writes each number so that it reads back to its bits.
 */
const POSE_TOLERANCE = 0;

if (!existsSync(join(BOOK, 'index.html'))) throw new Error(`${BOOK} is missing: run make docs first`);
const chapters = [...readFileSync(SUMMARY, 'utf8').matchAll(/\]\(([\w-]+)\.md\)/g)].map((m) => `${m[1]}.html`);

const DECLARATIONS = join(ROOT, 'www', 'dvf-playground.d.ts');
const EMBEDDING = join(ROOT, 'docs', 'book', 'src', 'embedding.md');
/** Where the table's kinds are declared: the attributes, the class's members, the events. */
const KIND_GROUP = {
  attribute: 'attribute',
  method: 'member',
  property: 'member',
  'static property': 'member',
  event: 'event',
};

/**
 * The names www/dvf-playground.d.ts declares: the keys of `DvfPlaygroundAttributes`, the members
 * of `DvfPlayground` before its diagnostics, the keys of `DvfPlaygroundEventMap`.
 */
function declaredApi() {
  const dts = readFileSync(DECLARATIONS, 'utf8');
  const names = (text) => [...text.matchAll(/^ {2}(?:static |readonly )*(\w+)\??[:(<]/gm)].map((m) => m[1]);
  const body = (name) => dts.match(new RegExp(`interface ${name}\\b[^{]*\\{([\\s\\S]*?)\\n\\}`))[1];
  const members = dts.match(/declare class DvfPlayground\b[^{]*\{([\s\S]*?)\/\/ Diagnostics/)[1];
  return {
    attribute: names(body('DvfPlaygroundAttributes')),
    member: names(members),
    event: names(body('DvfPlaygroundEventMap')),
  };
}

/** The names the embedding chapter's API table gives, by group (a row may name several). */
function documentedApi() {
  const found = { attribute: [], member: [], event: [] };
  for (const [, cell, kind] of readFileSync(EMBEDDING, 'utf8').matchAll(/^\| ([^|]+) \| ([a-z ]+) \|/gm)) {
    const group = KIND_GROUP[kind];
    if (!group) continue;
    for (const [, name] of cell.matchAll(/`(\w+)/g)) found[group].push(name);
  }
  return found;
}

const declared = declaredApi();
const documented = documentedApi();
for (const group of Object.keys(declared)) {
  const missing = declared[group].filter((n) => !documented[group].includes(n));
  const extra = documented[group].filter((n) => !declared[group].includes(n));
  check(
    declared[group].length > 0 && missing.length === 0 && extra.length === 0,
    `embedding.md's API table names the ${group}s of dvf-playground.d.ts (${declared[group].length}; missing: ${missing.join(', ') || 'none'}; not declared: ${extra.join(', ') || 'none'})`,
  );
}

/** The package's entry points as a page at the book's root reaches them. */
const SPECIFIERS = [
  ["'dvf-playground/inline'", "'./dvf-playground/dvf-playground.inline.js'"],
  ["'dvf-playground'", "'./dvf-playground/dvf-playground.js'"],
];
const ELEMENT_SCRIPT = '<script type="module" src="dvf-playground/dvf-playground.js"></script>';

/**
 * The `html` and `js` blocks of README.md and the embedding chapter, each as a page at the
 * book's root (where the package is, as `dvf-playground/`): an `html` block as it is (with the
 * element's script when it has none), a `js` block as a module with the package's names
 * resolved, followed by a figure that connects after it.
 */
function blockPages() {
  const pages = [];
  for (const file of [join(ROOT, 'README.md'), EMBEDDING]) {
    const name = file.split('/').pop();
    for (const m of readFileSync(file, 'utf8').matchAll(/^```(html|js)\n([\s\S]*?)^```$/gm)) {
      const line = readFileSync(file, 'utf8').slice(0, m.index).split('\n').length;
      let body;
      if (m[1] === 'html') body = `${m[2].includes('<script') ? '' : ELEMENT_SCRIPT}\n${m[2]}`;
      else {
        let js = m[2];
        for (const [from, to] of SPECIFIERS) js = js.replaceAll(from, to);
        body = `<script type="module">\n${js}</script>\n<script type="module">document.body.insertAdjacentHTML('beforeend', '<dvf-playground preset="example3-line-swap" readonly></dvf-playground>');</script>`;
      }
      const page = `doc-block-${name.replace('.md', '')}-${line}.html`;
      writeFileSync(
        join(BOOK, page),
        `<!doctype html>\n<meta charset="utf-8">\n<link rel="icon" href="data:,">\n<title>${name}:${line}</title>\n<body>\n${body}\n</body>\n`,
      );
      pages.push({ page, what: `${name}:${line} (${m[1]})` });
    }
  }
  return pages;
}

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
    const blocks = blockPages();
    for (const { page: file, what } of blocks) {
      const page = await newPage({ viewport: { width: 1200, height: 900 } });
      await page.goto(`${base}/${file}`);
      await page.waitForFunction(() => document.querySelector('dvf-playground'));
      const count = await page.evaluate(() => document.querySelectorAll('dvf-playground').length);
      for (let k = 0; k < count; k++) {
        const sel = `dvf-playground:nth-of-type(${k + 1})`;
        await page.locator(sel).scrollIntoViewIfNeeded();
        await waitLoaded(page, sel);
        const { coloured } = await canvasStats(page, sel);
        check(coloured > DREW_PIXELS, `${what}: figure ${k + 1} drew (${coloured} coloured pixels)`);
      }
      checkQuiet(page, what);
      await page.context().close();
    }
    check(blocks.length >= 5, `${blocks.length} html and js blocks loaded`);
    console.log(
      `${chapters.length} chapters, ${figures} figures, ${timed} at a time; largest pose difference ${worst.toExponential(1)}`,
    );
  } finally {
    server.kill();
  }
});
