// Time plots beside the canvas: the minimum distance between two robots with the safe
// distance marked (the paper's last figure), and the selected robot's position and heading
// errors. The past comes from the trail rings (solid), the future from the prediction (dashed).

import { POSE_STRIDE } from './render.js';

const PLOT_FONT = '10.5px system-ui, sans-serif';
const PLOT_TEXT = '#4b5563';
const PLOT_AXIS = '#d1d5db';
const SAFE_COLOUR = '#dc2626';
const NOW_COLOUR = '#2563eb';
/** Inner margins of a plot (CSS px): left holds the y labels, bottom the time labels. */
const PLOT_MARGIN_PX = { left: 34, right: 8, top: 16, bottom: 16 };
export const PAIR_COLOUR = '#111827';
export const POSITION_COLOUR = '#0f766e';
export const HEADING_COLOUR = '#b45309';

/** The past of a ring as `[t, value]` pairs, oldest first (value NaN: skipped). */
function ringSeries(times, head, len, value) {
  const cap = times.length;
  const out = [];
  for (let k = 0; k < len; k++) {
    const slot = (head - len + k + cap) % cap;
    const v = value(slot);
    if (Number.isFinite(v)) out.push([times[slot], v]);
  }
  return out;
}

/** Wraps an angle to (−π, π]. */
function wrap(a) {
  return a - 2 * Math.PI * Math.ceil((a - Math.PI) / (2 * Math.PI));
}

/** Series for the two plots from what the element read from wasm this frame. */
export function plotSeries(scene, robot) {
  const cap = scene.trailCapacity;
  const pastPair = ringSeries(scene.trailTimes, scene.trailHead, scene.historyLength, (s) => scene.trailMinPair[s]);
  const futurePair = [];
  for (let k = 0; k < scene.predictedSamples; k++) {
    const v = scene.predictedMinPair[k];
    if (Number.isFinite(v)) futurePair.push([scene.predictedTimes[k], v]);
  }
  // The prediction stops once every robot has converged: they stay put from there on.
  const extend = (series) => {
    const last = series[series.length - 1];
    if (last && last[0] < scene.duration) series.push([scene.duration, last[1]]);
    return series;
  };
  extend(futurePair);
  const r = scene.scenario.robots[robot];
  const err = (x, y, th) => [Math.hypot(x - r.goal[0], y - r.goal[1]), Math.abs(wrap(th - r.goal[2]))];
  const base = robot * cap * POSE_STRIDE;
  const tr = scene.trails;
  const len = scene.trailLens[robot] ?? 0;
  const pastPos = ringSeries(scene.trailTimes, scene.trailHead, len, (s) => err(tr[base + s * POSE_STRIDE], tr[base + s * POSE_STRIDE + 1], 0)[0]);
  const pastHead = ringSeries(scene.trailTimes, scene.trailHead, len,
    (s) => err(0, 0, tr[base + s * POSE_STRIDE + 2])[1]);
  const futurePos = [];
  const futureHead = [];
  const n = scene.predictedSamples;
  const p = scene.predicted;
  for (let k = 0; k < n; k++) {
    const o = (robot * n + k) * POSE_STRIDE;
    const [e, h] = err(p[o], p[o + 1], p[o + 2]);
    futurePos.push([scene.predictedTimes[k], e]);
    futureHead.push([scene.predictedTimes[k], h]);
  }
  extend(futurePos);
  extend(futureHead);
  return { pastPair, futurePair, pastPos, futurePos, pastHead, futureHead };
}

/**
 * Draws one plot on `ctx` in the box (x, y, w, h): `lines` is a list of
 * `{points, colour, dashed, axis}` (axis 'left' or 'right'), `hline` an optional
 * `{value, colour, label}` on the left axis.
 */
