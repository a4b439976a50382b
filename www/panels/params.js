// The parameters panel: one field per parameter of the scenario's `params`, and the run's dt,
// duration and tolerances, applied on Enter. A value the core refuses keeps the typed text,
// marked, with the core's message under the form in the panel's own names (R_c, not
// params.avoid_radius); a value taken, or a new scene, clears every mark and the message.

import { humanize } from '../playground/message.js';
import { el } from './dom.js';

/**
 * The editable fields: key (in `params`, or `dt` and `duration` of the scenario), label, unit,
 * meaning, whether it may be empty (no saturation, no barrier).
 * @type {[key: string, label: string, unit: string, title: string, optional?: boolean][]}
 */
export const PARAMETERS = [
  ['k_v', 'k_v', '1/s', 'gain of the forward speed on the field'],
  ['k_omega', 'k_ω', '1/s', 'gain of the attitude feedback −k_ω θ̃'],
  ['k_a', 'k_a', '1/s', 'gain of the alignment term'],
  ['transition_width', 'ε', 'm', 'width of the transition band ς'],
  ['avoid_speed', 'v_c', 'm/s', 'speed while circling a virtual obstacle'],
  ['avoid_radius', 'R_c', 'm', 'radius of the ring about a virtual obstacle'],
  ['safe_radius', 'r_ij', 'm', 'safe radius: closer than 2·r_ij is a collision'],
  ['sense_radius', 'R_s', 'm', 'sensing radius'],
  ['v_max', 'v_max', 'm/s', 'speed saturation (empty: none)', true],
  ['omega_max', 'ω_max', 'rad/s', 'turn-rate saturation (empty: none)', true],
  [
    'barrier_rate',
    'α',
    '1/s',
    'safety barrier: a gap to a safe disc or an obstacle shrinks by at most α·dt per step (empty: off, the paper alone)',
    true,
  ],
  ['tol_position', 'tol_p', 'm', 'a robot has converged within this distance of its goal'],
  ['tol_heading', 'tol_θ', 'rad', 'a robot has converged within this heading error'],
  ['dt', 'dt', 's', 'the step of the simulation'],
  ['duration', 'T', 's', 'the duration of the run'],
];
/** Fields of the scenario itself rather than of its `params`. */
const SCENARIO_FIELDS = new Set(['dt', 'duration']);
/** The avoidance modes, as in `params.avoidance`. */
const AVOIDANCE_MODES = ['exit', 'paper'];

/** The parameter form of one playground. */
export class ParamsPanel {
  /**
   * Builds the form in `form`; `apply(key, value)` gets a number, `null` (an empty optional
   * field) or the avoidance mode, and returns an error message or null.
   * @param {HTMLFormElement} form
   * @param {(key: string, value: number | string | null) => string | null} apply
   */
  constructor(form, apply) {
    this.form = form;
    /** @type {Map<string, HTMLInputElement | HTMLSelectElement>} */
    this.inputs = new Map();
    /** @type {Record<string, any> | null} the scenario last filled in */
    this.scenario = null;
    form.replaceChildren();
    for (const [key, label, unit, title, optional] of PARAMETERS) {
      const row = el('label', undefined, 'param');
      row.title = title;
      const input = el('input');
      input.type = 'number';
      input.step = 'any';
      input.name = key;
      input.setAttribute('aria-label', `${label} (${unit}): ${title}`);
      if (optional) input.placeholder = 'off';
      row.append(el('span', label, 'param-name'), input, el('span', unit, 'param-unit'));
      form.append(row);
      this.inputs.set(key, input);
      input.addEventListener('change', () => {
        const text = input.value.trim();
        if (text === '' && !optional) {
          this.refuse(input, `${label}: a value is needed`);
          return;
        }
        const value = text === '' ? null : Number(text);
        if (value !== null && !Number.isFinite(value)) {
          this.refuse(input, `${label}: must be a number`);
          return;
        }
        this.result(input, label, apply(key, value));
      });
    }
    const row = el('label', undefined, 'param wide');
    row.title = "how robots avoid each other: the paper's ring, or the ring with an exit (default)";
    const select = el('select');
    select.name = 'avoidance';
    select.setAttribute('aria-label', 'robot avoidance mode');
    for (const mode of AVOIDANCE_MODES) {
      const o = el('option', mode);
      o.value = mode;
      select.append(o);
    }
    select.addEventListener('change', () => this.result(select, 'avoidance', apply('avoidance', select.value)));
    row.append(el('span', 'avoidance', 'param-name'), select);
    form.append(row);
    this.inputs.set('avoidance', select);
    this.error = el('p', '', 'param-error');
    this.error.setAttribute('role', 'alert');
    this.error.hidden = true;
    this.warning = el('p', '', 'param-warning');
    this.warning.dataset.id = 'gain-warning';
    this.warning.hidden = true;
    form.append(this.error, this.warning);
  }

  /**
   * Warns of gains known to fail (docs/notes-on-the-paper.md, 3.2, and README.md,
   * Parameters): k_a ≤ 2·k_ω lets a robot stall where the field is perpendicular to
   * its heading; k_v > k_ω leaves the attitude loop slower than the position loop.
   */
  warn(p) {
    const notes = [];
    if (p.k_a <= 2 * p.k_omega) {
      notes.push(
        `k_a ≤ 2·k_ω (${p.k_a} ≤ ${2 * p.k_omega}): a robot can stall where the field is perpendicular to its heading.`,
      );
    }
    if (p.k_v > p.k_omega) {
      notes.push(
        `k_v > k_ω (${p.k_v} > ${p.k_omega}): the heading lags the position; robots may end with a large heading error.`,
      );
    }
    this.warning.textContent = notes.join(' ');
    this.warning.hidden = notes.length === 0;
  }

  /** After `apply`: a refusal keeps the typed text and shows why; a value taken clears all. */
  result(input, label, message) {
    if (!message) {
      this.clearMarks();
      return;
    }
    const text = humanize(message);
    // The field the user changed comes first, whichever field the core names.
    this.refuse(input, text.startsWith(`${label}:`) ? text : `${label} refused: ${text}`);
  }

  /** Marks `input` as refused with `message`; its typed text stays for the user to fix. */
  refuse(input, message) {
    input.setAttribute('aria-invalid', 'true');
    this.error.textContent = message;
    this.error.hidden = false;
  }

  /** No field marked, no message, every field showing the scenario's value. */
  clearMarks() {
    for (const input of this.inputs.values()) input.removeAttribute('aria-invalid');
    this.error.textContent = '';
    this.error.hidden = true;
    if (this.scenario) this.fill(this.scenario);
  }

  /**
   * Puts scenario `s`'s values into the form; not into `typing` (the field being typed in, if
   * any) unless it is null. A new value anywhere clears the marks of earlier refusals.
   */
  fill(s, typing = null) {
    this.scenario = s;
    for (const [key, input] of this.inputs) {
      if (input === typing) continue;
      const v = SCENARIO_FIELDS.has(key) ? s[key] : s.params[key];
      input.value = v == null ? '' : String(v);
      input.removeAttribute('aria-invalid');
    }
    this.error.textContent = '';
    this.error.hidden = true;
    this.warn(s.params);
  }
}
