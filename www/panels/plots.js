// The plots panel: time plots beside the canvas, the minimum distance between two robots with
// the safe distance marked (the paper's last figure), and the inspected robot's position and
// heading errors. The past comes from the trail rings (solid), the future from the prediction
// (dashed).

import { GHOST_COLOUR } from '../playground/ghost.js';
import { POSE_STRIDE } from '../playground/wasm-views.js';
import { fitCanvas } from '../render/canvas.js';

const PLOT_FONT = '10.5px system-ui, sans-serif';
const SAFE_COLOUR = '#dc2626';
const NOW_COLOUR = '#2563eb';
/**
 * Inner margins of a plot (CSS px), at least: left holds the value labels, right the second
 * axis's, bottom the times. Left and right widen to the widest label of either plot (the same
 * in both plots, so that their time axes and "now" lines line up): 20000 fits
 * (tests/e2e/forms.mjs, "plot ticks").
 */
const PLOT_MARGIN_PX = { left: 34, right: 30, top: 16, bottom: 16 };
/** Space between a value label and its axis, and before the canvas's edge (CSS px). */
const LABEL_GAP_PX = 3;
export const POSITION_COLOUR = '#0f766e';
export const HEADING_COLOUR = '#d97706';

/** About this many ticks per axis (ends included). */
const TICKS = 5;
/** Dashes of the predicted part of a line and of the safe distance. */
const DASH_PX = [4, 3];
/** Space between the two plots (CSS px). */
const PLOT_GAP_PX = 8;

/**
 * A series of points in two reusable typed arrays: `count` points `(t[k], v[k])`. Filled
 * anew every frame without allocating (the arrays grow only when a series gets longer).
 */
class Series {
  constructor() {
    this.t = new Float64Array(64);
    this.v = new Float64Array(64);
    this.count = 0;
  }

  clear() {
    this.count = 0;
    return this;
  }

  push(t, v) {
    if (this.count === this.t.length) {
      const grow = (a) => {
        const b = new Float64Array(2 * a.length);
        b.set(a);
        return b;
      };
      this.t = grow(this.t);
      this.v = grow(this.v);
    }
    this.t[this.count] = t;
    this.v[this.count] = v;
    this.count += 1;
  }

  /** Holds the last value to `end` (the prediction stops once every robot has converged). */
  extendTo(end) {
    if (this.count > 0 && this.t[this.count - 1] < end) this.push(end, this.v[this.count - 1]);
    return this;
  }
}

/** The six series of the two plots, reused from frame to frame. */
function makeSeries() {
  const names = ['pastPair', 'futurePair', 'pastPos', 'futurePos', 'pastHead', 'futureHead'];
  return Object.fromEntries(names.map((n) => [n, new Series()]));
}

/** Wraps an angle to (−π, π]. */
function wrap(a) {
  return a - 2 * Math.PI * Math.ceil((a - Math.PI) / (2 * Math.PI));
}

/**
 * Fills `series` (from makeSeries) for the two plots from what the element read from wasm this
 * frame: the past from the rings (oldest first, NaN skipped), the future from the prediction.
 */
function plotSeries(scene, robot, series) {
  const cap = scene.trailCapacity;
  const times = scene.trailTimes;
  const head = scene.trailHead;
  const slot = (len, k) => (head - len + k + cap) % cap;
  const { pastPair, futurePair, pastPos, futurePos, pastHead, futureHead } = series;
  for (const s of Object.values(series)) s.clear();
  const pairs = scene.trailMinPair;
  for (let k = 0; k < scene.historyLength; k++) {
    const i = slot(scene.historyLength, k);
    if (Number.isFinite(pairs[i])) pastPair.push(times[i], pairs[i]);
  }
  const n = scene.predictedSamples;
  for (let k = 0; k < n; k++) {
    const v = scene.predictedMinPair[k];
    if (Number.isFinite(v)) futurePair.push(scene.predictedTimes[k], v);
  }
  futurePair.extendTo(scene.duration);
  const r = scene.scenario.robots[robot];
  if (!r) return series;
  const [gx, gy, gth] = r.goal;
  const base = robot * cap * POSE_STRIDE;
  const tr = scene.trails;
  const len = scene.trailLens[robot] ?? 0;
  for (let k = 0; k < len; k++) {
    const i = slot(len, k);
    const o = base + i * POSE_STRIDE;
    if (!Number.isFinite(tr[o])) continue;
    pastPos.push(times[i], Math.hypot(tr[o] - gx, tr[o + 1] - gy));
    pastHead.push(times[i], Math.abs(wrap(tr[o + 2] - gth)));
  }
  const p = scene.predicted;
  for (let k = 0; k < n; k++) {
    const o = (robot * n + k) * POSE_STRIDE;
    futurePos.push(scene.predictedTimes[k], Math.hypot(p[o] - gx, p[o + 1] - gy));
    futureHead.push(scene.predictedTimes[k], Math.abs(wrap(p[o + 2] - gth)));
  }
  futurePos.extendTo(scene.duration);
  futureHead.extendTo(scene.duration);
  return series;
}

