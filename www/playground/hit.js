// What is under a point of the canvas: the handles of the selection first, then robots and
// goals (the nearest), then obstacles (the topmost), else the background (a pan).

import { handlePoint } from '../render/glyphs.js';
import { HANDLE_RADIUS_PX } from '../render/theme.js';
import { POSE_STRIDE } from './wasm-views.js';

/** Hit radius around robots, goals and handles (CSS px). */
export const HIT_PX = 12;
/** Robots or goals whose distances to the pointer differ by less than this are on top of one another (CSS px). */
const STACKED_PX = 2;
/** Handles are easier to hit than they are wide. */
const HANDLE_HIT_PX = HANDLE_RADIUS_PX + 4;

/**
 * @typedef {{kind: 'robot' | 'goal' | 'obstacle' | 'robot-heading' | 'goal-heading'
 *   | 'obstacle-radius' | 'obstacle-influence', index: number} | {kind: 'pan'}} Target
 */

/**
 * What hit testing reads of the controller.
 * @typedef {Pick<import('./controller.js').Controller, 'model' | 'selection' | 'view' | 'views'>} HitHost
 */

/**
 * The target at canvas point (px, py) of controller `c` (CSS px).
 * @param {HitHost} c
 * @returns {Target}
 */
export function hitTest(c, px, py) {
  const view = c.view();
  const s = c.model;
  const near = (x, y, r = HIT_PX) => Math.hypot(px - x, py - y) <= r;
  const sel = c.selection;
  if (sel && (sel.kind === 'robot' || sel.kind === 'goal')) {
    const i = sel.index;
    const [x, y, theta] = c.views.pose(i);
    const g = s.robots[i].goal;
    if (near(...handlePoint(view.sx(x), view.sy(y), theta), HANDLE_HIT_PX)) return { kind: 'robot-heading', index: i };
    if (near(...handlePoint(view.sx(g[0]), view.sy(g[1]), g[2]), HANDLE_HIT_PX))
      return { kind: 'goal-heading', index: i };
  }
  if (sel?.kind === 'obstacle') {
    const o = s.obstacles[sel.index];
    const x = view.sx(o.center[0]);
    const y = view.sy(o.center[1]);
    // The nearer of the two handles: on a small obstacle they can lie within reach of both.
    const dr = Math.hypot(px - (x + o.radius * view.scale), py - y);
    const di = Math.hypot(px - (x + o.influence * view.scale), py - y);
    if (Math.min(dr, di) <= HANDLE_HIT_PX) {
      return { kind: dr < di ? 'obstacle-radius' : 'obstacle-influence', index: sel.index };
    }
  }
  /** @type {{kind: 'robot' | 'goal', index: number, d: number}[]} */
  const hits = [];
  const consider = (kind, index, d) => {
    if (d <= HIT_PX) hits.push({ kind, index, d });
  };
  const p = c.views.poses;
  for (let i = 0; i < s.robots.length; i++) {
    consider('robot', i, Math.hypot(px - view.sx(p[i * POSE_STRIDE]), py - view.sy(p[i * POSE_STRIDE + 1])));
    const g = s.robots[i].goal;
    consider('goal', i, Math.hypot(px - view.sx(g[0]), py - view.sy(g[1])) + 0.5);
  }
  if (hits.length) {
    // The nearest; of several on top of one another (within STACKED_PX), the one after the
    // selection, so that clicking again picks each in turn.
    const nearest = hits.reduce((a, b) => (b.d < a.d ? b : a));
    const stacked = hits.filter((h) => h.kind === nearest.kind && h.d <= nearest.d + STACKED_PX);
    const at = sel ? stacked.findIndex((h) => h.kind === sel.kind && h.index === sel.index) : -1;
    const pick = at >= 0 ? stacked[(at + 1) % stacked.length] : nearest;
    return { kind: pick.kind, index: pick.index };
  }
  for (let k = s.obstacles.length - 1; k >= 0; k--) {
    const o = s.obstacles[k];
    const d = Math.hypot(px - view.sx(o.center[0]), py - view.sy(o.center[1]));
    if (d <= Math.max(o.radius * view.scale, HIT_PX)) return { kind: 'obstacle', index: k };
  }
  return { kind: 'pan' };
}
