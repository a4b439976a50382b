// Drawing: the world-to-screen view (equal aspect, y up, pan and zoom) and the live scene on a
// 2-D canvas. All sizes are CSS pixels; the backing store is scaled by devicePixelRatio.
// Knows nothing of the DOM beyond the canvas it is given.

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
export const FIELD_COLOUR = '#94a3b8';
export const CURVE_COLOUR = '#7c3aed';
export const VIRTUAL_OBSTACLE_COLOUR = '#dc2626';
export const SENSE_COLOUR = 'rgba(37, 99, 235, 0.35)';
export const HANDLE_FILL = '#ffffff';
export const HANDLE_STROKE = '#111827';
export const SELECTION_COLOUR = '#2563eb';

/** Space kept free around the scenario's bounds when fitting (CSS px). */
const MARGIN_PX = { left: 44, right: 14, top: 14, bottom: 26 };
/** Desired distance between grid lines (CSS px); the step is rounded to 1, 2 or 5 × 10^k m. */
const GRID_SPACING_PX = 70;
const LABEL_FONT = '11px system-ui, sans-serif';
/** Robot glyph: length nose to tail and width at the tail (CSS px). */
export const ROBOT_LENGTH_PX = 18;
export const ROBOT_WIDTH_PX = 12;
/** Start and goal glyphs are smaller than the moving robot. */
export const MARKER_SCALE = 0.85;
/** Heading handles sit this far from the body's centre (CSS px), radius HANDLE_RADIUS_PX. */
export const HANDLE_DISTANCE_PX = 30;
export const HANDLE_RADIUS_PX = 5;
/** Field arrows: one per FIELD_SPACING_PX, at most FIELD_ARROW_PX long. */
export const FIELD_SPACING_PX = 34;
const FIELD_ARROW_PX = 22;
const TRAIL_WIDTH_PX = 2.5;
const PREDICTED_WIDTH_PX = 1.75;
const PREDICTED_ALPHA = 0.55;
const PREDICTED_DASH_PX = [5, 4];
const START_ALPHA = 0.45;
const GOAL_DASH_PX = [3, 2];
const INFLUENCE_DASH_PX = [6, 4];
const SAFE_DASH_PX = [2, 3];
/** Values per pose / per status / per field sample / per obstacle in the wasm arrays. */
export const POSE_STRIDE = 3;
export const STATUS_STRIDE = 6;
export const FIELD_STRIDE = 4;

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
  const width = Math.max(1, canvas.clientWidth);
  const height = Math.max(1, canvas.clientHeight);
  const bw = Math.max(1, Math.round(width * dpr));
  const bh = Math.max(1, Math.round(height * dpr));
  if (canvas.width !== bw) canvas.width = bw;
  if (canvas.height !== bh) canvas.height = bh;
  const ctx = canvas.getContext('2d');
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  return { ctx, width, height };
}

/**
 * A view: world centre (m) and scale (CSS px per m) for a `width`×`height` box. `fitted`
 * places `bounds` in the box, equal aspect.
 */
export function fittedCamera(bounds, width, height) {
  const [xmin, ymin, xmax, ymax] = bounds;
  const innerW = Math.max(1, width - MARGIN_PX.left - MARGIN_PX.right);
  const innerH = Math.max(1, height - MARGIN_PX.top - MARGIN_PX.bottom);
  const scale = Math.min(innerW / (xmax - xmin), innerH / (ymax - ymin));
  // The centre of the box shifted so that the margins (labels) stay clear.
  const cx = (xmin + xmax) / 2 - (MARGIN_PX.left - MARGIN_PX.right) / 2 / scale;
  const cy = (ymin + ymax) / 2 + (MARGIN_PX.top - MARGIN_PX.bottom) / 2 / scale;
  return { cx, cy, scale };
}

