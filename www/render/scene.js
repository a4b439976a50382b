// The live scene on the playground's canvas: bounds, grid, field overlays, obstacles,
// predicted paths, trails, robots (or a crowd), the selection and the axis labels. Knows
// nothing of the DOM beyond the canvas it is given (and the canvases of its layers).

import { POSE_STRIDE, STATUS, STATUS_STRIDE } from '../playground/wasm-views.js';
import { CROWD_DISC_MIN_PX, CROWD_OUTLINE_MIN_PX, crowdGlyphScale, drawCrowd, nearView } from './crowd.js';
import { drawCurves, drawField } from './field.js';
import {
  addCircle,
  addTriangle,
  drawHandle,
  drawInfluence,
  drawObstacleDisc,
  drawSaturated,
  drawVirtualObstacles,
  handlePoint,
  paintBodies,
  paintGoals,
  paintSafeDiscs,
  paintSenseCircles,
  paintStarts,
  strokeDashed,
} from './glyphs.js';
import { drawGrid, drawLabels } from './grid.js';
import {
  BOUNDS_FILL,
  CANVAS_BACKGROUND,
  CROWD_STYLE_ABOVE,
  FOCUS_HALO,
  hairline,
  LABEL_COLOUR,
  MARKER_SCALE,
  NUMBER_FONT,
  NUMBERS_MAX,
  NUMBERS_MIN_DISC_PX,
  PREDICTED_ALPHA,
  PREDICTED_DASH_PX,
  PREDICTED_WIDTH_PX,
  ROBOT_COLOURS,
  ROBOT_LENGTH_PX,
  SELECTION_COLOUR,
  THIN_PREDICTED_ABOVE,
} from './theme.js';

/**
 * What one frame draws, read from wasm and the playground's state (see playground/paint.js).
 * @typedef {import('../playground/wasm-views.js').Frame & {
 *   scenario: import('../dvf-playground').Scenario,
 *   selection: {kind: string, index: number} | null,
 *   focusRobot: number,
 *   showSensing: boolean,
 *   field: Float64Array | null,
 *   curves: Float64Array | null,
 *   curvePoints: number,
 *   trailLayer: import('./trails.js').TrailLayer,
 *   spriteLayer: import('./sprites.js').SpriteLayer,
 *   dpr: number,
 *   vector?: boolean,
 * }} Scene
 */

/**
 * Draws the whole live scene in `view` (render/camera.js).
 * @param {CanvasRenderingContext2D} ctx
 * @param {import('./camera.js').View} view
 * @param {Scene} scene
 * @param {(() => void) | null} [underlay] draws under the scene's marks, over its grid (a
 *   pinned run's paths, playground/ghost.js)
 */
export function drawScene(ctx, view, scene, underlay = null) {
  const s = scene.scenario;
  ctx.fillStyle = CANVAS_BACKGROUND;
  ctx.fillRect(0, 0, view.width, view.height);
  const [xmin, ymin, xmax, ymax] = s.bounds;
  ctx.fillStyle = BOUNDS_FILL;
  ctx.fillRect(view.sx(xmin), view.sy(ymax), (xmax - xmin) * view.scale, (ymax - ymin) * view.scale);
  drawGrid(ctx, view);
  underlay?.();
  if (scene.curves) drawCurves(ctx, view, scene.curves, scene.curvePoints);
  drawObstacles(ctx, view, s.obstacles, scene.selection);
  if (scene.field) drawField(ctx, view, scene.field, s.obstacles, hairline(scene.dpr));
  const n = s.robots.length;
  drawPredicted(ctx, view, scene);
  // A vector picture (render/svg.js) has no pixels: its trails and crowd are paths.
  if (scene.vector) scene.trailLayer?.draw(ctx, view, scene, 0, n > CROWD_STYLE_ABOVE);
  else scene.trailLayer?.composite(ctx, view);
  if (n > CROWD_STYLE_ABOVE && !scene.vector) {
    drawCrowd(ctx, view, scene);
  } else {
    drawRobots(ctx, view, scene);
  }
  drawNumbers(ctx, view, scene);
  drawSelection(ctx, view, scene);
  drawLabels(ctx, view);
}

