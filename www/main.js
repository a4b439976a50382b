// The main page: one <dvf-playground> that fills the window, with the scene kept in the
// address's fragment (#s=<scenario JSON>, or #<preset name>) so that a copied link reopens it.

import './dvf-playground.js';
import { fragmentFor, parseFragment } from './io.js';

const playground = document.getElementById('playground');
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
    playground.showMessage(`This link does not hold a scenario the playground can open. ${e.message ?? e}`);
  }
}

async function main() {
  await playground.loaded;
  openFragment(location.hash);
  playground.addEventListener('change', () => {
    written = fragmentFor(playground.scenario());
    history.replaceState(null, '', written);
  });
  window.addEventListener('hashchange', () => {
    if (location.hash !== written) openFragment(location.hash);
  });
  document.body.dataset.ready = '';
}

main();