export function drawPlot(ctx, box, { title, duration, time, lines, hline, leftLabel, rightLabel }) {
  const { x, y, w, h } = box;
  const px0 = x + PLOT_MARGIN_PX.left;
  const px1 = x + w - PLOT_MARGIN_PX.right - (rightLabel ? 26 : 0);
  const py0 = y + PLOT_MARGIN_PX.top;
  const py1 = y + h - PLOT_MARGIN_PX.bottom;
  const max = { left: 0, right: 0 };
  for (const l of lines) for (const [, v] of l.points) max[l.axis] = Math.max(max[l.axis], v);
  if (hline) max.left = Math.max(max.left, hline.value * 1.5);
  for (const k of ['left', 'right']) max[k] = niceCeil(max[k] || 1);
  const sx = (t) => px0 + ((px1 - px0) * t) / (duration || 1);
  const sy = (v, axis) => py1 - ((py1 - py0) * v) / max[axis];

  ctx.font = PLOT_FONT;
  ctx.fillStyle = PLOT_TEXT;
  ctx.textBaseline = 'top';
  ctx.textAlign = 'left';
  ctx.fillText(title, x + 4, y + 2);
  ctx.strokeStyle = PLOT_AXIS;
  ctx.lineWidth = 1;
  ctx.strokeRect(Math.round(px0) + 0.5, Math.round(py0) + 0.5, Math.round(px1 - px0), Math.round(py1 - py0));
  ctx.textBaseline = 'middle';
  ctx.textAlign = 'right';
  ctx.fillText(fmt(max.left), px0 - 3, py0 + 1);
  ctx.fillText('0', px0 - 3, py1);
  if (leftLabel) {
    ctx.textAlign = 'left';
    ctx.fillText(leftLabel, x + 2, (py0 + py1) / 2);
  }
  if (rightLabel) {
    ctx.textAlign = 'left';
    ctx.fillText(fmt(max.right), px1 + 3, py0 + 1);
    ctx.fillText(rightLabel, px1 + 3, (py0 + py1) / 2);
  }
  ctx.textBaseline = 'top';
  ctx.textAlign = 'right';
  ctx.fillText(`${fmt(duration)} s`, px1, py1 + 2);
  ctx.textAlign = 'left';
  ctx.fillText('0', px0, py1 + 2);

  if (lines.length === 0) {
    ctx.textAlign = 'center';
    ctx.textBaseline = 'middle';
    ctx.fillText('no pair of interacting robots', (px0 + px1) / 2, (py0 + py1) / 2);
  }
  if (hline) {
    const hy = Math.round(sy(hline.value, 'left')) + 0.5;
    ctx.beginPath();
    ctx.moveTo(px0, hy);
    ctx.lineTo(px1, hy);
    ctx.setLineDash([4, 3]);
    ctx.strokeStyle = hline.colour ?? SAFE_COLOUR;
    ctx.stroke();
    ctx.setLineDash([]);
    ctx.fillStyle = hline.colour ?? SAFE_COLOUR;
    ctx.textAlign = 'right';
    ctx.textBaseline = 'bottom';
    ctx.fillText(hline.label, px1 - 2, hy - 1);
  }
  ctx.save();
  ctx.beginPath();
  ctx.rect(px0, py0 - 1, px1 - px0, py1 - py0 + 2);
  ctx.clip();
  for (const l of lines) {
    if (l.points.length < 1) continue;
    ctx.beginPath();
    l.points.forEach(([t, v], k) => (k ? ctx.lineTo(sx(t), sy(v, l.axis)) : ctx.moveTo(sx(t), sy(v, l.axis))));
    ctx.setLineDash(l.dashed ? [4, 3] : []);
    ctx.globalAlpha = l.dashed ? 0.6 : 1;
    ctx.lineWidth = 1.5;
    ctx.strokeStyle = l.colour;
    ctx.stroke();
  }
  ctx.restore();
  ctx.setLineDash([]);
  ctx.globalAlpha = 1;
  const nx = Math.round(sx(time)) + 0.5;
  ctx.beginPath();
  ctx.moveTo(nx, py0);
  ctx.lineTo(nx, py1);
  ctx.strokeStyle = NOW_COLOUR;
  ctx.stroke();
}

/** 1, 2, 2.5 or 5 × 10^k at or above `v`. */
function niceCeil(v) {
  const pow = 10 ** Math.floor(Math.log10(v));
  for (const m of [1, 2, 2.5, 5, 10]) if (m * pow >= v) return m * pow;
  return 10 * pow;
}

function fmt(v) {
  return Math.abs(v) >= 10 || Number.isInteger(v) ? v.toFixed(0) : v.toPrecision(2);
}

export { SAFE_COLOUR };
