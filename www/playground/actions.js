// What a key or a button does to the scenario: add a robot or an obstacle where the view is,
// delete the selection, nudge it, change a parameter. Each is one gesture of the controller
// (one undo entry, one `change` event) made of its fine-grained edits.

import { messageOf } from './message.js';
import { POSE_STRIDE } from './wasm-views.js';

/**
 * A new obstacle's radius as a fraction of the view's smaller side, rounded to two significant
 * digits (3.2 m, not 3.1719…; tests/e2e/forms.mjs checks it); its ring is twice that.
 */
const NEW_OBSTACLE_FRACTION = 0.05;
/** Candidate spots tried, along a spiral about the view's centre, for a new robot. */
const ADD_ROBOT_TRIES = 400;
/** A new robot keeps this many safe radii from every robot and obstacle ring. */
const ADD_ROBOT_GAP = 3;

/**
 * What the actions use of the controller: its scenario, selection and view, its edit methods,
 * one gesture, and the message.
 * @typedef {Pick<import('./controller.js').Controller, 'addObstacle' | 'addRobot' | 'gestures'
 *   | 'inspect' | 'model' | 'moveGoal' | 'moveObstacle' | 'moveRobot' | 'params' | 'pg'
 *   | 'removeObstacle' | 'removeRobot' | 'select' | 'selection' | 'setParam' | 'showMessage'
 *   | 'view' | 'views'>} ActionsHost
 */

/** The power of ten at or below `v` (> 0): the grid step of a new robot or obstacle. */
function gridStep(v) {
  return 10 ** Math.floor(Math.log10(v));
}

/** `v` on the grid of step `step` (a power of ten), written as that grid writes it (0.3, not 0.30000000000000004). */
function onGrid(v, step) {
  return Number((Math.round(v / step) * step).toPrecision(12)) || 0;
}

/**
 * The first start/goal pair along a widening spiral about (x, y) that keeps clear of every
 * robot and obstacle ring of `s`, the start `span` · (−0.2, −0.1) off it and the goal
 * `span` · (0.2, 0.1), so that repeated clicks add robots side by side instead of one on top
 * of another (which the core refuses). Without one, the spiral's first pair.
 */
function freeSpot(s, x, y, span) {
  const gap = ADD_ROBOT_GAP * (s.params?.safe_radius ?? 1);
  // Starts and goals on a round grid, a tenth of the gap or finer.
  const step = gridStep(gap / 10);
  const at = (px, py) => [onGrid(px, step), onGrid(py, step)];
  const free = (p, key, ring) =>
    s.robots.every((r) => Math.hypot(r[key][0] - p[0], r[key][1] - p[1]) >= gap) &&
    s.obstacles.every(
      (o) => Math.hypot(o.center[0] - p[0], o.center[1] - p[1]) > (ring ? o.influence : o.radius) + gap,
    );
  for (let k = 0; k < ADD_ROBOT_TRIES; k++) {
    const a = k * 2.4; // radians: the golden angle spreads the tries evenly
    const r = gap * Math.sqrt(k);
    const start = at(x - 0.2 * span + r * Math.cos(a), y - 0.1 * span + r * Math.sin(a));
    const goal = at(x + 0.2 * span + r * Math.cos(a), y + 0.1 * span + r * Math.sin(a));
    if (free(start, 'start', false) && free(goal, 'goal', true)) return [start, goal];
  }
  return [at(x - 0.2 * span, y - 0.1 * span), at(x + 0.2 * span, y + 0.1 * span)];
}

/**
 * Adds a robot, heading 0 to a goal heading 0, about the view's centre, and selects it.
 * @param {ActionsHost} c
 */
export function addRobotInView(c) {
  const view = c.view();
  const span = Math.min(view.width, view.height) / view.scale;
  const [start, goal] = freeSpot(c.model, view.wx(view.width / 2), view.wy(view.height / 2), span);
  let index = 0;
  const ok = c.gestures.change('add-robot', () => {
    index = c.addRobot([start[0], start[1], 0], [goal[0], goal[1], 0]);
  });
  if (ok) {
    c.select({ kind: 'robot', index });
    c.inspect(index);
  }
}

