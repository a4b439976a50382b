// The nearest-rank quantile of the benchmarks' figures (`drag.mjs`, `tests/e2e/bench-browser.mjs`).

/** The q-quantile of `values` (a sorted copy, nearest rank). */
export function quantile(values, q) {
  const s = [...values].sort((a, b) => a - b);
  return s[Math.min(s.length - 1, Math.max(0, Math.ceil(q * s.length) - 1))];
}
