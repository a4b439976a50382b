// Drawing: the world-to-screen view (equal aspect, y up) and the scene on a 2-D canvas.
// All sizes below are CSS pixels; the backing store is scaled by devicePixelRatio.

import { OBSTACLE_STRIDE, POSE_STRIDE, SAMPLE_STRIDE, locateTime, poseAt, sampleOffset } from './state.js';

/** One colour per robot, cycled (Tableau 10: distinct, and legible on white). */
export const ROBOT_COLOURS = [
  '#4e79a7', '#f28e2b', '#e15759', '#76b7b2', '#59a14f',
  '#edc948', '#b07aa1', '#ff9da7', '#9c755f', '#17becf',
];
export const CANVAS_BACKGROUND = '#eef0f3';
export const BOUNDS_FILL = '#ffffff';
const GRID_COLOUR = '#e3e6ea';
const AXIS_COLOUR = '#c3c8cf';
const LABEL_COLOUR = '#6b7280';
export const OBSTACLE_FILL = '#4b5563';
export const INFLUENCE_STROKE = '#9ca3af';
export const INFLUENCE_FILL = 'rgba(156, 163, 175, 0.14)';

/** Space kept free around the scenario's bounds (CSS px): left and bottom hold the labels. */
const MARGIN_PX = { left: 44, right: 14, top: 14, bottom: 26 };
/** Desired distance between grid lines (CSS px); the step is rounded to 1, 2 or 5 × 10^k m. */
const GRID_SPACING_PX = 70;
const LABEL_FONT = '11px system-ui, sans-serif';
/** Robot glyph: length nose to tail and width at the tail (CSS px). */
export const ROBOT_LENGTH_PX = 16;
export const ROBOT_WIDTH_PX = 11;
/** Start and goal glyphs are smaller than the moving robot. */
export const MARKER_SCALE = 0.8;
/** Line widths (CSS px). */
const TRAIL_WIDTH_PX = 2;
const TRAIL_AHEAD_ALPHA = 0.25;
const START_ALPHA = 0.6;
const GOAL_DASH_PX = [3, 2];
const INFLUENCE_DASH_PX = [6, 4];
const SAFE_DASH_PX = [2, 3];

/** Colour of robot `i`. */
export function robotColour(i) {
  return ROBOT_COLOURS[i % ROBOT_COLOURS.length];
}

/**
 * Sizes the canvas' backing store to its CSS box times devicePixelRatio and returns the
 * context with CSS pixels as drawing units, plus the box size.
 */
export function fitCanvas(canvas) {
  const dpr = window.devicePixelRatio || 1;
  const rect = canvas.getBoundingClientRect();
  const width = Math.max(1, Math.round(rect.width * dpr));
  const height = Math.max(1, Math.round(rect.height * dpr));
  if (canvas.width !== width) canvas.width = width;
  if (canvas.height !== height) canvas.height = height;
  const ctx = canvas.getContext('2d');
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  return { ctx, width: rect.width, height: rect.height };
}

/** The world-to-screen map fitting `bounds` into a `width`×`height` box, equal aspect, y up. */
export function makeView(bounds, width, height) {
  const [xmin, ymin, xmax, ymax] = bounds;
  const innerW = Math.max(1, width - MARGIN_PX.left - MARGIN_PX.right);
  const innerH = Math.max(1, height - MARGIN_PX.top - MARGIN_PX.bottom);
  const scale = Math.min(innerW / (xmax - xmin), innerH / (ymax - ymin)); // px per m
  const ox = MARGIN_PX.left + (innerW - scale * (xmax - xmin)) / 2;
  const oy = MARGIN_PX.top + (innerH - scale * (ymax - ymin)) / 2;
  return {
    scale,
    width,
    height,
    sx: (x) => ox + (x - xmin) * scale,
    sy: (y) => oy + (ymax - y) * scale,
    wx: (px) => xmin + (px - ox) / scale,
    wy: (py) => ymax - (py - oy) / scale,
  };
}

