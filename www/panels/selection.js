// The selection panel: the selected robot's pose (its start at t = 0, where it is now later),
// goal or obstacle as numbers to edit, and with nothing selected the scene's bounds. Applied
// on Enter as one gesture of the controller (one undo entry); a refused value keeps the typed
// text, marked, with the core's message.

import { el } from './dom.js';

/** A pose's fields: key, label, unit. */
const POSE = [
  ['x', 'x', 'm'],
  ['y', 'y', 'm'],
  ['theta', 'θ', 'rad'],
];
/** The fields of each kind of selection: key, label, unit. */
const FIELDS = {
  robot: POSE,
  goal: POSE,
  obstacle: [
    ['x', 'x', 'm'],
    ['y', 'y', 'm'],
    ['radius', 'r_o', 'm'],
    ['influence', 'R_o', 'm'],
  ],
  bounds: [
    ['xmin', 'x min', 'm'],
    ['ymin', 'y min', 'm'],
    ['xmax', 'x max', 'm'],
    ['ymax', 'y max', 'm'],
  ],
};

/**
 * What the panel reads and how it edits: its form and title; the selection, the scenario (the
 * controller's model, read only), robot `i`'s pose now, the time (s) and the focused element;
 * one gesture of edits (Gestures.change); the controller's edit methods it calls; the text of
 * the message a refused gesture showed.
 * @typedef {{
 *   form: HTMLElement,
 *   title: HTMLElement,
 *   selection: () => import('../playground/controller.js').Selection | null,
 *   scenario: () => any,
 *   pose: (i: number) => number[],
 *   time: () => number,
 *   focused: () => Element | null,
 *   change: (kind: string, edits: () => void) => boolean,
 *   edits: Pick<import('../playground/controller.js').Controller,
 *     'edit' | 'moveRobot' | 'moveGoal' | 'moveObstacle' | 'resizeObstacle'>,
 *   message: () => string,
 * }} SelectionHost
 */

export class SelectionPanel {
  /** @param {SelectionHost} host */
  constructor(host) {
    this.host = host;
    this.form = host.form;
    this.title = host.title;
    this.key = '';
    /** @type {Map<string, HTMLInputElement>} */
    this.inputs = new Map();
    this.error = el('p', '', 'param-error');
  }

  /** The values shown for the selection now, by field key. */
  values() {
    const { selection, scenario, pose } = this.host;
    const sel = selection();
    const s = scenario();
    if (!sel) {
      const [xmin, ymin, xmax, ymax] = s.bounds;
      return { xmin, ymin, xmax, ymax };
    }
    if (sel.kind === 'robot') {
      const [x, y, theta] = pose(sel.index);
      return { x, y, theta };
    }
    if (sel.kind === 'goal') {
      const [x, y, theta] = s.robots[sel.index].goal;
      return { x, y, theta };
    }
    const o = s.obstacles[sel.index];
    return { x: o.center[0], y: o.center[1], radius: o.radius, influence: o.influence };
  }

  /** Shows the selection (each frame): the form is built when it changes, filled unless typed in. */
  update() {
    const sel = this.host.selection();
    const kind = sel ? sel.kind : 'bounds';
    const key = sel ? `${kind}${sel.index}` : 'bounds';
    if (key !== this.key) this.build(kind, key);
    const now = this.host.time() > 0;
    this.title.textContent = sel
      ? `${kind === 'obstacle' ? 'Obstacle' : 'Robot'} ${sel.index + 1}${kind === 'goal' ? ': its goal' : kind === 'robot' ? (now ? ': where it is now' : ': its start') : ''}`
      : 'Scene bounds (select a robot, goal or obstacle to edit it)';
    const values = this.values();
    const focused = this.host.focused();
    for (const [k, input] of this.inputs) {
      if (input === focused || input.getAttribute('aria-invalid') === 'true') continue;
      const text = String(Number(values[k].toPrecision(10)));
      if (input.value !== text) input.value = text;
    }
  }

  build(kind, key) {
    this.key = key;
    this.inputs.clear();
    this.form.replaceChildren();
    for (const [k, label, unit] of FIELDS[kind]) {
      const row = el('label', undefined, 'param');
      const input = el('input');
      input.type = 'number';
      input.step = 'any';
      input.name = `selection-${k}`;
      input.setAttribute('aria-label', `${label} (${unit})`);
      input.addEventListener('change', () => this.apply(kind, input));
      row.append(el('span', label, 'param-name'), input, el('span', unit, 'param-unit'));
      this.form.append(row);
      this.inputs.set(k, input);
    }
    this.error.hidden = true;
    this.form.append(this.error);
  }

  /** Applies the form to the selection (or the bounds) as one gesture. */
  apply(kind, changed) {
    const { selection, scenario, change, edits: c, message } = this.host;
    const v = { ...this.values() };
    for (const [k, input] of this.inputs) {
      const n = Number(input.value);
      if (input.value.trim() !== '' && Number.isFinite(n)) v[k] = n;
    }
    const sel = selection();
    const ok = change(kind === 'bounds' ? 'params' : kind, () => {
      if (kind === 'bounds') c.edit({ ...scenario(), bounds: [v.xmin, v.ymin, v.xmax, v.ymax] });
      else if (kind === 'robot') c.moveRobot(sel.index, v.x, v.y, v.theta);
      else if (kind === 'goal') c.moveGoal(sel.index, v.x, v.y, v.theta);
      else {
        c.moveObstacle(sel.index, v.x, v.y);
        c.resizeObstacle(sel.index, v.radius, v.influence);
      }
    });
    for (const input of this.inputs.values()) input.removeAttribute('aria-invalid');
    this.error.hidden = ok;
    if (!ok) {
      changed.setAttribute('aria-invalid', 'true');
      this.error.textContent = message();
    }
  }
}