/**
 * @typedef {{points: Series, colour: string, axis: 'left' | 'right', dashed?: boolean, ghost?: boolean}} Line
 * @typedef {{
 *   title: string, duration: number, time: number, lines: Line[],
 *   hline?: {value: number, colour?: string, label: string} | null,
 *   leftLabel?: string, rightLabel?: string,
 * }} Plot
 */

/**
 * Draws one plot on `ctx` in the box (x, y, w, h): `lines` (`points` a series of plotSeries),
 * `hline` an optional line on the left axis.
 * @param {CanvasRenderingContext2D} ctx
 * @param {{x: number, y: number, w: number, h: number}} box
 * @param {Plot} plot
 */
function drawPlot(ctx, box, plot, axes, margin, colours) {
  const { title, duration, time, lines, hline, leftLabel, rightLabel } = plot;
  const { x, y, w, h } = box;
  const px0 = x + margin.left;
  const px1 = x + w - margin.right;
  const py0 = y + PLOT_MARGIN_PX.top;
  const py1 = y + h - PLOT_MARGIN_PX.bottom;
  const max = { left: axes.left.max, right: axes.right.max };
  const sx = (t) => px0 + ((px1 - px0) * t) / (duration || 1);
  const sy = (v, axis) => py1 - ((py1 - py0) * v) / max[axis];

  ctx.font = PLOT_FONT;
  ctx.fillStyle = colours.text;
  ctx.textBaseline = 'top';
  ctx.textAlign = 'left';
  ctx.fillText(title, x + 4, y + 2);
  ctx.lineWidth = 1;
  // Ticks: light grid lines across the plot, labelled on the axes.
  const timeTicks = ticks(duration || 1);
  const timeLabels = tickLabels(timeTicks);
  const valueTicks = axes.left.ticks;
  ctx.strokeStyle = colours.axis;
  ctx.globalAlpha = 0.5;
  ctx.beginPath();
  for (const t of timeTicks) {
    const tx = Math.round(sx(t)) + 0.5;
    ctx.moveTo(tx, py0);
    ctx.lineTo(tx, py1);
  }
  for (const v of valueTicks) {
    const ty = Math.round(sy(v, 'left')) + 0.5;
    ctx.moveTo(px0, ty);
    ctx.lineTo(px1, ty);
  }
  ctx.stroke();
  ctx.globalAlpha = 1;
  ctx.strokeRect(Math.round(px0) + 0.5, Math.round(py0) + 0.5, Math.round(px1 - px0), Math.round(py1 - py0));
  ctx.textBaseline = 'middle';
  ctx.textAlign = 'right';
  for (const [k, v] of valueTicks.entries()) {
    ctx.fillText(axes.left.labels[k], px0 - LABEL_GAP_PX, Math.min(py1, Math.max(py0 + 1, sy(v, 'left'))));
  }
  if (leftLabel) {
    ctx.textAlign = 'left';
    ctx.fillText(leftLabel, x + 2, (py0 + py1) / 2);
  }
  if (rightLabel) {
    ctx.textAlign = 'left';
    ctx.fillStyle = HEADING_COLOUR;
    for (const [k, v] of axes.right.ticks.entries()) {
      ctx.fillText(axes.right.labels[k], px1 + LABEL_GAP_PX, Math.min(py1, Math.max(py0 + 1, sy(v, 'right'))));
    }
    ctx.fillStyle = colours.text;
  }
  ctx.textBaseline = 'top';
  for (const [k, t] of timeTicks.entries()) {
    ctx.textAlign = k === 0 ? 'left' : k === timeTicks.length - 1 ? 'right' : 'center';
    ctx.fillText(k === timeTicks.length - 1 ? `${timeLabels[k]} s` : timeLabels[k], sx(t), py1 + 2);
  }

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
    ctx.setLineDash(DASH_PX);
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
    const { count, t, v } = l.points;
    if (count < 1) continue;
    ctx.beginPath();
    ctx.moveTo(sx(t[0]), sy(v[0], l.axis));
    for (let k = 1; k < count; k++) ctx.lineTo(sx(t[k]), sy(v[k], l.axis));
    ctx.setLineDash(l.dashed ? DASH_PX : []);
    ctx.globalAlpha = l.ghost ? 0.45 : l.dashed ? 0.6 : 1;
    ctx.lineWidth = l.ghost ? 3 : 1.5;
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
  return {
    x0: px0,
    x1: px1,
    nowX: nx,
    timeTicks,
    valueTicks,
    valueLabels: axes.left.labels,
    rightLabels: rightLabel ? axes.right.labels : [],
  };
}

