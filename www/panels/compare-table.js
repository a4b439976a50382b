// The compare mode's table (playground/compare.js): one row per metric, one column per planner
// (the scenario's, then the compared one), from the module's `compare()` — the JSON of
// `dvf compare --json`, so every number but the compute per step is the command line's for the
// same scene. Each cell shows its metric rounded and keeps it whole in `data-value` (empty for
// none), so that a test reads the numbers the page shows; tests/e2e/planners.mjs holds them to
// the command line's.

import { el } from './dom.js';

/** @param {number | null} v @param {number} digits */
const num = (v, digits = 4) => (v == null ? '—' : Number(v).toPrecision(digits));

/**
 * The rows: the metric's key in `metrics` of a planner's run (the cell's `data-metric`), its
 * label, and its text from the run's metrics and the scene's robot count.
 * @type {[string, string, (v: any, robots: number) => string][]}
 */
const ROWS = [
  ['arrived', 'at goal and heading', (v, robots) => `${v} of ${robots}`],
  ['arrival_rate', 'arrival rate', (v) => `${Math.round(v * 100)} %`],
  ['time_to_last_arrival', 'time to the last arrival (s)', (v) => (v == null ? 'not all' : v.toFixed(2))],
  ['path_length', 'path length, all robots (m)', (v) => num(v)],
  ['control_effort', 'control effort ∫(v² + ω²)dt', (v) => num(v)],
  ['peak_curvature', 'peak curvature (1/m)', (v) => num(v)],
  ['reversals', 'turn-rate reversals', (v) => String(v)],
  ['chattering_robots', 'robots chattering at the goal', (v) => String(v)],
  ['min_pair_distance', 'closest pair (m)', (v) => num(v)],
  ['min_obstacle_clearance', 'closest to an obstacle (m)', (v) => num(v)],
  ['violations', 'violations', (v) => String(v)],
  ['steps', 'steps simulated', (v) => String(v)],
  ['ms_per_step', 'compute per step (ms), measured in this browser', (v) => num(v, 3)],
];

/** The name of a run's planner: a name, or an object with its name and gains. @param {any} p */
const nameOf = (p) => (typeof p === 'string' ? p : p.name);

/**
 * The table of `comparison` (the module's `compare()` of the scene with the scenario's planner,
 * then the compared one), and a line on the conditions every run shares; `colour` marks the
 * compared run's column.
 * @param {any} comparison
 * @param {string} colour
 * @returns {HTMLElement[]}
 */
export function compareTable(comparison, colour) {
  const runs = comparison.planners;
  const table = el('table', undefined, 'results-table compare-table');
  table.dataset.id = 'compare-table';
  const head = el('tr');
  head.append(el('th', ''));
  runs.forEach((r, i) => {
    const name = nameOf(r.planner);
    const th = el('th');
    th.append(el('span', name, 'compare-name'));
    th.dataset.planner = name;
    th.title = r.title;
    if (i === 0) th.append(el('span', '(live)', 'compare-live'));
    else th.style.color = colour;
    head.append(th);
  });
  table.append(head);
  const avoids = el('tr');
  avoids.append(el('th', 'avoids on its own'));
  for (const r of runs) avoids.append(el('td', r.avoids));
  table.append(avoids);
  const robots = comparison.conditions.robots;
  for (const [key, label, text] of ROWS) {
    const row = el('tr');
    row.append(el('th', label));
    for (const r of runs) {
      const v = r.metrics[key];
      const td = el('td', text(v, robots));
      td.dataset.metric = key;
      td.dataset.planner = nameOf(r.planner);
      td.dataset.value = v == null ? '' : String(v);
      row.append(td);
    }
    table.append(row);
  }
  const { duration, barrier, v_max, omega_max } = comparison.conditions;
  const shared = barrier ? 'with the same safety barrier' : 'without the safety barrier';
  const limits =
    v_max == null && omega_max == null ? 'no speed limits' : `v_max ${v_max ?? 'none'}, ω_max ${omega_max ?? 'none'}`;
  return [el('p', `Both runs: the scene from t = 0 to ${duration} s, ${shared}, ${limits}.`, 'muted'), table];
}
