// A module worker that runs a scenario to its end off the page's thread (`Run`: the run that
// `dvf simulate` makes) and posts its report, the figures of the results panel
// (panels/results.js), and with `trajectories` its trajectories too (a pinned run,
// ghost.js). Messages in: {id, scenario, trajectories?}; out: {id, report, trajectories?,
// samples?} or {id, error}.

import init, { Run } from '../pkg/dvf.js';

const ready = init();

self.onmessage = async (e) => {
  const { id, scenario } = e.data;
  try {
    await ready;
    const run = new Run(scenario);
    try {
      if (e.data.trajectories) {
        const trajectories = run.trajectories();
        self.postMessage(
          { id, report: run.report(), trajectories, samples: run.sampleCount },
          { transfer: [trajectories.buffer] },
        );
      } else {
        self.postMessage({ id, report: run.report() });
      }
    } finally {
      run.free();
    }
  } catch (err) {
    self.postMessage({ id, error: String(err instanceof Error ? err.message : err) });
  }
};