/**
 * The scales of `plot`'s two value axes: each its top (a niceCeil of the largest value, of 1.5
 * times `hline` on the left, 1 for none), ticks and their labels.
 * @param {Plot} plot
 */
function axesOf({ lines, hline }) {
  const max = { left: 0, right: 0 };
  for (const l of lines) {
    for (let k = 0; k < l.points.count; k++) {
      const v = l.points.v[k];
      if (Number.isFinite(v)) max[l.axis] = Math.max(max[l.axis], v);
    }
  }
  if (hline) max.left = Math.max(max.left, hline.value * 1.5);
  const axis = (m) => {
    const top = niceCeil(m || 1);
    const t = ticks(top);
    return { max: top, ticks: t, labels: tickLabels(t) };
  };
  return { left: axis(max.left), right: axis(max.right) };
}

/** Ticks from 0 to `max` (a niceCeil) at a 1, 2, 2.5 or 5 × 10^k step: about TICKS of them. */
function ticks(max) {
  const step = niceCeil(max / (TICKS - 1));
  const out = [];
  for (let k = 0; k * step <= max * (1 + 1e-9); k++) out.push(k * step);
  if (out[out.length - 1] < max * (1 - 1e-9)) out.push(max);
  return out;
}

/** 1, 2, 2.5 or 5 × 10^k at or above `v`. */
function niceCeil(v) {
  const pow = 10 ** Math.floor(Math.log10(v));
  for (const m of [1, 2, 2.5, 5, 10]) if (m * pow >= v) return m * pow;
  return 10 * pow;
}

/** Ticks at or above this (or at or below its inverse, but 0) are labelled in exponential notation. */
const EXPONENTIAL_FROM = 1e5;

/**
 * Labels of `values` (ticks at a 1, 2, 2.5 or 5 × 10^k step from 0), as many decimals as the
 * step needs, so that no two are the same ("0.25", "0.5", "0.75"; never "0.000" at every tick);
 * in exponential notation ("2.5e-5", "1e6") when plain text would take more than four
 * decimals or six digits.
 * @param {number[]} values
 */
export function tickLabels(values) {
  const top = Math.max(...values.map(Math.abs), 0);
  if (top === 0) return values.map(() => '0');
  const exact = (d) => values.every((v) => Math.abs(Number(v.toFixed(d)) - v) <= top * 1e-9);
  let decimals = 0;
  while (decimals < 12 && !exact(decimals)) decimals++;
  if (top >= EXPONENTIAL_FROM || decimals > 4) {
    return values.map((v) => (v === 0 ? '0' : Number(v.toPrecision(3)).toExponential().replace('e+', 'e')));
  }
  return values.map((v) => v.toFixed(decimals));
}

/** The two plots of one playground on their canvas, with their series kept between frames. */
export class PlotsPanel {
  /** @param {HTMLCanvasElement} canvas */
  constructor(canvas) {
    this.canvas = canvas;
    this.series = makeSeries();
    /** The colours of text, axes and the pair line (render/theme.js, readPalette). */
    this.colours = { text: '#4b5563', axis: '#d1d5db', pair: '#111827' };
    /** @type {import('../dvf-playground.js').PlotGeometry[]} the plots as last drawn */
    this.geometry = [];
    /** The time shown across the plots (s), for a click to find the time under it. */
    this.duration = 0;
  }

  /** The time (s) at canvas x `px` (CSS px), clamped to the run; null before a draw. */
  timeAt(px) {
    const g = this.geometry[0];
    if (!g) return null;
    const f = (px - g.x0) / (g.x1 - g.x0);
    return Math.min(1, Math.max(0, f)) * this.duration;
  }

