// The drag benchmark: milliseconds of work per pointer move when one robot of the 10,000-robot
// crowd is dragged (the facade's moveRobot, which checks what the move touches and updates the
// model in place, between setDragging(true) and setDragging(false) as the page's drag: up to
// 100 robots each move predicts a shorter way ahead, and the release in full, timed apart), in
// Node on the RELEASE wasm package. Paused at t = 0 (editing the starts) and
// paused at t > 0 (editing where the robots are now). Prints one JSON line per case with the
// median and the 90th percentile; `--budget MS` makes it exit 1 when a median exceeds MS (make
// bench-wasm passes 5). Not part of `make test`: a time is not behaviour. The figures are also
// written to test-results/bench-drag.json.
//
//   make build-wasm && node benches/drag.mjs [--robots 10000] [--moves 200] [--budget 5]

import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { performance } from 'node:perf_hooks';
import { fileURLToPath } from 'node:url';
import init, { Playground } from '../www/pkg/dvf.js';
import { quantile } from './quantile.mjs';

/** The value after `--name` as a number, or `fallback`. */
function option(name, fallback) {
  const at = process.argv.indexOf(`--${name}`);
  if (at < 0) return fallback;
  const value = Number(process.argv[at + 1]);
  if (!Number.isFinite(value) || value < 0) {
    console.error(`${name}: expected a non-negative number, not ${process.argv[at + 1]}`);
    process.exit(2);
  }
  return value;
}

const robots = option('robots', 10_000);
const moves = option('moves', 200);
const budget = option('budget', Number.POSITIVE_INFINITY);

const wasmPath = fileURLToPath(new URL('../www/pkg/dvf_bg.wasm', import.meta.url));
const { memory } = await init({ module_or_path: readFileSync(wasmPath) });

let failed = false;
const lines = [];
for (const ahead of [0, 50]) {
  const pg = Playground.fromPreset(`crowd-${robots}`);
  if (ahead > 0) pg.step(ahead);
  // Robot 0 of the crowd sits on the circle; it is dragged along a short arc inward and back,
  // a small step per move as a pointer gives, from where it is now.
  const { poses } = pg.layout();
  const [x0, y0, theta] = new Float64Array(memory.buffer, poses.pointer, poses.stride);
  const times = [];
  let refused = 0;
  pg.setDragging(true);
  for (let k = 0; k < moves; k++) {
    const s = 0.5 * Math.sin((2 * Math.PI * k) / moves);
    const t0 = performance.now();
    try {
      pg.moveRobot(0, x0 - s, y0 + 0.25 * s, theta);
    } catch {
      refused += 1;
    }
    times.push(performance.now() - t0);
  }
  const released = performance.now();
  pg.setDragging(false);
  const releaseMs = performance.now() - released;
  // The whole-scenario path the fine-grained edit replaces (serialise, validate, rebuild), for
  // the ratio: a few moves, it is slow.
  const whole = [];
  const scenario = pg.scenario();
  for (let k = 0; k < Math.min(10, moves); k++) {
    scenario.robots[0].start = [x0 - 0.01 * k, y0, theta];
    const t0 = performance.now();
    pg.edit(scenario);
    whole.push(performance.now() - t0);
  }
  const median = quantile(times, 0.5);
  const line = {
    robots,
    t: pg.time,
    moves,
    refused,
    ms_per_move_median: Number(median.toFixed(3)),
    ms_per_move_p90: Number(quantile(times, 0.9).toFixed(3)),
    ms_release: Number(releaseMs.toFixed(3)),
    ms_per_whole_edit_median: Number(quantile(whole, 0.5).toFixed(3)),
  };
  if (Number.isFinite(budget)) line.budget_ms = budget;
  console.log(JSON.stringify(line));
  lines.push(line);
  if (median > budget) failed = true;
  pg.free();
}

// The figures, recorded beside the other benchmarks' (an ignored folder).
const results = fileURLToPath(new URL('../test-results/', import.meta.url));
mkdirSync(results, { recursive: true });
writeFileSync(`${results}bench-drag.json`, `${JSON.stringify(lines, null, 2)}\n`);
process.exit(failed ? 1 : 0);
