// The parameters panel: one field per entry of the scenario's `params`, applied on Enter.
// A value the core refuses shows the core's message under the form and the field returns to
// the value it had.

import { el } from './dom.js';

/**
 * The editable parameters: key in `params`, label, unit, meaning, whether it may be empty
 * (no saturation, no barrier).
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
];
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
        const value = text === '' ? (optional ? null : Number.NaN) : Number(text);
        this.mark(input, apply(key, value));
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
    select.addEventListener('change', () => this.mark(select, apply('avoidance', select.value)));
    row.append(el('span', 'avoidance', 'param-name'), select);
    form.append(row);
    this.inputs.set('avoidance', select);
    this.error = el('p', '', 'param-error');
    this.error.setAttribute('role', 'alert');
    this.error.hidden = true;
    form.append(this.error);
  }

  /** Shows (or clears) the message of the last parameter change under the form. */
  mark(input, message) {
    input.setAttribute('aria-invalid', String(Boolean(message)));
    this.error.textContent = message ?? '';
    this.error.hidden = !message;
  }

  /**
   * Puts the scenario's parameter values into the form; not into `typing` (the field being
   * typed in, if any), unless it is null.
   */
  fill(params, typing = null) {
    for (const [key, input] of this.inputs) {
      if (input === typing) continue;
      const v = params[key];
      input.value = v == null ? '' : String(v);
    }
  }
}
