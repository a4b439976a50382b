// End-to-end test of <dvf-playground> as a figure in running text: `time` (the state at a time
// on load), `seek(t)` and the `time` getter, `tick` and `finished` events, `loop`, `readonly`
// and a figure without `controls` (nothing to drag; keys it uses stop there, keys it does not
// reach the page), `autoplay="visible"` and `loading="lazy"` (IntersectionObserver), and a bad
// `src` or `preset` (its message stays, no other scene instead). Figures are put into
// www/embed.html's body, so that they load the release package as the page does.
//
// Run: make test-e2e   (or: node tests/e2e/figures.mjs after make build-wasm)

import { canvasStats, check, checkQuiet, frames, run } from './lib.mjs';

/** Height of the spacer that puts a figure below the fold (CSS px; the viewport is 800). */
const BELOW_FOLD_PX = 3000;
/** One step of the presets is 0.01 s: a time reached by whole steps is exact to rounding. */
const TIME_TOLERANCE_S = 1e-9;

await run(async ({ base, newPage }) => {
  const page = await newPage({ viewport: { width: 1000, height: 800 } });
  await page.goto(`${base}/embed.html`);
  await page.evaluate(
    (below) => {
      document.body.innerHTML = `
      <dvf-playground id="at6" preset="example4-obstacle-formation" time="6" style="height:300px"></dvf-playground>
      <dvf-playground id="ro" preset="example3-circle-swap" readonly style="height:300px"></dvf-playground>
      <dvf-playground id="plain" preset="example3-line-swap" style="height:300px"></dvf-playground>
      <dvf-playground id="badpreset" preset="no-such-preset" style="height:200px"></dvf-playground>
      <dvf-playground id="badsrc" src="missing/nowhere.json" style="height:200px"></dvf-playground>
      <div style="height:${below}px"></div>
      <dvf-playground id="visible" preset="example3-line-swap" autoplay="visible" style="height:300px"></dvf-playground>
      <dvf-playground id="lazy" preset="table2-obstacles" loading="lazy" style="height:300px"></dvf-playground>`;
      window.keysSeen = [];
      document.addEventListener('keydown', (e) => window.keysSeen.push(e.key));
    },
    [BELOW_FOLD_PX],
  );
  const ids = ['at6', 'ro', 'plain', 'badpreset', 'badsrc'];
  await page.evaluate((ids) => Promise.all(ids.map((id) => document.getElementById(id).loaded)), ids);
  await frames(page);

  // time="6": the state at t = 6 s, paused; seek and the time getter.
  const at6 = await page.evaluate(() => {
    const el = document.getElementById('at6');
    const ticks = [];
    el.addEventListener('tick', (e) => ticks.push(e.detail.time));
    const shown = { time: el.time, playing: el.playing };
    const back = el.seek(2.5);
    const clamped = el.seek(1e9);
    return { shown, back, clamped, duration: el.scenario().duration, ticks };
  });
  check(
    Math.abs(at6.shown.time - 6) < TIME_TOLERANCE_S && !at6.shown.playing,
    `time="6" shows t = ${at6.shown.time} s, paused`,
  );
  check(Math.abs(at6.back - 2.5) < TIME_TOLERANCE_S, `seek(2.5) goes back to t = ${at6.back}`);
  check(at6.clamped === at6.duration, `seek past the end stops at the duration (${at6.clamped} s)`);
  check(at6.ticks.length === 2, `each seek sends one tick event (${at6.ticks.length})`);
  const drew = await canvasStats(page, '#at6');
  check(drew.coloured > 500, `the time figure drew (${drew.coloured} coloured pixels)`);

  // readonly and a figure without controls: a drag edits nothing.
  for (const id of ['ro', 'plain']) {
    const before = await page.evaluate((id) => JSON.stringify(document.getElementById(id).scenario()), id);
    const robot = await page.evaluate((id) => {
      const el = document.getElementById(id);
      const [x, y] = el.scenario().robots[0].start;
      const p = el.worldToScreen(x, y);
      return { x: p.x - window.scrollX, y: p.y - window.scrollY };
    }, id);
    await page.mouse.move(robot.x, robot.y);
    await page.mouse.down();
    for (let k = 1; k <= 8; k++) await page.mouse.move(robot.x + 5 * k, robot.y + 5 * k);
    await page.mouse.up();
    const after = await page.evaluate((id) => JSON.stringify(document.getElementById(id).scenario()), id);
    check(after === before, `#${id}: a drag on a robot changes nothing`);
  }
  // Keys: the plain figure steps on S and the page never sees it, nor A (an editor's key it
  // ignores); a readonly one acts on none, and keeps those it knows from the page too; a key
  // neither knows (X) reaches the page.
  await page.evaluate(() => {
    document.getElementById('plain').shadowRoot.querySelector('[data-id="canvas"]').focus();
    window.keysSeen = [];
  });
  await page.keyboard.press('s');
  await page.keyboard.press('a');
  await page.keyboard.press('x');
  const plainKeys = await page.evaluate(() => ({
    time: document.getElementById('plain').time,
    robots: document.getElementById('plain').scenario().robots.length,
    seen: window.keysSeen,
  }));
  check(plainKeys.time > 0, `S steps the figure without controls (t = ${plainKeys.time})`);
  check(plainKeys.robots === 5, 'A adds no robot to a figure without controls');
  check(
    JSON.stringify(plainKeys.seen) === '["x"]',
    `the keys the figure knows stop there, used or not; the page sees only the other (${plainKeys.seen})`,
  );
  await page.evaluate(() => {
    document.getElementById('ro').shadowRoot.querySelector('[data-id="canvas"]').focus();
    window.keysSeen = [];
  });
  await page.keyboard.press('s');
  await page.keyboard.press('x');
  const roKeys = await page.evaluate(() => ({ time: document.getElementById('ro').time, seen: window.keysSeen }));
  check(
    roKeys.time === 0 && JSON.stringify(roKeys.seen) === '["x"]',
    `a readonly figure takes no key, and keeps S from the page; X, a key it does not know, reaches it (${roKeys.seen})`,
  );
  const roButtons = await page.evaluate(() => {
    const root = document.getElementById('ro').shadowRoot;
    const shown = (id) => root.querySelector(`[data-id="${id}"]`).checkVisibility();
    return ['play', 'reset', 'step', 'field', 'add-robot'].map((id) => `${id}:${shown(id)}`).join(' ');
  });
  check(
    roButtons === 'play:true reset:true step:false field:false add-robot:false',
    `a readonly figure shows play and reset only (${roButtons})`,
  );

  // A bad preset or src: the message stays, no scene instead.
  await page.waitForTimeout(300);
  for (const [id, expected] of [
    ['badpreset', 'no-such-preset'],
    ['badsrc', 'missing/nowhere.json'],
  ]) {
    const state = await page.evaluate((id) => {
      const el = document.getElementById(id);
      const box = el.shadowRoot.querySelector('[data-id="message"]');
      return { text: box.textContent, shown: box.checkVisibility(), scenario: el.scenario() };
    }, id);
    check(
      state.shown && state.text.includes(expected) && state.scenario === null,
      `#${id}: the message stays and no other scene is shown ("${state.text}")`,
    );
  }
  // The bad src's own 404 (the request and Chromium's console line for it) is expected.
  page.problems = page.problems.filter((p) => !p.includes('missing/nowhere.json') && !p.includes('404'));

  // loop: a short run starts over and keeps playing; `finished` is sent at each end.
  const looped = await page.evaluate(async () => {
    const el = document.getElementById('plain');
    const s = el.scenario();
    el.load({ ...s, duration: 0.3 });
    el.setAttribute('loop', '');
    let finished = 0;
    el.addEventListener('finished', () => {
      finished += 1;
    });
    el.play();
    await new Promise((r) => setTimeout(r, 1200));
    return { finished, playing: el.playing, time: el.time };
  });
  check(
    looped.finished >= 2 && looped.playing && looped.time < 0.3,
    `loop: ${looped.finished} finished events, still playing (t = ${looped.time.toFixed(2)} s)`,
  );

  // autoplay="visible" and loading="lazy": nothing below the fold until it is scrolled to.
  const early = await page.evaluate(() => ({
    visible: document.getElementById('visible').playing,
    lazy: document.getElementById('lazy').scenario(),
  }));
  check(!early.visible, 'autoplay="visible" does not play below the fold');
  check(early.lazy === null, 'loading="lazy" loads nothing below the fold');
  await page.evaluate(() => document.getElementById('visible').scrollIntoView());
  await page.waitForFunction(() => document.getElementById('visible').playing);
  await page.waitForFunction(() => document.getElementById('lazy').scenario() !== null);
  check(true, 'scrolled into view, the figure plays and the lazy one loads');
  // Its time has moved (a frame has run) before it leaves the view: playing is set at once,
  // the first frame comes later, and on a loaded machine the scroll could come first.
  await page.waitForFunction(() => document.getElementById('visible').time > 0);
  await page.evaluate(() => window.scrollTo(0, 0));
  await page.waitForFunction(() => !document.getElementById('visible').playing);
  const paused = await page.evaluate(() => document.getElementById('visible').time);
  check(paused > 0, `scrolled out, it pauses (t = ${paused.toFixed(2)} s)`);
  // A lazy figure taken out of the page before it loaded loads once it is back in view.
  const back = await page.evaluate(async (below) => {
    const el = document.createElement('dvf-playground');
    el.setAttribute('preset', 'example3-line-swap');
    el.setAttribute('loading', 'lazy');
    el.style.cssText = `height: 200px; margin-top: ${below}px`;
    document.body.append(el);
    await new Promise((r) => setTimeout(r, 300));
    const before = el.scenario();
    el.remove();
    el.style.marginTop = '0';
    document.body.prepend(el);
    window.scrollTo(0, 0);
    await el.loaded;
    return { before, after: el.scenario()?.robots.length };
  }, BELOW_FOLD_PX * 2);
  check(back.before === null && back.after === 5, 'a lazy figure moved into view after leaving the page loads there');
  checkQuiet(page, 'figures page (the bad src aside)');
});
