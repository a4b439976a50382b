// The legend panel: what each colour, line and handle of the scene means, each beside its own
// glyph drawn with the scene's painters.

import { drawSmallCanvas } from '../render/canvas.js';
import {
  addArrowHead,
  drawGoal,
  drawHandle,
  drawInfluence,
  drawObstacleDisc,
  drawRobot,
  drawSafeDisc,
  drawSaturatedRing,
  drawSenseCircle,
  drawStart,
  drawVirtualObstacle,
  strokeDashed,
} from '../render/glyphs.js';
import { drawViolationGlyph } from '../render/marks.js';
import {
  AXIS_COLOUR,
  BOUNDS_FILL,
  CANVAS_BACKGROUND,
  CURVE_COLOUR,
  FIELD_COLOUR,
  PREDICTED_ALPHA,
  PREDICTED_WIDTH_PX,
  TRAIL_WIDTH_PX,
} from '../render/theme.js';
import { el } from './dom.js';

/** Legend glyph size (CSS px). */
const GLYPH_PX = 24;
/** Neutral colour for the legend's shapes (robots take their own colours). */
const LEGEND_NEUTRAL = '#4e79a7';
/** The predicted path's dashes, finer than on the canvas so that a short glyph shows them. */
const PREDICTED_GLYPH_DASH_PX = [4, 3];

/** A predicted-path glyph. */
function drawPredictedGlyph(ctx, x, y, colour) {
  ctx.beginPath();
  ctx.moveTo(x - 10, y + 5);
  ctx.lineTo(x + 10, y - 5);
  ctx.globalAlpha = PREDICTED_ALPHA + 0.2;
  strokeDashed(ctx, PREDICTED_GLYPH_DASH_PX, PREDICTED_WIDTH_PX, colour);
  ctx.globalAlpha = 1;
}

/** A trail glyph. */
function drawTrailGlyph(ctx, x, y, colour) {
  ctx.beginPath();
  ctx.moveTo(x - 10, y + 5);
  ctx.quadraticCurveTo(x, y + 6, x + 10, y - 5);
  ctx.lineWidth = TRAIL_WIDTH_PX;
  ctx.lineCap = 'round';
  ctx.strokeStyle = colour;
  ctx.stroke();
}

/** A field-arrow glyph. */
function drawArrowGlyph(ctx, x, y) {
  ctx.strokeStyle = FIELD_COLOUR;
  ctx.fillStyle = FIELD_COLOUR;
  ctx.lineWidth = 1.1;
  ctx.beginPath();
  ctx.moveTo(x - 8, y + 4);
  ctx.lineTo(x + 8, y - 4);
  ctx.stroke();
  ctx.beginPath();
  addArrowHead(ctx, x + 8, y - 4, 16 / Math.hypot(16, 8), -8 / Math.hypot(16, 8));
  ctx.fill();
}

/** An integral-curve glyph. */
function drawCurveGlyph(ctx, x, y) {
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

/** The grey outside the scenario's bounds, beside the white inside. */
function drawOutsideGlyph(ctx, x, y) {
  ctx.fillStyle = CANVAS_BACKGROUND;
  ctx.fillRect(x - 10, y - 8, 20, 16);
  ctx.fillStyle = BOUNDS_FILL;
  ctx.fillRect(x - 2, y - 8, 12, 16);
  ctx.strokeStyle = AXIS_COLOUR;
  ctx.lineWidth = 1;
  ctx.strokeRect(x - 9.5, y - 7.5, 19, 15);
}

/** Fills the legend list `list`. */
export function buildLegend(list) {
  const n = LEGEND_NEUTRAL;
  const entries = [
    ['outside the bounds', drawOutsideGlyph],
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
    ['violation: closer than 2·r_ij, or inside r_o', (c, x, y) => drawViolationGlyph(c, x, y, 9)],
    [
      'command at v_max or ω_max',
      (c, x, y) => {
        drawRobot(c, x, y, 0.5, n);
        drawSaturatedRing(c, x, y, 10);
      },
    ],
    ['field Γ of the inspected robot', drawArrowGlyph],
    ['integral curve from θ(0)', drawCurveGlyph],
    ['handle: drag to turn / resize', (c, x, y) => drawHandle(c, x, y)],
  ];
  list.replaceChildren();
  for (const [label, draw] of entries) {
    const item = el('li');
    const glyph = el('canvas');
    glyph.setAttribute('aria-hidden', 'true');
    drawSmallCanvas(glyph, GLYPH_PX, draw);
    item.append(glyph, el('span', label));
    list.append(item);
  }
}
