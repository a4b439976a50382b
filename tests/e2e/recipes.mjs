// End-to-end test of the package and its recipes (examples/): the tarball `make package`
// wrote (target/package/) is installed offline into empty projects under target/recipes/ and
// used from there as a writer would:
//   - in Node, without a DOM: importing the element (twice, and its single-file build) throws
//     nothing, defines nothing and fetches nothing;
//   - examples/plain-html served over HTTP (both figures draw, the API answers), and opened
//     from file:// (the text in the tags says to serve it over HTTP); the single-file build
//     without any .wasm file beside it; the `wasm` attribute pointing elsewhere; a missing
//     wasm module (the message in the figure's box); in the single-file build and with the
//     `wasm` attribute, a figure with `controls` whose results panel runs in its worker;
//   - examples/mdbook built by mdBook: the chapter's two figures draw, keys typed in a figure
//     stay there while mdBook's search still opens and finds, the figures' theme follows
//     mdBook's theme menu, and going to the next chapter and back starts them again;
//   - examples/vite: main.ts type-checked against the package's declarations, `vite build`,
//     dist/ served, the figure works.
// Every page must log nothing (the file:// page and the missing module aside, whose failures
// are what they test).
//
// Run: make test-e2e   (or: node tests/e2e/recipes.mjs after make package)