/**
 * Each robot's number (from 1, as the panels and the messages count), once the view is zoomed
 * in far enough that the numbers do not cover each other: a safe disc at least
 * NUMBERS_MIN_DISC_PX wide on screen and at most NUMBERS_MAX robots on screen. Each number
 * sits at its robot's upper right, in the label colour over a halo of the background.
 */
function drawNumbers(ctx, view, scene) {
  const s = scene.scenario;
  const n = s.robots.length;
  if (s.params.safe_radius * view.scale * 2 < NUMBERS_MIN_DISC_PX) return;
  const p = scene.poses;
  const at = [];
  for (let i = 0; i < n; i++) {
    const x = view.sx(p[i * POSE_STRIDE]);
    const y = view.sy(p[i * POSE_STRIDE + 1]);
    if (x < 0 || y < 0 || x > view.width || y > view.height) continue;
    if (at.length === NUMBERS_MAX) return;
    at.push(i, x, y);
  }
  const off = ROBOT_LENGTH_PX * 0.55;
  ctx.font = NUMBER_FONT;
  ctx.textAlign = 'left';
  ctx.textBaseline = 'bottom';
  ctx.lineJoin = 'round';
  ctx.lineWidth = 3;
  ctx.strokeStyle = BOUNDS_FILL;
  for (let k = 0; k < at.length; k += 3) ctx.strokeText(String(at[k] + 1), at[k + 1] + off, at[k + 2] - off);
  ctx.fillStyle = LABEL_COLOUR;
  for (let k = 0; k < at.length; k += 3) ctx.fillText(String(at[k] + 1), at[k + 1] + off, at[k + 2] - off);
}

/**
 * Each robot with its own glyphs: goal, start, safe disc, sensing circle, body. Batched by
 * colour (each kind of glyph of the robots of one colour is one path, filled or stroked once):
 * without a GPU every fill or stroke has a fixed cost to rasterise, whatever its size, so the
 * cost of a frame follows the number of paths, not of robots. A dash pattern starts
 * afresh on each glyph of a path, so the picture is the same. A crowd comes here only to be
 * drawn as vectors (render/svg.js).
 */
function drawRobots(ctx, view, scene) {
  const s = scene.scenario;
  const n = s.robots.length;
  const k = ROBOT_COLOURS.length;
  const p = scene.poses;
  // A crowd drawn as vectors (drawScene) keeps what its canvas shows (render/crowd.js): goals
  // and bodies on screen, and safe discs only when wide enough to see.
  const crowd = n > CROWD_STYLE_ABOVE;
  const onScreen = (x, y) => nearView(view, x, y);
  const each = (c, add) => {
    ctx.beginPath();
    for (let i = c; i < n; i += k) add(i);
  };
  const glyph = crowd ? crowdGlyphScale(view, s.params.safe_radius) : 1;
  const addTriangleAt = (x, y, theta, size) => {
    if (!crowd || onScreen(x, y)) addTriangle(ctx, x, y, theta, size * glyph);
  };
  for (let c = 0; c < k && c < n; c++) {
    each(c, (i) => {
      const g = s.robots[i].goal;
      addTriangleAt(view.sx(g[0]), view.sy(g[1]), g[2], MARKER_SCALE);
    });
    paintGoals(ctx, ROBOT_COLOURS[c]);
    if (scene.time !== 0 && !crowd) {
      each(c, (i) => {
        const st = s.robots[i].start;
        addTriangle(ctx, view.sx(st[0]), view.sy(st[1]), st[2], MARKER_SCALE);
      });
      paintStarts(ctx, ROBOT_COLOURS[c]);
    }
  }
  if (scene.showSensing && !crowd) {
    const r = s.params.sense_radius * view.scale;
    ctx.beginPath();
    for (let i = 0; i < n; i++) addCircle(ctx, view.sx(p[i * POSE_STRIDE]), view.sy(p[i * POSE_STRIDE + 1]), r);
    paintSenseCircles(ctx);
  }
  if (!s.independent && !(crowd && s.params.safe_radius * view.scale < CROWD_DISC_MIN_PX)) {
    const r = s.params.safe_radius * view.scale;
    for (let c = 0; c < k && c < n; c++) {
      each(c, (i) => {
        const x = view.sx(p[i * POSE_STRIDE]);
        const y = view.sy(p[i * POSE_STRIDE + 1]);
        if (!crowd || onScreen(x, y)) addCircle(ctx, x, y, r);
      });
      paintSafeDiscs(ctx, ROBOT_COLOURS[c]);
    }
    if (!crowd) drawVirtualObstaclesOf(ctx, view, scene);
  }
  if (!crowd) drawSaturatedOf(ctx, view, scene);
  ctx.lineJoin = 'miter';
  // A crowd's small bodies go without their outline, as on its canvas (render/crowd.js).
  const outline = !crowd || glyph * ROBOT_LENGTH_PX >= CROWD_OUTLINE_MIN_PX;
  for (let c = 0; c < k && c < n; c++) {
    each(c, (i) =>
      addTriangleAt(view.sx(p[i * POSE_STRIDE]), view.sy(p[i * POSE_STRIDE + 1]), p[i * POSE_STRIDE + 2], 1),
    );
    if (outline) {
      paintBodies(ctx, ROBOT_COLOURS[c]);
    } else {
      ctx.fillStyle = ROBOT_COLOURS[c];
      ctx.fill();
    }
  }
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
      for (let k = 1; k < samples; k++)
        ctx.lineTo(view.sx(p[o + k * POSE_STRIDE]), view.sy(p[o + k * POSE_STRIDE + 1]));
    }
    const width = n > THIN_PREDICTED_ABOVE ? hairline(scene.dpr) : PREDICTED_WIDTH_PX;
    strokeDashed(ctx, PREDICTED_DASH_PX, width, ROBOT_COLOURS[c]);
  }
  ctx.globalAlpha = 1;
}

