// Where a run's violations happened, from its recorded trajectories (a `Run`'s, src/wasm/run.rs:
// per robot, per sample t, x, y, θ, v, ω): the closest approach of two robots below the safe
// distance 2·r_ij, and the deepest intrusion of a robot into an obstacle's disc, each with its
// time, place and who. The report counts the violation events at every step; the trajectories
// are samples of the run (every step, or every few steps of a long run), so a mark is the worst
// sample of the run: for a violation shorter than the recording interval, the closest sampled
// approach. Run in the results worker (results-worker.js), off the page's thread.

/** Values per trajectory sample: t, x, y, θ, v, ω. */
const SAMPLE = 6;
/** Pairs up to this many safe distances apart are searched for the closest approach. */
const PAIR_REACH = 2;

/**
 * A violation's mark: `kind` 'pair' (robots `robots[0]` and `robots[1]`, their midpoint) or
 * 'obstacle' (robot `robots[0]` inside obstacle `obstacle`, at the robot); the time (s), the
 * place (m) and the distance (m: between the two robots, or the robot's depth inside the disc).
 * @typedef {{kind: 'pair' | 'obstacle', time: number, x: number, y: number, distance: number,
 *   robots: number[], obstacle?: number}} ViolationMark
 */

/**
 * The marks of the run `trajectories` (`[robots · samples · 6]`) of `scenario` with report
 * `report`: the closest approach of two robots when it is below 2·r_ij (none for independent
 * robots) and the deepest obstacle intrusion, when there is one. When the report saw one that
 * fell between two samples, the closest sampled approach (or the smallest clearance) marks it.
 * @param {Float64Array} trajectories
 * @param {number} samples per robot
 * @param {any} scenario the scenario that was run
 * @param {any} report its report (the JSON of dvf simulate)
 * @returns {ViolationMark[]}
 */
export function findViolations(trajectories, samples, scenario, report) {
  const n = scenario.robots.length;
  const at = (i, k) => (i * samples + k) * SAMPLE;
  /** @type {ViolationMark[]} */
  const marks = [];
  const safe = 2 * scenario.params.safe_radius;
  if (!scenario.independent && n > 1) {
    const pair = closestPair(trajectories, samples, n, PAIR_REACH * safe);
    if (pair && (pair.distance < safe || report.min_pair_distance < safe)) {
      const [a, b] = [at(pair.i, pair.k), at(pair.j, pair.k)];
      marks.push({
        kind: 'pair',
        time: trajectories[a],
        x: (trajectories[a + 1] + trajectories[b + 1]) / 2,
        y: (trajectories[a + 2] + trajectories[b + 2]) / 2,
        distance: pair.distance,
        robots: [pair.i, pair.j],
      });
    }
  }
  /** @type {ViolationMark | null} */
  let deepest = null;
  scenario.obstacles.forEach((o, m) => {
    for (let i = 0; i < n; i++) {
      for (let k = 0; k < samples; k++) {
        const p = at(i, k);
        const depth = o.radius - Math.hypot(trajectories[p + 1] - o.center[0], trajectories[p + 2] - o.center[1]);
        if (!deepest || depth > deepest.distance) {
          deepest = {
            kind: 'obstacle',
            time: trajectories[p],
            x: trajectories[p + 1],
            y: trajectories[p + 2],
            distance: depth,
            robots: [i],
            obstacle: m,
          };
        }
      }
    }
  });
  if (deepest && (deepest.distance > 0 || report.min_obstacle_clearance < 0)) marks.push(deepest);
  return marks;
}

/**
 * The closest pair of robots at any sample, among pairs closer than `reach` (m): a sweep along
 * x of each sample's robots in x order, which looks only at pairs less than the closest
 * distance so far apart in x. Null when no pair comes within `reach`.
 */
function closestPair(trajectories, samples, n, reach) {
  const order = new Uint32Array(n);
  const xs = new Float64Array(n);
  const ys = new Float64Array(n);
  let best = null;
  let limit = reach;
  for (let k = 0; k < samples; k++) {
    for (let i = 0; i < n; i++) {
      const p = (i * samples + k) * SAMPLE;
      xs[i] = trajectories[p + 1];
      ys[i] = trajectories[p + 2];
      order[i] = i;
    }
    order.sort((a, b) => xs[a] - xs[b]);
    for (let u = 0; u < n; u++) {
      const i = order[u];
      for (let w = u + 1; w < n; w++) {
        const j = order[w];
        if (xs[j] - xs[i] >= limit) break;
        const d = Math.hypot(xs[j] - xs[i], ys[j] - ys[i]);
        if (d < limit) {
          limit = d;
          best = { i: Math.min(i, j), j: Math.max(i, j), k, distance: d };
        }
      }
    }
  }
  return best;
}
