// The main page: one <dvf-playground> that fills the window, with the scene kept in the
// address's fragment (#s=<scenario JSON>, or #<preset name>) so that a copied link reopens it,
// and after it the view (`&field=curves&theta0=45&sensing=1&robot=3&t=5.2&view=x0,y0,x1,y1&compare=dvf-paper`,
// io.js, viewSuffix).

import './dvf-playground.js';
import { fragmentFor, MAX_LINK_CHARS, parseFragment, viewSuffix } from './io.js';
import { messageOf } from './playground/message.js';

const playground = /** @type {import('./dvf-playground.js').DvfPlayground} */ (document.getElementById('playground'));
/**
 * The most robots a link can hold: each takes at least 69 characters of the fragment
 * (`{"start":[0,0,0],"goal":[0,0,0]},` URI-encoded), so more than MAX_LINK_CHARS / 69 never fit.
 */
const LINK_ROBOTS_MAX = Math.floor(MAX_LINK_CHARS / 69);
/** The fragment this page last wrote, so that its own hashchange is not read back. */
let written = location.hash;
/** The scene's part of the fragment (empty when the scene is too big for a link). */
let scenePart = '';
/** Whether the message says that the scene is too big for a link. */
let tooBigShown = false;

/** Shows the scene the fragment asks for; a bad fragment shows why and keeps the scene. */
function openFragment(hash) {
  let wanted;
  try {
    wanted = parseFragment(hash);
    if (wanted.kind === 'scenario') playground.load(wanted.text);
    else if (wanted.kind === 'preset' && !playground.loadPreset(wanted.name)) return;
    if (wanted.kind !== 'none') playground.showMessage('');
    tooBigShown = false;
    scenePart = hash.split('&')[0];
    if (wanted.view) playground.setViewState(wanted.view);
  } catch (e) {
    playground.showMessage(`This link does not hold a scenario the playground can open. ${messageOf(e)}`);
  }
}

/** Writes the scene's part and the view into the address (no history entry). */
function writeAddress() {
  written = scenePart ? scenePart + viewSuffix(playground.viewState()) : '';
  history.replaceState(null, '', written || `${location.pathname}${location.search}`);
}

/** After an edit: the scene's part anew. */
function sceneChanged() {
  // A preset by its name (a crowd of 10,000 is 600 KB of JSON); an edited scene as JSON. A
  // scene too big for a link leaves the address without one (a stale one would open another
  // scene) and the message over the canvas says so, offering the file instead.
  // A scene of more than LINK_ROBOTS_MAX robots cannot fit at all and is not written.
  const preset = playground.presetName();
  const robots = playground.robotCount;
  const scenario = preset || robots > LINK_ROBOTS_MAX ? null : playground.scenario();
  const fragment = preset ? `#${encodeURIComponent(preset)}` : scenario ? fragmentFor(scenario) : null;
  scenePart = fragment && fragment.length <= MAX_LINK_CHARS ? fragment : '';
  writeAddress();
  if (!scenePart) {
    const size = scenario
      ? `${fragment.length.toLocaleString('en')} characters`
      : `${robots.toLocaleString('en')} robots`;
    playground.showMessage(
      `This scene is too big for a link (${size}; a link holds at most ${MAX_LINK_CHARS.toLocaleString('en')} characters, about ${LINK_ROBOTS_MAX.toLocaleString('en')} robots), so the address no longer holds it. Save it with Scenario JSON; Import… opens the file again.`,
      { info: true, actions: [['Scenario JSON', () => playground.exportJson()]] },
    );
    tooBigShown = true;
  } else if (tooBigShown) {
    playground.showMessage('');
    tooBigShown = false;
  }
}

async function main() {
  await playground.loaded;
  openFragment(location.hash);
  // A fresh page: the default preset, named once the view changes.
  if (!location.hash && playground.presetName()) scenePart = `#${encodeURIComponent(playground.presetName())}`;
  playground.addEventListener('change', sceneChanged);
  playground.addEventListener('viewchange', () => {
    if (scenePart) writeAddress();
  });
  window.addEventListener('hashchange', () => {
    if (location.hash !== written) openFragment(location.hash);
  });
  document.body.dataset.ready = '';
}

main();
