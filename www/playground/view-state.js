// What the view of a playground shows, as the element's viewState() gives it and a link keeps
// it (www/main.js): the field overlay, θ(0) of the curves, the sensing circles, the inspected
// robot, the time, the planner compared with the scenario's (playground/compare.js) and, once
// the user panned or zoomed, the world box in view.

/** The field overlays. @type {import('../dvf-playground.js').FieldMode[]} */
export const FIELD_MODES = ['arrows', 'curves', 'none'];

/** θ(0) of the integral curves (rad) until the element or the link says otherwise: π/2, the paper's Fig. 1a. */
export const DEFAULT_THETA0 = Math.PI / 2;

/**
 * The display options of a view: the field overlay, θ(0) (rad, as every angle of the page),
 * the sensing circles.
 * @typedef {{field: import('../dvf-playground.js').FieldMode, theta0: number, sensing: boolean}} Display
 */

/**
 * The view state of `view` (render/camera.js) showing `display`, robot `robot` inspected, at
 * time `time` (s), compared with planner `compare` (null: none); `user`: the user moved the
 * camera, so the box in view is part of it.
 * @param {any} view
 * @param {Display} display
 * @param {string | null} compare
 * @returns {import('../dvf-playground.js').ViewState}
 */
export function viewStateOf(view, { field, theta0, sensing }, robot, time, user, compare) {
  return {
    field,
    theta0,
    sensing,
    robot,
    time,
    box: user ? [view.wx(0), view.wy(view.height), view.wx(view.width), view.wy(0)] : null,
    compare,
  };
}

/**
 * What of view `state` (viewStateOf's fields, each optional) is valid for a scene of `robots`
 * robots and `duration` seconds shown on a canvas of `width` × `height` CSS px: the display
 * (`shown`'s options where the state has none or a bad one), the robot to inspect, the camera
 * that shows the box, and the time to seek to; null for each that is not (a robot that does
 * not exist, a box that is not one, a time past the end); and the planner to compare with (a
 * name, which the compare mode checks, or null for none; undefined where the state has none).
 * @param {Partial<import('../dvf-playground.js').ViewState>} state
 * @param {Display} shown
 */
export function validViewState(state, shown, { robots, duration, width, height }) {
  const { field, theta0, sensing, robot, time, box } = state;
  const compare = typeof state.compare === 'string' || state.compare === null ? state.compare : undefined;
  const display = {
    field: FIELD_MODES.includes(field) ? field : shown.field,
    theta0: Number.isFinite(theta0) ? theta0 : shown.theta0,
    sensing: typeof sensing === 'boolean' ? sensing : shown.sensing,
  };
  const inspect = Number.isInteger(robot) && robot >= 0 && robot < robots ? robot : null;
  let camera = null;
  if (Array.isArray(box) && box.length === 4 && box.every(Number.isFinite) && box[2] > box[0] && box[3] > box[1]) {
    const w = Math.max(1, width);
    const h = Math.max(1, height);
    const scale = Math.min(w / (box[2] - box[0]), h / (box[3] - box[1]));
    camera = { cx: (box[0] + box[2]) / 2, cy: (box[1] + box[3]) / 2, scale };
  }
  const seek = Number.isFinite(time) && time > 0 && time <= duration ? time : null;
  return { display, inspect, camera, seek, compare };
}