import { execFileSync } from 'node:child_process';
import { cpSync, existsSync, mkdirSync, readdirSync, readFileSync, renameSync, rmSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { canvasStats, check, checkQuiet, frames, ROOT, run, startServer, waitLoaded } from './lib.mjs';

const PACKAGE_DIR = join(ROOT, 'target', 'package');
const SCRATCH = join(ROOT, 'target', 'recipes');
const EXAMPLES = join(ROOT, 'examples');
const BIN = join(ROOT, 'node_modules', '.bin');
/** A figure drew when this many of its canvas pixels are coloured (robots, goals, trails). */
const DREW_PIXELS = 500;
/** `time` figures land on a whole number of 0.01 s steps: equal to rounding. */
const TIME_TOLERANCE_S = 1e-9;

const tarball = readdirSync(PACKAGE_DIR).find((f) => f.endsWith('.tgz'));
if (!tarball) throw new Error(`no tarball in ${PACKAGE_DIR}: run make package first`);
const TARBALL = join(PACKAGE_DIR, tarball);

/** Runs `cmd args` in `cwd` (quietly) and returns its standard output. */
function sh(cwd, cmd, args) {
  return execFileSync(cmd, args, { cwd, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
}

/** `npm install` of the tarball into `dir`, offline (a package with no dependencies of its own). */
function installTarball(dir) {
  sh(dir, 'npm', ['install', '--offline', '--no-audit', '--no-fund', '--loglevel=error', TARBALL]);
}

/** Checks that every figure on `page` drew, and returns their pixel counts. */
async function checkDrew(page, what) {
  const ids = await page.evaluate(() => [...document.querySelectorAll('dvf-playground')].map((el) => el.id));
  for (const id of ids) {
    await page.locator(`#${id}`).scrollIntoViewIfNeeded();
    await waitLoaded(page, `#${id}`);
    const { coloured } = await canvasStats(page, `#${id}`);
    check(coloured > DREW_PIXELS, `${what}: #${id} drew (${coloured} coloured pixels)`);
  }
}

/** Checks that figure `id`'s results panel (a run in its worker, handed the page's module) reported. */
async function checkResults(page, id, what) {
  const sel = `#${id}`;
  await page
    .waitForFunction(
      (sel) => document.querySelector(sel).shadowRoot.querySelector('[data-id="results"]').dataset.ready !== undefined,
      sel,
      { timeout: 30_000 },
    )
    .catch(() => {});
  const text = await page.evaluate(
    (sel) => document.querySelector(sel).shadowRoot.querySelector('[data-id="results"]').textContent,
    sel,
  );
  check(/\d+ of \d+ robots converged/.test(text), `${what}: the results panel's worker ran ("${text.slice(0, 60)}…")`);
}

/** The time shown by figure `id` on `page`. */
function timeOf(page, id) {
  return page.evaluate((id) => document.getElementById(id).time, id);
}

rmSync(SCRATCH, { recursive: true, force: true });
mkdirSync(SCRATCH, { recursive: true });

await run(async ({ newPage }) => {
  const servers = [];
  const serve = async (dir) => {
    const started = await startServer(dir);
    servers.push(started.server);
    return started.base;
  };
  try {
    // --- An empty project: the tarball installs offline; Node imports it without a DOM. ---
    const empty = join(SCRATCH, 'empty');
    mkdirSync(empty);
    writeFileSync(join(empty, 'package.json'), '{ "name": "scratch", "private": true }\n');
    installTarball(empty);
    const installed = join(empty, 'node_modules', 'dvf-playground');
    check(existsSync(join(installed, 'pkg', 'dvf_bg.wasm')), `${tarball} installs offline into an empty project`);
    const probe = `
      let fetches = 0;
      globalThis.fetch = () => { fetches += 1; throw new Error('no fetch at import'); };
      const a = await import('dvf-playground');
      const b = await import('dvf-playground');
      const inline = await import('dvf-playground/inline');
      const wasm = await import('dvf-playground/wasm');
      const { createRequire } = await import('node:module');
      const { existsSync } = await import('node:fs');
      const resolve = createRequire(\`\${process.cwd()}/\`).resolve;
      const files = ['playground.css', 'dvf_bg.wasm', 'loader.js', 'mdbook.js', 'package.json']
        .map((f) => resolve(\`dvf-playground/\${f}\`))
        .filter((f) => existsSync(f)).length;
      console.log(JSON.stringify({
        same: a.DvfPlayground === b.DvfPlayground,
        inline: typeof inline.DvfPlayground,
        bindings: typeof wasm.Playground,
        defined: typeof globalThis.customElements,
        fetches,
        files,
      }));`;
    const node = JSON.parse(sh(empty, 'node', ['--input-type=module', '-e', probe]));
    check(
      node.same && node.inline === 'function' && node.bindings === 'function',
      'Node imports the element twice, its single-file build and the bindings without a DOM',
    );
    check(node.defined === 'undefined' && node.fetches === 0, 'importing in Node defines nothing and fetches nothing');
    check(
      node.files === 5,
      `the exports map names the stylesheet, the wasm module and the scripts (${node.files} of 5)`,
    );

    // --- Plain HTML from a static server, and from file://. ---
    const plain = join(SCRATCH, 'plain-html');
    cpSync(join(EXAMPLES, 'plain-html'), plain, { recursive: true });
    cpSync(installed, join(plain, 'dvf-playground'), { recursive: true });
    const plainBase = await serve(plain);
    const page = await newPage({ viewport: { width: 1000, height: 800 } });
    await page.goto(`${plainBase}/index.html`);
    await checkDrew(page, 'plain HTML');
    check(Math.abs((await timeOf(page, 'obstacle')) - 6) < TIME_TOLERANCE_S, 'plain HTML: time="6" shows t = 6 s');
    await page.locator('#swap').scrollIntoViewIfNeeded();
    await page.waitForFunction(() => document.getElementById('swap').time > 0.2);
    check(true, 'plain HTML: the autoplay="visible" figure plays on screen');
    checkQuiet(page, 'plain HTML');

    const local = await newPage();
    await local.goto(`file://${plain}/index.html`);
    await local.waitForTimeout(500);
    const shownThere = await local.locator('#swap').isVisible();
    const fallback = (await local.locator('#swap').textContent()).replace(/\s+/g, ' ').trim();
    check(
      shownThere && fallback.includes('served over HTTP') && fallback.includes('python3 -m http.server'),
      `from file:// the figure says to serve the page over HTTP ("${fallback.slice(0, 60)}…")`,
    );
    await local.context().close();

    // The single-file build, with no .wasm file anywhere beside it.
    const single = join(SCRATCH, 'single-file');
    mkdirSync(single);
    cpSync(join(installed, 'dvf-playground.inline.js'), join(single, 'dvf-playground.inline.js'));
    writeFileSync(
      join(single, 'index.html'),
      `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>one file</title><link rel="icon" href="data:,">
      <script type="module" src="dvf-playground.inline.js"></script></head>
      <body><dvf-playground id="one" preset="example3-line-swap" time="3" readonly style="height:400px"></dvf-playground>
      <dvf-playground id="two" preset="example3-line-swap" controls style="height:560px"></dvf-playground></body></html>`,
    );
    const singlePage = await newPage();
    await singlePage.goto(`${await serve(single)}/index.html`);
    await checkDrew(singlePage, 'single-file build');
    check(Math.abs((await timeOf(singlePage, 'one')) - 3) < TIME_TOLERANCE_S, 'single-file build: t = 3 s shown');
    await checkResults(singlePage, 'two', 'single-file build');
    checkQuiet(singlePage, 'single-file build');

    // The wasm attribute: the module moved elsewhere; and a module that is nowhere.
    const moved = join(SCRATCH, 'wasm-elsewhere');
    cpSync(join(installed), join(moved, 'dvf-playground'), { recursive: true });
    mkdirSync(join(moved, 'static'));
    renameSync(join(moved, 'dvf-playground', 'pkg', 'dvf_bg.wasm'), join(moved, 'static', 'dvf.wasm'));
    const figurePage = (wasm, more = '') =>
      `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>wasm</title><link rel="icon" href="data:,">
      <script type="module" src="dvf-playground/dvf-playground.js"></script></head>
      <body><dvf-playground id="w" ${wasm} preset="example3-line-swap" style="height:400px"></dvf-playground>${more}</body></html>`;
    writeFileSync(
      join(moved, 'index.html'),
      figurePage(
        'wasm="static/dvf.wasm"',
        '<dvf-playground id="wc" preset="example3-line-swap" controls style="height:560px"></dvf-playground>',
      ),
    );
    writeFileSync(join(moved, 'missing.html'), figurePage(''));
    const movedBase = await serve(moved);
    const movedPage = await newPage();
    await movedPage.goto(`${movedBase}/index.html`);
    await checkDrew(movedPage, 'wasm="static/dvf.wasm"');
    await checkResults(movedPage, 'wc', 'wasm="static/dvf.wasm"');
    checkQuiet(movedPage, 'wasm attribute');
    const missing = await newPage();
    await missing.goto(`${movedBase}/missing.html`);
    await missing.evaluate(() => document.getElementById('w').loaded);
    const message = await missing.evaluate(() => {
      const box = document.getElementById('w').shadowRoot.querySelector('[data-id="message"]');
      return box.checkVisibility() ? box.textContent : '';
    });
    check(
      message.startsWith('Could not load the simulator') && message.includes('dvf_bg.wasm'),
      `a wasm module that is not there shows its message in the box ("${message.slice(0, 70)}…")`,
    );

    // --- mdBook. ---
    const book = join(SCRATCH, 'mdbook');
    cpSync(join(EXAMPLES, 'mdbook'), book, { recursive: true });
    cpSync(installed, join(book, 'src', 'dvf-playground'), { recursive: true });
    sh(book, 'mdbook', ['build']);
    const bookBase = await serve(join(book, 'book'));
    const chapter = await newPage({ viewport: { width: 1100, height: 800 } });
    await chapter.goto(`${bookBase}/figures.html`);
    await checkDrew(chapter, 'mdBook');
    check(Math.abs((await timeOf(chapter, 'obstacles')) - 10) < TIME_TOLERANCE_S, 'mdBook: time="10" shows t = 10 s');
    await checkBookKeys(chapter);
    await checkBookTheme(chapter);
    // To the next chapter and back with mdBook's own keys (→, ←), typed on the page: the
    // figures start again on the new page.
    await chapter.locator('main h1').first().click();
    await chapter.keyboard.press('ArrowRight');
    await chapter.waitForURL(/another\.html$/);
    await chapter.locator('main h1').first().click();
    await chapter.keyboard.press('ArrowLeft');
    await chapter.waitForURL(/figures\.html$/);
    await checkDrew(chapter, 'mdBook, back from the next chapter');
    // A page left while it still loads (its favicon) cancels the request: not a failure.
    chapter.problems = chapter.problems.filter((p) => !p.endsWith('net::ERR_ABORTED'));
    checkQuiet(chapter, 'mdBook');

    // --- Vite. ---
    const vite = join(SCRATCH, 'vite');
    cpSync(join(EXAMPLES, 'vite'), vite, { recursive: true });
    const recipe = JSON.parse(readFileSync(join(vite, 'package.json'), 'utf8'));
    const tooling = JSON.parse(readFileSync(join(ROOT, 'package.json'), 'utf8')).devDependencies;
    check(
      recipe.devDependencies.vite === tooling.vite && recipe.devDependencies.typescript === tooling.typescript,
      `the Vite recipe pins the project's Vite (${recipe.devDependencies.vite}) and TypeScript`,
    );
    // The package from its tarball; Vite and TypeScript are the project's own (the same
    // versions, checked above), found up the folder tree: the registry is not needed.
    delete recipe.devDependencies;
    recipe.dependencies = {};
    writeFileSync(join(vite, 'package.json'), JSON.stringify(recipe));
    installTarball(vite);
    sh(vite, join(BIN, 'tsc'), ['-p', '.']);
    // The package's declarations themselves, too (the bindings' use Symbol.dispose).
    sh(vite, join(BIN, 'tsc'), [
      '-p',
      '.',
      '--skipLibCheck',
      'false',
      '--lib',
      'ES2022,DOM,DOM.Iterable,ESNext.Disposable',
    ]);
    check(true, 'main.ts type-checks against the package (HTMLElementTagNameMap, typed event details)');
    sh(vite, join(BIN, 'vite'), ['build', '--logLevel', 'warn']);
    const assets = readdirSync(join(vite, 'dist', 'assets'));
    check(
      assets.some((f) => f.endsWith('.wasm')),
      `vite build emits the wasm module as an asset (${assets.join(', ')})`,
    );
    const vitePage = await newPage();
    await vitePage.goto(`${await serve(join(vite, 'dist'))}/index.html`);
    await checkDrew(vitePage, 'Vite');
    const shown = await vitePage.locator('#time').textContent();
    check(shown === '10.00', `Vite: the tick event reaches the page's script (time ${shown})`);
    checkQuiet(vitePage, 'Vite');
  } finally {
    for (const s of servers) s.kill();
  }
});

/** Keys typed in a figure stay there; typed on the page, mdBook's search opens and finds. */
async function checkBookKeys(page) {
  const figure = await page.evaluate(() => {
    const el = document.getElementById('obstacles');
    el.shadowRoot.querySelector('[data-id="canvas"]').focus();
    return el.time;
  });
  await page.keyboard.press('s');
  await frames(page);
  const stepped = (await timeOf(page, 'obstacles')) > figure;
  const searchAfterFigureKey = await page.locator('#mdbook-search-wrapper').isVisible();
  check(stepped && !searchAfterFigureKey, 'mdBook: S typed in a figure steps it and does not open the search');
  await page.evaluate(() => document.activeElement?.blur());
  await page.locator('main h1').first().click();
  await page.keyboard.press('s');
  const bar = page.locator('#mdbook-searchbar');
  await bar.waitFor({ state: 'visible' });
  await bar.pressSequentially('holonomic');
  const result = page.locator('#mdbook-searchresults a').first();
  await result.waitFor({ state: 'visible' });
  const href = await result.getAttribute('href');
  check(href.includes('another.html'), `mdBook: the search still works (S opens it; "holonomic" finds ${href})`);
  await page.keyboard.press('Escape');
}

/** The figures' theme attribute follows mdBook's theme menu. */
async function checkBookTheme(page) {
  const themes = () =>
    page.evaluate(() => [...document.querySelectorAll('dvf-playground')].map((el) => el.getAttribute('theme')).join());
  const before = await themes();
  const pick = async (theme) => {
    if (!(await page.locator('#mdbook-theme-list').isVisible())) await page.locator('#mdbook-theme-toggle').click();
    await page.locator(`#mdbook-theme-${theme}`).click();
    await frames(page);
    return themes();
  };
  const coal = await pick('coal');
  const ayu = await pick('ayu');
  const rust = await pick('rust');
  check(
    before === 'light,light' && coal === 'dark,dark' && ayu === 'dark,dark' && rust === 'light,light',
    `mdBook: the figures' theme follows the book's (light: ${before}; coal: ${coal}; ayu: ${ayu}; rust: ${rust})`,
  );
}
