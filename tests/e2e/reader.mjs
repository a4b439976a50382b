// End-to-end test of the book as a reader meets it (`make docs` writes target/book/), in
// Chromium:
// - Layout: the two figures with `controls` (the editor of playground.html, the minimum-distance
//   figure of examples.html) hold their toolbar, canvas and side panel inside their own box, and
//   the text after them starts below that box, on a phone (390 × 844), a tablet and a desktop.
//   Screenshots in test-results/reader-*.png. On the phone, every figure of examples.html (the
//   readonly ones too) holds its parts inside its box, above its caption.
// - Keys: a focused figure keeps the keys it knows from mdBook's shortcuts (S opens the search,
//   ? the help, the arrows go to the next chapter), whether it acts on them or ignores them
//   (`readonly`); a key it does not know (Tab) still reaches the page.
//
// Run: make test-e2e   (or: node tests/e2e/reader.mjs after make docs)

import { existsSync } from 'node:fs';
import { join } from 'node:path';
import { check, checkQuiet, frames, RESULTS, ROOT, run, startServer, waitLoaded } from './lib.mjs';

const BOOK = join(ROOT, 'target', 'book');
if (!existsSync(join(BOOK, 'index.html'))) throw new Error(`${BOOK} is missing: run make docs first`);

/** A phone, a tablet (the side panel under the canvas) and a desktop. */
const SIZES = [
  { width: 390, height: 844, name: 'phone' },
  { width: 700, height: 900, name: 'tablet' },
  { width: 1200, height: 900, name: 'desktop' },
];
const CONTROLS_FIGURES = [
  { file: 'playground.html', sel: '#editor' },
  { file: 'examples.html', sel: '#min-distance' },
];
/** Boxes are laid out on whole and half CSS px: a box "inside" another may pass it by this much. */
const LAYOUT_SLACK_PX = 1;

/**
 * Where figure `sel`'s parts are, in page px: the element's box, the bottom of its toolbar,
 * stage and side panel, whether its root scrolls or lets its content out, and the top of the
 * first text after its figure.
 */
function layoutOf(page, sel) {
  return page.evaluate((sel) => {
    const el = document.querySelector(sel);
    const y = window.scrollY;
    const box = el.getBoundingClientRect();
    const parts = {};
    for (const name of ['toolbar', 'stage', 'side']) {
      const r = el.shadowRoot.querySelector(`.${name}`).getBoundingClientRect();
      parts[name] = { top: r.top + y, bottom: r.bottom + y, height: r.height };
    }
    const root = el.shadowRoot.querySelector('.pg');
    const figure = el.closest('figure') ?? el;
    // The figure's caption, then the paragraph after the figure.
    const after = [el.nextElementSibling, figure.nextElementSibling].filter(Boolean);
    return {
      top: box.top + y,
      bottom: box.bottom + y,
      height: box.height,
      parts,
      overflow: getComputedStyle(root).overflowY,
      spills: root.scrollHeight > root.clientHeight + 1,
      next: after.map((n) => ({ tag: n.tagName, top: n.getBoundingClientRect().top + y })),
    };
  }, sel);
}

/** Whether mdBook shows its search bar or its help, and the page's address. */
function bookState(page) {
  return page.evaluate(() => ({
    search: !document.getElementById('mdbook-search-wrapper').classList.contains('hidden'),
    help: getComputedStyle(document.getElementById('mdbook-help-container')).display === 'flex',
    url: location.href,
    keys: window.keysSeen.slice(),
  }));
}

/** Focuses the part `part` (a `data-id`) of figure `sel`. */
function focusPart(page, sel, part) {
  return page.evaluate(
    ([sel, part]) => {
      const el = document.querySelector(sel);
      el.shadowRoot.querySelector(`[data-id="${part}"]`).focus();
      return el.shadowRoot.activeElement?.dataset.id;
    },
    [sel, part],
  );
}