/** Draws the whole scene for `model` at time `t` (s). */
export function drawScene(ctx, view, model, t) {
  ctx.fillStyle = CANVAS_BACKGROUND;
  ctx.fillRect(0, 0, view.width, view.height);
  const [xmin, ymin, xmax, ymax] = model.bounds;
  ctx.fillStyle = BOUNDS_FILL;
  ctx.fillRect(view.sx(xmin), view.sy(ymax), (xmax - xmin) * view.scale, (ymax - ymin) * view.scale);
  drawGrid(ctx, view);
  drawObstacles(ctx, view, model);
  const at = locateTime(model, t);
  for (let i = 0; i < model.robotCount; i++) drawTrail(ctx, view, model, i, at);
  for (let i = 0; i < model.robotCount; i++) {
    const colour = robotColour(i);
    const s = i * POSE_STRIDE;
    const g = model.goals;
    drawGoal(ctx, view.sx(g[s]), view.sy(g[s + 1]), g[s + 2], colour);
    const st = model.starts;
    drawStart(ctx, view.sx(st[s]), view.sy(st[s + 1]), st[s + 2], colour);
  }
  for (let i = 0; i < model.robotCount; i++) {
    const p = poseAt(model, i, at);
    const x = view.sx(p.x);
    const y = view.sy(p.y);
    if (!model.independent) drawSafeDisc(ctx, x, y, model.safeRadius * view.scale, robotColour(i));
    drawRobot(ctx, x, y, p.theta, robotColour(i));
  }
  drawLabels(ctx, view);
}

/** Grid step (m): 1, 2 or 5 × 10^k, the nearest to GRID_SPACING_PX on screen. */
function gridStep(scale) {
  const raw = GRID_SPACING_PX / scale;
  const pow = 10 ** Math.floor(Math.log10(raw));
  for (const m of [1, 2, 5]) if (m * pow >= raw * 0.75) return m * pow;
  return 10 * pow;
}

function visibleTicks(view) {
  const step = gridStep(view.scale);
  const xs = [];
  const ys = [];
  for (let x = Math.ceil(view.wx(0) / step) * step; x <= view.wx(view.width); x += step) xs.push(x);
  for (let y = Math.ceil(view.wy(view.height) / step) * step; y <= view.wy(0); y += step) ys.push(y);
  return { step, xs, ys };
}

function drawGrid(ctx, view) {
  const { xs, ys } = visibleTicks(view);
  ctx.lineWidth = 1;
  for (const x of xs) {
    ctx.strokeStyle = Math.abs(x) < 1e-9 ? AXIS_COLOUR : GRID_COLOUR;
    const px = Math.round(view.sx(x)) + 0.5; // on a pixel centre: crisp 1-px lines
    ctx.beginPath();
    ctx.moveTo(px, 0);
    ctx.lineTo(px, view.height);
    ctx.stroke();
  }
  for (const y of ys) {
    ctx.strokeStyle = Math.abs(y) < 1e-9 ? AXIS_COLOUR : GRID_COLOUR;
    const py = Math.round(view.sy(y)) + 0.5;
    ctx.beginPath();
    ctx.moveTo(0, py);
    ctx.lineTo(view.width, py);
    ctx.stroke();
  }
}

/** Axis labels in metres, drawn last so nothing covers them. */
function drawLabels(ctx, view) {
  const { step, xs, ys } = visibleTicks(view);
  const decimals = Math.max(0, -Math.floor(Math.log10(step)));
  ctx.font = LABEL_FONT;
  ctx.fillStyle = LABEL_COLOUR;
  ctx.textAlign = 'center';
  ctx.textBaseline = 'bottom';
  for (const x of xs) {
    const px = view.sx(x);
    if (px > MARGIN_PX.left && px < view.width - 10) ctx.fillText(x.toFixed(decimals), px, view.height - 6);
  }
  ctx.textAlign = 'right';
  ctx.textBaseline = 'middle';
  for (const y of ys) {
    const py = view.sy(y);
    if (py > 8 && py <= view.height - MARGIN_PX.bottom + 1) ctx.fillText(y.toFixed(decimals), MARGIN_PX.left - 6, py);
  }
  ctx.textAlign = 'left';
  ctx.textBaseline = 'bottom';
  ctx.fillText('m', 4, view.height - 6);
}

function drawObstacles(ctx, view, model) {
  const ob = model.obstacles;
  for (let o = 0; o < ob.length; o += OBSTACLE_STRIDE) {
    const x = view.sx(ob[o]);
    const y = view.sy(ob[o + 1]);
    drawInfluence(ctx, x, y, ob[o + 3] * view.scale);
    drawObstacleDisc(ctx, x, y, ob[o + 2] * view.scale);
  }
}

/** The influence ring R_o: a faint disc with a dashed edge (radius in CSS px). */
export function drawInfluence(ctx, x, y, radius) {
  ctx.beginPath();
  ctx.arc(x, y, radius, 0, 2 * Math.PI);
  ctx.fillStyle = INFLUENCE_FILL;
  ctx.fill();
  strokeDashed(ctx, INFLUENCE_DASH_PX, 1.5, INFLUENCE_STROKE);
}

