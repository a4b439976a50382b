// The main page: one <dvf-playground> that fills the window, with the scene kept in the
// address's fragment (#s=<scenario JSON>, or #<preset name>) so that a copied link reopens it.

import './dvf-playground.js';
import { fragmentFor, MAX_SCENARIO_BYTES, parseFragment } from './io.js';
import { messageOf } from './playground/message.js';

const playground = /** @type {import('./dvf-playground.js').DvfPlayground} */ (document.getElementById('playground'));
/** The fragment this page last wrote, so that its own hashchange is not read back. */
let written = location.hash;

/** Shows the scene the fragment asks for; a bad fragment shows why and keeps the scene. */
function openFragment(hash) {
  let wanted;
  try {
    wanted = parseFragment(hash);
    if (wanted.kind === 'scenario') playground.load(wanted.text);
    else if (wanted.kind === 'preset' && !playground.loadPreset(wanted.name)) return;
    if (wanted.kind !== 'none') playground.showMessage('');
  } catch (e) {
    playground.showMessage(`This link does not hold a scenario the playground can open. ${messageOf(e)}`);
  }
}

async function main() {
  await playground.loaded;
  openFragment(location.hash);
  playground.addEventListener('change', () => {
    // A preset by its name (a crowd of 10,000 is 600 KB of JSON); an edited scene as JSON, or
    // no fragment at all when that is longer than a link may be (Scenario JSON saves it).
    const preset = playground.presetName();
    const fragment = preset ? `#${encodeURIComponent(preset)}` : fragmentFor(playground.scenario());
    written = fragment.length <= MAX_SCENARIO_BYTES ? fragment : '';
    history.replaceState(null, '', written || `${location.pathname}${location.search}`);
  });
  window.addEventListener('hashchange', () => {
    if (location.hash !== written) openFragment(location.hash);
  });
  document.body.dataset.ready = '';
}

main();
