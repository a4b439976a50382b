// The compare mode's table (playground/compare.js): one row per figure, one column per run
// (the scenario's planner, then the compared one). Each cell shows its figure rounded and
// keeps it whole in `data-value` (empty for none), so that a test reads the numbers the page
// computed; tests/e2e/planners.mjs holds them to the command line's.

import { el } from './dom.js';

/** @param {number | null} v @param {number} digits */
const num = (v, digits = 4) => (v == null ? '—' : Number(v).toPrecision(digits));

/**
 * The figures of a run, by row: its key (the cell's `data-metric`), its label, and its value
 * and text from a run (playground/compare.js ComparedRun).
 * @type {[string, string, (r: import('../playground/compare.js').ComparedRun) => [number | null, string]][]}
 */
const ROWS = [
  ['arrivals', 'at goal and heading', (r) => [r.arrivals, `${r.arrivals} of ${r.robots}`]],
  [
    'last_arrival',
    'time to the last arrival (s)',
    (r) => [r.lastArrival, r.lastArrival == null ? 'not all' : r.lastArrival.toFixed(2)],
  ],
  [
    'path_length',
    'path length, all robots (m)',
    // A run of more steps than its samples sums |v| every few steps: marked as approximate.
    (r) => [r.pathLength, `${r.everyStep ? '' : '≈ '}${num(r.pathLength)}`],
  ],
  ['min_pair', 'closest pair (m)', (r) => [r.minPair, num(r.minPair)]],
  ['min_clearance', 'closest to an obstacle (m)', (r) => [r.minClearance, num(r.minClearance)]],
  ['violations', 'violations', (r) => [r.violations, String(r.violations)]],
];

/**
 * The table of `runs` (the scenario's planner's, then the compared one's) of scenario `s`, and
 * a line on the conditions both share; `colour` marks the compared run's column; `planners`
 * (the wasm module's list) says what each planner avoids on its own, before the shared barrier.
 * @param {import('../playground/compare.js').ComparedRun[]} runs
 * @param {any} s
 * @param {string} colour
 * @param {import('../playground/wasm-views.js').PlannerInfo[]} planners
 * @returns {HTMLElement[]}
 */
export function compareTable(runs, s, colour, planners) {
  const table = el('table', undefined, 'results-table compare-table');
  table.dataset.id = 'compare-table';
  const head = el('tr');
  head.append(el('th', ''));
  runs.forEach((r, i) => {
    const th = el('th', i === 0 ? `${r.planner} (live)` : r.planner);
    th.dataset.planner = r.planner;
    if (i > 0) th.style.color = colour;
    head.append(th);
  });
  table.append(head);
  const avoids = el('tr');
  avoids.append(el('th', 'avoids on its own'));
  for (const r of runs) avoids.append(el('td', planners.find((p) => p.name === r.planner)?.avoids ?? '—'));
  table.append(avoids);
  for (const [key, label, value] of ROWS) {
    const row = el('tr');
    row.append(el('th', label));
    for (const r of runs) {
      const [v, text] = value(r);
      const td = el('td', text);
      td.dataset.metric = key;
      td.dataset.planner = r.planner;
      td.dataset.value = v == null ? '' : String(v);
      row.append(td);
    }
    table.append(row);
  }
  const barrier = s.params?.barrier_rate == null ? 'without the safety barrier' : 'with the same safety barrier';
  const limits =
    s.params?.v_max == null && s.params?.omega_max == null
      ? 'no speed limits'
      : `v_max ${s.params.v_max ?? 'none'}, ω_max ${s.params.omega_max ?? 'none'}`;
  return [el('p', `Both runs: the scene from t = 0 to ${s.duration} s, ${barrier}, ${limits}.`, 'muted'), table];
}
