// The results panel: what `dvf simulate` reports for the scenario (the run from its starts,
// docs/book/src/command-line.md): per robot when it converged and its final errors, the
// smallest distance between two robots, the smallest clearance to an obstacle and the
// violations, where they happened (a mark on the canvas, render/marks.js, and a button over
// the canvas with their count that goes there), and the report as JSON to copy. The run is made
// off the page's thread (a module
// worker, playground/results-worker.js) after each change; a change made meanwhile starts it
// again. Runs larger than AUTO_ROBOT_STEPS wait for the Compute button.

import { GHOST_MAX_ROBOTS } from '../playground/ghost.js';
import { messageOf } from '../playground/message.js';
import { runWorker } from '../playground/wasm-views.js';
import { markText } from '../render/marks.js';
import { el } from './dom.js';

/** Runs up to this many robot-steps start by themselves (the 100-robot crowd: about 2 s). */
const AUTO_ROBOT_STEPS = 2_000_000;
/** The table lists this many robots; Copy JSON has them all. */
const TABLE_ROBOTS = 20;
/** A change waits this long (ms) for the next before the run starts (a drag is many). */
const SETTLE_MS = 300;

/** The Pin button's title when it can pin the run. */
const PIN_TITLE = 'Pin this run as a ghost to compare with the next (faded on the canvas and in the plots)';

/** @param {number | null} v @param {number} digits */
const num = (v, digits = 3) => (v == null ? '—' : Number(v).toPrecision(digits));

/** The report's figures, a line each; `safeRadius` (m) adds 2·r_ij beside the pair distance. */
function summary(report, safeRadius) {
  const converged = report.robots.filter((r) => r.converged_at != null);
  const last = Math.max(...converged.map((r) => r.converged_at));
  const safe = safeRadius == null ? '' : ` (2·r_ij = ${num(2 * safeRadius)} m)`;
  return [
    `${converged.length} of ${report.robots.length} robots converged${converged.length ? `, the last at ${last.toFixed(2)} s` : ''} (run of ${report.time} s, ${report.steps} steps)`,
    `min distance between two robots: ${report.min_pair_distance == null ? 'none' : `${num(report.min_pair_distance)} m`}${safe}`,
    `min clearance to an obstacle: ${report.min_obstacle_clearance == null ? 'none' : `${num(report.min_obstacle_clearance)} m`}`,
    `violations: ${report.violations}`,
  ];
}

export class ResultsPanel {
  /**
   * @param {{
   *   $: (id: string) => any,
   *   active: () => boolean,
   *   scenario: () => any,
   *   pin: import('../playground/ghost.js').Pin,
   *   showMessage: (text: string, options?: {info?: boolean}) => void,
   *   goTo: (mark: import('../playground/violations.js').ViolationMark) => void,
   *   requestDraw: () => void,
   * }} host the template's parts by `data-id`; whether the panel is shown (`controls`); the
   *   scenario (the model itself, not a copy: read only); the pin; the message over the canvas;
   *   what shows a violation's time and robot; what redraws the canvas
   */
  constructor(host) {
    this.host = host;
    this.box = host.$('results');
    /** @type {import('../playground/violations.js').ViolationMark[]} where the run's violations happened */
    this.marks = [];
    /** The mark the violations button goes to next. */
    this.nextMark = 0;
    host.$('violations').addEventListener('click', () => this.goToMark());
    /** @type {Worker | null} */
    this.worker = null;
    this.id = 0;
    /** @type {any} the last report shown */
    this.report = null;
    /** @type {ReturnType<typeof setTimeout> | null} */
    this.timer = null;
    host.$('copy-results').addEventListener('click', () => this.copy());
    host.$('pin').addEventListener('click', () => host.pin.toggle());
  }

  /** The pinned run (playground/ghost.js): its figures above the current run's, and the Pin button. */
  showGhost() {
    const c = this.host;
    const { ghost, pending } = c.pin;
    const box = c.$('pinned');
    c.$('pin').textContent = ghost ? 'Unpin' : pending ? 'Pinning…' : 'Pin';
    this.showPin();
    box.hidden = !ghost;
    if (!ghost) return;
    const lines = summary(ghost.report, null);
    box.replaceChildren(el('p', `Pinned run (faded), ${ghost.name}:`, 'muted'), ...lines.map((t) => el('p', t)));
  }

  /**
   * The Pin button: offered for a scene it can pin, disabled with the reason in its title for
   * a crowd above GHOST_MAX_ROBOTS (a pinned run stays unpinnable).
   */
  showPin() {
    const c = this.host;
    const button = c.$('pin');
    const robots = c.scenario()?.robots.length ?? 0;
    const refused = robots > GHOST_MAX_ROBOTS && !c.pin.ghost && !c.pin.pending;
    button.disabled = refused;
    button.title = refused
      ? `Pin compares runs of up to ${GHOST_MAX_ROBOTS} robots; this scene has ${robots.toLocaleString('en')}`
      : PIN_TITLE;
  }

