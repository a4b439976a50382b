// The page's controls and panels: preset picker, time slider, legend, metrics, errors.
// Text from the scenario (names, summaries) is set with textContent only.

import {
  drawGlyph, drawGoal, drawInfluence, drawObstacleDisc, drawRobot, drawSafeDisc, drawStart,
  robotColour, MARKER_SCALE, ROBOT_LENGTH_PX,
} from './render.js';

/** Legend glyph size (CSS px). */
const GLYPH_PX = 22;
/** Neutral colour for the shape legend (the robots' own colours are in the metrics table). */
const LEGEND_NEUTRAL = '#6b7280';
/** Slider resolution: steps over the whole run. */
const SLIDER_STEPS = 1000;

/** Looks up an element by id, failing loudly if the page lacks it. */
function byId(id) {
  const el = document.getElementById(id);
  if (!el) throw new Error(`page element #${id} is missing`);
  return el;
}

function el(tag, text, className) {
  const e = document.createElement(tag);
  if (text !== undefined) e.textContent = text;
  if (className) e.className = className;
  return e;
}

/** Shows `message` in the page's error banner (and the console). */
export function showError(message) {
  const box = document.getElementById('error');
  if (box) {
    box.textContent = message;
    box.hidden = false;
  }
  console.error(message);
}

export function clearError() {
  const box = document.getElementById('error');
  if (box) {
    box.textContent = '';
    box.hidden = true;
  }
}

/** Fills the preset <select> and calls `onChange(name)` when the user picks one. */
export function initPresetPicker(presets, selected, onChange) {
  const select = byId('preset');
  select.replaceChildren();
  for (const p of presets) {
    const option = el('option', p.name);
    option.value = p.name;
    option.title = p.summary;
    select.append(option);
  }
  select.value = selected;
  select.addEventListener('change', () => onChange(select.value));
}

export function setSelectedPreset(name) {
  byId('preset').value = name;
}

/** Shows the scenario's name and the preset's one-line summary. */
export function showScenario(model, summary) {
  byId('scenario-name').textContent = model.name;
  const line = byId('scenario-summary');
  line.textContent = summary ?? '';
  line.title = summary ?? ''; // the whole line when it is cut short
}

/**
 * Wires the time slider and the play button. `onTime(t)` gets the time (s) the user scrubs
 * to; `onPlay()` toggles playback.
 */
export function initPlayback(onTime, onPlay) {
  const slider = byId('time');
  slider.max = String(SLIDER_STEPS);
  slider.addEventListener('input', () => onTime(Number(slider.value) / SLIDER_STEPS));
  byId('play').addEventListener('click', onPlay);
}

/** Moves the slider and the time label to `t` of `duration` (s). */
export function showTime(t, duration, playing) {
  const slider = byId('time');
  slider.value = String(duration > 0 ? Math.round((t / duration) * SLIDER_STEPS) : 0);
  byId('time-label').textContent = `t = ${t.toFixed(2)} s / ${duration.toFixed(2)} s`;
  const play = byId('play');
  play.textContent = playing ? 'Pause' : 'Play';
  play.setAttribute('aria-pressed', String(playing));
}

/** The legend of shapes (what each mark means). */
export function buildLegend(model) {
  const list = byId('legend');
  list.replaceChildren();
  const r = ROBOT_LENGTH_PX * 0.55;
  const entries = [
    ['robot now', (c, x, y) => drawRobot(c, x, y, 0.5, LEGEND_NEUTRAL)],
    ['start pose', (c, x, y) => drawStart(c, x, y, 0.5, LEGEND_NEUTRAL)],
    ['goal pose', (c, x, y) => drawGoal(c, x, y, 0.5, LEGEND_NEUTRAL)],
    ['path done / ahead', drawTrailGlyph],
  ];
  if (model.obstacles.length > 0) {
    entries.push(['obstacle r_o', (c, x, y) => drawObstacleDisc(c, x, y, r * 0.8)]);
    entries.push(['influence ring R_o', (c, x, y) => drawInfluence(c, x, y, r * MARKER_SCALE + 2)]);
  }
  if (!model.independent) {
    entries.push(['safe radius r_ij', (c, x, y) => drawSafeDisc(c, x, y, r, LEGEND_NEUTRAL)]);
  }
  for (const [label, draw] of entries) {
    const item = el('li');
    const glyph = el('canvas');
    drawGlyph(glyph, GLYPH_PX, draw);
    item.append(glyph, el('span', label));
    list.append(item);
  }
}

function drawTrailGlyph(ctx, x, y) {
  ctx.lineWidth = 2;
  ctx.lineCap = 'round';
  ctx.strokeStyle = LEGEND_NEUTRAL;
  ctx.beginPath();
  ctx.moveTo(x - 9, y + 5);
  ctx.lineTo(x, y);
  ctx.stroke();
  ctx.globalAlpha = 0.25;
  ctx.beginPath();
  ctx.moveTo(x, y);
  ctx.lineTo(x + 9, y - 5);
  ctx.stroke();
  ctx.globalAlpha = 1;
}

const metres = (v) => (v == null ? '—' : `${v.toFixed(3)} m`);
const degrees = (rad) => `${((rad * 180) / Math.PI).toFixed(2)}°`;

/** The report: run-wide metrics and one row per robot (its colour doubles as legend). */
export function showReport(model) {
  const rep = model.report;
  const summary = byId('metrics');
  summary.replaceChildren();
  const rows = [['simulated', `${rep.time.toFixed(2)} s, ${rep.steps} steps`]];
  if (model.independent) {
    rows.push(['min pair distance', '— (independent runs)']);
  } else {
    rows.push(['min pair distance', metres(rep.min_pair_distance)]);
    rows.push(['safe distance 2·r_ij', metres(2 * model.safeRadius)]);
  }
  rows.push(
    ['min obstacle clearance', rep.min_obstacle_clearance == null ? '— (no obstacles)' : metres(rep.min_obstacle_clearance)],
    ['violations', String(rep.violations)],
  );
  for (const [k, v] of rows) {
    const dd = el('dd', v);
    if (k === 'violations') dd.className = rep.violations > 0 ? 'bad' : 'good';
    summary.append(el('dt', k), dd);
  }

  const body = byId('robots');
  body.replaceChildren();
  rep.robots.forEach((r, i) => {
    const tr = el('tr');
    const swatch = el('span', undefined, 'swatch');
    swatch.style.background = robotColour(i);
    const id = el('td');
    id.append(swatch, document.createTextNode(String(i + 1)));
    tr.append(
      id,
      el('td', r.position_error.toFixed(3)),
      el('td', degrees(r.heading_error)),
      el('td', r.converged_at == null ? '—' : r.converged_at.toFixed(2)),
    );
    body.append(tr);
  });
}