/** The world↔screen maps of a camera in a `width`×`height` box (y up on screen). */
export function makeView(camera, width, height) {
  const { cx, cy, scale } = camera;
  const ox = width / 2 - cx * scale;
  const oy = height / 2 + cy * scale;
  return {
    scale,
    width,
    height,
    sx: (x) => ox + x * scale,
    sy: (y) => oy - y * scale,
    wx: (px) => (px - ox) / scale,
    wy: (py) => (oy - py) / scale,
  };
}

/**
 * Draws the whole live scene. `scene` holds what the element read from wasm this frame:
 * scenario, poses, status, trails (+ head, lens), predicted (+ samples), field, curves,
 * selection and display options.
 */
export function drawScene(ctx, view, scene) {
  const s = scene.scenario;
  ctx.fillStyle = CANVAS_BACKGROUND;
  ctx.fillRect(0, 0, view.width, view.height);
  const [xmin, ymin, xmax, ymax] = s.bounds;
  ctx.fillStyle = BOUNDS_FILL;
  ctx.fillRect(view.sx(xmin), view.sy(ymax), (xmax - xmin) * view.scale, (ymax - ymin) * view.scale);
  drawGrid(ctx, view);
  if (scene.curves) drawCurves(ctx, view, scene.curves, scene.curvePoints);
  drawObstacles(ctx, view, s.obstacles, scene.selection);
  if (scene.field) drawField(ctx, view, scene.field, s.obstacles);
  const n = s.robots.length;
  for (let i = 0; i < n; i++) drawPredicted(ctx, view, scene, i);
  for (let i = 0; i < n; i++) drawTrail(ctx, view, scene, i);
  const atStart = scene.time === 0;
  for (let i = 0; i < n; i++) {
    const colour = robotColour(i);
    const g = s.robots[i].goal;
    drawGoal(ctx, view.sx(g[0]), view.sy(g[1]), g[2], colour);
    if (!atStart) {
      const st = s.robots[i].start;
      drawStart(ctx, view.sx(st[0]), view.sy(st[1]), st[2], colour);
    }
  }
  const p = scene.poses;
  const rs = s.params.safe_radius;
  for (let i = 0; i < n; i++) {
    const x = view.sx(p[i * POSE_STRIDE]);
    const y = view.sy(p[i * POSE_STRIDE + 1]);
    if (scene.showSensing) drawSenseCircle(ctx, x, y, s.params.sense_radius * view.scale);
    if (!s.independent) drawSafeDisc(ctx, x, y, rs * view.scale, robotColour(i));
  }
  if (!s.independent) drawVirtualObstacles(ctx, view, scene);
  for (let i = 0; i < n; i++) {
    drawRobot(ctx, view.sx(p[i * POSE_STRIDE]), view.sy(p[i * POSE_STRIDE + 1]), p[i * POSE_STRIDE + 2], robotColour(i));
  }
  drawSelection(ctx, view, scene);
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
    if (px > 40 && px < view.width - 10) ctx.fillText(x.toFixed(decimals), px, view.height - 6);
  }
  ctx.textAlign = 'right';
  ctx.textBaseline = 'middle';
  for (const y of ys) {
    const py = view.sy(y);
    if (py > 8 && py <= view.height - 24) ctx.fillText(y.toFixed(decimals), 36, py);
  }
  ctx.textAlign = 'left';
  ctx.textBaseline = 'bottom';
  ctx.fillText('m', 4, view.height - 6);
}

