// Drawing: the world-to-screen view (equal aspect, y up, pan and zoom) and the live scene on a
// 2-D canvas. All sizes are CSS pixels; the backing store is scaled by devicePixelRatio.
// Knows nothing of the DOM beyond the canvas it is given (and the canvases of its layers).

import { GlyphLayer } from './glyphs.js';

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
/**
 * Above this many robots, predicted paths are hairlines, one device pixel wide: without a GPU
 * a wider stroke is outlined and filled as a polygon, a hairline takes the rasteriser's fast
 * path (100 robots' paths: 30 ms against 5).
 */
const THIN_PREDICTED_ABOVE = 20;

/** One device pixel in CSS pixels: the width of a hairline (see THIN_PREDICTED_ABOVE). */
function hairline(scene) {
  return 1 / (scene.dpr || 1);
}
const PREDICTED_ALPHA = 0.55;
const PREDICTED_DASH_PX = [5, 4];
const START_ALPHA = 0.45;
const GOAL_DASH_PX = [3, 2];
const INFLUENCE_DASH_PX = [6, 4];
const SAFE_DASH_PX = [2, 3];
/**
 * Above this many robots the scene is drawn as a crowd: one path per colour for each kind of
 * glyph (ten fills or strokes in all, whatever the count), glyphs shrunk with the zoom, start
 * markers and dashes left out, and the sensing circle and virtual obstacle of the inspected
 * robot only.
 */
export const CROWD_STYLE_ABOVE = 100;
/** A crowd's glyphs are about 3·r_ij long on screen, within these bounds (CSS px). */
const CROWD_GLYPH_MIN_PX = 4;
/** A crowd's safe discs are drawn only when at least this wide (radius, CSS px) and at most
 * this many robots are on screen (each disc is a path call: see glyphs.js). */
const CROWD_DISC_MIN_PX = 3;
const CROWD_DISC_MAX = 1500;
/** A full redraw of the trails skips points closer than this to the last one drawn (CSS px). */
const TRAIL_DECIMATE_PX = 1;
/**
 * While the view moves, trails that took longer than TRAIL_DEFER_MS to draw are shown
 * stretched from their last drawing, and drawn again once the view has been still for
 * TRAIL_SETTLE_MS.
 */
const TRAIL_DEFER_MS = 12;
export const TRAIL_SETTLE_MS = 150;
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
  if (scene.field) drawField(ctx, view, scene.field, s.obstacles, hairline(scene));
  const n = s.robots.length;
  drawPredicted(ctx, view, scene);
  scene.trailLayer?.composite(ctx, view);
  if (n > CROWD_STYLE_ABOVE) {
    drawCrowd(ctx, view, scene);
  } else {
    drawRobots(ctx, view, scene);
  }
  drawSelection(ctx, view, scene);
  drawLabels(ctx, view);
}

/**
 * Each robot with its own glyphs: goal, start, safe disc, sensing circle, body. Batched by
 * colour (each kind of glyph of the robots of one colour is one path, filled or stroked once):
 * without a GPU every fill or stroke costs tens of microseconds to rasterise, whatever its
 * size, so a hundred robots drawn one by one cost over 20 ms a frame. A dash pattern starts
 * afresh on each glyph of a path, so the picture is the same.
 */
