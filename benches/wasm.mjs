// The wasm build's counterpart of `dvf bench`: times the crowd scenario in Node and prints
// {"robots": N, "steps": S, "obstacles": M, "ms_per_step": x}.
//
//   make build-wasm && node benches/wasm.mjs --robots 1000 --steps 100 [--obstacles 0] [--warmup MS]
//
// Before the timed crowd, another crowd of the same size steps untimed for MS milliseconds (500
// by default): V8 first runs a module in its baseline tier and compiles the functions it finds
// hot with its optimising tier meanwhile, so that the first steps of a fresh page cost more than
// the rest (`node --no-liftoff` starts in the optimising tier, for comparison). The timed crowd
// starts at t = 0 like the native one. `--warmup 0` times the cold module.
//
// `--wasm FILE` times another build of the same crate (say, one with SIMD128) through the same
// bindings: two builds compared in one run.

import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import init, { CrowdBench } from '../www/pkg/dvf.js';
import { msPerStep, warmUp } from './crowd-bench.mjs';
import { option } from './options.mjs';

const robots = option('robots', 1000);
const steps = option('steps', 100);
const obstacles = option('obstacles', 0);
const warmup = option('warmup', 500);

const other = process.argv.indexOf('--wasm');
const wasmPath =
  other >= 0 ? process.argv[other + 1] : fileURLToPath(new URL('../www/pkg/dvf_bg.wasm', import.meta.url));
await init({ module_or_path: readFileSync(wasmPath) });

try {
  if (steps < 1) throw new Error(`steps: must be at least 1, not ${steps}`);
  warmUp(CrowdBench, robots, obstacles, warmup);
  const ms = msPerStep(CrowdBench, robots, obstacles, steps);
  console.log(`{"robots": ${robots}, "steps": ${steps}, "obstacles": ${obstacles}, "ms_per_step": ${ms}}`);
} catch (e) {
  console.error(e.message ?? String(e));
  process.exit(2);
}