function drawObstacles(ctx, view, obstacles, selection) {
  obstacles.forEach((o, k) => {
    const x = view.sx(o.center[0]);
    const y = view.sy(o.center[1]);
    drawInfluence(ctx, x, y, o.influence * view.scale);
    drawObstacleDisc(ctx, x, y, o.radius * view.scale);
    if (selection?.kind === 'obstacle' && selection.index === k) {
      ctx.beginPath();
      ctx.arc(x, y, o.radius * view.scale + 3, 0, 2 * Math.PI);
      ctx.lineWidth = 2;
      ctx.strokeStyle = SELECTION_COLOUR;
      ctx.stroke();
      drawHandle(ctx, x + o.radius * view.scale, y);
      drawHandle(ctx, x + o.influence * view.scale, y);
    }
  });
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

/** Field arrows, each scaled to FIELD_ARROW_PX at the largest magnitude shown (log-ish). */
function drawField(ctx, view, field, obstacles) {
  let max = 0;
  for (let k = 0; k < field.length; k += FIELD_STRIDE) {
    max = Math.max(max, Math.hypot(field[k + 2], field[k + 3]));
  }
  if (!(max > 0)) return;
  ctx.strokeStyle = FIELD_COLOUR;
  ctx.fillStyle = FIELD_COLOUR;
  ctx.lineWidth = 1.1;
  ctx.beginPath();
  const heads = [];
  for (let k = 0; k < field.length; k += FIELD_STRIDE) {
    const [x, y, gx, gy] = [field[k], field[k + 1], field[k + 2], field[k + 3]];
    if (obstacles.some((o) => Math.hypot(x - o.center[0], y - o.center[1]) < o.radius)) continue;
    const m = Math.hypot(gx, gy);
    if (!(m > 0)) continue;
    // Length grows with magnitude but saturates, so arrows near the goal stay visible.
    const len = FIELD_ARROW_PX * (0.35 + 0.65 * Math.sqrt(m / max));
    const ux = gx / m;
    const uy = -gy / m; // screen y is down
    const px = view.sx(x) - (ux * len) / 2;
    const py = view.sy(y) - (uy * len) / 2;
    ctx.moveTo(px, py);
    ctx.lineTo(px + ux * len, py + uy * len);
    heads.push([px + ux * len, py + uy * len, ux, uy]);
  }
  ctx.stroke();
  ctx.beginPath();
  for (const [hx, hy, ux, uy] of heads) {
    ctx.moveTo(hx, hy);
    ctx.lineTo(hx - ux * 5 - uy * 2.5, hy - uy * 5 + ux * 2.5);
    ctx.lineTo(hx - ux * 5 + uy * 2.5, hy - uy * 5 - ux * 2.5);
    ctx.closePath();
  }
  ctx.fill();
}

/** Integral curves of the goal field, each from its start (dot) on. */
function drawCurves(ctx, view, curves, points) {
  ctx.strokeStyle = CURVE_COLOUR;
  ctx.globalAlpha = 0.6;
  ctx.lineWidth = 1.2;
  ctx.beginPath();
  const stride = points * 2;
  for (let c = 0; c + stride <= curves.length; c += stride) {
    ctx.moveTo(view.sx(curves[c]), view.sy(curves[c + 1]));
    for (let k = 2; k < stride; k += 2) ctx.lineTo(view.sx(curves[c + k]), view.sy(curves[c + k + 1]));
  }
  ctx.stroke();
  ctx.globalAlpha = 1;
  ctx.fillStyle = CURVE_COLOUR;
  ctx.beginPath();
  for (let c = 0; c + stride <= curves.length; c += stride) {
    ctx.moveTo(view.sx(curves[c]) + 2, view.sy(curves[c + 1]));
    ctx.arc(view.sx(curves[c]), view.sy(curves[c + 1]), 2, 0, 2 * Math.PI);
  }
  ctx.fill();
}

/** Robot `i`'s predicted path from now to the end: dashed, in its colour. */
function drawPredicted(ctx, view, scene, i) {
  const n = scene.predictedSamples;
  const p = scene.predicted;
  if (n < 2) return;
  const o = i * n * POSE_STRIDE;
  ctx.beginPath();
  ctx.moveTo(view.sx(p[o]), view.sy(p[o + 1]));
  for (let k = 1; k < n; k++) ctx.lineTo(view.sx(p[o + k * POSE_STRIDE]), view.sy(p[o + k * POSE_STRIDE + 1]));
  ctx.globalAlpha = PREDICTED_ALPHA;
  ctx.lineJoin = 'round';
  strokeDashed(ctx, PREDICTED_DASH_PX, PREDICTED_WIDTH_PX, robotColour(i));
  ctx.globalAlpha = 1;
}

/** Robot `i`'s trail: the ring of past poses, oldest first, solid. */
function drawTrail(ctx, view, scene, i) {
  const len = scene.trailLens[i];
  if (len < 2) return;
  const cap = scene.trailCapacity;
  const t = scene.trails;
  const base = i * cap * POSE_STRIDE;
  let slot = (scene.trailHead - len + cap) % cap;
  ctx.beginPath();
  ctx.moveTo(view.sx(t[base + slot * POSE_STRIDE]), view.sy(t[base + slot * POSE_STRIDE + 1]));
  for (let k = 1; k < len; k++) {
    slot = (slot + 1) % cap;
    ctx.lineTo(view.sx(t[base + slot * POSE_STRIDE]), view.sy(t[base + slot * POSE_STRIDE + 1]));
  }
  ctx.lineWidth = TRAIL_WIDTH_PX;
  ctx.lineJoin = 'round';
  ctx.lineCap = 'round';
  ctx.strokeStyle = robotColour(i);
  ctx.stroke();
}

/** Virtual obstacles (robots avoiding each other): a red cross and the ring R_c. */
function drawVirtualObstacles(ctx, view, scene) {
  const st = scene.status;
  const rc = scene.scenario.params.avoid_radius * view.scale;
  const seen = new Set();
  for (let k = 0; k < st.length; k += STATUS_STRIDE) {
    const vx = st[k + 4];
    const vy = st[k + 5];
    if (Number.isNaN(vx)) continue;
    const key = `${vx.toFixed(3)},${vy.toFixed(3)}`;
    if (seen.has(key)) continue;
    seen.add(key);
    drawVirtualObstacle(ctx, view.sx(vx), view.sy(vy), rc);
  }
}

/** One virtual obstacle glyph at (x, y) with ring radius `rc` (CSS px). */
export function drawVirtualObstacle(ctx, x, y, rc) {
  ctx.beginPath();
  ctx.arc(x, y, rc, 0, 2 * Math.PI);
  ctx.globalAlpha = 0.7;
  strokeDashed(ctx, [4, 3], 1.25, VIRTUAL_OBSTACLE_COLOUR);
  ctx.globalAlpha = 1;
  ctx.beginPath();
  ctx.moveTo(x - 4, y - 4);
  ctx.lineTo(x + 4, y + 4);
  ctx.moveTo(x + 4, y - 4);
  ctx.lineTo(x - 4, y + 4);
  ctx.lineWidth = 2;
  ctx.strokeStyle = VIRTUAL_OBSTACLE_COLOUR;
  ctx.stroke();
}

/** The sensing circle R_s (radius in CSS px). */
export function drawSenseCircle(ctx, x, y, radius) {
  ctx.beginPath();
  ctx.arc(x, y, radius, 0, 2 * Math.PI);
  ctx.lineWidth = 1;
  ctx.strokeStyle = SENSE_COLOUR;
  ctx.stroke();
}

/** The selected robot (or its goal): a ring and the heading handles of body and goal. */
function drawSelection(ctx, view, scene) {
  const f = scene.focusRobot;
  if (f != null && f < scene.scenario.robots.length) {
    // The robot whose field is drawn: a faint halo even when nothing is selected.
    ctx.beginPath();
    ctx.arc(view.sx(scene.poses[f * POSE_STRIDE]), view.sy(scene.poses[f * POSE_STRIDE + 1]), ROBOT_LENGTH_PX, 0, 2 * Math.PI);
    ctx.fillStyle = 'rgba(37, 99, 235, 0.12)';
    ctx.fill();
  }
  const sel = scene.selection;
  if (!sel || (sel.kind !== 'robot' && sel.kind !== 'goal')) return;
  const i = sel.index;
  const r = scene.scenario.robots[i];
  if (!r) return;
  const p = scene.poses;
  const bodies = [
    [view.sx(p[i * POSE_STRIDE]), view.sy(p[i * POSE_STRIDE + 1]), p[i * POSE_STRIDE + 2], sel.kind === 'robot'],
    [view.sx(r.goal[0]), view.sy(r.goal[1]), r.goal[2], sel.kind === 'goal'],
  ];
  for (const [x, y, theta, active] of bodies) {
    ctx.beginPath();
    ctx.arc(x, y, ROBOT_LENGTH_PX * 0.8, 0, 2 * Math.PI);
    ctx.lineWidth = active ? 2 : 1;
    ctx.strokeStyle = SELECTION_COLOUR;
    ctx.stroke();
    const [hx, hy] = handlePoint(x, y, theta);
    ctx.beginPath();
    ctx.moveTo(x + Math.cos(theta) * ROBOT_LENGTH_PX * 0.8, y - Math.sin(theta) * ROBOT_LENGTH_PX * 0.8);
    ctx.lineTo(hx, hy);
    ctx.lineWidth = 1.25;
    ctx.stroke();
    drawHandle(ctx, hx, hy);
  }
}

/** Screen position of the heading handle of a body at (x, y) heading `theta`. */
export function handlePoint(x, y, theta) {
  return [x + Math.cos(theta) * HANDLE_DISTANCE_PX, y - Math.sin(theta) * HANDLE_DISTANCE_PX];
}

/** A round drag handle. */
export function drawHandle(ctx, x, y) {
  ctx.beginPath();
  ctx.arc(x, y, HANDLE_RADIUS_PX, 0, 2 * Math.PI);
  ctx.fillStyle = HANDLE_FILL;
  ctx.fill();
  ctx.lineWidth = 1.5;
  ctx.strokeStyle = HANDLE_STROKE;
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

/** A predicted-path glyph for the legend. */
export function drawPredictedGlyph(ctx, x, y, colour) {
  ctx.beginPath();
  ctx.moveTo(x - 10, y + 5);
  ctx.lineTo(x + 10, y - 5);
  ctx.globalAlpha = PREDICTED_ALPHA + 0.2;
  strokeDashed(ctx, [4, 3], PREDICTED_WIDTH_PX, colour);
  ctx.globalAlpha = 1;
}

/** A trail glyph for the legend. */
export function drawTrailGlyph(ctx, x, y, colour) {
  ctx.beginPath();
  ctx.moveTo(x - 10, y + 5);
  ctx.quadraticCurveTo(x, y + 6, x + 10, y - 5);
  ctx.lineWidth = TRAIL_WIDTH_PX;
  ctx.lineCap = 'round';
  ctx.strokeStyle = colour;
  ctx.stroke();
}

/** A field-arrow glyph for the legend. */
export function drawArrowGlyph(ctx, x, y) {
  ctx.strokeStyle = FIELD_COLOUR;
  ctx.fillStyle = FIELD_COLOUR;
  ctx.lineWidth = 1.1;
  ctx.beginPath();
  ctx.moveTo(x - 8, y + 4);
  ctx.lineTo(x + 8, y - 4);
  ctx.stroke();
  const ux = 16 / Math.hypot(16, 8);
  const uy = -8 / Math.hypot(16, 8);
  ctx.beginPath();
  ctx.moveTo(x + 8, y - 4);
  ctx.lineTo(x + 8 - ux * 5 - uy * 2.5, y - 4 - uy * 5 + ux * 2.5);
  ctx.lineTo(x + 8 - ux * 5 + uy * 2.5, y - 4 - uy * 5 - ux * 2.5);
  ctx.closePath();
  ctx.fill();
}

/** An integral-curve glyph for the legend. */
export function drawCurveGlyph(ctx, x, y) {
  ctx.beginPath();
  ctx.moveTo(x - 9, y + 6);
  ctx.bezierCurveTo(x - 9, y - 8, x + 4, y - 6, x + 9, y - 2);
  ctx.lineWidth = 1.4;
  ctx.strokeStyle = CURVE_COLOUR;
  ctx.stroke();
  ctx.beginPath();
  ctx.arc(x - 9, y + 6, 2, 0, 2 * Math.PI);
  ctx.fillStyle = CURVE_COLOUR;
  ctx.fill();
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