/**
 * The first centre along a widening spiral about (x, y) where an obstacle of influence radius
 * `ring` keeps its ring clear of every other obstacle's ring and its disc clear of every
 * robot's start, pose now and goal (`poses`, flat x, y, θ); without one, (x, y).
 * @returns {[number, number]}
 */
function freeObstacleSpot(s, poses, x, y, radius, ring) {
  const gap = s.params?.safe_radius ?? 1;
  // Centres on a round grid: the power of ten at or below the radius.
  const step = gridStep(radius);
  const clear = (cx, cy) =>
    s.obstacles.every((o) => Math.hypot(o.center[0] - cx, o.center[1] - cy) > o.influence + ring) &&
    s.robots.every(
      (r, i) =>
        Math.hypot(r.start[0] - cx, r.start[1] - cy) > radius + gap &&
        Math.hypot(r.goal[0] - cx, r.goal[1] - cy) > radius + gap &&
        Math.hypot(poses[POSE_STRIDE * i] - cx, poses[POSE_STRIDE * i + 1] - cy) > radius + gap,
    );
  for (let k = 0; k < ADD_ROBOT_TRIES; k++) {
    const a = k * 2.4; // the golden angle, as in freeSpot
    const d = ring * Math.sqrt(k);
    const cx = onGrid(x + d * Math.cos(a), step);
    const cy = onGrid(y + d * Math.sin(a), step);
    if (clear(cx, cy)) return [cx, cy];
  }
  return [onGrid(x, step), onGrid(y, step)];
}

/**
 * Adds an obstacle about the view's centre, clear of the others, sized to the view, and selects it.
 * @param {ActionsHost} c
 */
export function addObstacleInView(c) {
  const view = c.view();
  const r = Number(((NEW_OBSTACLE_FRACTION * Math.min(view.width, view.height)) / view.scale).toPrecision(2));
  let index = 0;
  const ok = c.gestures.change('add-obstacle', () => {
    const center = freeObstacleSpot(
      c.model,
      c.views.poses,
      view.wx(view.width / 2),
      view.wy(view.height / 2),
      r,
      2 * r,
    );
    index = c.addObstacle({ center, radius: r, influence: 2 * r });
  });
  if (ok) c.select({ kind: 'obstacle', index });
}

/**
 * Deletes the selected obstacle, or the selected robot (or the robot of the selected goal).
 * @param {ActionsHost} c
 */
export function deleteSelection(c) {
  const sel = c.selection;
  if (!sel) return;
  const ok = c.gestures.change('delete', () => {
    if (sel.kind === 'obstacle') c.removeObstacle(sel.index);
    else c.removeRobot(sel.index);
  });
  if (ok) {
    c.select(null);
    c.inspect(0);
  }
}

/**
 * Moves the selection by (dx, dy) (m) and turns it by `dTheta` (rad).
 * @param {ActionsHost} c
 */
export function nudgeSelection(c, dx, dy, dTheta) {
  const sel = c.selection;
  const i = sel.index;
  if (sel.kind === 'robot') {
    c.gestures.change('robot', () => {
      const [x, y, theta] = c.views.pose(i);
      c.moveRobot(i, x + dx, y + dy, theta + dTheta);
    });
  } else if (sel.kind === 'goal') {
    c.gestures.change('goal', () => {
      const g = c.model.robots[i].goal;
      c.moveGoal(i, g[0] + dx, g[1] + dy, g[2] + dTheta);
    });
  } else if (sel.kind === 'obstacle') {
    c.gestures.change('obstacle', () => {
      const o = c.model.obstacles[i].center;
      c.moveObstacle(i, o[0] + dx, o[1] + dy);
    });
  }
}

/**
 * Sets parameter `key` (or the scenario's `dt` or `duration`) from the parameters panel:
 * `value` is a number, null (an empty optional field) or the avoidance mode. Returns the
 * core's message when it refuses the value (the scenario is kept; the panel keeps the typed
 * text), else null (the panel shows the scenario's values again).
 * @param {ActionsHost} c
 */
export function changeParam(c, key, value) {
  if (!c.pg) return null;
  c.gestures.begin();
  try {
    c.setParam(key, value);
  } catch (e) {
    c.gestures.cancel();
    return messageOf(e);
  }
  c.showMessage('');
  c.gestures.commit('params');
  c.params.fill();
  return null;
}