  /**
   * Draws both plots for `scene` (render/scene.js) and inspected robot `robot`, with the
   * pinned run `ghost` (playground/ghost.js) faded, if any.
   */
  draw(scene, robot, ghost = null) {
    const { ctx, width, height } = fitCanvas(this.canvas);
    ctx.clearRect(0, 0, width, height);
    const s = scene.scenario;
    const series = plotSeries(scene, robot, this.series);
    const half = height / 2;
    const gap = PLOT_GAP_PX / 2;
    /** @type {Line[]} */
    const pairLines =
      s.independent || s.robots.length < 2
        ? []
        : [
            { points: series.pastPair, colour: this.colours.pair, axis: 'left' },
            { points: series.futurePair, colour: this.colours.pair, axis: 'left', dashed: true },
          ];
    const ghostPair = new Series();
    const ghostPos = new Series();
    if (ghost) {
      for (let k = 0; k < ghost.samples; k++) {
        if (Number.isFinite(ghost.minPair[k])) ghostPair.push(ghost.times[k], ghost.minPair[k]);
        if (robot < ghost.robots) ghostPos.push(ghost.times[k], ghost.positionError[robot * ghost.samples + k]);
      }
      if (pairLines.length) pairLines.push({ points: ghostPair, colour: GHOST_COLOUR, axis: 'left', ghost: true });
    }
    this.duration = scene.duration;
    /** @type {Plot} */
    const pairPlot = {
      title: 'min distance between two robots (m)',
      duration: scene.duration,
      time: scene.time,
      lines: pairLines,
      hline: pairLines.length ? { value: 2 * s.params.safe_radius, colour: SAFE_COLOUR, label: '2·r_ij' } : null,
    };
    /** @type {Plot} */
    const errorPlot = {
      title: `robot ${robot + 1}: errors to its goal`,
      duration: scene.duration,
      time: scene.time,
      rightLabel: 'rad',
      lines: [
        { points: series.pastPos, colour: POSITION_COLOUR, axis: 'left' },
        { points: series.futurePos, colour: POSITION_COLOUR, axis: 'left', dashed: true },
        { points: series.pastHead, colour: HEADING_COLOUR, axis: 'right' },
        { points: series.futureHead, colour: HEADING_COLOUR, axis: 'right', dashed: true },
        ...(ghost
          ? [{ points: ghostPos, colour: GHOST_COLOUR, axis: /** @type {'left'} */ ('left'), ghost: true }]
          : []),
      ],
    };
    const axes = [axesOf(pairPlot), axesOf(errorPlot)];
    // Both plots' margins fit the widest label of either, so that their time axes line up.
    ctx.font = PLOT_FONT;
    const widest = (labels) => Math.max(0, ...labels.map((t) => ctx.measureText(t).width));
    const room = (side) => Math.ceil(Math.max(...axes.map((a) => widest(a[side].labels))) + 2 * LABEL_GAP_PX);
    const margin = {
      left: Math.max(PLOT_MARGIN_PX.left, room('left')),
      right: Math.max(PLOT_MARGIN_PX.right, widest(axes[1].right.labels) + 2 * LABEL_GAP_PX),
    };
    const top = drawPlot(ctx, { x: 0, y: 0, w: width, h: half - gap }, pairPlot, axes[0], margin, this.colours);
    const bottom = drawPlot(
      ctx,
      { x: 0, y: half + gap, w: width, h: half - gap },
      errorPlot,
      axes[1],
      margin,
      this.colours,
    );
    this.geometry = [top, bottom];
  }
}

/** Fills `list` with the plots' legend: which line is which, and what dashes mean. */
export function buildPlotsLegend(list) {
  /** @type {[label: string, colour: string, dashed: boolean][]} */
  const entries = [
    ['min distance between two robots', 'var(--pg-plot-pair)', false],
    ['2·r_ij: closer is a collision', SAFE_COLOUR, true],
    ['position error (m, left axis)', POSITION_COLOUR, false],
    ['heading error (rad, right axis)', HEADING_COLOUR, false],
    ['dashed: predicted from now on', 'var(--pg-muted)', true],
    ['"now"; click a plot to go to a time', NOW_COLOUR, false],
    ['wide, faded: the pinned run', GHOST_COLOUR, false],
  ];
  list.replaceChildren();
  for (const [label, colour, dashed] of entries) {
    const item = document.createElement('li');
    const swatch = document.createElement('span');
    swatch.className = dashed ? 'swatch dashed' : 'swatch';
    swatch.style.borderTopColor = colour;
    swatch.setAttribute('aria-hidden', 'true');
    const text = document.createElement('span');
    text.textContent = label;
    item.append(swatch, text);
    list.append(item);
  }
}