function drawRobots(ctx, view, scene) {
  const s = scene.scenario;
  const n = s.robots.length;
  const k = ROBOT_COLOURS.length;
  const p = scene.poses;
  const each = (c, add) => {
    ctx.beginPath();
    for (let i = c; i < n; i += k) add(i);
  };
  for (let c = 0; c < k && c < n; c++) {
    each(c, (i) => {
      const g = s.robots[i].goal;
      addTriangle(ctx, view.sx(g[0]), view.sy(g[1]), g[2], MARKER_SCALE);
    });
    ctx.fillStyle = 'rgba(255, 255, 255, 0.7)';
    ctx.fill();
    strokeDashed(ctx, GOAL_DASH_PX, 1.5, ROBOT_COLOURS[c]);
    if (scene.time !== 0) {
      each(c, (i) => {
        const st = s.robots[i].start;
        addTriangle(ctx, view.sx(st[0]), view.sy(st[1]), st[2], MARKER_SCALE);
      });
      ctx.globalAlpha = START_ALPHA;
      ctx.fillStyle = ROBOT_COLOURS[c];
      ctx.fill();
      ctx.globalAlpha = 1;
    }
  }
  if (scene.showSensing) {
    const r = s.params.sense_radius * view.scale;
    ctx.beginPath();
    for (let i = 0; i < n; i++) {
      const x = view.sx(p[i * POSE_STRIDE]);
      const y = view.sy(p[i * POSE_STRIDE + 1]);
      ctx.moveTo(x + r, y);
      ctx.arc(x, y, r, 0, 2 * Math.PI);
    }
    ctx.lineWidth = 1;
    ctx.strokeStyle = SENSE_COLOUR;
    ctx.stroke();
  }
  if (!s.independent) {
    const r = s.params.safe_radius * view.scale;
    for (let c = 0; c < k && c < n; c++) {
      each(c, (i) => {
        const x = view.sx(p[i * POSE_STRIDE]);
        const y = view.sy(p[i * POSE_STRIDE + 1]);
        ctx.moveTo(x + r, y);
        ctx.arc(x, y, r, 0, 2 * Math.PI);
      });
      strokeDashed(ctx, SAFE_DASH_PX, 1, ROBOT_COLOURS[c]);
    }
    drawVirtualObstacles(ctx, view, scene);
  }
  ctx.lineJoin = 'miter';
  for (let c = 0; c < k && c < n; c++) {
    each(c, (i) => addTriangle(ctx, view.sx(p[i * POSE_STRIDE]), view.sy(p[i * POSE_STRIDE + 1]), p[i * POSE_STRIDE + 2], 1));
    ctx.fillStyle = ROBOT_COLOURS[c];
    ctx.fill();
    ctx.lineWidth = 1.25;
    ctx.strokeStyle = '#1f2937';
    ctx.stroke();
  }
}

/** Length of a crowd's glyphs in device pixels (a whole number, so sprites can be reused). */
function crowdGlyphPx(view, safeRadius, dpr) {
  const css = Math.min(ROBOT_LENGTH_PX, Math.max(CROWD_GLYPH_MIN_PX, 3 * safeRadius * view.scale));
  return Math.max(3, Math.round(css * dpr));
}

/**
 * A crowd: goals and bodies stamped as pre-rasterised sprites into scene.glyphLayer (see
 * glyphs.js; paths cost too much per call for thousands), safe discs as paths when they are
 * wide enough and few enough to matter. Glyphs off screen are skipped. The inspected robot
 * keeps its sensing circle and virtual obstacle.
 */
function drawCrowd(ctx, view, scene) {
  const s = scene.scenario;
  const n = s.robots.length;
  const p = scene.poses;
  const k = ROBOT_COLOURS.length;
  const dpr = scene.dpr;
  const pad = ROBOT_LENGTH_PX;
  const onScreen = (x, y) => x > -pad && y > -pad && x < view.width + pad && y < view.height + pad;
  const rs = s.params.safe_radius * view.scale;
  if (!s.independent && rs >= CROWD_DISC_MIN_PX) {
    let shown = 0;
    for (let i = 0; i < n && shown <= CROWD_DISC_MAX; i++) {
      if (onScreen(view.sx(p[i * POSE_STRIDE]), view.sy(p[i * POSE_STRIDE + 1]))) shown += 1;
    }
    if (shown <= CROWD_DISC_MAX) {
      ctx.globalAlpha = 0.55;
      ctx.lineWidth = 1;
      for (let c = 0; c < k; c++) {
        ctx.beginPath();
        for (let i = c; i < n; i += k) {
          const x = view.sx(p[i * POSE_STRIDE]);
          const y = view.sy(p[i * POSE_STRIDE + 1]);
          if (!onScreen(x, y)) continue;
          ctx.moveTo(x + rs, y);
          ctx.arc(x, y, rs, 0, 2 * Math.PI);
        }
        ctx.strokeStyle = ROBOT_COLOURS[c];
        ctx.stroke();
      }
      ctx.globalAlpha = 1;
    }
  }
  const layer = scene.glyphLayer;
  layer.begin(ctx.canvas.width, ctx.canvas.height);
  const px = crowdGlyphPx(view, s.params.safe_radius, dpr);
  // The glyph spans 2/3 of its length either side of its centre, plus the stroke.
  const side = Math.ceil((4 / 3) * px) + 3;
  const scale = px / dpr / ROBOT_LENGTH_PX;
  const goals = layer.sprites(`goal|${px}|${dpr}`, side, ROBOT_COLOURS, (g, c, theta, colour) => {
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    g.beginPath();
    addTriangle(g, c / dpr, c / dpr, theta, scale * MARKER_SCALE);
    g.globalAlpha = 0.55;
    g.lineWidth = 1;
    g.strokeStyle = colour;
    g.stroke();
  });
  const outline = px >= 10 * dpr;
  const bodies = layer.sprites(`body|${px}|${dpr}`, side, ROBOT_COLOURS, (g, c, theta, colour) => {
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    g.beginPath();
    addTriangle(g, c / dpr, c / dpr, theta, scale);
    g.fillStyle = colour;
    g.fill();
    if (outline) {
      g.lineWidth = 0.75;
      g.strokeStyle = '#1f2937';
      g.stroke();
    }
  });
  for (let i = 0; i < n; i++) {
    const g = s.robots[i].goal;
    const x = view.sx(g[0]);
    const y = view.sy(g[1]);
    if (onScreen(x, y)) layer.stamp(GlyphLayer.pick(goals, i % k, g[2]), x * dpr, y * dpr);
  }
  for (let i = 0; i < n; i++) {
    const x = view.sx(p[i * POSE_STRIDE]);
    const y = view.sy(p[i * POSE_STRIDE + 1]);
    if (onScreen(x, y)) layer.stamp(GlyphLayer.pick(bodies, i % k, p[i * POSE_STRIDE + 2]), x * dpr, y * dpr);
  }
  layer.end(ctx, view.width, view.height);
  const f = scene.focusRobot;
  if (f != null && f < n) {
    const x = view.sx(p[f * POSE_STRIDE]);
    const y = view.sy(p[f * POSE_STRIDE + 1]);
    if (scene.showSensing) drawSenseCircle(ctx, x, y, s.params.sense_radius * view.scale);
    const vx = scene.status[f * STATUS_STRIDE + 4];
    const vy = scene.status[f * STATUS_STRIDE + 5];
    if (!s.independent && !Number.isNaN(vx)) {
      drawVirtualObstacle(ctx, view.sx(vx), view.sy(vy), s.params.avoid_radius * view.scale);
    }
  }
}

