// The marks of the scene, one function each: robot, start, goal, safe disc, obstacle disc and
// influence ring, virtual obstacle, sensing circle, saturation ring, drag handle, arrowhead. The scene, the
// crowd and the legend draw with these, so a mark looks the same everywhere.

import {
  BODY_OUTLINE,
  GOAL_DASH_PX,
  GOAL_FILL,
  HANDLE_DISTANCE_PX,
  HANDLE_FILL,
  HANDLE_RADIUS_PX,
  HANDLE_STROKE,
  INFLUENCE_DASH_PX,
  INFLUENCE_FILL,
  INFLUENCE_STROKE,
  MARKER_SCALE,
  OBSTACLE_FILL,
  ROBOT_LENGTH_PX,
  ROBOT_WIDTH_PX,
  SAFE_DASH_PX,
  SATURATED_COLOUR,
  SENSE_COLOUR,
  START_ALPHA,
  VIRTUAL_OBSTACLE_COLOUR,
  VIRTUAL_OBSTACLE_DASH_PX,
} from './theme.js';

/** Strokes the current path with a dash pattern, then restores solid lines. */
export function strokeDashed(ctx, dash, width, colour) {
  ctx.setLineDash(dash);
  ctx.lineWidth = width;
  ctx.strokeStyle = colour;
  ctx.stroke();
  ctx.setLineDash([]);
}

/** Adds a circle of `radius` about (x, y) to the current path as a closed sub-path of its own. */
export function addCircle(ctx, x, y, radius) {
  ctx.moveTo(x + radius, y);
  ctx.arc(x, y, radius, 0, 2 * Math.PI);
}

/**
 * Adds a triangle pointing along world heading `theta` (rad, CCW) at screen point (x, y),
 * `size` times the robot glyph, to the current path (no allocation: crowds add many).
 */
export function addTriangle(ctx, x, y, theta, size) {
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

/** Adds an arrowhead with its tip at (x, y) pointing along the screen unit vector (ux, uy). */
export function addArrowHead(ctx, x, y, ux, uy) {
  ctx.moveTo(x, y);
  ctx.lineTo(x - ux * 5 - uy * 2.5, y - uy * 5 + ux * 2.5);
  ctx.lineTo(x - ux * 5 + uy * 2.5, y - uy * 5 - ux * 2.5);
  ctx.closePath();
}

/** Fills and outlines the current path as robot bodies in `colour`. */
export function paintBodies(ctx, colour) {
  ctx.fillStyle = colour;
  ctx.fill();
  ctx.lineWidth = 1.25;
  ctx.strokeStyle = BODY_OUTLINE;
  ctx.stroke();
}

/** Paints the current path as goal ghosts in `colour`: a dashed outline over a faint fill. */
export function paintGoals(ctx, colour) {
  ctx.fillStyle = GOAL_FILL;
  ctx.fill();
  strokeDashed(ctx, GOAL_DASH_PX, 1.5, colour);
}

/** Paints the current path as start markers in `colour`: faded solid triangles. */
export function paintStarts(ctx, colour) {
  ctx.globalAlpha = START_ALPHA;
  ctx.fillStyle = colour;
  ctx.fill();
  ctx.globalAlpha = 1;
}

/** Strokes the current path as safe discs r_ij in `colour`. */
export function paintSafeDiscs(ctx, colour) {
  strokeDashed(ctx, SAFE_DASH_PX, 1, colour);
}

/** Strokes the current path as sensing circles R_s. */
export function paintSenseCircles(ctx) {
  ctx.lineWidth = 1;
  ctx.strokeStyle = SENSE_COLOUR;
  ctx.stroke();
}

/** The robot now: solid, outlined in dark grey. */
export function drawRobot(ctx, x, y, theta, colour) {
  ctx.beginPath();
  addTriangle(ctx, x, y, theta, 1);
  paintBodies(ctx, colour);
}

/** The start pose: a faded solid triangle. */
export function drawStart(ctx, x, y, theta, colour) {
  ctx.beginPath();
  addTriangle(ctx, x, y, theta, MARKER_SCALE);
  paintStarts(ctx, colour);
}

/** The goal pose: a ghost, dashed outline over a faint fill. */
export function drawGoal(ctx, x, y, theta, colour) {
  ctx.beginPath();
  addTriangle(ctx, x, y, theta, MARKER_SCALE);
  paintGoals(ctx, colour);
}

/** The safe radius r_ij around a robot (radius in CSS px). */
export function drawSafeDisc(ctx, x, y, radius, colour) {
  ctx.beginPath();
  ctx.arc(x, y, radius, 0, 2 * Math.PI);
  paintSafeDiscs(ctx, colour);
}

/** The sensing circle R_s (radius in CSS px). */
export function drawSenseCircle(ctx, x, y, radius) {
  ctx.beginPath();
  ctx.arc(x, y, radius, 0, 2 * Math.PI);
  paintSenseCircles(ctx);
}

/** The influence ring R_o: a faint disc with a dashed edge (radius in CSS px). */
export function drawInfluence(ctx, x, y, radius) {
  ctx.beginPath();
  ctx.arc(x, y, radius, 0, 2 * Math.PI);
  ctx.fillStyle = INFLUENCE_FILL;
  ctx.fill();
  strokeDashed(ctx, INFLUENCE_DASH_PX, 1.5, INFLUENCE_STROKE);
}

/** The obstacle disc r_o (radius in CSS px). */
export function drawObstacleDisc(ctx, x, y, radius) {
  ctx.beginPath();
  ctx.arc(x, y, radius, 0, 2 * Math.PI);
  ctx.fillStyle = OBSTACLE_FILL;
  ctx.fill();
}

/** Virtual obstacle glyphs at screen `points` ([x, y] each): the rings R_c, then the crosses. */
export function drawVirtualObstacles(ctx, points, rc) {
  ctx.beginPath();
  for (const [x, y] of points) addCircle(ctx, x, y, rc);
  ctx.globalAlpha = 0.7;
  strokeDashed(ctx, VIRTUAL_OBSTACLE_DASH_PX, 1.25, VIRTUAL_OBSTACLE_COLOUR);
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

/** One virtual obstacle glyph at (x, y) with ring radius `rc` (CSS px). */
export function drawVirtualObstacle(ctx, x, y, rc) {
  drawVirtualObstacles(ctx, [[x, y]], rc);
}

/**
 * Rings of `radius` (CSS px) about the robots at screen `points` ([x, y] each) whose command
 * is at a limit.
 */
export function drawSaturated(ctx, points, radius = ROBOT_LENGTH_PX * 0.75) {
  ctx.beginPath();
  for (const [x, y] of points) addCircle(ctx, x, y, radius);
  ctx.lineWidth = 2;
  ctx.strokeStyle = SATURATED_COLOUR;
  ctx.stroke();
}

/** One saturation ring of `radius` (CSS px) at (x, y). */
export function drawSaturatedRing(ctx, x, y, radius) {
  drawSaturated(ctx, [[x, y]], radius);
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
