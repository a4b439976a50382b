// The notebook widget's view (anywidget): one <dvf-playground> per view. The element comes
// from its single-file build (the wasm module and the stylesheet inlined, so that no server
// hosts a file), which the model carries as text (`_element`, dvf/widget.py) and the first
// view of the page imports. The model's traits and the element stay in step both ways:
//   scenario: an edit in the figure (its `change` event) sets the trait to the element's
//             scenario; a scenario set in Python loads into the figure (t = 0);
//   time:     the clock (its `tick` events, a few a second while playing) sets the trait; a
//             time set in Python seeks the figure there (paused);
//   playing:  the clock's state sets the trait; set in Python, it plays or pauses the figure.
// A change that arrives from the element is not sent back to it: each direction compares
// with what the other side already holds.

/** Longest wait between two time updates sent while playing (ms). */
const TIME_UPDATE_MS = 250;

/** Deep equality of JSON values (numbers by ===). */
function same(a, b) {
  if (a === b) return true;
  if (typeof a !== 'object' || typeof b !== 'object' || a === null || b === null) return false;
  if (Array.isArray(a) !== Array.isArray(b)) return false;
  const ka = Object.keys(a).filter((k) => a[k] !== undefined);
  const kb = Object.keys(b).filter((k) => b[k] !== undefined);
  return ka.length === kb.length && ka.every((k) => same(a[k], b[k]));
}

/** A data URL of the scenario, which the element's `src` loads without a server. */
function dataUrl(scenario) {
  return `data:application/json,${encodeURIComponent(JSON.stringify(scenario))}`;
}

/** Defines <dvf-playground> from the model's copy of the element, once per page. */
async function defineElement(model) {
  if (customElements.get('dvf-playground')) return;
  const url = URL.createObjectURL(new Blob([model.get('_element')], { type: 'text/javascript' }));
  try {
    await import(url);
  } finally {
    URL.revokeObjectURL(url);
  }
}

async function render({ model, el }) {
  await defineElement(model);
  const fig = document.createElement('dvf-playground');
  fig.style.display = 'block';
  fig.style.height = model.get('height');
  if (model.get('controls')) fig.setAttribute('controls', '');
  else fig.setAttribute('editable', '');
  const scenario = model.get('scenario');
  if (scenario && Object.keys(scenario).length) fig.setAttribute('src', dataUrl(scenario));
  if (model.get('time') > 0) fig.setAttribute('time', String(model.get('time')));
  el.classList.add('dvf-widget');
  el.appendChild(fig);

  let sentAt = 0;
  const sendTime = (force) => {
    const now = performance.now();
    if (!force && now - sentAt < TIME_UPDATE_MS) return;
    sentAt = now;
    if (model.get('time') !== fig.time || model.get('playing') !== fig.playing) {
      model.set('time', fig.time);
      model.set('playing', fig.playing);
      model.save_changes();
    }
  };
  const onChange = () => {
    const s = fig.scenario();
    if (s && !same(s, model.get('scenario'))) {
      model.set('scenario', s);
      model.save_changes();
    }
    sendTime(true);
  };
  const onTick = () => sendTime(!fig.playing);
  const onRest = () => sendTime(true);
  fig.addEventListener('change', onChange);
  fig.addEventListener('tick', onTick);
  fig.addEventListener('finished', onRest);
  // `viewchange` comes, among others, when the clock comes to rest (a pause).
  fig.addEventListener('viewchange', onRest);
  // The clock has no event of its own for play and pause: its state is also read a few times
  // a second.
  const poll = setInterval(() => {
    if (fig.playing !== model.get('playing')) sendTime(true);
  }, TIME_UPDATE_MS);

  const onScenario = () => {
    const s = model.get('scenario');
    if (!s || !Object.keys(s).length || same(s, fig.scenario())) return;
    try {
      fig.load(s);
    } catch (e) {
      fig.showMessage(String(e?.message ?? e));
    }
    sendTime(true);
  };
  const onTime = () => {
    const t = model.get('time');
    // The clock moves in whole steps: a time within half a step is the time shown.
    const dt = fig.scenario()?.dt ?? 0;
    if (Number.isFinite(t) && Math.abs(t - fig.time) > dt / 2) fig.seek(t);
  };
  const onPlaying = () => {
    const want = model.get('playing');
    if (want === fig.playing) return;
    if (want) fig.play();
    else fig.pause();
  };
  const onControls = () => {
    if (model.get('controls')) fig.setAttribute('controls', '');
    else fig.removeAttribute('controls');
  };
  const onHeight = () => {
    fig.style.height = model.get('height');
  };
  model.on('change:scenario', onScenario);
  model.on('change:time', onTime);
  model.on('change:playing', onPlaying);
  model.on('change:controls', onControls);
  model.on('change:height', onHeight);
  fig.loaded.then(() => {
    // The scene the view opened with: Python learns its resolved form and the clock's state.
    onChange();
    onPlaying();
  });
  return () => {
    clearInterval(poll);
    model.off('change:scenario', onScenario);
    model.off('change:time', onTime);
    model.off('change:playing', onPlaying);
    model.off('change:controls', onControls);
    model.off('change:height', onHeight);
  };
}

export default { render };