/**
 * The trails, kept on a canvas of their own that is brought up to date each frame: while the
 * view stays put only the samples recorded since the last frame are drawn (a few segments
 * per robot), so trails cost O(robots) per frame however long they are. A new view, size,
 * scene or ring layout redraws them all, one path per colour, points closer than
 * TRAIL_DECIMATE_PX to the previous one skipped.
 *
 * Sample `g` (counting from the last reset, `scene.recorded` in all) lies in ring slot
 * `g % cap`; robot `i` holds its last `trailLens[i]` samples.
 */
export class TrailLayer {
  constructor() {
    this.canvas = document.createElement('canvas');
    this.state = { width: 0, height: 0, scale: 0, ox: 0, oy: 0, generation: -1, robots: -1, cap: -1, drawn: 0 };
    /** The camera of the last frame and when it last changed (ms). */
    this.seen = { scale: 0, ox: 0, oy: 0, at: 0 };
    /** How long the last full drawing took (ms). */
    this.costMs = 0;
    /** Whether the layer shows an older view (a redraw is due once the view is still). */
    this.stale = false;
  }

  /**
   * Updates the layer for `view` (a makeView) and `scene` at devicePixelRatio `dpr`; `nowMs`
   * is the frame's time.
   */
  update(view, scene, dpr, generation, nowMs) {
    const bw = Math.max(1, Math.round(view.width * dpr));
    const bh = Math.max(1, Math.round(view.height * dpr));
    const n = scene.scenario.robots.length;
    const cap = scene.trailCapacity;
    const st = this.state;
    const recorded = scene.recorded;
    const ox = view.sx(0);
    const oy = view.sy(0);
    const seen = this.seen;
    if (seen.scale !== view.scale || seen.ox !== ox || seen.oy !== oy) Object.assign(seen, { scale: view.scale, ox, oy, at: nowMs });
    const sameScene = st.width === bw && st.height === bh && st.generation === generation && st.robots === n && st.cap === cap
      && recorded >= st.drawn && recorded - st.drawn < cap;
    const sameCamera = st.scale === view.scale && st.ox === ox && st.oy === oy;
    const ctx = this.canvas.getContext('2d');
    const crowd = n > CROWD_STYLE_ABOVE;
    this.stale = false;
    if (sameScene && !sameCamera && this.costMs > TRAIL_DEFER_MS && nowMs - seen.at < TRAIL_SETTLE_MS) {
      this.stale = true;
      return;
    }
    if (!sameScene || !sameCamera) {
      const t0 = performance.now();
      if (this.canvas.width !== bw) this.canvas.width = bw;
      if (this.canvas.height !== bh) this.canvas.height = bh;
      ctx.setTransform(1, 0, 0, 1, 0, 0);
      ctx.clearRect(0, 0, bw, bh);
      ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
      this.draw(ctx, view, scene, 0, crowd);
      Object.assign(st, { width: bw, height: bh, scale: view.scale, ox, oy, generation, robots: n, cap });
      this.costMs = performance.now() - t0;
    } else if (recorded > st.drawn) {
      ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
      this.draw(ctx, view, scene, st.drawn - 1, crowd);
    }
    st.drawn = recorded;
  }

