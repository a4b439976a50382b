// The wasm build against the native one in alternating rounds: each round times S steps of
// the crowd natively (`dvf bench`, one thread, a process of its own) and then S steps of the
// same crowd in this Node process (the release package), and takes the ratio of the two. Prints
// {"robots": N, "steps": S, "rounds": R, "wasm_over_native": median, "min": …, "max": …} and
// each round's pair of ms per step on stderr.
//
//   make build-wasm && cargo build --release
//   taskset -c 0 node benches/wasm-native.mjs --robots 1000 --steps 100 --rounds 40
//
// Why rounds, on one core: on a virtual machine whose host is shared the speed of a core can
// change by half from one second to the next, and two cores can differ as much at the same
// moment (docs/book/src/performance.md), so that one run of each build, seconds
// apart, measures the host as much as the builds. A round takes a fraction of a second, the
// median of the rounds' ratios sees both builds under the same load, and `taskset` keeps this
// process and its native children on the same core.

import { existsSync, readFileSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import init, { CrowdBench } from '../www/pkg/dvf.js';
import { msPerStep, warmUp } from './crowd-bench.mjs';
import { option } from './options.mjs';

const robots = option('robots', 1000);
const steps = option('steps', 100);
const rounds = option('rounds', 40);
const warmup = option('warmup', 500);
if (steps < 1 || rounds < 1) {
  console.error(`steps and rounds: must be at least 1, not ${steps} and ${rounds}`);
  process.exit(2);
}
const dvf = fileURLToPath(new URL('../target/release/dvf', import.meta.url));

await init({
  module_or_path: readFileSync(fileURLToPath(new URL('../www/pkg/dvf_bg.wasm', import.meta.url))),
});

/** Milliseconds per step of `steps` steps of the crowd in the native build, on one thread. */
function native() {
  if (!existsSync(dvf)) throw new Error(`${dvf}: not built; run \`cargo build --release\` first`);
  const out = execFileSync(dvf, ['bench', '--robots', String(robots), '--steps', String(steps)], {
    env: { ...process.env, RAYON_NUM_THREADS: '1' },
  });
  const line = out
    .toString()
    .split('\n')
    .filter((l) => l.startsWith('{'))
    .pop();
  return JSON.parse(line).ms_per_step;
}

const ratios = [];
try {
  warmUp(CrowdBench, robots, 0, warmup);
  for (let k = 0; k < rounds; k++) {
    const n = native();
    const w = msPerStep(CrowdBench, robots, 0, steps);
    ratios.push(w / n);
    process.stderr.write(`${n.toFixed(3)}/${w.toFixed(3)} `);
  }
  process.stderr.write('\n');
} catch (e) {
  console.error(e.message ?? String(e));
  process.exit(2);
}
ratios.sort((a, b) => a - b);
const r = (x) => x.toFixed(3);
console.log(
  `{"robots": ${robots}, "steps": ${steps}, "rounds": ${rounds}, "wasm_over_native": ${r(ratios[rounds >> 1])}, "min": ${r(ratios[0])}, "max": ${r(ratios[rounds - 1])}}`,
);
