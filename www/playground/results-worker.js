// A module worker that runs a scenario to its end off the page's thread (`Run`: the run that
// `dvf simulate` makes) and posts its report, the figures of the results panel
// (panels/results.js), and with `trajectories` its trajectories too (a pinned run,
// ghost.js), and for a run with violations where they happened (violations.js: `marks`).
// Messages in: first {wasm}, where the page loads the module from (its URL or its bytes:
// wasm-views.js, runWorker), then {id, scenario, trajectories?}; out:
// {id, report, marks, trajectories?, samples?} or {id, error}. With `compare` (a list of
// planners, names or objects with their gains) it runs the scene with each instead, through
// the module's `compare()` (the JSON of `dvf compare --json`, compare.js's table): out
// {id, comparison} or {id, error}. The module is loaded on the first run only.

import init, { compare, Run } from '../pkg/dvf.js';
import { findViolations } from './violations.js';

/** Where the module comes from (the first message), and the module once a run asks for it. */
let source = null;
/** @type {Promise<unknown> | null} */
let ready = null;

self.onmessage = async (e) => {
  if ('wasm' in e.data) {
    source = e.data.wasm;
    return;
  }
  const { id, scenario } = e.data;
  try {
    if (source === null) throw new Error('no wasm module was given to the worker');
    ready ??= init({ module_or_path: source });
    await ready;
    if (e.data.compare) {
      self.postMessage({ id, comparison: compare(scenario, e.data.compare) });
      return;
    }
    const run = new Run(scenario);
    try {
      if (e.data.trajectories) {
        const trajectories = run.trajectories();
        self.postMessage(
          { id, report: run.report(), trajectories, samples: run.sampleCount },
          { transfer: [trajectories.buffer] },
        );
      } else {
        const report = run.report();
        const marks =
          report.violations > 0 ? findViolations(run.trajectories(), run.sampleCount, scenario, report) : [];
        self.postMessage({ id, report, marks });
      }
    } finally {
      run.free();
    }
  } catch (err) {
    self.postMessage({ id, error: String(err instanceof Error ? err.message : err) });
  }
};
