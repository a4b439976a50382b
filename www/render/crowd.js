// A crowd (more than CROWD_STYLE_ABOVE robots): goals and bodies stamped as pre-rasterised
// sprites (render/sprites.js; paths cost too much per call for thousands), safe discs as paths
// when they are wide enough and few enough to matter, glyphs off screen skipped. The
// inspected robot keeps its sensing circle and virtual obstacle.

import { POSE_STRIDE, STATUS, STATUS_STRIDE } from '../playground/wasm-views.js';
import { addCircle, addTriangle, drawSenseCircle, drawVirtualObstacle } from './glyphs.js';
import { SpriteLayer } from './sprites.js';
import { BODY_OUTLINE, MARKER_SCALE, ROBOT_COLOURS, ROBOT_LENGTH_PX } from './theme.js';

/** A crowd's glyphs are about 3·r_ij long on screen, at least this (CSS px). */
const CROWD_GLYPH_MIN_PX = 4;
/**
 * A crowd's safe discs are drawn only when at least this wide (radius, CSS px) and at most
 * CROWD_DISC_MAX robots are on screen (each disc is a path call: see sprites.js).
 */
export const CROWD_DISC_MIN_PX = 3;
/** A crowd's bodies are outlined only when at least this long (CSS px). */
export const CROWD_OUTLINE_MIN_PX = 10;
const CROWD_DISC_MAX = 1500;

/** Whether screen point (x, y) is in `view` or within a glyph's length of it (the glyphs drawn). */
export function nearView(view, x, y) {
  const pad = ROBOT_LENGTH_PX;
  return x > -pad && y > -pad && x < view.width + pad && y < view.height + pad;
}

/** A crowd's glyphs as a multiple of a robot's (CSS px: what crowdGlyphPx rounds). */
export function crowdGlyphScale(view, safeRadius) {
  return Math.min(ROBOT_LENGTH_PX, Math.max(CROWD_GLYPH_MIN_PX, 3 * safeRadius * view.scale)) / ROBOT_LENGTH_PX;
}

/** Length of a crowd's glyphs in device pixels (a whole number, so sprites can be reused). */
function crowdGlyphPx(view, safeRadius, dpr) {
  const css = crowdGlyphScale(view, safeRadius) * ROBOT_LENGTH_PX;
  return Math.max(3, Math.round(css * dpr));
}

/** Draws the crowd of `scene` (see scene.js) with its sprites in `scene.spriteLayer`. */
export function drawCrowd(ctx, view, scene) {
  const s = scene.scenario;
  const n = s.robots.length;
  const p = scene.poses;
  const k = ROBOT_COLOURS.length;
  const dpr = scene.dpr;
  const onScreen = (x, y) => nearView(view, x, y);
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
          addCircle(ctx, x, y, rs);
        }
        ctx.strokeStyle = ROBOT_COLOURS[c];
        ctx.stroke();
      }
      ctx.globalAlpha = 1;
    }
  }
  const layer = scene.spriteLayer;
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
  const outline = px >= CROWD_OUTLINE_MIN_PX * dpr;
  const bodies = layer.sprites(`body|${px}|${dpr}`, side, ROBOT_COLOURS, (g, c, theta, colour) => {
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    g.beginPath();
    addTriangle(g, c / dpr, c / dpr, theta, scale);
    g.fillStyle = colour;
    g.fill();
    if (outline) {
      g.lineWidth = 0.75;
      g.strokeStyle = BODY_OUTLINE;
      g.stroke();
    }
  });
  for (let i = 0; i < n; i++) {
    const g = s.robots[i].goal;
    const x = view.sx(g[0]);
    const y = view.sy(g[1]);
    if (onScreen(x, y)) layer.stamp(SpriteLayer.pick(goals, i % k, g[2]), x * dpr, y * dpr);
  }
  for (let i = 0; i < n; i++) {
    const x = view.sx(p[i * POSE_STRIDE]);
    const y = view.sy(p[i * POSE_STRIDE + 1]);
    if (onScreen(x, y)) layer.stamp(SpriteLayer.pick(bodies, i % k, p[i * POSE_STRIDE + 2]), x * dpr, y * dpr);
  }
  layer.end(ctx, view.width, view.height);
  const f = scene.focusRobot;
  if (f != null && f < n) {
    const x = view.sx(p[f * POSE_STRIDE]);
    const y = view.sy(p[f * POSE_STRIDE + 1]);
    if (scene.showSensing) drawSenseCircle(ctx, x, y, s.params.sense_radius * view.scale);
    const vx = scene.status[f * STATUS_STRIDE + STATUS.virtualX];
    const vy = scene.status[f * STATUS_STRIDE + STATUS.virtualY];
    if (!s.independent && !Number.isNaN(vx)) {
      drawVirtualObstacle(ctx, view.sx(vx), view.sy(vy), s.params.avoid_radius * view.scale);
    }
  }
}
