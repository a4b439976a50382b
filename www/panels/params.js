// The parameters panel: one field per parameter of the scenario's `params`, and the run's dt,
// duration and tolerances, applied on Enter. A value the core refuses keeps the typed text,
// marked, with the core's message under the form in the panel's own names (R_c, not
// params.avoid_radius); a value taken, or a new scene, clears every mark and the message.

import { humanize } from '../playground/message.js';
import { el } from './dom.js';

/**
 * One row of the core's parameter table (`parameters()` of the wasm module, src/params.rs):
 * the key in `params`, the page's symbol, unit, kind, range and meaning, and whether the panel
 * shows it.
 * @typedef {{name: string, symbol: string, unit: string, kind: 'number' | 'optional' | 'mode',
 *   range: string, meaning: string, panel: boolean}} Parameter
 */

/** The run's own numbers, fields of the scenario rather than of its `params`, after them. */
const RUN_FIELDS = [
  { name: 'dt', symbol: 'dt', unit: 's', kind: 'number', meaning: 'the step of the simulation' },
  { name: 'duration', symbol: 'T', unit: 's', kind: 'number', meaning: 'the duration of the run' },
];
/** Fields of the scenario itself rather than of its `params`. */
const SCENARIO_FIELDS = new Set(RUN_FIELDS.map((f) => f.name));

/** The parameter form of one playground. */
export class ParamsPanel {
  /**
   * The form in `form`, built once the table is known (build); `apply(key, value)` gets a
   * number, `null` (an empty optional field) or the avoidance mode, and returns an error
   * message or null; `scenario()` is the scenario shown (the controller's model, read only),
   * null before the first.
   * @param {HTMLFormElement} form
   * @param {(key: string, value: number | string | null) => string | null} apply
   * @param {() => Record<string, any> | null} scenario
   */
  constructor(form, apply, scenario) {
    this.form = form;
    this.apply = apply;
    this.scenario = scenario;
    /** @type {Map<string, HTMLInputElement | HTMLSelectElement>} */
    this.inputs = new Map();
    this.error = el('p', '', 'param-error');
    this.error.setAttribute('role', 'alert');
    this.error.hidden = true;
    this.warning = el('p', '', 'param-warning');
    this.warning.dataset.id = 'gain-warning';
    this.warning.hidden = true;
  }

  /**
   * Builds the form from the core's parameter table (`{rows, modes}`): a number field per
   * number the panel shows, the run's dt and duration, and the avoidance menu.
   * @param {{rows: Parameter[], modes: string[]}} table
   */
  build({ rows, modes }) {
    const form = this.form;
    const apply = this.apply;
    form.replaceChildren();
    this.inputs.clear();
    const numbers = [...rows.filter((r) => r.panel && r.kind !== 'mode'), ...RUN_FIELDS];
    for (const { name: key, symbol: label, unit, kind, meaning: title } of numbers) {
      const optional = kind === 'optional';
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
    for (const { name: key, symbol: label, meaning } of rows.filter((r) => r.panel && r.kind === 'mode')) {
      const row = el('label', undefined, 'param wide');
      row.title = meaning;
      const select = el('select');
      select.name = key;
      select.setAttribute('aria-label', 'robot avoidance mode');
      for (const mode of modes) {
        const o = el('option', mode);
        o.value = mode;
        select.append(o);
      }
      select.addEventListener('change', () => this.result(select, label, apply(key, select.value)));
      row.append(el('span', label, 'param-name'), select);
      form.append(row);
      this.inputs.set(key, select);
    }
    form.append(this.error, this.warning);
  }

  /**
   * Warns of gains known to fail (docs/notes-on-the-paper.md, 3.2, and
   * docs/book/src/scenario-format.md): k_a ≤ 2·k_ω lets a robot stall where the field is perpendicular to
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
    if (this.scenario()) this.fill();
  }

  /**
   * Puts the scenario's values into the form; not into `typing` (the field being typed in, if
   * any) unless it is null. A new value anywhere clears the marks of earlier refusals.
   * @param {Element | null} [typing]
   */
  fill(typing = null) {
    const s = this.scenario();
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