  /** Puts the layer on `ctx`, stretched from the view it was drawn in to `view`. */
  composite(ctx, view) {
    const st = this.state;
    if (st.scale === 0) return;
    const r = view.scale / st.scale;
    const w = view.width * r;
    const h = view.height * r;
    ctx.drawImage(this.canvas, view.sx(0) - st.ox * r, view.sy(0) - st.oy * r, w, h);
  }

  /** Draws every robot's trail from global sample `from` on (the first kept one at least). */
  draw(ctx, view, scene, from, crowd) {
    const n = scene.scenario.robots.length;
    const cap = scene.trailCapacity;
    const t = scene.trails;
    const lens = scene.trailLens;
    const end = scene.recorded;
    const k = ROBOT_COLOURS.length;
    const full = from <= 0;
    // A crowd's trails are hairlines (the rasteriser's fast path; see THIN_PREDICTED_ABOVE).
    ctx.lineWidth = crowd ? hairline(scene) : TRAIL_WIDTH_PX;
    ctx.lineJoin = 'round';
    ctx.lineCap = 'round';
    for (let c = 0; c < k; c++) {
      ctx.beginPath();
      for (let i = c; i < n; i += k) {
        const first = Math.max(from, end - lens[i]);
        if (end - first < 2) continue;
        const base = i * cap * POSE_STRIDE;
        let o = base + (first % cap) * POSE_STRIDE;
        let lx = view.sx(t[o]);
        let ly = view.sy(t[o + 1]);
        ctx.moveTo(lx, ly);
        for (let g = first + 1; g < end; g++) {
          o = base + (g % cap) * POSE_STRIDE;
          const x = view.sx(t[o]);
          const y = view.sy(t[o + 1]);
          // Skipping only on a full redraw, and never the newest point, where the next
          // frame's segments start.
          if (full && g < end - 1 && Math.abs(x - lx) < TRAIL_DECIMATE_PX && Math.abs(y - ly) < TRAIL_DECIMATE_PX) continue;
          ctx.lineTo(x, y);
          lx = x;
          ly = y;
        }
      }
      ctx.strokeStyle = ROBOT_COLOURS[c];
      ctx.stroke();
    }
  }
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
  // Two paths: the grid lines, then the axes over them.
  for (const axes of [false, true]) {
    ctx.beginPath();
    for (const x of xs) {
      if ((Math.abs(x) < 1e-9) !== axes) continue;
      const px = Math.round(view.sx(x)) + 0.5; // on a pixel centre: crisp 1-px lines
      ctx.moveTo(px, 0);
      ctx.lineTo(px, view.height);
    }
    for (const y of ys) {
      if ((Math.abs(y) < 1e-9) !== axes) continue;
      const py = Math.round(view.sy(y)) + 0.5;
      ctx.moveTo(0, py);
      ctx.lineTo(view.width, py);
    }
    ctx.strokeStyle = axes ? AXIS_COLOUR : GRID_COLOUR;
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
function drawField(ctx, view, field, obstacles, width) {
  let max = 0;
  for (let k = 0; k < field.length; k += FIELD_STRIDE) {
    max = Math.max(max, Math.hypot(field[k + 2], field[k + 3]));
  }
  if (!(max > 0)) return;
  const inside = (x, y) => {
    for (const o of obstacles) if (Math.hypot(x - o.center[0], y - o.center[1]) < o.radius) return true;
    return false;
  };
  ctx.strokeStyle = FIELD_COLOUR;
  ctx.fillStyle = FIELD_COLOUR;
  // A hairline: the rasteriser's fast path (see THIN_PREDICTED_ABOVE).
  ctx.lineWidth = width;
  // Two passes over the samples, shafts then heads: one path each, nothing kept in between.
  for (const heads of [false, true]) {
    ctx.beginPath();
    for (let k = 0; k < field.length; k += FIELD_STRIDE) {
      const x = field[k];
      const y = field[k + 1];
      const m = Math.hypot(field[k + 2], field[k + 3]);
      if (!(m > 0) || inside(x, y)) continue;
      // Length grows with magnitude but saturates, so arrows near the goal stay visible.
      const len = FIELD_ARROW_PX * (0.35 + 0.65 * Math.sqrt(m / max));
      const ux = field[k + 2] / m;
      const uy = -field[k + 3] / m; // screen y is down
      const px = view.sx(x) - (ux * len) / 2;
      const py = view.sy(y) - (uy * len) / 2;
      const hx = px + ux * len;
      const hy = py + uy * len;
      if (heads) {
        ctx.moveTo(hx, hy);
        ctx.lineTo(hx - ux * 5 - uy * 2.5, hy - uy * 5 + ux * 2.5);
        ctx.lineTo(hx - ux * 5 + uy * 2.5, hy - uy * 5 - ux * 2.5);
        ctx.closePath();
      } else {
        ctx.moveTo(px, py);
        ctx.lineTo(hx, hy);
      }
    }
    if (heads) ctx.fill();
    else ctx.stroke();
  }
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

/** The predicted paths from now to the end: dashed, each in its robot's colour. */
function drawPredicted(ctx, view, scene) {
  const samples = scene.predictedSamples;
  const p = scene.predicted;
  const n = scene.scenario.robots.length;
  if (samples < 2) return;
  ctx.globalAlpha = PREDICTED_ALPHA;
  ctx.lineJoin = n > THIN_PREDICTED_ABOVE ? 'miter' : 'round';
  // One path per colour (see drawRobots).
  for (let c = 0; c < ROBOT_COLOURS.length && c < n; c++) {
    ctx.beginPath();
    for (let i = c; i < n; i += ROBOT_COLOURS.length) {
      const o = i * samples * POSE_STRIDE;
      ctx.moveTo(view.sx(p[o]), view.sy(p[o + 1]));
      for (let k = 1; k < samples; k++) ctx.lineTo(view.sx(p[o + k * POSE_STRIDE]), view.sy(p[o + k * POSE_STRIDE + 1]));
    }
    strokeDashed(ctx, PREDICTED_DASH_PX, n > THIN_PREDICTED_ABOVE ? hairline(scene) : PREDICTED_WIDTH_PX, ROBOT_COLOURS[c]);
  }
  ctx.globalAlpha = 1;
}

/** Virtual obstacles (robots avoiding each other): a red cross and the ring R_c. */
function drawVirtualObstacles(ctx, view, scene) {
  const st = scene.status;
  const rc = scene.scenario.params.avoid_radius * view.scale;
  // Two robots avoiding each other share one virtual obstacle: draw each place once.
  const drawn = [];
  const seen = (x, y) => drawn.some(([a, b]) => Math.abs(a - x) < 0.5 && Math.abs(b - y) < 0.5);
  for (let k = 0; k < st.length; k += STATUS_STRIDE) {
    if (Number.isNaN(st[k + 4])) continue;
    const x = view.sx(st[k + 4]);
    const y = view.sy(st[k + 5]);
    if (!seen(x, y)) drawn.push([x, y]);
  }
  if (drawn.length) drawVirtualObstacleGlyphs(ctx, drawn, rc);
}

/** One virtual obstacle glyph at (x, y) with ring radius `rc` (CSS px). */
export function drawVirtualObstacle(ctx, x, y, rc) {
  drawVirtualObstacleGlyphs(ctx, [[x, y]], rc);
}

/** Virtual obstacle glyphs at screen `points` ([x, y] each): the rings R_c, then the crosses. */
function drawVirtualObstacleGlyphs(ctx, points, rc) {
  ctx.beginPath();
  for (const [x, y] of points) {
    ctx.moveTo(x + rc, y);
    ctx.arc(x, y, rc, 0, 2 * Math.PI);
  }
  ctx.globalAlpha = 0.7;
  strokeDashed(ctx, [4, 3], 1.25, VIRTUAL_OBSTACLE_COLOUR);
  ctx.globalAlpha = 1;
  ctx.beginPath();
  for (const [x, y] of points) {
    ctx.moveTo(x - 4, y - 4);
    ctx.lineTo(x + 4, y + 4);
    ctx.moveTo(x + 4, y - 4);
    ctx.lineTo(x - 4, y + 4);
  }
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
  ctx.beginPath();
  addTriangle(ctx, x, y, theta, size);
}

/** Adds the triangle of trianglePath to the current path (no allocation: crowds add many). */
function addTriangle(ctx, x, y, theta, size) {
  const l = ROBOT_LENGTH_PX * size;
  const w = ROBOT_WIDTH_PX * size;
  // Screen y points down, so a CCW world angle is a CW screen angle.
  const c = Math.cos(theta);
  const s = -Math.sin(theta);
  const a = (2 / 3) * l;
  const b = -l / 3;
  const h = w / 2;
  ctx.moveTo(x + a * c, y + a * s);
  ctx.lineTo(x + b * c - h * s, y + b * s + h * c);
  ctx.lineTo(x + b * c + h * s, y + b * s - h * c);
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
