// The selection panel: the selected robot's pose (its start at t = 0, where it is now later),
// goal or obstacle as numbers to edit, and with nothing selected the scene's bounds. Applied
// on Enter as one gesture of the controller (one undo entry); a refused value keeps the typed
// text, marked, with the core's message in the panel's names (x, θ, r_o). A box shows its value
// rounded to what it holds whole, the exact value on focus (format.js); only the boxes typed in
// are applied, so that the rounding never changes a value.

import { humanize } from '../playground/message.js';
import { el } from './dom.js';
import { boxText, exact, numberBox, parseNumber } from './format.js';

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
 * the message a refused gesture showed, and what shows a message over the canvas.
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
 *   showMessage: (text: string) => void,
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
      if (input.getAttribute('aria-invalid') === 'true' || 'edited' in input.dataset) continue;
      const text = input === focused ? exact(values[k]) : boxText(values[k], input);
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
      numberBox(input, () => this.values()[k]);
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

  /**
   * Applies the boxes typed in to the selection (or the bounds) as one gesture, the others at
   * their exact values; a box whose text is not a number is named and nothing changes.
   */
  apply(kind, changed) {
    const { selection, scenario, change, edits: c, message } = this.host;
    const v = { ...this.values() };
    const labels = new Map(FIELDS[kind].map(([k, label]) => [k, label]));
    /** The field typed too large to be a number: the core's refusal of the largest number names its limit. */
    let tooLarge = null;
    for (const [k, input] of this.inputs) {
      if (!('edited' in input.dataset) && input !== changed) continue;
      const typed = parseNumber(input.value);
      const label = labels.get(k);
      if (typed.empty || (typed.error && typed.value === undefined)) {
        this.refuse(input, `${label}: ${typed.empty ? 'a value is needed' : typed.error}`);
        return;
      }
      v[k] = /** @type {number} */ (typed.value);
      if (typed.error) tooLarge = label;
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
    if (ok) {
      for (const input of this.inputs.values()) delete input.dataset.edited;
      return;
    }
    let text = panelMessage(message(), kind);
    // The largest number stood for what was typed: the message does not quote it.
    if (tooLarge && text.startsWith(`${tooLarge}: `))
      text = `${tooLarge}: too large, ${text.slice(tooLarge.length + 2).replace(/, not \S+$/, '')}`;
    this.refuse(changed, text);
    this.host.showMessage(text);
  }

  /** Marks `input` as refused with `text`; its typed text stays for the user to fix. */
  refuse(input, text) {
    for (const other of this.inputs.values()) other.removeAttribute('aria-invalid');
    input.setAttribute('aria-invalid', 'true');
    this.error.textContent = text;
    this.error.hidden = false;
  }
}

/**
 * The panel's names of the core's fields, as the core writes them (`robots[0].start[0]`) or as
 * the page's messages do (`robot 1's start[0]`, message.js): a pose's x, y, θ; an obstacle's
 * x, y, r_o, R_o; the bounds'.
 * @type {[RegExp, (...m: string[]) => string][]}
 */
const PATHS = [
  [/\b(?:robots\[\d+\]\.|robot \d+'s )(?:start|goal)\[(\d)\]/g, (_m, k) => POSE[Number(k)][1]],
  [/\b(?:obstacles\[\d+\]\.|obstacle \d+'s )center\[(\d)\]/g, (_m, k) => FIELDS.obstacle[Number(k)][1]],
  [/\b(?:obstacles\[\d+\]\.|obstacle \d+'s )radius\b/g, () => 'r_o'],
  [/\b(?:obstacles\[\d+\]\.|obstacle \d+'s )influence\b/g, () => 'R_o'],
  [/\bbounds\[(\d)\]/g, (_m, k) => FIELDS.bounds[Number(k)][1]],
];

/**
 * The core's message `text` in the panel's names (`robots[0].start[0]` → x) and, for a limit
 * "at most … in magnitude", with the field's unit; what the panel does not show keeps the
 * page's names (robot 2, R_c).
 */
export function panelMessage(text, kind) {
  let out = String(text);
  for (const [re, name] of PATHS) out = out.replace(re, name);
  const field = FIELDS[kind]?.find(([, label]) => out.startsWith(`${label}:`));
  if (field) out = out.replace(/at most (\S+) in magnitude/, `at most $1 ${field[2]} in magnitude`);
  return humanize(out);
}