  /** The scenario changed: its results are computed again (after SETTLE_MS). */
  stale() {
    this.showPin();
    this.showMarks(null, []);
    if (!this.host.active()) return;
    this.report = null;
    delete this.box.dataset.ready;
    this.host.$('copy-results').disabled = true;
    if (this.timer) clearTimeout(this.timer);
    this.stop();
    const s = this.host.scenario();
    const steps = Math.round(s.duration / s.dt);
    if (s.robots.length * steps > AUTO_ROBOT_STEPS) {
      const button = el('button', 'Compute');
      button.type = 'button';
      button.dataset.id = 'compute-results';
      button.addEventListener('click', () => this.start());
      this.box.replaceChildren(
        el(
          'p',
          `A run of ${s.robots.length.toLocaleString('en')} robots over ${steps.toLocaleString('en')} steps: `,
          'muted',
        ),
        button,
      );
      return;
    }
    this.box.replaceChildren(el('p', 'Running the scenario…', 'muted'));
    this.timer = setTimeout(() => this.start(), SETTLE_MS);
  }

  /** Ends a run in progress. */
  stop() {
    this.worker?.terminate();
    this.worker = null;
  }

  /** Runs the scenario in a worker and shows its report. */
  start() {
    this.timer = null;
    this.stop();
    const id = ++this.id;
    const worker = runWorker();
    this.worker = worker;
    this.box.replaceChildren(el('p', 'Running the scenario…', 'muted'));
    worker.onmessage = (e) => {
      if (e.data.id !== id) return;
      this.stop();
      if (e.data.error) this.box.replaceChildren(el('p', `Could not run the scenario: ${messageOf(e.data)}`));
      else this.show(e.data.report, e.data.marks ?? []);
    };
    worker.postMessage({ id, scenario: this.host.scenario() });
  }

  /**
   * The run's violations over the canvas: a button with their count that goes to each in turn,
   * hidden without; the marks drawn on the canvas.
   * @param {any} report the run's report, null while there is none
   * @param {import('../playground/violations.js').ViolationMark[]} marks
   */
  showMarks(report, marks) {
    this.marks = marks;
    this.nextMark = 0;
    const button = this.host.$('violations');
    const count = report?.violations ?? 0;
    button.hidden = count === 0;
    button.textContent = `⚠ ${count} violation${count === 1 ? '' : 's'}${marks.length ? `: go to t = ${marks[0].time.toFixed(2)} s` : ''}`;
    button.title = marks.length
      ? `Where: ${marks.map(markText).join('; ')}. Click to go there.`
      : 'Robots closer than 2·r_ij, or inside an obstacle';
    this.host.requestDraw();
  }

  /** Goes to the next mark: its time, its robot inspected; the button names the one after. */
  goToMark() {
    const marks = this.marks;
    if (!marks.length) return;
    const m = marks[this.nextMark % marks.length];
    this.nextMark = (this.nextMark + 1) % marks.length;
    this.host.goTo(m);
    const next = marks[this.nextMark];
    const count = this.report?.violations ?? 0;
    this.host.$('violations').textContent =
      `⚠ ${count} violation${count === 1 ? '' : 's'}: go to t = ${next.time.toFixed(2)} s`;
  }

  /** Shows `report` (the JSON of `dvf simulate`) and `marks`, where its violations happened. */
  show(report, marks = []) {
    this.report = report;
    this.showMarks(report, marks);
    this.host.$('copy-results').disabled = false;
    const lines = summary(report, this.host.scenario().params.safe_radius);
    if (marks.length) lines.push(...marks.map((m) => `where: ${markText(m)}`));
    const table = el('table', undefined, 'results-table');
    const head = el('tr');
    for (const h of ['robot', 'converged at (s)', 'position error (m)', 'heading error (rad)'])
      head.append(el('th', h));
    table.append(head);
    report.robots.slice(0, TABLE_ROBOTS).forEach((r, i) => {
      const row = el('tr');
      row.append(
        el('td', String(i + 1)),
        el('td', r.converged_at == null ? 'not' : r.converged_at.toFixed(2)),
        el('td', num(r.position_error, 2)),
        el('td', num(r.heading_error, 2)),
      );
      table.append(row);
    });
    const more = report.robots.length - TABLE_ROBOTS;
    this.box.replaceChildren(
      ...lines.map((t) => el('p', t)),
      table,
      ...(more > 0 ? [el('p', `… and ${more.toLocaleString('en')} more (Copy JSON has them all).`, 'muted')] : []),
    );
    this.box.dataset.ready = '';
  }

  /** Copies the report as JSON (the text `dvf simulate` prints). */
  async copy() {
    if (!this.report) return;
    try {
      await navigator.clipboard.writeText(JSON.stringify(this.report));
      this.host.showMessage('The results are on the clipboard as JSON.', { info: true });
    } catch (e) {
      this.host.showMessage(`Could not copy the results: ${messageOf(e)}`);
    }
  }
}