await run(async ({ newPage }) => {
  const { server, base } = await startServer(BOOK);
  try {
    for (const size of SIZES) {
      for (const { file, sel } of CONTROLS_FIGURES) {
        const page = await newPage({ viewport: { width: size.width, height: size.height } });
        await page.goto(`${base}/${file}`);
        await page.locator(sel).scrollIntoViewIfNeeded();
        await waitLoaded(page, sel);
        const l = await layoutOf(page, sel);
        const what = `${file} ${sel} at ${size.width}×${size.height}`;
        const inside = Object.entries(l.parts).filter(
          ([, p]) => p.height > 0 && (p.top < l.top - LAYOUT_SLACK_PX || p.bottom > l.bottom + LAYOUT_SLACK_PX),
        );
        check(
          inside.length === 0,
          `${what}: toolbar, canvas and side panel inside the element's box (${Math.round(l.top)}–${Math.round(l.bottom)} px)${inside.map(([n, p]) => `; ${n} ends at ${Math.round(p.bottom)}`).join('')}`,
        );
        check(
          l.overflow !== 'visible' || !l.spills,
          `${what}: nothing spills out of the element (its root's overflow is ${l.overflow})`,
        );
        check(
          l.next.length > 0 && l.next.every((n) => n.top >= l.bottom - LAYOUT_SLACK_PX),
          `${what}: the text after the figure starts below it (${l.next.map((n) => `${n.tag} at ${Math.round(n.top)}`).join(', ')}; the element ends at ${Math.round(l.bottom)})`,
        );
        if (size.name === 'phone') {
          check(
            l.parts.stage.height >= 300,
            `${what}: the canvas stays tall on a phone (${Math.round(l.parts.stage.height)} px)`,
          );
        }
        await page.evaluate((sel) => document.querySelector(sel).scrollIntoView(), sel);
        await frames(page);
        await page.screenshot({ path: join(RESULTS, `reader-${size.name}-${file.replace('.html', '')}.png`) });
        checkQuiet(page, what);
        await page.context().close();
      }
    }

    // Every figure of the examples on a phone.
    const phone = await newPage({ viewport: { width: 390, height: 844 } });
    await phone.goto(`${base}/examples.html`);
    const count = await phone.evaluate(() => {
      const all = document.querySelectorAll('dvf-playground');
      all.forEach((el, k) => {
        el.dataset.check = String(k);
      });
      return all.length;
    });
    const outside = [];
    for (let k = 0; k < count; k++) {
      const sel = `dvf-playground[data-check="${k}"]`;
      await phone.locator(sel).scrollIntoViewIfNeeded();
      await waitLoaded(phone, sel);
      const l = await layoutOf(phone, sel);
      const out = Object.values(l.parts).some(
        (p) => p.height > 0 && (p.top < l.top - LAYOUT_SLACK_PX || p.bottom > l.bottom + LAYOUT_SLACK_PX),
      );
      const over = l.next.some((n) => n.top < l.bottom - LAYOUT_SLACK_PX);
      if (out || over || (l.overflow === 'visible' && l.spills)) outside.push(k + 1);
    }
    check(
      count > 10 && outside.length === 0,
      `examples.html at 390×844: each of its ${count} figures holds its parts inside its box, above the text after it${outside.length ? ` (not figures ${outside.join(', ')})` : ''}`,
    );
    checkQuiet(phone, 'examples.html at 390×844');
    await phone.context().close();

    // Keys: a readonly figure (examples.html's first), the readonly figure with controls, the
    // editor (playground.html).
    const keyCases = [
      { file: 'examples.html', sel: 'dvf-playground', part: 'canvas', what: 'a readonly figure' },
      {
        file: 'examples.html',
        sel: '#min-distance',
        part: 'play',
        what: 'the readonly figure with controls, Play focused',
      },
      { file: 'playground.html', sel: '#editor', part: 'canvas', what: 'the editor' },
    ];
    for (const { file, sel, part, what } of keyCases) {
      const page = await newPage({ viewport: { width: 1200, height: 900 } });
      await page.goto(`${base}/${file}`);
      await page.locator(sel).first().scrollIntoViewIfNeeded();
      await waitLoaded(page, sel);
      await page.evaluate(() => {
        window.keysSeen = [];
        document.addEventListener('keydown', (e) => window.keysSeen.push(e.key));
      });
      const focused = await focusPart(page, sel, part);
      check(focused === part, `${file}, ${what}: its ${part} has the focus`);
      const t0 = await page.evaluate((sel) => document.querySelector(sel).time, sel);
      for (const key of ['s', 'S', '?', 'ArrowRight', 'ArrowLeft']) {
        await page.keyboard.press(key);
        await frames(page);
        const state = await bookState(page);
        check(
          !state.search && !state.help && state.url === `${base}/${file}` && !state.keys.includes(key),
          `${file}, ${what}: ${key} stays in the figure (mdBook's search ${state.search ? 'opened' : 'closed'}, help ${state.help ? 'opened' : 'closed'}, the page ${state.url === `${base}/${file}` ? 'stayed' : `went to ${state.url}`})`,
        );
        if (state.help) await page.keyboard.press('Escape');
      }
      const t1 = await page.evaluate((sel) => document.querySelector(sel).time, sel);
      const readonly = await page.evaluate((sel) => document.querySelector(sel).hasAttribute('readonly'), sel);
      if (readonly) check(t1 === t0, `${file}, ${what}: readonly, S did not step the clock (t = ${t1} s)`);
      else check(t1 > t0, `${file}, ${what}: S stepped the clock (t = ${t0} → ${t1} s)`);
      await page.keyboard.press('Tab');
      const { keys } = await bookState(page);
      check(keys.includes('Tab'), `${file}, ${what}: Tab, a key it does not know, reaches the page`);
      checkQuiet(page, `${file}, ${what}: keys`);
      await page.context().close();
    }
  } finally {
    server.kill();
  }
});
