// The metre grid of the scene, its axes, and their labels.

import { fixed } from '../panels/format.js';
import { AXIS_COLOUR, GRID_COLOUR, LABEL_COLOUR, LABEL_FONT } from './theme.js';

/** Desired distance between grid lines (CSS px); the step is rounded to 1, 2 or 5 × 10^k m. */
const GRID_SPACING_PX = 70;

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

export function drawGrid(ctx, view) {
  const { xs, ys } = visibleTicks(view);
  ctx.lineWidth = 1;
  // Two paths: the grid lines, then the axes over them.
  for (const axes of [false, true]) {
    ctx.beginPath();
    for (const x of xs) {
      if (Math.abs(x) < 1e-9 !== axes) continue;
      const px = Math.round(view.sx(x)) + 0.5; // on a pixel centre: crisp 1-px lines
      ctx.moveTo(px, 0);
      ctx.lineTo(px, view.height);
    }
    for (const y of ys) {
      if (Math.abs(y) < 1e-9 !== axes) continue;
      const py = Math.round(view.sy(y)) + 0.5;
      ctx.moveTo(0, py);
      ctx.lineTo(view.width, py);
    }
    ctx.strokeStyle = axes ? AXIS_COLOUR : GRID_COLOUR;
    ctx.stroke();
  }
}

/** Axis labels in metres, drawn last so nothing covers them. */
export function drawLabels(ctx, view) {
  const { step, xs, ys } = visibleTicks(view);
  const decimals = Math.max(0, -Math.floor(Math.log10(step)));
  ctx.font = LABEL_FONT;
  ctx.fillStyle = LABEL_COLOUR;
  ctx.textAlign = 'center';
  ctx.textBaseline = 'bottom';
  for (const x of xs) {
    const px = view.sx(x);
    if (px > 40 && px < view.width - 10) ctx.fillText(fixed(x, decimals), px, view.height - 6);
  }
  ctx.textAlign = 'right';
  ctx.textBaseline = 'middle';
  for (const y of ys) {
    const py = view.sy(y);
    if (py > 8 && py <= view.height - 24) ctx.fillText(fixed(y, decimals), 36, py);
  }
  ctx.textAlign = 'left';
  ctx.textBaseline = 'bottom';
  ctx.fillText('m', 4, view.height - 6);
}
