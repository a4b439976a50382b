// The side panels of <dvf-playground>: legend, selected robot, parameters. DOM only; every
// text that comes from a scenario is set with textContent.

import {
  drawArrowGlyph, drawCurveGlyph, drawGlyph, drawGoal, drawHandle, drawInfluence, drawObstacleDisc,
  drawPredictedGlyph, drawRobot, drawSafeDisc, drawSenseCircle, drawStart, drawTrailGlyph,
  drawVirtualObstacle,
} from './render.js';

/** Legend glyph size (CSS px). */
const GLYPH_PX = 24;
/** Neutral colour for the legend's shapes (robots take their own colours). */
const LEGEND_NEUTRAL = '#4e79a7';

/**
 * The editable parameters: key in `params`, label, unit/meaning, whether it may be empty
 * (no saturation).
 */
export const PARAMETERS = [
  ['k_v', 'k_v', '1/s', 'gain of the forward speed on the field'],
  ['k_omega', 'k_ω', '1/s', 'gain of the attitude feedback −k_ω θ̃'],
  ['k_a', 'k_a', '1/s', 'gain of the alignment term'],
  ['transition_width', 'ε', 'm', 'width of the transition band ς'],
  ['avoid_speed', 'v_c', 'm/s', 'speed while circling a virtual obstacle'],
  ['avoid_radius', 'R_c', 'm', 'radius of the ring about a virtual obstacle'],
  ['safe_radius', 'r_ij', 'm', 'safe radius: closer than 2·r_ij is a collision'],
  ['sense_radius', 'R_s', 'm', 'sensing radius'],
  ['v_max', 'v_max', 'm/s', 'speed saturation (empty: none)', true],
  ['omega_max', 'ω_max', 'rad/s', 'turn-rate saturation (empty: none)', true],
  ['barrier_rate', 'α', '1/s', 'safety barrier: a gap to a safe disc or an obstacle shrinks by at most α·dt per step (empty: off, the paper alone)', true],
];

function el(tag, text, className) {
  const e = document.createElement(tag);
  if (text !== undefined) e.textContent = text;
  if (className) e.className = className;
  return e;
}

/** The legend: what each colour, line and handle means. */
export function buildLegend(list) {
  const n = LEGEND_NEUTRAL;
  const entries = [
    ['robot now', (c, x, y) => drawRobot(c, x, y, 0.5, n)],
    ['goal pose (ghost)', (c, x, y) => drawGoal(c, x, y, 0.5, n)],
    ['start pose', (c, x, y) => drawStart(c, x, y, 0.5, n)],
    ['trail travelled', (c, x, y) => drawTrailGlyph(c, x, y, n)],
    ['predicted path', (c, x, y) => drawPredictedGlyph(c, x, y, n)],
    ['obstacle r_o', (c, x, y) => drawObstacleDisc(c, x, y, 7)],
    ['influence ring R_o', (c, x, y) => drawInfluence(c, x, y, 10)],
    ['safe radius r_ij', (c, x, y) => drawSafeDisc(c, x, y, 9, n)],
    ['virtual obstacle, R_c', (c, x, y) => drawVirtualObstacle(c, x, y, 9)],
    ['sensing radius R_s', (c, x, y) => drawSenseCircle(c, x, y, 10)],
    ['field Γ of the inspected robot', drawArrowGlyph],
    ['integral curve from θ(0)', drawCurveGlyph],
    ['handle: drag to turn / resize', (c, x, y) => drawHandle(c, x, y)],
  ];
  list.replaceChildren();
  for (const [label, draw] of entries) {
    const item = el('li');
    const glyph = el('canvas');
    glyph.setAttribute('aria-hidden', 'true');
    drawGlyph(glyph, GLYPH_PX, draw);
    item.append(glyph, el('span', label));
    list.append(item);
  }
}

/**
 * Builds the parameter form in `form`; `onChange(key, value)` gets a number, `null` (empty
 * optional) or the avoidance mode, and returns an error message or null. On an error the
 * field shows it and goes back to the value it had.
 */
export function buildParams(form, onChange) {
  form.replaceChildren();
  const inputs = new Map();
  for (const [key, label, unit, title, optional] of PARAMETERS) {
    const row = el('label', undefined, 'param');
    row.title = title;
    const name = el('span', label, 'param-name');
    const input = el('input');
    input.type = 'number';
    input.step = 'any';
    input.name = key;
    input.setAttribute('aria-label', `${label} (${unit}): ${title}`);
    if (optional) input.placeholder = 'off';
    row.append(name, input, el('span', unit, 'param-unit'));
    form.append(row);
    inputs.set(key, input);
    input.addEventListener('change', () => {
      const text = input.value.trim();
      const value = text === '' ? (optional ? null : Number.NaN) : Number(text);
      const error = onChange(key, value);
      markError(form, input, error);
    });
  }
  const row = el('label', undefined, 'param wide');
  row.title = 'how robots avoid each other: the paper\'s ring, or the ring with an exit (default)';
  const select = el('select');
  select.name = 'avoidance';
  select.setAttribute('aria-label', 'robot avoidance mode');
  for (const mode of ['exit', 'paper']) {
    const o = el('option', mode);
    o.value = mode;
    select.append(o);
  }
  select.addEventListener('change', () => markError(form, select, onChange('avoidance', select.value)));
  row.append(el('span', 'avoidance', 'param-name'), select);
  form.append(row);
  inputs.set('avoidance', select);
  const error = el('p', '', 'param-error');
  error.setAttribute('role', 'alert');
  error.hidden = true;
  form.append(error);
  return inputs;
}

/** Shows (or clears) the message of the last parameter change under the form. */
function markError(form, input, message) {
  const box = form.querySelector('.param-error');
  input.setAttribute('aria-invalid', String(Boolean(message)));
  box.textContent = message ?? '';
  box.hidden = !message;
}

/** Puts the scenario's parameter values into the form (not into a field being typed in). */
export function fillParams(inputs, params, root) {
  for (const [key, input] of inputs) {
    if (root.activeElement === input) continue;
    const v = params[key];
    input.value = v == null ? '' : String(v);
  }
}
