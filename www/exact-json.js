// Scenario JSON that the core reads back to the very numbers that wrote it. The core reads
// JSON with serde_json's fast number parser (without its `float_roundtrip` feature, which would
// cost the wasm package 29 KB): the digits accumulate in a u64 significand M, which is rounded
// to a double and then divided (or multiplied) by 10^k, two roundings where a correct parser
// makes one. For a shortest decimal of 17 digits that lands one unit in the last place off
// about a third of the time, so an exported scene would import a hair away from itself. For
// such a number this module writes other digits: an M of up to 19 digits whose two roundings
// give the number exactly and whose exact value M / 10^k still lies within half a unit of it,
// so that correct parsers (JavaScript's, Python's) read the same number too.

/** Powers of ten exact in a double (serde_json's POW10 table goes on, but inexactly). */
const MAX_EXACT_POW10 = 22;
/** serde_json accumulates at most this significand before it takes its overflow path. */
const MAX_SIGNIFICAND = 10n ** 19n - 1n;

const f64 = new Float64Array(1);
const bits = new BigUint64Array(f64.buffer);

/** The double that serde_json's default parser makes of digits `m` (BigInt) and exponent `e`. */
function serdeValue(m, e) {
  const f = Number(m);
  return e >= 0 ? f * 10 ** e : f / 10 ** -e;
}

/** What serde_json reads for the shortest text of positive `x`, or null when out of the model. */
function serdeReads(text) {
  const m = /^(\d+)(?:\.(\d+))?(?:e([+-]?\d+))?$/.exec(text);
  if (!m) return null;
  const digits = m[1] + (m[2] ?? '');
  const e = Number(m[3] ?? 0) - (m[2]?.length ?? 0);
  const sig = BigInt(digits);
  if (sig > MAX_SIGNIFICAND || Math.abs(e) > MAX_EXACT_POW10) return null;
  return serdeValue(sig, e);
}

/** The next double above positive `d`. */
function nextUp(d) {
  f64[0] = d;
  bits[0] += 1n;
  return f64[0];
}

/** Positive `x` as mantissa·2^exp (BigInt mantissa), exactly. */
function decompose(x) {
  f64[0] = x;
  const b = bits[0];
  const biased = Number((b >> 52n) & 0x7ffn);
  const frac = b & ((1n << 52n) - 1n);
  return biased === 0 ? { m: frac, e: -1074 } : { m: frac | (1n << 52n), e: biased - 1075 };
}

/** `m · 10^k` written with the decimal point `k` places from the right. */
function withPoint(m, k) {
  const s = m.toString().padStart(k + 1, '0');
  return k ? `${s.slice(0, s.length - k)}.${s.slice(s.length - k)}` : s;
}

/**
 * Digits for positive `x` that serde_json reads as `x` and whose exact value rounds to `x`,
 * or null when none is found.
 */
function exactDigits(x) {
  const { m, e } = decompose(x);
  if (m === 1n << 52n) return null; // a power of two: its lower neighbour is closer; rare, skip
  const kMax = Math.min(MAX_EXACT_POW10, Math.floor(Math.log10(Number(MAX_SIGNIFICAND) / x)));
  for (let k = kMax; k >= Math.max(0, kMax - 3); k--) {
    // The open interval of integers M with M / 10^k within half a unit of x:
    // ((2m − 1) · 10^k · 2^(e−1), (2m + 1) · 10^k · 2^(e−1)).
    const p = 10n ** BigInt(k);
    const scale = e - 1;
    const bound = (n) => (scale >= 0 ? n * p * (1n << BigInt(scale)) : (n * p) / (1n << BigInt(-scale)));
    const lo = bound(2n * m - 1n) + 1n;
    const hi = bound(2n * m + 1n) - 1n;
    if (lo > hi || hi > MAX_SIGNIFICAND) continue;
    // Below 2^53 an M is a double already: one rounding, the correct one.
    if (lo <= 2n ** 53n) {
      if (serdeValue(lo, -k) === x) return withPoint(lo, k);
      continue;
    }
    // The doubles that some M in [lo, hi] rounds to (integers, lo > 2^53 here): that of lo,
    // those in between, that of hi. For each, an M in [lo, hi] that rounds to it.
    for (let d = Number(lo); d <= Number(hi); d = nextUp(d)) {
      const at = BigInt(d);
      const sig = at < lo ? lo : at > hi ? hi : at;
      if (Number(sig) === d && serdeValue(sig, -k) === x) return withPoint(sig, k);
    }
  }
  return null;
}

/** A JSON replacer: numbers that serde_json would misread as raw JSON digits it reads exactly. */
function replacer(_key, value) {
  if (typeof value !== 'number' || !Number.isFinite(value) || value === 0) return value;
  const abs = Math.abs(value);
  const read = serdeReads(String(abs));
  if (read === null || read === abs) return value;
  const digits = exactDigits(abs);
  // JSON.rawJSON: Chromium 114 and later; elsewhere the shortest digits (a hair off in the core).
  const raw = /** @type {any} */ (JSON).rawJSON;
  return digits && raw ? raw(value < 0 ? `-${digits}` : digits) : value;
}

/** `value` as JSON text (indented by `indent` spaces) that the core reads back exactly. */
export function exactJson(value, indent = 0) {
  return JSON.stringify(value, replacer, indent || undefined);
}