/** Virtual obstacles (robots avoiding each other): a red cross and the ring R_c. */
function drawVirtualObstaclesOf(ctx, view, scene) {
  const st = scene.status;
  const rc = scene.scenario.params.avoid_radius * view.scale;
  // Two robots avoiding each other share one virtual obstacle: draw each place (to the
  // nearest pixel) once.
  const drawn = [];
  const seen = new Set();
  for (let k = 0; k < st.length; k += STATUS_STRIDE) {
    if (Number.isNaN(st[k + STATUS.virtualX])) continue;
    const x = view.sx(st[k + STATUS.virtualX]);
    const y = view.sy(st[k + STATUS.virtualY]);
    const key = `${Math.round(x)},${Math.round(y)}`;
    if (seen.has(key)) continue;
    seen.add(key);
    drawn.push([x, y]);
  }
  if (drawn.length) drawVirtualObstacles(ctx, drawn, rc);
}

/**
 * A ring about each robot whose command is at a limit of the scenario's (|v| = v_max or
 * |ω| = ω_max): the controller clamps to the limit exactly, so a saturated command equals it.
 */
function drawSaturatedOf(ctx, view, scene) {
  const { v_max: vMax, omega_max: omegaMax } = scene.scenario.params;
  if (vMax == null && omegaMax == null) return;
  const st = scene.status;
  const p = scene.poses;
  const at = [];
  for (let i = 0; i * STATUS_STRIDE < st.length; i++) {
    const v = Math.abs(st[i * STATUS_STRIDE + STATUS.v]);
    const omega = Math.abs(st[i * STATUS_STRIDE + STATUS.omega]);
    if ((vMax != null && v >= vMax) || (omegaMax != null && omega >= omegaMax))
      at.push([view.sx(p[i * POSE_STRIDE]), view.sy(p[i * POSE_STRIDE + 1])]);
  }
  if (at.length) drawSaturated(ctx, at);
}

/** The selected robot (or its goal): a ring and the heading handles of body and goal. */
function drawSelection(ctx, view, scene) {
  const f = scene.focusRobot;
  const p = scene.poses;
  if (f != null && f < scene.scenario.robots.length) {
    // The robot whose field is drawn: a faint halo even when nothing is selected.
    ctx.beginPath();
    ctx.arc(view.sx(p[f * POSE_STRIDE]), view.sy(p[f * POSE_STRIDE + 1]), ROBOT_LENGTH_PX, 0, 2 * Math.PI);
    ctx.fillStyle = FOCUS_HALO;
    ctx.fill();
  }
  const sel = scene.selection;
  if (!sel || (sel.kind !== 'robot' && sel.kind !== 'goal')) return;
  const i = sel.index;
  const r = scene.scenario.robots[i];
  if (!r) return;
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
