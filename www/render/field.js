// The field overlays: arrows of the field Γ the inspected robot follows, and integral curves
// of its goal field.

import { CURVE_POINT_STRIDE, FIELD_STRIDE } from '../playground/wasm-views.js';
import { addArrowHead, addCircle } from './glyphs.js';
import { CURVE_COLOUR, FIELD_ARROW_PX, FIELD_COLOUR } from './theme.js';

/**
 * Field arrows (samples `x, y, Γx, Γy`), each scaled to FIELD_ARROW_PX at the largest magnitude
 * shown (log-ish), none inside an obstacle disc; `width` is the shafts' line width.
 */
export function drawField(ctx, view, field, obstacles, width) {
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
  // A hairline: the rasteriser's fast path (see THIN_PREDICTED_ABOVE in theme.js).
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
        addArrowHead(ctx, hx, hy, ux, uy);
      } else {
        ctx.moveTo(px, py);
        ctx.lineTo(hx, hy);
      }
    }
    if (heads) ctx.fill();
    else ctx.stroke();
  }
}

/** Integral curves of the goal field (`points` points each), each from its start (dot) on. */
export function drawCurves(ctx, view, curves, points) {
  ctx.strokeStyle = CURVE_COLOUR;
  ctx.globalAlpha = 0.6;
  ctx.lineWidth = 1.2;
  ctx.beginPath();
  const stride = points * CURVE_POINT_STRIDE;
  for (let c = 0; c + stride <= curves.length; c += stride) {
    ctx.moveTo(view.sx(curves[c]), view.sy(curves[c + 1]));
    for (let k = CURVE_POINT_STRIDE; k < stride; k += CURVE_POINT_STRIDE)
      ctx.lineTo(view.sx(curves[c + k]), view.sy(curves[c + k + 1]));
  }
  ctx.stroke();
  ctx.globalAlpha = 1;
  ctx.fillStyle = CURVE_COLOUR;
  ctx.beginPath();
  for (let c = 0; c + stride <= curves.length; c += stride) {
    addCircle(ctx, view.sx(curves[c]), view.sy(curves[c + 1]), 2);
  }
  ctx.fill();
}