/** Strokes the current path with a dash pattern, then restores solid lines. */
function strokeDashed(ctx, dash, width, colour) {
  ctx.setLineDash(dash);
  ctx.lineWidth = width;
  ctx.strokeStyle = colour;
  ctx.stroke();
  ctx.setLineDash([]);
}

/** The obstacle disc r_o (radius in CSS px). */
export function drawObstacleDisc(ctx, x, y, radius) {
  ctx.beginPath();
  ctx.arc(x, y, radius, 0, 2 * Math.PI);
  ctx.fillStyle = OBSTACLE_FILL;
  ctx.fill();
}

/** Robot `i`'s path: solid up to the shown time, faint beyond it. */
function drawTrail(ctx, view, model, i, at) {
  const tr = model.trajectories;
  const first = sampleOffset(model, i, 0);
  const now = poseAt(model, i, at);
  ctx.lineWidth = TRAIL_WIDTH_PX;
  ctx.lineJoin = 'round';
  ctx.lineCap = 'round';
  ctx.strokeStyle = robotColour(i);

  ctx.globalAlpha = TRAIL_AHEAD_ALPHA;
  ctx.beginPath();
  ctx.moveTo(view.sx(now.x), view.sy(now.y));
  for (let k = at.k + 1; k < model.sampleCount; k++) {
    const o = first + k * SAMPLE_STRIDE;
    ctx.lineTo(view.sx(tr[o + 1]), view.sy(tr[o + 2]));
  }
  ctx.stroke();

  ctx.globalAlpha = 1;
  ctx.beginPath();
  ctx.moveTo(view.sx(tr[first + 1]), view.sy(tr[first + 2]));
  for (let k = 1; k <= at.k; k++) {
    const o = first + k * SAMPLE_STRIDE;
    ctx.lineTo(view.sx(tr[o + 1]), view.sy(tr[o + 2]));
  }
  ctx.lineTo(view.sx(now.x), view.sy(now.y));
  ctx.stroke();
}

/** A triangle pointing along world heading `theta` (rad, CCW) at screen point (x, y). */
function trianglePath(ctx, x, y, theta, size = 1) {
  const l = ROBOT_LENGTH_PX * size;
  const w = ROBOT_WIDTH_PX * size;
  // Screen y points down, so a CCW world angle is a CW screen angle.
  const c = Math.cos(theta);
  const s = -Math.sin(theta);
  const pt = (u, v) => [x + u * c - v * s, y + u * s + v * c];
  ctx.beginPath();
  ctx.moveTo(...pt((2 / 3) * l, 0));
  ctx.lineTo(...pt(-l / 3, w / 2));
  ctx.lineTo(...pt(-l / 3, -w / 2));
  ctx.closePath();
}

/** The robot now: solid, outlined in dark grey. */
export function drawRobot(ctx, x, y, theta, colour) {
  trianglePath(ctx, x, y, theta);
  ctx.fillStyle = colour;
  ctx.fill();
  ctx.lineWidth = 1.25;
  ctx.strokeStyle = '#1f2937';
  ctx.stroke();
}

/** The start pose: a faded solid triangle. */
export function drawStart(ctx, x, y, theta, colour) {
  trianglePath(ctx, x, y, theta, MARKER_SCALE);
  ctx.globalAlpha = START_ALPHA;
  ctx.fillStyle = colour;
  ctx.fill();
  ctx.globalAlpha = 1;
}

/** The goal pose: a ghost, dashed outline over a faint fill. */
export function drawGoal(ctx, x, y, theta, colour) {
  trianglePath(ctx, x, y, theta, MARKER_SCALE);
  ctx.fillStyle = 'rgba(255, 255, 255, 0.7)';
  ctx.fill();
  strokeDashed(ctx, GOAL_DASH_PX, 1.5, colour);
}

/** The safe radius r_ij around a robot (radius in CSS px). */
export function drawSafeDisc(ctx, x, y, radius, colour) {
  ctx.beginPath();
  ctx.arc(x, y, radius, 0, 2 * Math.PI);
  strokeDashed(ctx, SAFE_DASH_PX, 1, colour);
}

/** Draws a legend glyph on a small canvas (CSS size `size`×`size` px). */
export function drawGlyph(canvas, size, draw) {
  canvas.style.width = `${size}px`;
  canvas.style.height = `${size}px`;
  const dpr = window.devicePixelRatio || 1;
  canvas.width = Math.round(size * dpr);
  canvas.height = Math.round(size * dpr);
  const ctx = canvas.getContext('2d');
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  draw(ctx, size / 2, size / 2);
}
