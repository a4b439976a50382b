// The marks of a run's violations on the scene (playground/violations.js): at the place of the
// closest approach of two robots below 2·r_ij, or of the deepest intrusion into an obstacle, a
// red ring with "!" in it (not the cross of a virtual obstacle) and a label saying what, when
// and how close; solid while the time shown is that of the violation, dashed otherwise.

import { fixed } from '../panels/format.js';
import { BOUNDS_FILL } from './theme.js';

/** The marks' colour: the plots' 2·r_ij line and the page's errors. */
export const VIOLATION_COLOUR = '#dc2626';
const MARK_FONT = '600 11px system-ui, sans-serif';
const BANG_FONT = '700 13px system-ui, sans-serif';
/** A mark's ring (CSS px): large enough to see beside a robot's glyph. */
const MARK_RADIUS_PX = 14;
/** A mark is "now" (drawn bolder) within this many seconds of the time shown. */
const NOW_WITHIN_S = 0.05;

/** The text of mark `m`: what, between whom (numbered from 1, as the page counts), when, how close. */
export function markText(m) {
  const what =
    m.kind === 'pair'
      ? `robots ${m.robots[0] + 1} and ${m.robots[1] + 1} ${fixed(m.distance, 2)} m apart`
      : `robot ${m.robots[0] + 1} ${fixed(m.distance, 2)} m inside obstacle ${(m.obstacle ?? 0) + 1}`;
  return `${what} at t = ${fixed(m.time, 2)} s`;
}

/**
 * The glyph of a violation at canvas point (x, y): a red ring of radius `r` (CSS px) with "!"
 * in it, solid when `now`, else dashed. The legend draws it too.
 */
export function drawViolationGlyph(ctx, x, y, r, now = true) {
  ctx.save();
  ctx.strokeStyle = VIOLATION_COLOUR;
  ctx.lineWidth = now ? 3 : 2;
  ctx.setLineDash(now ? [] : [4, 3]);
  ctx.beginPath();
  ctx.arc(x, y, r, 0, 2 * Math.PI);
  ctx.stroke();
  ctx.setLineDash([]);
  ctx.fillStyle = VIOLATION_COLOUR;
  ctx.font = BANG_FONT;
  ctx.textAlign = 'center';
  ctx.textBaseline = 'middle';
  ctx.fillText('!', x, y + 1);
  ctx.restore();
}

/**
 * Draws `marks` on `ctx` through `view` (render/camera.js) at time `time` (s).
 * @param {CanvasRenderingContext2D} ctx
 * @param {any} view
 * @param {import('../playground/violations.js').ViolationMark[]} marks
 * @param {number} time
 */
export function drawViolationMarks(ctx, view, marks, time) {
  if (!marks?.length) return;
  ctx.save();
  ctx.font = MARK_FONT;
  ctx.textBaseline = 'bottom';
  ctx.textAlign = 'left';
  for (const m of marks) {
    const x = view.sx(m.x);
    const y = view.sy(m.y);
    drawViolationGlyph(ctx, x, y, MARK_RADIUS_PX, Math.abs(time - m.time) <= NOW_WITHIN_S);
    const text = markText(m);
    const w = ctx.measureText(text).width;
    // Right of the ring, or left of it where the canvas ends first; never past its left edge.
    let tx = x + MARK_RADIUS_PX + 3;
    if (tx + w > view.width - 4) tx = Math.max(4, x - MARK_RADIUS_PX - 3 - w);
    const ty = y - MARK_RADIUS_PX + 2;
    // The label on the scene's own background (light or dark), a little see-through.
    ctx.globalAlpha = 0.85;
    ctx.fillStyle = BOUNDS_FILL;
    ctx.fillRect(tx - 2, ty - 14, w + 4, 15);
    ctx.globalAlpha = 1;
    ctx.fillStyle = VIOLATION_COLOUR;
    ctx.fillText(text, tx, ty);
  }
  ctx.restore();
}
