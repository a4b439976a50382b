// Entry point: loads the wasm module, runs the chosen preset and keeps canvas, slider and
// panels in step. The preset can be named in the address: index.html#example3-line-swap.

import init, { defaultPreset, presets } from './pkg/dvf.js';
import { createState, loadPreset } from './state.js';
import { drawScene, fitCanvas, makeView } from './render.js';
import {
  buildLegend, clearError, initPlayback, initPresetPicker, setSelectedPreset, showError,
  showReport, showScenario, showTime,
} from './ui.js';

/** A whole run plays back in this much wall-clock time (s), whatever its simulated length. */
const PLAYBACK_WALL_TIME_S = 10;

const canvas = document.getElementById('view');
const state = createState();
let presetList = [];
let frameRequested = false;
let lastFrameMs = null;

window.addEventListener('error', (e) => showError(`Error: ${e.message}`));
window.addEventListener('unhandledrejection', (e) => showError(`Error: ${e.reason?.message ?? e.reason}`));

/** Schedules one redraw on the next animation frame (many requests, one frame). */
function requestDraw() {
  if (frameRequested) return;
  frameRequested = true;
  requestAnimationFrame(frame);
}

function frame(nowMs) {
  frameRequested = false;
  const model = state.model;
  if (!model) return;
  if (state.playing) {
    const dt = lastFrameMs == null ? 0 : (nowMs - lastFrameMs) / 1000;
    lastFrameMs = nowMs;
    state.time += (dt * model.duration) / PLAYBACK_WALL_TIME_S;
    if (state.time >= model.duration) {
      state.time = model.duration;
      state.playing = false;
      lastFrameMs = null;
    }
  }
  const { ctx, width, height } = fitCanvas(canvas);
  drawScene(ctx, makeView(model.bounds, width, height), model, state.time);
  showTime(state.time, model.duration, state.playing);
  if (state.playing) requestDraw();
}

/** Runs preset `name` and shows it; on failure keeps what was shown and says why. */
function selectPreset(name) {
  try {
    const model = loadPreset(name);
    state.model = model;
    state.time = model.duration; // open on the outcome: whole paths, robots at their end
    state.playing = false;
    lastFrameMs = null;
    clearError();
    setSelectedPreset(name);
    showScenario(model, presetList.find((p) => p.name === name)?.summary);
    buildLegend(model);
    showReport(model);
    if (location.hash.slice(1) !== name) history.replaceState(null, '', `#${encodeURIComponent(name)}`);
    document.body.dataset.preset = name; // for tests: the run shown
    requestDraw();
  } catch (e) {
    showError(`Could not show preset "${name}": ${e.message ?? e}`);
    if (state.model) {
      setSelectedPreset(state.model.presetName);
      history.replaceState(null, '', `#${encodeURIComponent(state.model.presetName)}`);
    }
  }
}

function togglePlay() {
  const model = state.model;
  if (!model) return;
  if (!state.playing && state.time >= model.duration) state.time = 0; // replay from the start
  state.playing = !state.playing;
  lastFrameMs = null;
  requestDraw();
}

async function main() {
  try {
    await init();
  } catch (e) {
    showError(`Could not load the simulator (pkg/dvf_bg.wasm): ${e.message ?? e}. Build it with "make serve".`);
    return;
  }
  presetList = presets();
  const wanted = decodeURIComponent(location.hash.slice(1));
  const first = presetList.some((p) => p.name === wanted) ? wanted : defaultPreset();
  initPresetPicker(presetList, first, selectPreset);
  initPlayback(
    (fraction) => {
      if (!state.model) return;
      state.playing = false;
      state.time = fraction * state.model.duration;
      requestDraw();
    },
    togglePlay,
  );
  new ResizeObserver(requestDraw).observe(canvas);
  // A change of devicePixelRatio (browser zoom, another screen) fires resize but may keep the
  // CSS box, which ResizeObserver would not report.
  window.addEventListener('resize', requestDraw);
  window.addEventListener('hashchange', () => {
    const name = decodeURIComponent(location.hash.slice(1));
    if (name && name !== state.model?.presetName) selectPreset(name);
  });
  selectPreset(first);
}

main();
