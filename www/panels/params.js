// The parameters panel: one field per parameter of the scenario's `params`, and the run's dt,
// duration and tolerances, applied on Enter. A value the core refuses keeps the typed text,
// marked, with the core's message under the form in the panel's own names (R_c, not
// params.avoid_radius; T, not duration) and units; a value taken, or a new scene, clears every
// mark and the message. A box shows its value rounded to what it holds whole, the exact value
// on focus (format.js).

import { humanize } from '../playground/message.js';
import { el } from './dom.js';
import { boxText, exact, numberBox, parseNumber } from './format.js';

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
    /** Each number field's unit by key, for the messages. */
    this.units = new Map();
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
      numberBox(input, () => this.valueOf(key));
      input.name = key;
      input.setAttribute('aria-label', `${label} (${unit}): ${title}`);
      if (optional) input.placeholder = 'off';
      row.append(el('span', label, 'param-name'), input, el('span', unit, 'param-unit'));
      form.append(row);
      this.inputs.set(key, input);
      this.units.set(key, unit);
      input.addEventListener('change', () => {
        const typed = parseNumber(input.value);
        if (typed.empty && !optional) {
          this.refuse(input, `${label}: a value is needed`);
          return;
        }
        if (typed.error && typed.value === undefined) {
          this.refuse(input, `${label}: ${typed.error}`);
          return;
        }
        // Too large to be a number: the largest number, which the core refuses with the
        // field's own limit, the one message of that limit.
        const value = typed.empty ? null : /** @type {number} */ (typed.value);
        this.result(input, label, apply(key, value), typed.error);
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
   * Warns of parameters known to fail (docs/notes-on-the-paper.md, 3.2, and
   * docs/book/src/scenario-format.md): R_s < 2·r_ij lets two robots sense each other only once
   * they are closer than the safe distance (a violation already); k_a ≤ 2·k_ω lets a robot
   * stall where the field is perpendicular to its heading; k_v > k_ω leaves the attitude loop
   * slower than the position loop.
   */
  warn(p) {
    const notes = [];
    const n = (v) => Number(v.toPrecision(6));
    if (p.sense_radius < 2 * p.safe_radius) {
      notes.push(
        `R_s < 2·r_ij (${n(p.sense_radius)} < ${n(2 * p.safe_radius)}): a robot senses a neighbour only once the two are closer than the safe distance, a collision already; it cannot see one coming.`,
      );
    }
    if (p.k_a <= 2 * p.k_omega) {
      notes.push(
        `k_a ≤ 2·k_ω (${n(p.k_a)} ≤ ${n(2 * p.k_omega)}): a robot can stall where the field is perpendicular to its heading.`,
      );
    }
    if (p.k_v > p.k_omega) {
      notes.push(
        `k_v > k_ω (${n(p.k_v)} > ${n(p.k_omega)}): the heading lags the position; robots may end with a large heading error.`,
      );
    }
    this.warning.textContent = notes.join(' ');
    this.warning.hidden = notes.length === 0;
  }

  /**
   * After `apply`: a refusal keeps the typed text and shows why (with `why`, what was wrong with
   * the typed text first: "too large"); a value taken clears all.
   */
  result(input, label, message, why) {
    if (!message) {
      delete input.dataset.edited;
      this.clearMarks();
      return;
    }
    const text = this.panelText(message);
    // The field the user changed comes first, whichever field the core names.
    if (!text.startsWith(`${label}: `)) {
      this.refuse(input, `${label} refused${why ? ` (${why})` : ''}: ${text}`);
      return;
    }
    // The largest number stood for what was typed: the message does not quote it.
    const rest = text.slice(label.length + 2).replace(/, not \S+$/, '');
    this.refuse(input, why ? `${label}: ${why}, ${rest}` : text);
  }

  /**
   * The core's `message` in the panel's names and units: the parameters' symbols (humanize),
   * T for the duration, and a limit "at most … in magnitude" with the field's unit.
   */
  panelText(message) {
    let text = humanize(message).replace(/\bduration(?=:| \/)/g, 'T');
    const field = [...this.inputs.keys()].find((key) => text.startsWith(`${this.labelOf(key)}: `));
    const unit = field ? this.units.get(field) : '';
    if (unit) text = text.replace(/at most (\S+) in magnitude/, `at most $1 ${unit} in magnitude`);
    return text;
  }

  /** The symbol the panel shows for `key`. */
  labelOf(key) {
    return this.inputs.get(key)?.closest('label')?.querySelector('.param-name')?.textContent ?? key;
  }

  /** The value of field `key` in the scenario shown (null for an optional one that is off). */
  valueOf(key) {
    const s = this.scenario();
    if (!s) return null;
    return SCENARIO_FIELDS.has(key) ? s[key] : s.params[key];
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
      const v = this.valueOf(key);
      if (input instanceof HTMLSelectElement) input.value = String(v);
      else {
        delete input.dataset.edited;
        const focused = input === /** @type {Document | ShadowRoot} */ (this.form.getRootNode()).activeElement;
        input.value = v == null ? '' : focused ? exact(v) : boxText(v, input);
      }
      input.removeAttribute('aria-invalid');
    }
    this.error.textContent = '';
    this.error.hidden = true;
    this.warn(s.params);
  }
}
